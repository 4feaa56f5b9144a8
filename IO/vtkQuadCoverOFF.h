// vtkQuadCoverOFF.h (private): reads ASCII OFF files (Geomview's Object File Format), which VTK
// has no reader for; vtkQuadCoverReader reads .off files through it.
#ifndef vtkQuadCoverOFF_h
#define vtkQuadCoverOFF_h

#include <string>

class vtkPolyData;

namespace vtkQuadCoverOFF
{
/**
 * Reads `path` into `output`. Accepted: the header keyword OFF with the usual prefixes (ST, C,
 * N: texture coordinates, colours and normals after each vertex's coordinates, which are
 * skipped), the counts on the header line or the next, comments from '#' to the end of a line,
 * one vertex per line (its first three numbers), one face per line ("n i_1 ... i_n", a colour
 * after it skipped). Faces of one or two points become vertex and line cells.
 * @return "" or one line: a file that is not text (binary data), or, naming the line of the
 * file: 4OFF and nOFF (not three-dimensional), binary OFF, counts that are negative or larger
 * than the file could hold, non-finite coordinates, a face index that is not a vertex, a file
 * that ends early
 */
std::string Read(const std::string& path, vtkPolyData* output);
}

#endif
// VTK-HeaderTest-Exclude: vtkQuadCoverOFF.h
