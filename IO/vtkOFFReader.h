/**
 * @class   vtkOFFReader
 * @brief   reads a polygon surface from an ASCII OFF file (Geomview's Object File Format)
 *
 * Much of geometry processing's data comes as OFF, which VTK has no reader for. Accepted: the
 * header keyword OFF with the usual prefixes (ST, C, N: texture coordinates, colours and normals
 * after each vertex's coordinates, which are skipped), the counts on the header line or the next,
 * comments from '#' to the end of a line, one vertex per line (its first three numbers), one face
 * per line ("n i_1 ... i_n", a colour after it skipped). Faces of one or two points become vertex
 * and line cells. Refused with one line that names the line of the file: 4OFF and nOFF
 * (not three-dimensional), binary OFF, counts that are negative or larger than the file could
 * hold, non-finite coordinates, a face index that is not a vertex, a file that ends early.
 * @sa vtkQuadCoverReader
 */
#ifndef vtkOFFReader_h
#define vtkOFFReader_h

#include "vtkAbstractPolyDataReader.h"
#include "vtkQuadCoverIOModule.h" // for export macro

class VTKQUADCOVERIO_EXPORT vtkOFFReader : public vtkAbstractPolyDataReader
{
public:
  static vtkOFFReader* New();
  vtkTypeMacro(vtkOFFReader, vtkAbstractPolyDataReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkOFFReader() = default;
  ~vtkOFFReader() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkOFFReader(const vtkOFFReader&) = delete;
  void operator=(const vtkOFFReader&) = delete;
};

#endif
