// VTK-HeaderTest-Exclude: vtkQuadCoverPLYChecks.cxx
// vtkQuadCoverPLYChecks.cxx: vtkQuadCoverFileChecks::CheckPly, the checks a PLY file gets
// before VTK's reader sees it.
#include "vtkQuadCoverFileChecks.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
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

struct PlyHeader
{
  std::string format;
  std::vector<PlyElement> elements;
  long long lines = 1; // the header's lines, the "ply" line included
  std::string problem; // "" or what is wrong with the header
};

/// The header after the "ply" line, up to end_header: the format and the elements with their
/// properties.
PlyHeader ReadPlyHeader(std::istream& in)
{
  PlyHeader header;
  std::string line;
  while (std::getline(in, line))
  {
    ++header.lines;
    std::istringstream words(line);
    std::string word;
    words >> word;
    if (word == "format")
    {
      words >> header.format;
    }
    else if (word == "element")
    {
      PlyElement e;
      if (!(words >> e.name >> e.count) || e.count < 0)
      {
        header.problem = "the header's line " + std::to_string(header.lines) +
          " gives an element without a count of zero or more";
        return header;
      }
      header.elements.push_back(e);
    }
    else if (word == "property" && !header.elements.empty())
    {
      PlyProperty p;
      words >> p.type;
      if (p.type == "list")
      {
        words >> p.countType >> p.type;
      }
      words >> p.name;
      header.elements.back().properties.push_back(p);
    }
    else if (word == "end_header")
    {
      return header;
    }
  }
  header.problem = "the header has no end_header line";
  return header;
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

/// "" or why the file's `bytes` after the header cannot hold the elements the header claims:
/// at least the scalars and the list counts of each element in binary, at least a digit and a
/// separator per property in ASCII. Refused before any of them is read or allocated.
std::string CheckPlySizes(const PlyHeader& header, long long bytes)
{
  const bool ascii = header.format == "ascii";
  for (const PlyElement& e : header.elements)
  {
    long long least = 0;
    for (const PlyProperty& p : e.properties)
    {
      least += ascii ? 2 : PlySize(p.countType.empty() ? p.type : p.countType);
    }
    if (least > 0 && e.count > bytes / least)
    {
      return "the header claims " + std::to_string(e.count) + " '" + e.name +
        "' elements, more than the file can hold (" + std::to_string(bytes) +
        " bytes after the header)";
    }
  }
  return "";
}

/// The lines after the header, counted without reading them as numbers.
long long CountDataLines(std::istream& in)
{
  long long lines = 0;
  bool open = false; // a last line without its newline counts too
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0)
  {
    const std::streamsize n = in.gcount();
    lines += std::count(buffer, buffer + n, '\n');
    open = buffer[n - 1] != '\n';
  }
  return lines + open;
}

/// Reads the values of one element after another: in ASCII one line each (as VTK's reader
/// does), in binary straight on (exact for every integer type up to 32 bits).
class PlyValues
{
public:
  PlyValues(std::istream& in, const std::string& format, long long headerLines)
    : In(in)
    , Ascii(format == "ascii")
    , Swap(format == "binary_big_endian")
    , Line(headerLines)
  {}

  /// Moves to the next element (ASCII: the next line, blank or not, as VTK's reader takes
  /// it); false at the end of the file.
  bool NextElement()
  {
    if (!this->Ascii)
    {
      return this->In.peek() != std::char_traits<char>::eof();
    }
    std::string line;
    if (!std::getline(this->In, line))
    {
      return false;
    }
    ++this->Line;
    // VTK's reader finds the end of a line's last word by the newline after it, and reads
    // past the end of a last line that has none.
    this->Unterminated = this->In.eof();
    this->Words.clear();
    this->Words.str(line);
    return true;
  }

