// VTK-HeaderTest-Exclude: vtkQuadCoverOFF.cxx
#include "vtkQuadCoverOFF.h"

#include "vtkQuadCoverFileChecks.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
/// The file's lines without comments, skipping blank ones; errors name the current line.
class OffLines
{
public:
  explicit OffLines(std::istream& in)
    : In(in)
  {}

  /// The next line that holds something; false at the end of the file.
  bool Next(std::istringstream& words)
  {
    std::string line;
    while (std::getline(this->In, line))
    {
      ++this->Number;
      const auto hash = line.find('#');
      if (hash != std::string::npos)
      {
        line.erase(hash);
      }
      if (line.find_first_not_of(" \t\r") != std::string::npos)
      {
        words.clear();
        words.str(line);
        return true;
      }
    }
    return false;
  }

  [[noreturn]] void Fail(const std::string& why) const
  {
    throw std::runtime_error("line " + std::to_string(this->Number) + ": " + why);
  }

private:
  std::istream& In;
  long long Number = 0;
};

/// The header: keyword and counts (on the keyword's line or the next); returns the counts.
void ReadHeader(OffLines& lines, long long fileSize, long long& nv, long long& nf)
{
  std::istringstream words;
  std::string keyword;
  if (!lines.Next(words) || !(words >> keyword) || keyword.size() < 3 ||
    keyword.compare(keyword.size() - 3, 3, "OFF") != 0)
  {
    lines.Fail("not an OFF file (it must start with OFF, COFF, NOFF, STOFF or the like)");
  }
  const std::string prefix = keyword.substr(0, keyword.size() - 3);
  if (prefix.find('4') != std::string::npos || prefix.find('n') != std::string::npos)
  {
    lines.Fail(keyword + " files are not three-dimensional surfaces");
  }
  if (prefix.find_first_not_of("STCN") != std::string::npos)
  {
    lines.Fail("not an OFF file (" + keyword + " is not OFF, COFF, NOFF, STOFF or the like)");
  }
  std::string rest;
  std::getline(words, rest);
  if (rest.find("BINARY") != std::string::npos)
  {
    lines.Fail("binary OFF files are not supported");
  }
  std::istringstream counts(rest);
  if (rest.find_first_not_of(" \t\r") == std::string::npos && !lines.Next(counts))
  {
    lines.Fail("the file ends before the vertex and face counts");
  }
  if (!(counts >> nv >> nf))
  {
    lines.Fail("the vertex and face counts are missing or not numbers");
  }
  // every vertex takes at least 6 bytes ("0 0 0\n"), every face at least 4 ("1 0\n"), the
  // file's last line perhaps without its newline
  if (nv < 0 || nf < 0 || nv > (fileSize + 1) / 6 || nf > (fileSize + 1) / 4)
  {
    lines.Fail("the counts " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
      " faces are negative or larger than the file could hold");
  }
}

void ReadVertices(OffLines& lines, long long nv, vtkPoints* points)
{
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(nv);
  for (long long i = 0; i < nv; ++i)
  {
    std::istringstream words;
    if (!lines.Next(words))
    {
      lines.Fail(
        "the file ends after " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
    }
    double x[3];
    for (double& c : x)
    {
      // strtod, unlike operator>>, reads nan and inf: they are refused below, not misread
      std::string token;
      char* end = nullptr;
      if (!(words >> token) || (c = std::strtod(token.c_str(), &end), *end != '\0'))
      {
        lines.Fail("a vertex needs three coordinates");
      }
    }
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
    {
      lines.Fail("a non-finite (NaN or infinite) coordinate");
    }
    points->SetPoint(i, x);
  }
}

void ReadFaces(OffLines& lines, long long nv, long long nf, vtkPolyData* out)
{
  vtkNew<vtkCellArray> verts, edges, polys;
  std::vector<vtkIdType> ids;
  for (long long i = 0; i < nf; ++i)
  {
    std::istringstream words;
    if (!lines.Next(words))
    {
      lines.Fail(
        "the file ends after " + std::to_string(i) + " of " + std::to_string(nf) + " faces");
    }
    long long n = 0;
    if (!(words >> n) || n < 1 || n > nv)
    {
      lines.Fail("a face must start with its number of points, from 1 to the vertex count");
    }
    ids.resize(n);
    for (long long k = 0; k < n; ++k)
    {
      long long id = -1;
      if (!(words >> id))
      {
        lines.Fail("the face lists fewer than its " + std::to_string(n) + " points");
      }
      if (id < 0 || id >= nv)
      {
        lines.Fail("the face refers to vertex " + std::to_string(id) + ", but the file has only " +
          std::to_string(nv) + " (numbered from 0)");
      }
      ids[k] = static_cast<vtkIdType>(id);
    }
    vtkCellArray* cells = n == 1 ? verts.Get() : (n == 2 ? edges.Get() : polys.Get());
    cells->InsertNextCell(static_cast<vtkIdType>(n), ids.data());
  }
  out->SetVerts(verts);
  out->SetLines(edges);
  out->SetPolys(polys);
}
}

namespace vtkQuadCoverOFF
{
std::string Read(const std::string& path, vtkPolyData* output)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    return "cannot open the file";
  }
  char head[256];
  in.read(head, sizeof head);
  const std::string start(head, static_cast<std::size_t>(in.gcount()));
  // Binary data would be read as a header of garbage and echoed in the error; a binary OFF
  // file (its header line says BINARY) gets its own message below.
  if (vtkQuadCoverFileChecks::LooksBinary(path) &&
    start.substr(0, start.find('\n')).find("BINARY") == std::string::npos)
  {
    return "not a text OFF file (it holds binary data)";
  }
  in.clear();
  in.seekg(0, std::ios::end);
  const long long size = static_cast<long long>(in.tellg());
  in.seekg(0);
  try
  {
    OffLines lines(in);
    long long nv = 0, nf = 0;
    ReadHeader(lines, size, nv, nf);
    vtkNew<vtkPoints> points;
    ReadVertices(lines, nv, points);
    vtkNew<vtkPolyData> surface;
    surface->SetPoints(points);
    ReadFaces(lines, nv, nf, surface);
    output->ShallowCopy(surface);
  }
  catch (const std::exception& e)
  {
    return e.what();
  }
  return "";
}
}
