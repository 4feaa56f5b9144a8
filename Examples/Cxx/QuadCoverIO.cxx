#include "QuadCoverIO.h"

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCleanPolyData.h"
#include "vtkExecutive.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkOBJWriter.h"
#include "vtkPLYReader.h"
#include "vtkPLYWriter.h"
#include "vtkPointData.h"
#include "vtkPolyDataNormals.h"
#include "vtkPolyDataReader.h"
#include "vtkPolyDataWriter.h"
#include "vtkSTLReader.h"
#include "vtkTriangleFilter.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"

#include "MeshTopology.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sys/stat.h>

namespace QuadCoverIO
{
namespace
{
std::string Extension(const std::string& path)
{
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
  {
    return "";
  }
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

/// VTK 9.1's OBJ reader turns "nan" and "inf" into 0 without a word: scan the vertex lines.
/// Returns "" or the first offending line.
std::string FindNonFiniteObjVertex(const std::string& path)
{
  std::ifstream in(path);
  std::string line;
  for (long long number = 1; std::getline(in, line); ++number)
  {
    if (line.size() < 2 || line[0] != 'v' || (line[1] != ' ' && line[1] != '\t'))
    {
      continue;
    }
    const char* p = line.c_str() + 1;
    for (int k = 0; k < 3; ++k)
    {
      char* end = nullptr;
      const double x = std::strtod(p, &end);
      if (end == p)
      {
        break; // not a number: the reader reports what it makes of it
      }
      if (!std::isfinite(x))
      {
        return "line " + std::to_string(number) + " has a non-finite (NaN or infinite) coordinate";
      }
      p = end;
    }
  }
  return "";
}

/// Runs an algorithm with an attached observer; returns its first error ("" if none).
std::string Run(vtkAlgorithm* algorithm)
{
  vtkNew<ErrorObserver> errors;
  errors->Attach(algorithm);
  algorithm->Update();
  return errors->Error();
}
}

void ErrorObserver::Execute(vtkObject*, unsigned long event, void* callData)
{
  const std::string text = Clean(static_cast<const char*>(callData));
  if (event == vtkCommand::ErrorEvent)
  {
    if (this->FirstError.empty())
    {
      this->FirstError = text.empty() ? "unknown error" : text;
    }
  }
  else if (event == vtkCommand::WarningEvent)
  {
    this->WarningList.push_back(text);
  }
}

void ErrorObserver::Attach(vtkAlgorithm* algorithm)
{
  algorithm->AddObserver(vtkCommand::ErrorEvent, this);
  algorithm->AddObserver(vtkCommand::WarningEvent, this);
  algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this);
  algorithm->GetExecutive()->AddObserver(vtkCommand::WarningEvent, this);
}

void ErrorObserver::Clear()
{
  this->FirstError.clear();
  this->WarningList.clear();
}

std::string ErrorObserver::Clean(const char* message)
{
  std::string s = message ? message : "";
  // VTK formats "ERROR: In <file>, line <n>\n<class> (<address>): <text>\n\n".
  const auto header = s.find("line ");
  if (header != std::string::npos)
  {
    const auto newline = s.find('\n', header);
    if (newline != std::string::npos)
    {
      s = s.substr(newline + 1);
      const auto colon = s.find("): ");
      if (colon != std::string::npos && colon < 80)
      {
        s = s.substr(colon + 3);
      }
    }
  }
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back())))
  {
    s.pop_back();
  }
  std::replace(s.begin(), s.end(), '\n', ' ');
  return s;
}

bool CanRead(const std::string& path)
{
  const std::string e = Extension(path);
  return e == ".obj" || e == ".ply" || e == ".stl" || e == ".vtp" || e == ".vtk";
}

bool CanWrite(const std::string& path)
{
  const std::string e = Extension(path);
  return e == ".vtp" || e == ".vtk" || e == ".obj" || e == ".ply";
}

