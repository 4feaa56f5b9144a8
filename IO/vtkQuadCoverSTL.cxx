// VTK-HeaderTest-Exclude: vtkQuadCoverSTL.cxx
#include "vtkQuadCoverSTL.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace
{
/// Points with equal coordinates joined, in the order they first appear, and the facets.
class Facets
{
public:
  /// The index of the point (x, y, z), a new one if no earlier point has these coordinates.
  vtkIdType Point(double x, double y, double z)
  {
    // +0 and -0 are one coordinate
    const std::array<double, 3> key{ x + 0.0, y + 0.0, z + 0.0 };
    const auto found = this->Index.emplace(key, static_cast<vtkIdType>(this->Index.size()));
    if (found.second)
    {
      this->Coordinates.insert(this->Coordinates.end(), key.begin(), key.end());
    }
    return found.first->second;
  }

  /// Room for about n points.
  void Reserve(std::size_t n)
  {
    this->Index.reserve(n);
    this->Coordinates.reserve(3 * n);
  }

  /// A facet of these points, unless two of them are one.
  void Add(const std::vector<vtkIdType>& corners)
  {
    std::vector<vtkIdType> sorted = corners;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end())
    {
      this->Polys->InsertNextCell(static_cast<vtkIdType>(corners.size()), corners.data());
    }
  }

  void Store(vtkPolyData* output) const
  {
    vtkNew<vtkDoubleArray> xyz;
    xyz->SetNumberOfComponents(3);
    xyz->SetNumberOfTuples(static_cast<vtkIdType>(this->Index.size()));
    std::copy(this->Coordinates.begin(), this->Coordinates.end(), xyz->GetPointer(0));
    vtkNew<vtkPoints> points;
    points->SetData(xyz);
    vtkNew<vtkPolyData> surface;
    surface->SetPoints(points);
    surface->SetPolys(this->Polys);
    output->ShallowCopy(surface);
  }

private:
  struct Hash
  {
    std::size_t operator()(const std::array<double, 3>& key) const
    {
      std::size_t h = 0;
      for (const double x : key)
      {
        std::uint64_t bits;
        std::memcpy(&bits, &x, sizeof bits);
        h = (h ^ bits) * 0x100000001b3ULL + (h >> 29);
      }
      return h;
    }
  };
  std::unordered_map<std::array<double, 3>, vtkIdType, Hash> Index;
  std::vector<double> Coordinates;
  vtkNew<vtkCellArray> Polys;
};

/// The little-endian 32-bit word at p.
std::uint32_t WordAt(const unsigned char* p)
{
  return static_cast<std::uint32_t>(p[0]) | (static_cast<std::uint32_t>(p[1]) << 8) |
    (static_cast<std::uint32_t>(p[2]) << 16) | (static_cast<std::uint32_t>(p[3]) << 24);
}

