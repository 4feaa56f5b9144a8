/**
 * @class   vtkQuadCoverWriter
 * @brief   writes a surface as .vtp, .vtk, .obj or .ply, chosen by extension
 *
 * .vtp (XML, appended, zlib-compressed) and .vtk (legacy binary) keep every array; .obj and
 * .ply (binary) keep the geometry: points and polygons (a quad mesh stays quads). Errors are
 * one line ("cannot write 'out.obj': ...").
 * @sa vtkQuadCoverReader
 */
#ifndef vtkQuadCoverWriter_h
#define vtkQuadCoverWriter_h

#include "vtkQuadCoverIOModule.h" // for export macro
#include "vtkWriter.h"

class VTKQUADCOVERIO_EXPORT vtkQuadCoverWriter : public vtkWriter
{
public:
  static vtkQuadCoverWriter* New();
  vtkTypeMacro(vtkQuadCoverWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The file to write (default none). */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  /** True when the file name ends in an extension this writer knows (case ignored). */
  static bool CanWriteFile(const char* fileName);

protected:
  vtkQuadCoverWriter();
  ~vtkQuadCoverWriter() override;

  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  char* FileName = nullptr;

private:
  vtkQuadCoverWriter(const vtkQuadCoverWriter&) = delete;
  void operator=(const vtkQuadCoverWriter&) = delete;
};

#endif