vtkSmartPointer<vtkPolyData> ReadSurface(const std::string& path, std::string& error)
{
  if (!CanRead(path))
  {
    error = "cannot read '" + path + "': unknown extension (use .obj .ply .stl .vtp or .vtk)";
    return nullptr;
  }
  struct stat info;
  if (stat(path.c_str(), &info) != 0)
  {
    error = "cannot read '" + path + "': no such file";
    return nullptr;
  }
  if (S_ISDIR(info.st_mode) || !std::ifstream(path).good())
  {
    error = "cannot read '" + path + "': not a readable file";
    return nullptr;
  }
  if (info.st_size == 0)
  {
    error = "cannot read '" + path + "': the file is empty";
    return nullptr;
  }
  const std::string ext = Extension(path);
  vtkSmartPointer<vtkAlgorithm> reader;
  if (ext == ".obj")
  {
    const std::string bad = FindNonFiniteObjVertex(path);
    if (!bad.empty())
    {
      error = "cannot read '" + path + "': " + bad;
      return nullptr;
    }
    auto r = vtkSmartPointer<vtkOBJReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else if (ext == ".ply")
  {
    auto r = vtkSmartPointer<vtkPLYReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else if (ext == ".stl")
  {
    auto r = vtkSmartPointer<vtkSTLReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else if (ext == ".vtp")
  {
    auto r = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else
  {
    auto r = vtkSmartPointer<vtkPolyDataReader>::New();
    r->SetFileName(path.c_str());
    if (!r->IsFilePolyData())
    {
      error = "cannot read '" + path + "': not a legacy VTK polydata file";
      return nullptr;
    }
    reader = r;
  }
  const std::string problem = Run(reader);
  if (!problem.empty())
  {
    error = "cannot read '" + path + "': " + problem;
    return nullptr;
  }
  vtkPolyData* read = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!read || read->GetNumberOfPoints() == 0)
  {
    error = "cannot read '" + path + "': no points found (empty, or not a valid " + ext + " file)";
    return nullptr;
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(read);
  return out;
}

vtkSmartPointer<vtkPolyData> PrepareSurface(
  vtkPolyData* input, Repairs& repairs, std::string& error)
{
  repairs = Repairs();
  if (!input || input->GetNumberOfPoints() == 0)
  {
    error = "the mesh is empty (no points)";
    return nullptr;
  }
  double p[3];
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    input->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
    {
      error = "point " + std::to_string(i) + " has a non-finite (NaN or infinite) coordinate";
      return nullptr;
    }
  }
  if (input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    error = "the mesh has no polygons (a surface of triangles is needed)";
    return nullptr;
  }

  // Surface cells only: vertices and lines are not part of a surface.
  vtkNew<vtkPolyData> polys;
  polys->SetPoints(input->GetPoints());
  polys->GetPointData()->PassData(input->GetPointData());
  polys->SetPolys(input->GetPolys());
  polys->SetStrips(input->GetStrips());
  repairs.removedCells += input->GetNumberOfVerts() + input->GetNumberOfLines();
  {
    vtkCellArray* cells = input->GetPolys();
    for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c)
    {
      repairs.triangulatedPolygons += cells->GetCellSize(c) > 3 ? 1 : 0;
    }
    repairs.triangulatedPolygons += input->GetNumberOfStrips();
  }

  vtkNew<vtkCleanPolyData> clean; // exact duplicates only (tolerance 0)
  clean->SetInputData(polys);
  clean->PointMergingOn();
  clean->SetTolerance(0.0);
  clean->ConvertPolysToLinesOn();
  clean->ConvertLinesToPointsOn();
  std::string problem = Run(clean);
  if (!problem.empty())
  {
    error = problem;
    return nullptr;
  }
  vtkIdType used = 0;
  {
    std::vector<char> referenced(input->GetNumberOfPoints(), 0);
    vtkCellArray* cells = polys->GetPolys();
    vtkNew<vtkIdList> ids;
    for (cells->InitTraversal(); cells->GetNextCell(ids);)
    {
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      {
        used += referenced[ids->GetId(k)] ? 0 : 1;
        referenced[ids->GetId(k)] = 1;
      }
    }
  }
  repairs.mergedPoints = std::max<vtkIdType>(0, used - clean->GetOutput()->GetNumberOfPoints());

  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(clean->GetOutputPort());
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  problem = Run(triangles);
  if (!problem.empty())
  {
    error = problem;
    return nullptr;
  }
  vtkPolyData* tri = triangles->GetOutput();
  if (tri->GetNumberOfPolys() == 0)
  {
    error = "the mesh has no non-degenerate triangles";
    return nullptr;
  }
  repairs.removedCells +=
    clean->GetOutput()->GetNumberOfVerts() + clean->GetOutput()->GetNumberOfLines();

  // Orientation: make neighbours agree, counting the triangles that turned.
  vtkNew<vtkPolyDataNormals> orient;
  orient->SetInputData(tri);
  orient->ConsistencyOn();
  orient->SplittingOff();
  orient->ComputePointNormalsOff();
  orient->ComputeCellNormalsOn(); // with neither kind of normal requested it reorients nothing
  orient->AutoOrientNormalsOff();
  orient->NonManifoldTraversalOff();
  problem = Run(orient);
  if (!problem.empty())
  {
    error = problem;
    return nullptr;
  }
  vtkPolyData* oriented = orient->GetOutput();
  {
    vtkCellArray* a = tri->GetPolys();
    vtkCellArray* b = oriented->GetPolys();
    vtkNew<vtkIdList> ia, ib;
    for (vtkIdType c = 0; c < a->GetNumberOfCells() && c < b->GetNumberOfCells(); ++c)
    {
      a->GetCellAtId(c, ia);
      b->GetCellAtId(c, ib);
      // vtkPolyDataNormals reverses the point list of a triangle it turns.
      bool same = ia->GetNumberOfIds() == ib->GetNumberOfIds();
      for (vtkIdType k = 0; same && k < ia->GetNumberOfIds(); ++k)
      {
        same = ia->GetId(k) == ib->GetId(k);
      }
      repairs.flippedTriangles += same ? 0 : 1;
    }
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(oriented);
  if (!tri->GetCellData()->GetArray("Normals"))
  {
    out->GetCellData()->RemoveArray("Normals"); // the by-product of the reorientation
  }

  // Bowtie vertices: one copy of the vertex per fan, point data copied along.
  const vtkIdType nv = out->GetNumberOfPoints();
  Eigen::MatrixX3d V(nv, 3);
  for (vtkIdType i = 0; i < nv; ++i)
  {
    out->GetPoint(i, p);
    V.row(i) << p[0], p[1], p[2];
  }
  Eigen::MatrixX3i F(out->GetNumberOfPolys(), 3);
  {
    vtkNew<vtkIdList> ids;
    vtkIdType f = 0;
    for (out->GetPolys()->InitTraversal(); out->GetPolys()->GetNextCell(ids); ++f)
    {
      F.row(f) << static_cast<int>(ids->GetId(0)), static_cast<int>(ids->GetId(1)),
        static_cast<int>(ids->GetId(2));
    }
  }
  const quadcover::MeshTopology topo = quadcover::buildTopology(F, static_cast<int>(nv));
  if (!topo.nonManifoldEdges.empty())
  {
    error = "the surface has " + std::to_string(topo.nonManifoldEdges.size()) +
      " non-manifold edges (more than two triangles on one edge); QuadCover needs a manifold "
      "surface";
    return nullptr;
  }
  const std::vector<int> copies = quadcover::splitNonManifoldVertices(V, F);
  repairs.splitVertices = static_cast<long long>(copies.size());
  if (!copies.empty())
  {
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(V.rows());
    for (Eigen::Index i = 0; i < V.rows(); ++i)
    {
      points->SetPoint(i, V(i, 0), V(i, 1), V(i, 2));
    }
    vtkNew<vtkPointData> pointData;
    pointData->CopyAllocate(out->GetPointData(), V.rows());
    for (vtkIdType i = 0; i < V.rows(); ++i)
    {
      pointData->CopyData(out->GetPointData(), i < nv ? i : copies[i - nv], i);
    }
    vtkNew<vtkCellArray> polys;
    for (Eigen::Index f = 0; f < F.rows(); ++f)
    {
      const vtkIdType ids[3] = { F(f, 0), F(f, 1), F(f, 2) };
      polys->InsertNextCell(3, ids);
    }
    out->SetPoints(points);
    out->GetPointData()->ShallowCopy(pointData);
    out->SetPolys(polys);
  }
  return out;
}

bool WriteSurface(vtkPolyData* surface, const std::string& path, std::string& error)
{
  const std::string ext = Extension(path);
  vtkSmartPointer<vtkAlgorithm> writer;
  if (ext == ".vtp")
  {
    auto w = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    w->SetFileName(path.c_str());
    w->SetDataModeToAppended();
    w->SetCompressorTypeToZLib();
    w->SetInputData(surface);
    writer = w;
  }
  else if (ext == ".vtk")
  {
    auto w = vtkSmartPointer<vtkPolyDataWriter>::New();
    w->SetFileName(path.c_str());
    w->SetFileTypeToBinary();
    w->SetInputData(surface);
    writer = w;
  }
  else if (ext == ".obj")
  {
    auto w = vtkSmartPointer<vtkOBJWriter>::New();
    w->SetFileName(path.c_str());
    w->SetInputData(surface);
    writer = w;
  }
  else if (ext == ".ply")
  {
    auto w = vtkSmartPointer<vtkPLYWriter>::New();
    w->SetFileName(path.c_str());
    w->SetFileTypeToBinary();
    w->SetInputData(surface);
    writer = w;
  }
  else
  {
    error = "cannot write '" + path + "': unknown extension (use .vtp .vtk .obj or .ply)";
    return false;
  }
  const std::string problem = Run(writer);
  if (!problem.empty())
  {
    error = "cannot write '" + path + "': " + problem;
    return false;
  }
  if (!std::ifstream(path).good())
  {
    error = "cannot write '" + path + "'";
    return false;
  }
  return true;
}
}