/// The little-endian float at p.
float FloatAt(const unsigned char* p)
{
  const std::uint32_t bits = WordAt(p);
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

/// How many triangles the binary file holds: as many as its header says, which must fit in the
/// file; and where that is not the file's own count (many writers leave 0), the file must end on
/// a triangle and is read to its end, as VTK's reader read it.
/// @throws std::runtime_error for a file shorter than its header or count, or cut in a triangle
long long BinaryTriangles(const std::string& data)
{
  const long long size = static_cast<long long>(data.size());
  if (size < 84)
  {
    throw std::runtime_error(
      "a binary STL file needs 84 bytes for its header, this one has " + std::to_string(size));
  }
  const long long claimed = WordAt(reinterpret_cast<const unsigned char*>(data.data()) + 80);
  const long long present = (size - 84) / 50;
  if (claimed > present)
  {
    throw std::runtime_error("the binary STL header says " + std::to_string(claimed) +
      " triangles (" + std::to_string(84 + 50 * claimed) + " bytes), but the file has " +
      std::to_string(size) + " bytes, " + std::to_string(present) + " triangles (cut short?)");
  }
  if (claimed != present && (size - 84) % 50 != 0)
  {
    throw std::runtime_error("the binary STL file ends in the middle of a triangle (" +
      std::to_string(size) + " bytes is not 84 and 50 a triangle; cut short?)");
  }
  return present; // the header's count, or the file's own where the header says another
}

/// The binary file's facets.
void ReadBinary(const std::string& data, Facets& facets)
{
  const long long count = BinaryTriangles(data);
  const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
  std::vector<vtkIdType> corners(3);
  for (long long t = 0; t < count; ++t)
  {
    const unsigned char* facet = bytes + 84 + 50 * t + 12; // after the normal
    for (int k = 0; k < 3; ++k)
    {
      const unsigned char* p = facet + 12 * k;
      corners[k] = facets.Point(FloatAt(p), FloatAt(p + 4), FloatAt(p + 8));
    }
    facets.Add(corners);
  }
}

/// Blanks between words.
bool IsSpace(char c)
{
  return c == ' ' || c == '\n' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

/// The words of an ASCII file, with the line each is on.
class Words
{
public:
  explicit Words(const std::string& text)
    : P(text.data())
    , End(text.data() + text.size())
  {}

  /// The next word, "" at the end of the file.
  std::string_view Next()
  {
    this->SkipSpace();
    const char* start = this->P;
    while (this->P < this->End && !IsSpace(*this->P))
    {
      ++this->P;
    }
    return std::string_view(start, static_cast<std::size_t>(this->P - start));
  }

  /// The next word in lower case.
  std::string Keyword()
  {
    std::string word(this->Next());
    std::transform(word.begin(), word.end(), word.begin(),
      [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return word;
  }

  /// Skips to the end of the line (a solid's name).
  void SkipLine()
  {
    while (this->P < this->End && *this->P != '\n')
    {
      ++this->P;
    }
  }

  double Number()
  {
    const std::string_view word = this->Next();
    double value = 0.0;
    const char* first = word.data();
    if (!word.empty() && *first == '+')
    {
      ++first; // from_chars takes no plus sign
    }
    const auto [end, error] = std::from_chars(first, word.data() + word.size(), value);
    if (word.empty() || error != std::errc() || end != word.data() + word.size())
    {
      this->Fail(word.empty() ? "the file ends in the middle of a facet"
                              : "a vertex needs three numbers, found '" + std::string(word) + "'");
    }
    return value;
  }

  /// The next keyword, which must be `expected`.
  void Expect(const std::string& expected)
  {
    const std::string word = this->Keyword();
    if (word != expected)
    {
      this->Fail(word.empty() ? "the file ends in the middle of a facet"
                              : "'" + expected + "' expected, found '" + word + "'");
    }
  }

  [[noreturn]] void Fail(const std::string& why) const
  {
    throw std::runtime_error("line " + std::to_string(this->Line) + ": " + why);
  }

private:
  void SkipSpace()
  {
    while (this->P < this->End && IsSpace(*this->P))
    {
      this->Line += *this->P++ == '\n';
    }
  }

  const char* P;
  const char* End;
  long long Line = 1;
};

/// The ASCII file's facets.
void ReadText(const std::string& text, Facets& facets)
{
  Words words(text);
  if (words.Keyword() != "solid")
  {
    words.Fail("not an ASCII STL file ('solid' expected at its start)");
  }
  words.SkipLine();
  std::vector<vtkIdType> corners;
  for (std::string word = words.Keyword(); !word.empty(); word = words.Keyword())
  {
    if (word == "endsolid" || word == "solid")
    {
      words.SkipLine();
      continue;
    }
    if (word != "facet")
    {
      words.Fail("'facet' expected, found '" + word + "'");
    }
    words.Expect("normal");
    for (int k = 0; k < 3; ++k)
    {
      words.Number();
    }
    words.Expect("outer");
    words.Expect("loop");
    corners.clear();
    for (word = words.Keyword(); word == "vertex"; word = words.Keyword())
    {
      const double x = words.Number();
      const double y = words.Number();
      const double z = words.Number();
      corners.push_back(facets.Point(x, y, z));
    }
    if (word != "endloop")
    {
      words.Fail(word.empty() ? "the file ends in the middle of a facet"
                              : "'vertex' or 'endloop' expected, found '" + word + "'");
    }
    if (corners.size() < 3)
    {
      words.Fail("a facet needs three vertices, this one has " + std::to_string(corners.size()));
    }
    words.Expect("endfacet");
    facets.Add(corners);
  }
}
}

namespace vtkQuadCoverSTL
{
std::string Read(const std::string& path, vtkPolyData* output)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    return "cannot open the file";
  }
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const bool binary =
    vtksys::SystemTools::DetectFileType(path.c_str()) != vtksys::SystemTools::FileTypeText;
  try
  {
    Facets facets;
    // about half as many points as facets: 50 bytes a binary facet, some 250 an ASCII one
    facets.Reserve(data.size() / (binary ? 100 : 500));
    if (binary)
    {
      ReadBinary(data, facets);
    }
    else
    {
      ReadText(data, facets);
    }
    facets.Store(output);
  }
  catch (const std::exception& e)
  {
    return e.what();
  }
  return "";
}
}
