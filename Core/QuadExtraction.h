// QuadExtraction.h: the quad mesh of an integer-grid map (stage 5), its quality and relaxation.
#ifndef quadcover_QuadExtraction_h
#define quadcover_QuadExtraction_h

#include "MeshTopology.h"
#include "Progress.h"
#include "QuadMesh.h"
#include "QuadQuality.h"
#include "QuadRelaxation.h"

#include <Eigen/Core>

#include <array>

#include <utility>
#include <vector>

namespace quadcover
{

struct QuadExtractionOptions
{
  /// Barycentric tolerance for a grid point on a triangle's edge or corner.
  double tolerance = 1e-7;
  /// A grid point within this (u, v) distance of a point of the surface (in grid units) is that
  /// point, seen alike from every triangle around it.
  double pointTolerance = 1e-5;
  /// A flipped triangle whose (u, v) area is at most this times its longest (u, v) edge squared
  /// is flat: its image is a segment, which a walk crosses (it holds no cell).
  double flatTolerance = 1e-4;
  /// Triangles a walk from a cell's centre to one of its corners may cross.
  int maximumWalk = 10000;
};

/**
 * What overlapping cells of a folded map leave behind: repeated quads (the same corners in the
 * same cyclic order: a centre on an edge or point is held by every triangle there) are merged,
 * and every quad that shares a directed edge with another, or lies on an edge of more than two
 * quads, is removed, so that what is left is manifold. `owner` (one entry per quad) follows.
 * @return the quads removed (merged repeats not counted)
 * @throws std::invalid_argument when owner and quads differ in size
 */
int removeOverlappingQuads(std::vector<std::array<int, 4>>& quads, std::vector<int>& owner);

/**
 * Cuts the quads out of an integer-grid map: every unit cell [a, a+1] x [b, b+1] of the grid
 * becomes one quad, found through its centre (a + 1/2, b + 1/2) in the triangle that holds it
 * (a centre on an edge or point is found from each triangle there, and the copies merged). Its four
 * corners are found by walking in the (u, v) plane from the centre, across edges and seams (through
 * the transition functions read off the map), to the triangle that holds each corner; a corner on a
 * point, on an edge or inside a triangle gets one identity wherever it is reached from, so that
 * quads share vertices across seams and a branch point of index k/4 becomes a vertex of valence 4 -
 * k. Triangles with a flipped (u, v) image hold no quad centre and stop walks; quads that still
 * overlap (the same corner reached twice along one edge direction) are removed and counted, so
 * the output stays manifold.
 * @param[in] cornerUV #F x 6 (u, v at corners 0, 1, 2), as computeParameterization gives
 * @throws std::invalid_argument on sizes that do not match or a non-manifold surface
 */
QuadMesh extractQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const Eigen::MatrixXd& cornerUV,
  const QuadExtractionOptions& options = QuadExtractionOptions(),
  const Progress& progress = Progress());

}

#endif
