// QuadQuality.h: the quality figures of a quad mesh (the paper's Table 1 and more).
#ifndef quadcover_QuadQuality_h
#define quadcover_QuadQuality_h

#include <Eigen/Core>

namespace quadcover
{

/// The paper's Table 1 figures and more, for a quad (or polygon) mesh.
struct QuadQuality
{
  int vertices = 0;
  int faces = 0;
  int quads = 0;             ///< faces with four distinct corners
  int irregularInner = 0;    ///< inner vertices of valence other than 4
  int irregularBoundary = 0; ///< boundary vertices of valence other than 2 (corner) or 3
  double edgeLengthRSD = 0;  ///< relative standard deviation of edge lengths
  double angleRSD = 0;       ///< of corner angles (about pi/2)
  double minScaledJacobian = 0;
  double meanScaledJacobian = 0;
  int nonManifoldEdges = 0; ///< edges of more than two faces, or twice in one direction
  int boundaryEdges = 0;
  int boundaryLoops = 0;
  int eulerCharacteristic = 0;
  int components = 0;
  Eigen::VectorXi valence;        ///< per vertex
  Eigen::VectorXd scaledJacobian; ///< per face: the smallest over its corners
};

/// Figures of a quad mesh (vertices V, faces Q as 4 vertex ids).
QuadQuality measureQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& Q);

/// Quads with a corner turned inside out: scaled Jacobian <= 0, as measureQuads measures it.
int countInvertedQuads(const Eigen::MatrixX3d& V, const Eigen::MatrixX4i& Q);

}

#endif
