// VTK-HeaderTest-Exclude: vtkQuadCoverOBJ.cxx
#include "vtkQuadCoverOBJ.h"

#include "vtkQuadCoverFileChecks.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace
{
/// Blanks between tokens (a newline ends the statement, so it is not one).
bool IsBlank(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

/// At most 32 characters of [a, b) as they may be shown in a one-line error: other bytes than
/// printable ASCII as '?', a longer token cut with "...".
std::string Shown(const char* a, const char* b)
{
  std::string shown;
  for (const char* c = a; c < b && shown.size() < 32; ++c)
  {
    shown += (*c >= 32 && *c < 127) ? *c : '?';
  }
  return b - a > 32 ? shown + "..." : shown;
}

/// One kind of cell as it is read: the point ids of all cells in a row, and where each starts.
struct Cells
{
  std::vector<vtkIdType> offsets{ 0 };
  std::vector<vtkIdType> ids;

  vtkSmartPointer<vtkCellArray> Make() const
  {
    vtkNew<vtkIdTypeArray> o, c;
    o->SetNumberOfValues(static_cast<vtkIdType>(this->offsets.size()));
    std::copy(this->offsets.begin(), this->offsets.end(), o->GetPointer(0));
    c->SetNumberOfValues(static_cast<vtkIdType>(this->ids.size()));
    std::copy(this->ids.begin(), this->ids.end(), c->GetPointer(0));
    vtkNew<vtkCellArray> cells;
    cells->SetData(o, c);
    return cells;
  }
};

/// Reads the statements of an OBJ file held in memory, in place; errors name the line.
class ObjParser
{
public:
  explicit ObjParser(const std::string& text)
    : P(text.data())
    , End(text.data() + text.size())
  {}

  void Parse()
  {
    while (this->P < this->End)
    {
      this->SkipBlanks();
      const char* end = this->TokenEnd();
      const std::string_view keyword(this->P, static_cast<std::size_t>(end - this->P));
      this->P = end;
      if (keyword == "v")
      {
        this->ReadVertex();
      }
      else if (keyword == "f")
      {
        this->ReadCell(this->Polys, 3, "a face of fewer than three vertices");
      }
      else if (keyword == "l")
      {
        this->ReadCell(this->Lines, 2, "a line of fewer than two vertices");
      }
      else if (keyword == "p")
      {
        this->ReadCell(this->Verts, 1, "a point statement without a vertex");
      }
      this->NextLine();
    }
    if (this->MaxIndex > this->PointCount())
    {
      throw std::runtime_error("line " + std::to_string(this->MaxIndexLine) + " refers to vertex " +
        std::to_string(this->MaxIndex) + ", but the file has only " +
        std::to_string(this->PointCount()));
    }
  }

  long long PointCount() const { return static_cast<long long>(this->Points.size() / 3); }

  std::vector<double> Points;
  Cells Polys, Lines, Verts;

private:
  [[noreturn]] void Fail(const std::string& what) const
  {
    throw std::runtime_error("line " + std::to_string(this->Line) + " " + what);
  }

  /// Past spaces and tabs, and past a backslash that ends a line (the line goes on).
  void SkipBlanks()
  {
    for (;;)
    {
      while (this->P < this->End && IsBlank(*this->P))
      {
        ++this->P;
      }
      if (this->P == this->End || *this->P != '\\')
      {
        return;
      }
      const char* q = this->ContinuationEnd(this->P);
      if (q == nullptr)
      {
        return; // a backslash inside the line: a token of its own
      }
      this->Line += q > this->P + 1 && q[-1] == '\n'; // (none at the end of the file)
      this->P = q;
    }
  }

  /// When the backslash at b ends its line (only '\r' after it, then a newline or the end of the
  /// file): past that line's newline; else null.
  const char* ContinuationEnd(const char* b) const
  {
    const char* q = b + 1;
    while (q < this->End && *q == '\r')
    {
      ++q;
    }
    if (q == this->End)
    {
      return q;
    }
    return *q == '\n' ? q + 1 : nullptr;
  }

  bool AtLineEnd() const { return this->P == this->End || *this->P == '\n'; }

  /// The end of the token at P: the next blank, newline, backslash that continues the line, or
  /// the end of the file.
  const char* TokenEnd() const
  {
    const char* q = this->P;
    while (q < this->End && !IsBlank(*q) && *q != '\n' &&
      !(*q == '\\' && this->ContinuationEnd(q) != nullptr))
    {
      ++q;
    }
    return q;
  }

  /// Past the next newline. A backslash continues only "v", "f", "l" and "p" statements (read
  /// through SkipBlanks), not a comment or a statement that is skipped.
  void NextLine()
  {
    while (this->P < this->End && *this->P != '\n')
    {
      ++this->P;
    }
    if (this->P < this->End)
    {
      ++this->P;
      ++this->Line;
    }
  }

  void ReadVertex()
  {
    double x[3];
    for (double& c : x)
    {
      this->SkipBlanks();
      if (this->AtLineEnd())
      {
        this->Fail("has a vertex of fewer than three coordinates");
      }
      const char* end = this->TokenEnd();
      const char* start = this->P + (*this->P == '+'); // from_chars takes no '+'
      const auto read = std::from_chars(start, end, c);
      if (read.ec == std::errc::result_out_of_range && read.ptr == end)
      {
        // too large, or so small that it rounds to 0 (or a subnormal): strtod tells which
        c = std::strtod(std::string(this->P, end).c_str(), nullptr);
        if (std::isinf(c))
        {
          this->Fail("has a coordinate beyond double precision (1e308)");
        }
      }
      else if (read.ec != std::errc() || read.ptr != end)
      {
        this->Fail("has a vertex coordinate that is not a number");
      }
      if (!std::isfinite(c))
      {
        this->Fail("has a non-finite (NaN or infinite) coordinate");
      }
      this->P = end;
    }
    this->Points.insert(this->Points.end(), x, x + 3);
  }

  /// The point ids of an "f", "l" or "p" statement, at least `fewest` of them.
  void ReadCell(Cells& cells, std::size_t fewest, const char* tooFew)
  {
    const std::size_t before = cells.ids.size();
    const long long count = this->PointCount();
    for (;;)
    {
      this->SkipBlanks();
      if (this->AtLineEnd())
      {
        break;
      }
      const char* end = this->TokenEnd();
      long long i = 0;
      const auto read = std::from_chars(this->P, end, i);
      const bool beyond = read.ec == std::errc::result_out_of_range; // beyond 64 bits
      if ((read.ec != std::errc() && !beyond) || (read.ptr != end && *read.ptr != '/'))
      {
        this->Fail("has a vertex index that is not a number (" + Shown(this->P, end) + ")");
      }
      if (beyond || i == 0 || i < -count) // (-i would overflow at the lowest 64-bit index)
      {
        this->Fail("refers to vertex " + Shown(this->P, read.ptr) + ", which does not exist");
      }
      if (i > this->MaxIndex)
      {
        this->MaxIndex = i; // a later "v" line may still give it
        this->MaxIndexLine = this->Line;
      }
      cells.ids.push_back(static_cast<vtkIdType>(i < 0 ? count + i : i - 1));
      this->P = end;
    }
    if (cells.ids.size() - before < fewest)
    {
      const bool cut = this->P == this->End; // the last line, without its newline
      this->Fail(std::string("has ") + tooFew +
        (cut ? " (the file ends in the middle of it: cut short?)" : ""));
    }
    cells.offsets.push_back(static_cast<vtkIdType>(cells.ids.size()));
  }

  const char* P;
  const char* End;
  long long Line = 1;
  long long MaxIndex = 0;
  long long MaxIndexLine = 0;
};
}

namespace vtkQuadCoverOBJ
{
std::string Read(const std::string& path, vtkPolyData* output)
{
  if (vtkQuadCoverFileChecks::LooksBinary(path))
  {
    return "not a text OBJ file (it holds binary data)";
  }
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    return "cannot open the file";
  }
  std::string text;
  in.seekg(0, std::ios::end);
  text.resize(static_cast<std::size_t>(std::max<std::streamoff>(in.tellg(), 0)));
  in.seekg(0);
  in.read(&text[0], static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(in.gcount()));
  try
  {
    ObjParser obj(text);
    obj.Parse();
    vtkNew<vtkDoubleArray> xyz;
    xyz->SetNumberOfComponents(3);
    xyz->SetNumberOfTuples(obj.PointCount());
    std::copy(obj.Points.begin(), obj.Points.end(), xyz->GetPointer(0));
    vtkNew<vtkPoints> points;
    points->SetData(xyz);
    vtkNew<vtkPolyData> surface;
    surface->SetPoints(points);
    surface->SetPolys(obj.Polys.Make());
    surface->SetLines(obj.Lines.Make());
    surface->SetVerts(obj.Verts.Make());
    output->ShallowCopy(surface);
  }
  catch (const std::exception& e)
  {
    return e.what();
  }
  return "";
}

namespace
{
/// Appends x in the shortest decimals that read back to it.
void AppendNumber(std::string& out, double x)
{
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  out.append(buffer, result.ptr);
}

/// Appends a line `keyword i_1 ... i_n` (from 1) per cell of `cells`.
void AppendCells(std::string& out, const char* keyword, vtkCellArray* cells)
{
  auto it = vtk::TakeSmartPointer(cells->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    out += keyword;
    for (vtkIdType k = 0; k < n; ++k)
    {
      out += ' ';
      out += std::to_string(ids[k] + 1);
    }
    out += '\n';
  }
}

/// Appends an "f" line per triangle of the strips of `cells` (every other one turned back).
void AppendStrips(std::string& out, vtkCellArray* cells)
{
  auto it = vtk::TakeSmartPointer(cells->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    for (vtkIdType k = 0; k + 2 < n; ++k)
    {
      const vtkIdType a = ids[k] + 1, b = ids[k + 1] + 1, c = ids[k + 2] + 1;
      out += "f " + std::to_string(a) + ' ' + std::to_string(k % 2 == 0 ? b : c) + ' ' +
        std::to_string(k % 2 == 0 ? c : b) + '\n';
    }
  }
}
}

std::string Write(const std::string& path, vtkPolyData* input)
{
  std::string out = "# written by QuadCover\n";
  const vtkIdType n = input->GetNumberOfPoints();
  double x[3];
  for (vtkIdType p = 0; p < n; ++p)
  {
    input->GetPoint(p, x);
    out += 'v';
    for (const double c : x)
    {
      out += ' ';
      AppendNumber(out, c);
    }
    out += '\n';
  }
  AppendCells(out, "p", input->GetVerts());
  AppendCells(out, "l", input->GetLines());
  AppendCells(out, "f", input->GetPolys());
  AppendStrips(out, input->GetStrips());
  std::ofstream file(path, std::ios::binary);
  file.write(out.data(), static_cast<std::streamsize>(out.size()));
  file.close();
  return file ? "" : "cannot write the file";
}
}
