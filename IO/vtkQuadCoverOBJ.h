// vtkQuadCoverOBJ.h (private): reads Wavefront OBJ files in double precision, in one pass over
// the file held in memory, and writes them; vtkQuadCoverReader and vtkQuadCoverWriter read and
// write .obj files through it. (VTK's own reader
// stores single precision, reads "nan" as 0, reads past its points on a bad face index, and takes
// most of the time of a small run on a large file.)
#ifndef vtkQuadCoverOBJ_h
#define vtkQuadCoverOBJ_h

#include <string>

class vtkPolyData;

namespace vtkQuadCoverOBJ
{
/**
 * Reads `path` into `output`: the points of the "v" lines (their first three numbers, as
 * doubles), a polygon per "f" line, a polyline per "l" line and vertex cells per "p" line.
 * Indices are "i", "i/t", "i//n" or "i/t/n" (only i is used), from 1, or negative counting back
 * from the last point read; a backslash at the end of a line continues it. Every other line
 * (texture coordinates, normals, groups, materials, comments) is skipped. The points are the
 * file's own, in its order, none repeated per texture coordinate or normal.
 * @return "" or one line: a file that is not text (binary data), or, naming the line of the
 * file: a vertex without three coordinates, a non-finite coordinate, an index that is not a
 * point, a face of fewer than three points (noting a file that ends in the middle of it)
 */
std::string Read(const std::string& path, vtkPolyData* output);

/**
 * Writes `input` to `path`: a "v" line per point (the shortest decimals that read back to the
 * same double), then an "f" line per polygon, an "l" line per polyline and a "p" line per vertex
 * cell, indices from 1 (a strip as its triangles). Point and cell data are not written.
 * @return "" or why the file could not be written
 */
std::string Write(const std::string& path, vtkPolyData* input);
}

#endif
// VTK-HeaderTest-Exclude: vtkQuadCoverOBJ.h
