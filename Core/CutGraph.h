// CutGraph.h: a set of edges that cuts a surface into topological disks and passes through
// given points (the branch points), for the parameterization (QuadCover Sect. 2.5, 4.4).
#ifndef quadcover_CutGraph_h
#define quadcover_CutGraph_h

#include "MeshTopology.h"

#include <Eigen/Core>

#include <vector>

namespace quadcover
{

struct CutGraph
{
  std::vector<char> onCut; ///< #E, 1 for inner edges on the cut (boundary edges never are)
  int numCutEdges = 0;
  /// #V: copies of the point once the surface is cut open (sectors between cut or boundary
  /// edges around it); the cut surface has sum(copies) points.
  std::vector<int> copies;
  /// Euler characteristic of the cut surface, per component of the input: 1 (a disk) for each.
  std::vector<int> cutEuler;
};

/**
 * Cuts a manifold, consistently oriented surface into one disk per component: the inner edges
 * not crossed by a breadth-first spanning tree of the triangles, pruned of every dangling branch
 * that does not end at a terminal point or on the boundary. What is left is the union of the
 * loops that generate the surface's homology, the paths joining its boundary loops, and paths
 * from them to every terminal. The choice of tree only changes the result through rounding later
 * (Sect. 2.5); it is deterministic (the tree grows from the lowest triangle of each component).
 * A closed genus-0 component with fewer than two terminals has no loop to keep and nothing to
 * join: it stays uncut (cutEuler 2), and the caller decides (a sphere's field always has
 * singularities, Poincare-Hopf asks for index 2 in all).
 * @param[in] topo     buildTopology(F, #V); must be manifold
 * @param[in] terminal #V, points the cut must reach (e.g. non-zero LayerShift); may be empty
 * @throws std::invalid_argument on a non-manifold surface or a terminal list of the wrong size
 */
CutGraph computeCutGraph(const MeshTopology& topo, const std::vector<char>& terminal);

}

#endif
