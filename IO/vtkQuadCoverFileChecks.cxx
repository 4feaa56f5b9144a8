// VTK-HeaderTest-Exclude: vtkQuadCoverFileChecks.cxx
#include "vtkQuadCoverFileChecks.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>

namespace vtkQuadCoverFileChecks
{
namespace
{
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

bool LooksBinary(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  char head[4096];
  in.read(head, sizeof head);
  const std::streamsize n = in.gcount();
  long long control = 0;
  for (std::streamsize i = 0; i < n; ++i)
  {
    const unsigned char c = static_cast<unsigned char>(head[i]);
    if (c == 0)
    {
      return true;
    }
    // bytes of 128 and more are left alone: UTF-8 comments are text
    control += (c < 32 && !std::isspace(c)) || c == 127;
  }
  return control * 100 > n;
}

std::string CheckStl(const std::string& path)
{
  // vtkQuadCoverSTL tells binary from ASCII by this test too (and reports an ASCII file cut
  // short itself, with the line).
  const bool binary =
    vtksys::SystemTools::DetectFileType(path.c_str()) != vtksys::SystemTools::FileTypeText;
  return binary ? CheckBinaryStl(path, FileSize(path)) : "";
}
}
