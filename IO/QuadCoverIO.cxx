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
#include "vtkQuadCoverEigen.h"
#include "vtkQuadCoverInput.h"
#include "vtkSTLReader.h"
#include "vtkTriangleFilter.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"

#include "MeshTopology.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
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

/// What VTK 9.1's OBJ reader gets silently wrong: it reads "nan" and "inf" as 0, and a face
/// index past the vertices reads memory it does not own. Returns "" or the first offending line.
std::string CheckObjText(const std::string& path)
{
  std::ifstream in(path);
  std::string line;
  long long vertices = 0, maxIndex = 0, maxIndexLine = 0;
  for (long long number = 1; std::getline(in, line); ++number)
  {
    if (line.size() < 2 || (line[1] != ' ' && line[1] != '\t'))
    {
      continue;
    }
    if (line[0] == 'v')
    {
      ++vertices;
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
          return "line " + std::to_string(number) +
            " has a non-finite (NaN or infinite) coordinate";
        }
        p = end;
      }
    }
    else if (line[0] == 'f')
    {
      // Tokens "i", "i/t", "i//n" or "i/t/n"; negative i counts back from the last vertex.
      std::istringstream tokens(line.substr(2));
      std::string token;
      while (tokens >> token)
      {
        char* end = nullptr;
        const long long i = std::strtoll(token.c_str(), &end, 10);
        if (end == token.c_str())
        {
          break;
        }
        if (i == 0 || (i < 0 && -i > vertices))
        {
          return "line " + std::to_string(number) + " refers to vertex " + std::to_string(i) +
            ", which does not exist";
        }
        if (i > maxIndex)
        {
          maxIndex = i;
          maxIndexLine = number;
        }
      }
    }
  }
  if (maxIndex > vertices)
  {
    return "line " + std::to_string(maxIndexLine) + " refers to vertex " +
      std::to_string(maxIndex) + ", but the file has only " + std::to_string(vertices);
  }
  return "";
}

