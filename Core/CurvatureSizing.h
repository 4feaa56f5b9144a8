// CurvatureSizing.h: a grid finer where the surface curves sharply against the grid edge, so that
// thin parts (ears, fingers, horns) keep their shape (ParameterizationOptions::adaptiveCurvature).
#ifndef quadcover_CurvatureSizing_h
#define quadcover_CurvatureSizing_h

#include "MeshTopology.h"

#include <Eigen/Core>

#include <vector>

namespace quadcover
{

/**
 * The grid edge each triangle needs, over edgeLength, so that it is at most edgeOverRadius times
 * the surface's radius of curvature there, seen at the grid's scale: the points' normals are
 * averaged over their neighbours until they are smooth over about a grid edge (no smoothing on a
 * mesh as coarse as that), and a point's curvature is the largest turn of those normals
 * along one of its edges, per length. Sizes never go below edgeLength / maximumRefinement, grow
 * away from the curved parts by `gradation` times the distance walked (spreadGridSizes), and are
 * at most edgeLength. A tube of radius r gets about 2 pi / edgeOverRadius quads around it where
 * that is finer than the grid. Points on the `creases` (per edge, 1 on a crease; may be empty)
 * neither pass their normals on nor measure a turn: a crease is one bend, not a thin part, and
 * the grid stays as it is along it (the feature lines and the snapping keep creases).
 * @return #F, the mean over each triangle's points, in [1 / maximumRefinement, 1]; empty where
 * the grid stays uniform (edgeOverRadius <= 0, maximumRefinement <= 1, or no point curves enough)
 */
Eigen::VectorXd curvatureGridScale(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, double edgeLength, double edgeOverRadius, double maximumRefinement,
  const std::vector<char>& creases = {}, double gradation = 0.25);
}

#endif
