// vtkQuadCoverInput.h (private): the input checks and the triangulation every QuadCover filter
// shares (vtkQuadCoverAlgorithm). Not wrapped or installed (plain functions).
#ifndef vtkQuadCoverInput_h
#define vtkQuadCoverInput_h

#include "vtkPolyData.h"
#include "vtkQuadCoverFiltersModule.h" // for export macro

#include <string>

namespace vtkQuadCoverInput
{
/// "" when the input has points, every point id of every cell lies in [0, #points), #points fits
/// an int and every coordinate is finite; else a one-line reason (naming the first bad cell or
/// point). VTK's own filters do not check ids and crash on bad ones.
VTKQUADCOVERFILTERS_EXPORT std::string CheckPoints(vtkPolyData* input);

/**
 * Makes `output` a triangle-only surface over `input`: a shallow copy when `input` holds only
 * proper triangles, else polygons and strips triangulated (TriangulateCells, cell data copied to
 * the new triangles), vertices and lines dropped, and triangles that repeat a point id (strip
 * joins, collapsed polygons) dropped; `warning` counts what was dropped.
 * @return "" on success, else a one-line reason (no points, no polygons, point ids out of range,
 * non-finite points).
 */
VTKQUADCOVERFILTERS_EXPORT std::string Triangulate(
  vtkPolyData* input, vtkPolyData* output, std::string& warning);

/**
 * The polygons and strips of `input` as triangles, in that order, each with its cell's data:
 * a triangle as it is, a larger polygon by vtkPolygon's triangulation (none for fewer than three
 * points), a strip's triangles as vtkTriangleStrip lays them out (its degenerate joins too).
 * Vertex and line cells are left out; points, point data and field data are shared. What
 * vtkTriangleFilter makes with PassVerts and PassLines off (Testing/Cxx checks it), without
 * VTK::FiltersCore, which a command line's every run loaded for it (6 MB resident).
 */
VTKQUADCOVERFILTERS_EXPORT void TriangulateCells(vtkPolyData* input, vtkPolyData* output);

/**
 * `input`'s polygons (their cell data passed) over only the points they use, renumbered in the
 * order the polygons first use them, with their point data; field data shared. `input` has only
 * polygons, none that repeats a point. What vtkCleanPolyData makes of such a surface with
 * PointMerging off (Testing/Cxx checks it).
 */
VTKQUADCOVERFILTERS_EXPORT void RemoveUnusedPoints(vtkPolyData* input, vtkPolyData* output);

/**
 * The scale at which the stages compute (vtkQuadCoverSurface): the points times 2^e. 0 when the
 * largest side of the points' bounding box lies in [2^-16, 2^16] (at those sizes the stages'
 * tolerances work as they are, and their outputs stay what they were), or when the points all
 * coincide; else the e that brings the largest side into [1, 2), within [-1022, 1022] so that 2^e
 * and 2^-e are finite. The points must be finite (CheckPoints).
 */
VTKQUADCOVERFILTERS_EXPORT int UnitScaleExponent(vtkPolyData* input);
}

#endif
// VTK-HeaderTest-Exclude: vtkQuadCoverInput.h
