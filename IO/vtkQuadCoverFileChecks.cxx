// VTK-HeaderTest-Exclude: vtkQuadCoverFileChecks.cxx
#include "vtkQuadCoverFileChecks.h"

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
}
