// vtkQuadCoverSTL.h (private): reads binary and ASCII STL files; vtkQuadCoverReader reads .stl
// files through it. (VTK's own reader lives in a module that brings the rendering and imaging
// libraries along: about 20 MB more resident memory for every run of the command line.)
#ifndef vtkQuadCoverSTL_h
#define vtkQuadCoverSTL_h

#include <string>

class vtkPolyData;

namespace vtkQuadCoverSTL
{
/**
 * Reads `path` into `output`: a triangle per binary facet (80 bytes of header, a little-endian
 * triangle count, then 50 bytes a triangle: a normal, three corners as floats, two bytes of
 * attributes), or a polygon per ASCII facet ("facet normal ... outer loop", a "vertex x y z" line
 * per corner, "endloop endfacet", in one or more "solid" blocks). The file is binary unless it
 * reads as text (vtksys's test). Points with equal coordinates are one point (STL repeats them
 * per facet), in the order they first appear; a facet left with two corners on one point is
 * dropped. The facets' normals are not kept. A binary file whose count is not its own (many
 * writers put 0 there) is read to its end.
 * @return "" or one line: a binary file shorter than its header or its count says, or one whose
 * count is not its own and that ends in the middle of a triangle; or, naming the line of an
 * ASCII file: a keyword out of place, a vertex without three numbers, a facet of fewer than three
 * corners, a file that ends in the middle of a facet
 */
std::string Read(const std::string& path, vtkPolyData* output);
}

#endif
// VTK-HeaderTest-Exclude: vtkQuadCoverSTL.h
