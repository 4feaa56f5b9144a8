// VTK-HeaderTest-Exclude: vtkQuadCoverPLYChecks.cxx
// vtkQuadCoverPLYChecks.cxx: vtkQuadCoverFileChecks::CheckPlyFaces, the checks a PLY file gets
// before VTK's reader sees it.
#include "vtkQuadCoverFileChecks.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace vtkQuadCoverFileChecks
{
namespace
{
struct PlyProperty
{
  std::string name;
  std::string type;      // scalar type, or the item type of a list
  std::string countType; // empty for scalars
};

struct PlyElement
{
  std::string name;
  long long count = 0;
  std::vector<PlyProperty> properties;
};

/// The header up to end_header: the format and the elements with their properties.
std::vector<PlyElement> ReadPlyHeader(std::istream& in, std::string& format)
{
  std::vector<PlyElement> elements;
  std::string line;
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
      PlyElement e;
      words >> e.name >> e.count;
      elements.push_back(e);
    }
    else if (word == "property" && !elements.empty())
    {
      PlyProperty p;
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
  return elements;
}

/// Bytes of a PLY scalar type, 0 for one it does not know.
int PlySize(const std::string& t)
{
  if (t == "char" || t == "uchar" || t == "int8" || t == "uint8")
    return 1;
  if (t == "short" || t == "ushort" || t == "int16" || t == "uint16")
    return 2;
  if (t == "int" || t == "uint" || t == "int32" || t == "uint32" || t == "float" || t == "float32")
    return 4;
  if (t == "double" || t == "float64")
    return 8;
  return 0;
}

/// Reads one value of PLY type t (exact for every integer type up to 32 bits).
class PlyValues
{
public:
  PlyValues(std::istream& in, const std::string& format)
    : In(in)
    , Ascii(format == "ascii")
    , Swap(format == "binary_big_endian")
  {}

  bool Read(const std::string& t, double& value)
  {
    if (this->Ascii)
    {
      return static_cast<bool>(this->In >> value);
    }
    const int n = PlySize(t);
    unsigned char b[8];
    if (n == 0 || !this->In.read(reinterpret_cast<char*>(b), n))
    {
      return false;
    }
    if (this->Swap)
    {
      std::reverse(b, b + n);
    }
    value = Decode(t, b);
    return true;
  }

private:
  static double Decode(const std::string& t, const unsigned char* b)
  {
    if (t == "char" || t == "int8")
      return static_cast<signed char>(b[0]);
    if (t == "uchar" || t == "uint8")
      return b[0];
    if (PlySize(t) == 2)
    {
      std::uint16_t u;
      std::memcpy(&u, b, 2);
      return (t == "short" || t == "int16") ? static_cast<std::int16_t>(u) : u;
    }
    if (t == "float" || t == "float32")
    {
      float f;
      std::memcpy(&f, b, 4);
      return f;
    }
    if (PlySize(t) == 4)
    {
      std::uint32_t u;
      std::memcpy(&u, b, 4);
      return (t == "int" || t == "int32") ? static_cast<std::int32_t>(u) : u;
    }
    double d;
    std::memcpy(&d, b, 8);
    return d;
  }

  std::istream& In;
  bool Ascii;
  bool Swap;
};

/// "" or the first face index of element e (count items) that is not one of `vertices` points;
/// `readable` turns false when the file ends early or holds a type it does not know.
std::string CheckPlyElement(
  PlyValues& values, const PlyElement& e, long long vertices, bool& readable)
{
  for (long long i = 0; i < e.count; ++i)
  {
    for (const PlyProperty& p : e.properties)
    {
      double value = 0;
      if (p.countType.empty())
      {
        readable = values.Read(p.type, value);
        if (!readable)
          return "";
        continue;
      }
      double count = 0;
      readable = values.Read(p.countType, count) && count >= 0;
      if (!readable)
        return "";
      const bool indices = e.name == "face" &&
        (p.name == "vertex_indices" || p.name == "vertex_index") && vertices >= 0;
      for (long long k = 0; k < static_cast<long long>(count); ++k)
      {
        readable = values.Read(p.type, value);
        if (!readable)
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
  return "";
}
}

std::string CheckPlyFaces(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || line.compare(0, 3, "ply") != 0)
  {
    return "";
  }
  std::string format;
  const std::vector<PlyElement> elements = ReadPlyHeader(in, format);
  if (format != "ascii" && format != "binary_big_endian" && format != "binary_little_endian")
  {
    return "";
  }
  PlyValues values(in, format);
  long long vertices = -1;
  for (const PlyElement& e : elements)
  {
    if (e.name == "vertex")
    {
      vertices = e.count;
    }
    bool readable = true;
    const std::string bad = CheckPlyElement(values, e, vertices, readable);
    if (!bad.empty() || !readable)
    {
      return bad;
    }
  }
  return "";
}
}
