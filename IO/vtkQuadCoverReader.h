/**
 * @class   vtkQuadCoverReader
 * @brief   reads a surface from .obj, .off, .ply, .stl, .vtp or .vtk, chosen by extension
 *
 * One reader for every format QuadCover takes, with one-line errors for what goes wrong:
 * a missing, unreadable, empty or truncated file, an unknown extension, a file with no points.
 * It checks what VTK 9.1's own readers get wrong before they read: OBJ files with NaN or
 * infinite coordinates (read as 0) or face indices past the vertices, PLY files with face
 * indices past the vertices (which crash its reader). OFF files are read by vtkOFFReader.
 * The output is whatever the file holds (polygons, strips, lines, vertices, point and cell
 * data); vtkQuadCoverSurfaceRepair makes a triangle surface of it.
 * @sa vtkOFFReader vtkQuadCoverWriter vtkQuadCoverSurfaceRepair
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
