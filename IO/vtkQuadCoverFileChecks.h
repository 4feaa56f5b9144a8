// vtkQuadCoverFileChecks.h (private): what VTK 9.1's OBJ and PLY readers get wrong on bad
// files, checked before they read them.
#ifndef vtkQuadCoverFileChecks_h
#define vtkQuadCoverFileChecks_h

#include <string>

namespace vtkQuadCoverFileChecks
{
/// The file's extension in lower case, with its dot ("" when there is none).
std::string Extension(const std::string& path);

/// VTK 9.1's OBJ reader reads "nan" and "inf" as 0, and a face index past the vertices reads
/// memory it does not own. Returns "" or a one-line reason naming the first offending line.
std::string CheckObjText(const std::string& path);

/// VTK 9.1's PLY reader dereferences face indices without checking them. Streams through the
/// file (ASCII or binary) and returns "" or a one-line reason for the first face index that is
/// not a vertex. A header it cannot follow is left to the reader to judge.
std::string CheckPlyFaces(const std::string& path);
}

#endif
// VTK-HeaderTest-Exclude: vtkQuadCoverFileChecks.h