  /// One value of type t; false when the element (ASCII) or the file (binary) has no more.
  bool Read(const std::string& t, double& value)
  {
    if (this->Ascii)
    {
      // as VTK's reader reads them (atof): "inf" and "nan" too, left for the repair to refuse
      std::string token;
      if (!(this->Words >> token))
      {
        return false;
      }
      value = std::strtod(token.c_str(), nullptr);
      return true;
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

  bool IsAscii() const { return this->Ascii; }
  bool IsUnterminated() const { return this->Unterminated; }
  long long GetLine() const { return this->Line; }

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
  long long Line;
  bool Unterminated = false;
  std::istringstream Words;
};

/// What streaming through the elements found.
struct PlyScan
{
  long long vertices = -1; // the vertex count, once the vertex element is known
  double largest = 0.0;    // the largest vertex coordinate's magnitude
  bool unknownType = false;
};

/// "" or why value `value` of property p of item i of element e is wrong: a face index that is
/// not a vertex, or a vertex coordinate that single precision cannot hold.
std::string CheckPlyValue(
  const PlyElement& e, const PlyProperty& p, long long i, double value, PlyScan& scan)
{
  if (e.name == "face" && (p.name == "vertex_indices" || p.name == "vertex_index") &&
    scan.vertices >= 0 && !(value >= 0 && value < static_cast<double>(scan.vertices)))
  {
    return "face " + std::to_string(i) + " refers to point " +
      std::to_string(static_cast<long long>(value)) + ", but there are only " +
      std::to_string(scan.vertices) + " points";
  }
  if (e.name == "vertex" && (p.name == "x" || p.name == "y" || p.name == "z") &&
    std::isfinite(value))
  {
    if (std::abs(value) > FloatMax)
    {
      return "vertex " + std::to_string(i) + " has a coordinate beyond single precision " +
        "(1e38); VTK reads PLY files in single precision, so write it as .vtp";
    }
    scan.largest = std::max(scan.largest, std::abs(value));
  }
  return "";
}

/// "" or what is wrong in element e: an item cut short (the file, or in ASCII its line, ends
/// before its properties do), or a value CheckPlyValue refuses.
std::string CheckPlyElement(PlyValues& values, const PlyElement& e, PlyScan& scan)
{
  long long i = 0;
  auto item = [&]() {
    return "'" + e.name + "' element " + std::to_string(i) + " of " + std::to_string(e.count);
  };
  for (; i < e.count; ++i)
  {
    if (!values.NextElement())
    {
      return "the file ends before " + item() + " (cut short?)";
    }
    if (values.IsUnterminated())
    {
      return "line " + std::to_string(values.GetLine()) + ", the last, has no newline at its " +
        "end, which VTK's PLY reader cannot read (cut short?)";
    }
    for (const PlyProperty& p : e.properties)
    {
      scan.unknownType = scan.unknownType || PlySize(p.type) == 0 ||
        (!p.countType.empty() && PlySize(p.countType) == 0);
      if (scan.unknownType)
      {
        return ""; // the reader judges a type this check does not know
      }
      double count = 1;
      if (!p.countType.empty() && !values.Read(p.countType, count))
      {
        return values.IsAscii()
          ? "line " + std::to_string(values.GetLine()) + ": " + item() + " lacks a list count"
          : "the file ends in " + item() + " (cut short?)";
      }
      if (!(count >= 0))
      {
        return item() + " has a list of negative length";
      }
      for (long long k = 0; k < static_cast<long long>(count); ++k)
      {
        double value = 0;
        if (!values.Read(p.type, value))
        {
          return values.IsAscii() ? "line " + std::to_string(values.GetLine()) + ": " + item() +
              " has fewer values than its properties"
                                  : "the file ends in " + item() + " (cut short?)";
        }
        const std::string bad = CheckPlyValue(e, p, i, value, scan);
        if (!bad.empty())
        {
          return bad;
        }
      }
    }
  }
  return "";
}

/// "" or why the data after the header do not match it.
std::string CheckPlyData(std::ifstream& in, const PlyHeader& header)
{
  const std::streampos dataStart = in.tellg();
  long long elements = 0;
  for (const PlyElement& e : header.elements)
  {
    elements += e.count;
  }
  if (header.format == "ascii")
  {
    // VTK's reader takes one line per element (and reads past the end of a short one); a
    // file with fewer lines than elements is cut short.
    const long long lines = CountDataLines(in);
    if (lines < elements)
    {
      return "the file has " + std::to_string(lines) + " lines after the header, fewer than the " +
        std::to_string(elements) + " elements it claims (cut short?)";
    }
    in.clear();
    in.seekg(dataStart);
  }
  PlyValues values(in, header.format, header.lines);
  PlyScan scan;
  for (const PlyElement& e : header.elements)
  {
    scan.vertices = e.name == "vertex" ? e.count : scan.vertices; // faces may come first
  }
  for (const PlyElement& e : header.elements)
  {
    const std::string bad = CheckPlyElement(values, e, scan);
    if (!bad.empty() || scan.unknownType)
    {
      return bad;
    }
  }
  if (scan.largest > 0.0 && scan.largest < FloatMin)
  {
    return "every vertex coordinate is below single precision (1e-38); VTK reads PLY files in "
           "single precision, so write it as .vtp";
  }
  return "";
}
}

std::string CheckPly(const std::string& path)
{
  const long long size = FileSize(path);
  std::ifstream in(path, std::ios::binary);
  char magic[4] = { 0, 0, 0, 0 };
  in.read(magic, 4);
  if (std::strncmp(magic, "ply\n", 4) != 0 && std::strncmp(magic, "ply\r", 4) != 0)
  {
    return "not a PLY file (it does not start with a line 'ply')";
  }
  in.seekg(0);
  std::string line;
  std::getline(in, line);
  const PlyHeader header = ReadPlyHeader(in);
  if (!header.problem.empty())
  {
    return header.problem;
  }
  if (header.format != "ascii" && header.format != "binary_big_endian" &&
    header.format != "binary_little_endian")
  {
    return "the PLY header names no format VTK reads (ascii, binary_little_endian or "
           "binary_big_endian)";
  }
  const long long bytes = size - static_cast<long long>(in.tellg());
  const std::string tooMany = CheckPlySizes(header, bytes);
  return tooMany.empty() ? CheckPlyData(in, header) : tooMany;
}
}
