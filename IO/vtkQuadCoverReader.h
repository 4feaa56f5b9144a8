/**
 * @class   vtkQuadCoverReader
 * @brief   reads a surface from .obj, .off, .ply, .stl, .vtp or .vtk, chosen by extension
 *
 * One reader for every format QuadCover takes, with one-line errors for what goes wrong:
 * a missing, unreadable or empty file, an unknown extension, a file with no points (and, for
 * OFF, one that ends early).
 * OBJ and ASCII OFF files it reads itself, in double precision: OBJ in one pass over the file
 * (its points in the file's order; NaN or infinite coordinates, face indices that are not
 * points, faces of fewer than three vertices and binary data refused, naming the line), OFF,
 * which VTK has no reader for (the header keyword with the usual prefixes ST, C and N, comments,
 * counts on the header line or the next; binary, 4D and nOFF files are refused). For the other
 * formats it checks what VTK 9.1's own readers get wrong before they read: PLY files with face
 * indices past the vertices, cut short, or whose header claims more elements than the file
 * holds (which crash its reader or make it allocate without bound), and PLY coordinates beyond
 * single precision (which it stores as infinite); binary STL files whose header counts more
 * triangles than the file holds (cut short; its reader allocates for the count).
 * The output is whatever the file holds (polygons, strips, lines, vertices, point and cell
 * data); vtkQuadCoverSurfaceRepair makes a triangle surface of it.
 * @sa vtkQuadCoverWriter vtkQuadCoverSurfaceRepair
 */
#ifndef vtkQuadCoverReader_h
#define vtkQuadCoverReader_h

#include "vtkAbstractPolyDataReader.h"
#include "vtkQuadCoverIOModule.h" // for export macro

class VTKQUADCOVERIO_EXPORT vtkQuadCoverReader : public vtkAbstractPolyDataReader
{
public:
  static vtkQuadCoverReader* New();
  vtkTypeMacro(vtkQuadCoverReader, vtkAbstractPolyDataReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** True when the file name ends in an extension this reader knows (case ignored). */
  static bool CanReadFile(const char* fileName);

protected:
  vtkQuadCoverReader() = default;
  ~vtkQuadCoverReader() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkQuadCoverReader(const vtkQuadCoverReader&) = delete;
  void operator=(const vtkQuadCoverReader&) = delete;
};

#endif
