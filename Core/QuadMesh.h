// QuadMesh.h: the quad mesh cut out of an integer-grid map, and the cells that gave no quad.
#ifndef quadcover_QuadMesh_h
#define quadcover_QuadMesh_h

#include <Eigen/Core>

#include <vector>

namespace quadcover
{

struct QuadMesh
{
  Eigen::MatrixX3d V;              ///< quad vertices, on the input surface
  Eigen::MatrixX4i Q;              ///< quads, counterclockwise seen from the surface's orientation
  std::vector<int> vertexTriangle; ///< the input triangle each vertex lies in (or was lifted off:
                                   ///< liftOffOtherComponents)
  std::vector<int> vertexPoint;    ///< the input point a vertex sits on, or -1
  std::vector<int> quadTriangle;   ///< the input triangle holding each quad's centre
  // what could not become a quad (all 0 on a seamless, flip-free map)
  int cellsOffSurface = 0;       ///< a corner beyond the boundary, or a walk that failed
  int cellsDegenerate = 0;       ///< two corners at one grid point
  int cellsConflicting = 0;      ///< removed: they overlapped others (folded maps)
  int nonIntegerTransitions = 0; ///< inner edges whose translation is not integer
  /// corners that could not be reached along the straight segment from their cell's centre (a
  /// flipped triangle or the boundary on it) and were searched for by stepping towards them
  int walkFallbacks = 0;
};

}

#endif
