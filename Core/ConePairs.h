// ConePairs.h: where a frame field's singularities leave the quads uneven in size, and the pairs
// of opposite quarter cones that even them out.
#ifndef quadcover_ConePairs_h
#define quadcover_ConePairs_h

#include "Matchings.h"
#include "MeshTopology.h"

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace quadcover
{

struct ConePairOptions
{
  /// A pair is added only where it lowers the variance of the modelled log scale u, summed over
  /// the grid's cells (conePairsForEvenScale), by at least this, a singularity moved only where
  /// by twice this; 0: neither.
  double minimumGain = 0.0;
  /// At most this many pairs and moves.
  int maximumPairs = 100;
  /// A new cone stays this many grid edges away from every other singularity and the boundary.
  double separation = 3.0;
  /// Worker threads (0: defaultThreadCount()); the result does not depend on it.
  int numberOfThreads = 0;
};

struct ConePairs
{
  /// (+1/4 point, -1/4 point) of each pair, in the order they were chosen; a move of one of the
  /// field's own quarters is such a pair with that quarter at one end (a +1/4 at the -1/4 end, a
  /// -1/4 at the +1/4 end), which cancels it there
  std::vector<std::pair<int, int>> pairs;
  /// for each of pairs, the quarter a move takes away (one of its two points), -1 for a new pair
  std::vector<int> from;
  /// the area-weighted RMS of the modelled log scale about its mean per component, with the
  /// field's own singularities and with the pairs added and the moves made
  double deviationBefore = 0.0;
  double deviationAfter = 0.0;
};

/**
 * Pairs of opposite quarter cones that make the quads more even in size. The model: the log
 * scale u of the flat metric with cones at the field's singularities (as in Ben-Chen, Gotsman and
 * Bunin 2008), L u = kappa - K, with L the cotangent Laplacian (free boundary), K the angle
 * defects (Gaussian curvature inside, geodesic on the boundary) and kappa = 2 pi index at every
 * point, seen at the grid's scale (diffused for a time of one grid edge squared, which takes out
 * the log peak of each cone: the quads do not follow it below a grid edge). The integer-grid map
 * follows it: its log area scale goes with u/2 (correlation 0.83 on spot with its 54
 * singularities, 0.99 on a dumbbell and bumpy-cube), so that where u is low the quads are large.
 * A single cone, or a pair far apart, spreads its log potential over the whole surface and
 * raises the variance; a dipole does not. So, greedily: w, what a unit cone at each point adds
 * to the variance of u to first order (two solves for all points at once), and at the faces
 * where w changes fastest (their points regular, inside, and `separation` grid edges from every
 * singularity and the boundary) a +1/4 cone on the low side of w and a -1/4 on the high side,
 * three and six grid edges apart (a dipole across a slope lowers it between the two and hardly
 * changes u elsewhere), until six are listed; and for each of the field's own inner quarters not
 * within `separation` of a sharp edge, its move to the free point within six grid edges (and
 * not near a sharp edge either) that gains most to first order (a +1/4 moved from s to t is the
 * dipole +1/4 at t, -1/4 at s). The three best to first order are measured (two solves each), the
 * next three only when none of those is kept (no more); a pair is kept that lowers the variance of
 * u, summed over the grid's cells (area / h^2), by `minimumGain`, a move that lowers it by twice
 * that. Two factorizations in all.
 * @param[in] defect     #V angleDefects
 * @param[in] index      #V the field's index at each point (FrameTopology::index)
 * @param[in] edgeLength the grid's edge length h
 * @param[in] sharp      #E (topo's edges) or empty: 1 for a sharp edge; a quarter within
 *                       `separation` of one stays (the frames are held along it, and a CAD part's
 *                       corners are where its creases need them)
 */
ConePairs conePairsForEvenScale(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const Eigen::VectorXd& defect, const Eigen::VectorXd& index,
  double edgeLength, const std::vector<char>& sharp, const ConePairOptions& options);

/**
 * Adds the cone pairs and makes the moves conePairsForEvenScale chose, in its order: for each
 * (a, b) a +1/4 singularity at a and a -1/4 at b, by a quarter turn of the matchings along the
 * shortest edge path between them over regular inner points; where `from` names a or b, that
 * point is the field's -1/4 (a) or +1/4 (b), and the same change moves it to the other point.
 * On a component with handles only where the triangles within twice the path's length of a form
 * a disk (see cancelClosePairs). (The twist check of optimizeBranchPoints cannot object: a
 * component keeps its singularities.) An entry that cannot be made (its points are not as
 * chosen, no path) is skipped, and so is every later one that touches its points (the search
 * chose those with it made). Updates `topology` in place.
 * @param[out] changedFaces #F, 1 for the faces on both sides of a changed edge
 * @param[out] moved        the number of quarters moved
 * @return the number of pairs added
 */
int addConePairs(const Eigen::MatrixX3i& F, const MeshTopology& topo, const FrameGeometry& geometry,
  const Eigen::MatrixX3d& frameU, FrameTopology& topology, const ConePairs& chosen,
  std::vector<char>& changedFaces, int& moved);
}

#endif
