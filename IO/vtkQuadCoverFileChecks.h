// vtkQuadCoverFileChecks.h (private): what VTK 9.1's PLY reader gets wrong on bad files, checked
// before it reads them, and what the readers share.
#ifndef vtkQuadCoverFileChecks_h
#define vtkQuadCoverFileChecks_h

#include <limits>
#include <string>

namespace vtkQuadCoverFileChecks
{
/// The range of the single-precision coordinates VTK's PLY reader stores.
constexpr double FloatMax = std::numeric_limits<float>::max();
constexpr double FloatMin = std::numeric_limits<float>::min();

/// The file's extension in lower case, with its dot ("" when there is none).
std::string Extension(const std::string& path);

/// The file's size in bytes, -1 when it cannot be opened.
long long FileSize(const std::string& path);

/// True when the file's first 4 KB hold a NUL byte or more than 1% control characters (bytes
/// from 128 up count as text, for UTF-8).
bool LooksBinary(const std::string& path);

/**
 * VTK 9.1's PLY reader dereferences face indices without checking them, crashes on a file cut
 * short, allocates whatever the header's element counts say and stores single precision. Checks
 * the header (the "ply" line, a known format, end_header), that the file could hold the elements
 * it claims (before anything is allocated), then streams through the elements (ASCII: one line
 * each, the last one ended by a newline; binary: to the byte): a file that ends early, a face
 * index that is not a vertex, a vertex coordinate beyond single precision or all of them below
 * it. Returns "" or a one-line reason.
 * A property type it does not know is left to the reader to judge.
 */
std::string CheckPly(const std::string& path);
}

#endif
// VTK-HeaderTest-Exclude: vtkQuadCoverFileChecks.h
