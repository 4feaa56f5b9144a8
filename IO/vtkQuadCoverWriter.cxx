#include "vtkQuadCoverWriter.h"

#include "vtkQuadCoverFileChecks.h"

#include "vtkErrorCode.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkOBJWriter.h"
#include "vtkObjectFactory.h"
#include "vtkPLYWriter.h"
#include "vtkPolyData.h"
#include "vtkPolyDataWriter.h"
#include "vtkQuadCoverErrorObserver.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataWriter.h"

#include <fstream>

vtkStandardNewMacro(vtkQuadCoverWriter);

namespace
{
/// The VTK writer for the extension, set up to write `surface` to `path`.
vtkSmartPointer<vtkAlgorithm> MakeWriter(const std::string& path, vtkPolyData* surface)
{
  const std::string ext = vtkQuadCoverFileChecks::Extension(path);
  if (ext == ".vtp")
  {
    auto w = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    w->SetFileName(path.c_str());
    w->SetDataModeToAppended();
    w->SetCompressorTypeToZLib();
    w->SetInputData(surface);
    return w;
  }
  if (ext == ".vtk")
  {
    auto w = vtkSmartPointer<vtkPolyDataWriter>::New();
    w->SetFileName(path.c_str());
    w->SetFileTypeToBinary();
    w->SetInputData(surface);
    return w;
  }
  if (ext == ".obj")
  {
    auto w = vtkSmartPointer<vtkOBJWriter>::New();
    w->SetFileName(path.c_str());
    w->SetInputData(surface);
    return w;
  }
  auto w = vtkSmartPointer<vtkPLYWriter>::New();
  w->SetFileName(path.c_str());
  w->SetFileTypeToBinary();
  w->SetInputData(surface);
  return w;
}
}

//------------------------------------------------------------------------------
vtkQuadCoverWriter::vtkQuadCoverWriter() = default;

//------------------------------------------------------------------------------
vtkQuadCoverWriter::~vtkQuadCoverWriter()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
bool vtkQuadCoverWriter::CanWriteFile(const char* fileName)
{
  const std::string e = vtkQuadCoverFileChecks::Extension(fileName ? fileName : "");
  return e == ".vtp" || e == ".vtk" || e == ".obj" || e == ".ply";
}

//------------------------------------------------------------------------------
int vtkQuadCoverWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
void vtkQuadCoverWriter::WriteData()
{
  this->SetErrorCode(vtkErrorCode::NoError);
  const std::string path = this->FileName ? this->FileName : "";
  vtkPolyData* surface = vtkPolyData::SafeDownCast(this->GetInput());
  std::string error;
  if (!CanWriteFile(path.c_str()))
  {
    error = "unknown extension (use .vtp .vtk .obj or .ply)";
  }
  else if (!surface)
  {
    error = "no surface to write";
  }
  else
  {
    vtkSmartPointer<vtkAlgorithm> writer = MakeWriter(path, surface);
    vtkNew<vtkQuadCoverErrorObserver> errors;
    errors->Attach(writer);
    writer->Update();
    error = errors->GetError();
    if (error.empty() && !std::ifstream(path).good())
    {
      error = "the file was not written";
    }
  }
  if (!error.empty())
  {
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
    vtkErrorMacro(<< "cannot write '" << path << "': " << error);
  }
}

//------------------------------------------------------------------------------
void vtkQuadCoverWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
