#include "vtkQuadCoverReader.h"

#include "vtkQuadCoverFileChecks.h"
#include "vtkQuadCoverOBJ.h"
#include "vtkQuadCoverOFF.h"
#include "vtkQuadCoverSTL.h"

#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPLYReader.h"
#include "vtkPolyData.h"
#include "vtkPolyDataReader.h"
#include "vtkQuadCoverErrorObserver.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataReader.h"

#include <fstream>
#include <sys/stat.h>

vtkStandardNewMacro(vtkQuadCoverReader);

namespace
{
/// "" when `path` names a non-empty, readable file, else why not.
std::string CheckFile(const std::string& path)
{
  struct stat info;
  if (stat(path.c_str(), &info) != 0)
  {
    return "no such file";
  }
  if (S_ISDIR(info.st_mode) || !std::ifstream(path).good())
  {
    return "not a readable file";
  }
  return info.st_size == 0 ? "the file is empty" : "";
}

/// The VTK reader for the extension, after the checks its format needs; null and `error` set
/// when a check fails.
vtkSmartPointer<vtkAlgorithm> MakeReader(const std::string& path, std::string& error)
{
  namespace checks = vtkQuadCoverFileChecks;
  const std::string ext = checks::Extension(path);
  auto make = [&](auto reader) -> vtkSmartPointer<vtkAlgorithm> {
    reader->SetFileName(path.c_str());
    return reader;
  };
  if (ext == ".ply")
  {
    error = checks::CheckPly(path);
    return error.empty() ? make(vtkSmartPointer<vtkPLYReader>::New()) : nullptr;
  }
  if (ext == ".vtp")
  {
    return make(vtkSmartPointer<vtkXMLPolyDataReader>::New());
  }
  auto legacy = vtkSmartPointer<vtkPolyDataReader>::New();
  legacy->SetFileName(path.c_str());
  if (!legacy->IsFilePolyData())
  {
    error = "not a legacy VTK polydata file";
    return nullptr;
  }
  return legacy;
}

/// Reads `path` (whose extension CanReadFile knows) into `out`; "" or the first error.
std::string ReadFile(const std::string& path, vtkPolyData* out)
{
  const std::string ext = vtkQuadCoverFileChecks::Extension(path);
  if (ext == ".obj")
  {
    return vtkQuadCoverOBJ::Read(path, out);
  }
  if (ext == ".off")
  {
    return vtkQuadCoverOFF::Read(path, out);
  }
  if (ext == ".stl")
  {
    return vtkQuadCoverSTL::Read(path, out);
  }
  std::string error;
  vtkSmartPointer<vtkAlgorithm> reader = MakeReader(path, error);
  if (!reader)
  {
    return error;
  }
  error = vtkQuadCoverErrorObserver::Run(reader);
  if (error.empty())
  {
    out->ShallowCopy(reader->GetOutputDataObject(0));
  }
  return error;
}
}

//------------------------------------------------------------------------------
bool vtkQuadCoverReader::CanReadFile(const char* fileName)
{
  const std::string e = vtkQuadCoverFileChecks::Extension(fileName ? fileName : "");
  return e == ".obj" || e == ".off" || e == ".ply" || e == ".stl" || e == ".vtp" || e == ".vtk";
}

//------------------------------------------------------------------------------
int vtkQuadCoverReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  const std::string path = this->FileName ? this->FileName : "";
  vtkNew<vtkPolyData> read;
  std::string error = path.empty() ? "no file name given"
    : !CanReadFile(path.c_str())   ? "unknown extension (use .obj .off .ply .stl .vtp or .vtk)"
                                   : CheckFile(path);
  if (error.empty())
  {
    error = ReadFile(path, read);
  }
  if (error.empty() && read->GetNumberOfPoints() == 0)
  {
    error = "no points found (empty, or not a valid " + vtkQuadCoverFileChecks::Extension(path) +
      " file)";
  }
  if (!error.empty())
  {
    vtkErrorMacro(<< "cannot read '" << path << "': " << error);
    return 0;
  }
  vtkPolyData::GetData(outputVector)->ShallowCopy(read);
  return 1;
}

//------------------------------------------------------------------------------
void vtkQuadCoverReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
