// MatchingAngles.h: internal to Core: the turning between neighbouring frames and what a matching
// leaves of it, shared by the matchings, the branch-point optimization and the frame fit.
#ifndef quadcover_MatchingAngles_h
#define quadcover_MatchingAngles_h

#include "Matchings.h"

#include <Eigen/Core>

namespace quadcover
{
namespace detail
{
constexpr double Pi = 3.14159265358979323846;
constexpr double Quarter = 0.5 * Pi;

inline int mod4(int r)
{
  return ((r % 4) + 4) % 4;
}

/// Rotation from f's first frame vector to g's (carried into f's plane), before matching.
inline double turning(const FrameGeometry& G, const Eigen::VectorXd& phi, int f, int k, int g)
{
  return wrapAngle(phi[g] + G.transport(f, k) - phi[f]);
}

/// What is left of a turning once the matching r (paper convention) is accounted for.
inline double residual(double turn, int r)
{
  // X_{g,0} = X_{f,-r}: g's vector is f's turned by -r quarter turns.
  return wrapAngle(turn + r * Quarter);
}

/// Position (0..2) in g of the edge g shares with f across f's edge k.
inline int twinEdge(const MeshTopology& topo, int f, int k, int g)
{
  const int e = topo.faceEdges(f, k);
  const int c =
    topo.edgeCorners(e, 0) == 3 * f + k ? topo.edgeCorners(e, 1) : topo.edgeCorners(e, 0);
  return c >= 0 && c / 3 == g ? c % 3 : -1;
}
}
}

#endif
