// VTK-HeaderTest-Exclude: vtkQuadCoverFileChecks.cxx
#include "vtkQuadCoverFileChecks.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace vtkQuadCoverFileChecks
{
namespace
{
/// "" or the reason why an OBJ "v" line's coordinates are not all finite.
std::string CheckObjVertex(const std::string& line, long long number)
{
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
  return "";
}

/// The binary STL's size against its header: 80 bytes, a triangle count, 50 bytes a triangle.
std::string CheckBinaryStl(const std::string& path, long long size)
{
  if (size < 84)
  {
    return "a binary STL file needs 84 bytes for its header, this one has " + std::to_string(size);
  }
  std::ifstream in(path, std::ios::binary);
  unsigned char b[4] = { 0, 0, 0, 0 };
  in.seekg(80);
  in.read(reinterpret_cast<char*>(b), 4);
  const long long claimed = static_cast<long long>(b[0]) | (static_cast<long long>(b[1]) << 8) |
    (static_cast<long long>(b[2]) << 16) | (static_cast<long long>(b[3]) << 24);
  const long long present = (size - 84) / 50;
  // VTK's reader allocates for the header's count, and reads on to the end of the file (many
  // writers put 0 there): so a count larger than the file is refused, a smaller one is not.
  if (claimed > present)
  {
    return "the binary STL header says " + std::to_string(claimed) + " triangles (" +
      std::to_string(84 + 50 * claimed) + " bytes), but the file has " + std::to_string(size) +
      " bytes, " + std::to_string(present) + " triangles (cut short?)";
  }
  // With a count that is not the file's (often 0), only the file's length tells whether it was
  // cut in the middle of a triangle; bytes after as many triangles as the header says are left.
  if (claimed != present && (size - 84) % 50 != 0)
  {
    return "the binary STL file ends in the middle of a triangle (" + std::to_string(size) +
      " bytes is not 84 and 50 a triangle; cut short?)";
  }
  return "";
}
}

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

long long FileSize(const std::string& path)
{
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  return in ? static_cast<long long>(in.tellg()) : -1;
}

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
      const std::string bad = CheckObjVertex(line, number);
      if (!bad.empty())
      {
        return bad;
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

std::string CheckStl(const std::string& path)
{
  // VTK's reader tells binary from ASCII by this test; the check follows its choice. (It
  // reports an ASCII file cut short itself, with the line.)
  const bool binary =
    vtksys::SystemTools::DetectFileType(path.c_str()) != vtksys::SystemTools::FileTypeText;
  return binary ? CheckBinaryStl(path, FileSize(path)) : "";
}
}