/// VTK 9.1's PLY reader dereferences face indices without checking them. Streams through the
/// file (ASCII or binary) and returns "" or a one-line reason for the first face index that is
/// not a vertex. A header it cannot follow is left to the reader to judge.
std::string CheckPlyFaces(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || line.compare(0, 3, "ply") != 0)
  {
    return "";
  }
  struct Property
  {
    std::string name;
    std::string type;      // scalar type, or the item type of a list
    std::string countType; // empty for scalars
  };
  struct Element
  {
    std::string name;
    long long count = 0;
    std::vector<Property> properties;
  };
  std::vector<Element> elements;
  std::string format;
  while (std::getline(in, line))
  {
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    std::istringstream words(line);
    std::string word;
    words >> word;
    if (word == "format")
    {
      words >> format;
    }
    else if (word == "element")
    {
      Element e;
      words >> e.name >> e.count;
      elements.push_back(e);
    }
    else if (word == "property" && !elements.empty())
    {
      Property p;
      words >> p.type;
      if (p.type == "list")
      {
        words >> p.countType >> p.type;
      }
      words >> p.name;
      elements.back().properties.push_back(p);
    }
    else if (word == "end_header")
    {
      break;
    }
  }
  auto size = [](const std::string& t) -> int {
    if (t == "char" || t == "uchar" || t == "int8" || t == "uint8")
      return 1;
    if (t == "short" || t == "ushort" || t == "int16" || t == "uint16")
      return 2;
    if (t == "int" || t == "uint" || t == "int32" || t == "uint32" || t == "float" ||
      t == "float32")
      return 4;
    if (t == "double" || t == "float64")
      return 8;
    return 0;
  };
  const bool ascii = format == "ascii";
  const bool swap = format == "binary_big_endian";
  if (!ascii && !swap && format != "binary_little_endian")
  {
    return "";
  }
  // One value of type t, as a double (exact for every integer type up to 32 bits).
  auto read = [&](const std::string& t, double& value) -> bool {
    if (ascii)
    {
      return static_cast<bool>(in >> value);
    }
    const int n = size(t);
    unsigned char b[8];
    if (n == 0 || !in.read(reinterpret_cast<char*>(b), n))
    {
      return false;
    }
    if (swap)
    {
      std::reverse(b, b + n);
    }
    if (t == "char" || t == "int8")
      value = static_cast<signed char>(b[0]);
    else if (t == "uchar" || t == "uint8")
      value = b[0];
    else if (t == "short" || t == "int16" || t == "ushort" || t == "uint16")
    {
      std::uint16_t u;
      std::memcpy(&u, b, 2);
      value = (t == "short" || t == "int16") ? static_cast<std::int16_t>(u) : u;
    }
    else if (t == "int" || t == "int32" || t == "uint" || t == "uint32")
    {
      std::uint32_t u;
      std::memcpy(&u, b, 4);
      value = (t == "int" || t == "int32") ? static_cast<std::int32_t>(u) : u;
    }
    else if (t == "float" || t == "float32")
    {
      float f;
      std::memcpy(&f, b, 4);
      value = f;
    }
    else
    {
      std::memcpy(&value, b, 8);
    }
    return true;
  };
  long long vertices = -1;
  for (const Element& e : elements)
  {
    if (e.name == "vertex")
    {
      vertices = e.count;
    }
    for (long long i = 0; i < e.count; ++i)
    {
      for (const Property& p : e.properties)
      {
        double value = 0;
        if (p.countType.empty())
        {
          if (!read(p.type, value))
            return "";
          continue;
        }
        double count = 0;
        if (!read(p.countType, count) || count < 0)
          return "";
        const bool indices = e.name == "face" &&
          (p.name == "vertex_indices" || p.name == "vertex_index") && vertices >= 0;
        for (long long k = 0; k < static_cast<long long>(count); ++k)
        {
          if (!read(p.type, value))
            return "";
          if (indices && !(value >= 0 && value < static_cast<double>(vertices)))
          {
            return "face " + std::to_string(i) + " refers to point " +
              std::to_string(static_cast<long long>(value)) + ", but there are only " +
              std::to_string(vertices) + " points";
          }
        }
      }
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
    const std::string bad = CheckObjText(path);
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
    const std::string bad = CheckPlyFaces(path);
    if (!bad.empty())
    {
      error = "cannot read '" + path + "': " + bad;
      return nullptr;
    }
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
  std::string problem = vtkQuadCoverInput::CheckPointIds(input);
  if (problem.empty())
  {
    problem = vtkQuadCoverInput::CheckFinitePoints(input);
  }
  if (!problem.empty())
  {
    error = problem;
    return nullptr;
  }
  if (input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
  {
    error = "the mesh has no polygons (a surface of triangles is needed)";
    return nullptr;
  }
  {
    vtkCellArray* cells = input->GetPolys();
    for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c)
    {
      repairs.triangulatedPolygons += cells->GetCellSize(c) > 3 ? 1 : 0;
    }
    repairs.triangulatedPolygons += input->GetNumberOfStrips();
  }

  // Triangulate first (so that the degenerate joins of strips stay degenerate), dropping vertex
  // and line cells; cell data follows the triangles.
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(input);
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  problem = Run(triangles);
  if (!problem.empty())
  {
    error = problem;
    return nullptr;
  }
  vtkPolyData* tri = triangles->GetOutput();
  repairs.removedCells += input->GetNumberOfVerts() + input->GetNumberOfLines();

  // Merge exactly coincident points; triangles left with a repeated point are removed.
  vtkNew<vtkCleanPolyData> clean;
  clean->SetInputData(tri);
  clean->PointMergingOn();
  clean->SetTolerance(0.0);
  clean->ConvertPolysToLinesOff();
  clean->ConvertLinesToPointsOff();
  clean->ConvertStripsToPolysOff();
  problem = Run(clean);
  if (!problem.empty())
  {
    error = problem;
    return nullptr;
  }
  vtkIdType used = 0;
  {
    std::vector<char> referenced(tri->GetNumberOfPoints(), 0);
    vtkNew<vtkIdList> ids;
    for (tri->GetPolys()->InitTraversal(); tri->GetPolys()->GetNextCell(ids);)
    {
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      {
        used += referenced[ids->GetId(k)] ? 0 : 1;
        referenced[ids->GetId(k)] = 1;
      }
    }
  }
  vtkPolyData* cleaned = clean->GetOutput();
  repairs.mergedPoints = std::max<vtkIdType>(0, used - cleaned->GetNumberOfPoints());
  repairs.removedCells += tri->GetNumberOfPolys() - cleaned->GetNumberOfPolys();
  if (cleaned->GetNumberOfPolys() == 0)
  {
    error = "the mesh has no non-degenerate triangles";
    return nullptr;
  }

  // Orientation: make neighbours agree, counting the triangles that turned.
  vtkNew<vtkPolyDataNormals> orient;
  orient->SetInputData(cleaned);
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
    vtkCellArray* a = cleaned->GetPolys();
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
  if (!cleaned->GetCellData()->GetArray("Normals"))
  {
    out->GetCellData()->RemoveArray("Normals"); // the by-product of the reorientation
  }

  // Bowtie vertices: one copy of the vertex per fan, point data copied along.
  const vtkIdType nv = out->GetNumberOfPoints();
  Eigen::MatrixX3d V = vtkQuadCoverEigen::Points(out);
  Eigen::MatrixX3i F = vtkQuadCoverEigen::Triangles(out);
  const quadcover::MeshTopology topo = quadcover::buildTopology(F, static_cast<int>(nv));
  if (!topo.nonManifoldEdges.empty())
  {
    error = "the surface has " + std::to_string(topo.nonManifoldEdges.size()) +
      " non-manifold edges (more than two triangles on one edge); QuadCover needs a manifold "
      "surface";
    return nullptr;
  }
  const std::vector<int> copies = topo.nonManifoldVertices.empty()
    ? std::vector<int>()
    : quadcover::splitNonManifoldVertices(V, F);
  repairs.splitVertices = static_cast<long long>(copies.size());
  if (!copies.empty())
  {
    vtkSmartPointer<vtkPolyData> split = vtkQuadCoverEigen::ToPolyData(V, F);
    vtkNew<vtkPointData> pointData;
    pointData->CopyAllocate(out->GetPointData(), V.rows());
    for (vtkIdType i = 0; i < V.rows(); ++i)
    {
      pointData->CopyData(out->GetPointData(), i < nv ? i : copies[i - nv], i);
    }
    out->SetPoints(split->GetPoints());
    out->GetPointData()->ShallowCopy(pointData);
    out->SetPolys(split->GetPolys());
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
