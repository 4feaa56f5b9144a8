// VTK-HeaderTest-Exclude: vtkQuadCoverFileChecks.cxx
#include "vtkQuadCoverFileChecks.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>

namespace vtkQuadCoverFileChecks
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
}
