// FrameField.cxx: triangle bases, transport, angle defects, frames as angles, sharp edges.
#include "FrameField.h"

#include "CurvatureFrames.h"
#include "UnionFind.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace quadcover
{
namespace
{
constexpr double Pi = 3.14159265358979323846;
}

double wrapAngle(double a)
{
  a = std::fmod(a, 2.0 * Pi);
  if (a <= -Pi)
  {
    a += 2.0 * Pi;
  }
  else if (a > Pi)
  {
    a -= 2.0 * Pi;
  }
  return a;
}

double wrapQuarter(double a)
{
  const double q = 0.5 * Pi;
  a = std::fmod(a, q);
  if (a <= -0.5 * q)
  {
    a += q;
  }
  else if (a > 0.5 * q)
  {
    a -= q;
  }
  return a;
}

FaceBases computeFaceBases(
  const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const MeshTopology& topo)
{
  const int nf = static_cast<int>(F.rows());
  FaceBases B;
  B.normal = computeFaceNormals(V, F, topo);
  B.b1.resize(nf, 3);
  B.b2.resize(nf, 3);
  for (int f = 0; f < nf; ++f)
  {
    const Eigen::Vector3d n = B.normal.row(f);
    Eigen::Vector3d t = V.row(F(f, 1)) - V.row(F(f, 0));
    t -= t.dot(n) * n;
    if (!(t.squaredNorm() > 0.0) || n.squaredNorm() == 0.0)
    {
      t = n.squaredNorm() > 0.0 ? n.unitOrthogonal() : Eigen::Vector3d::UnitX();
    }
    t.normalize();
    B.b1.row(f) = t.transpose();
    B.b2.row(f) = n.cross(t).transpose();
  }
  return B;
}

Eigen::VectorXd vectorAngles(const FaceBases& bases, const Eigen::MatrixX3d& U)
{
  const Eigen::Index nf = U.rows();
  Eigen::VectorXd a(nf);
  for (Eigen::Index f = 0; f < nf; ++f)
  {
    a[f] = std::atan2(U.row(f).dot(bases.b2.row(f)), U.row(f).dot(bases.b1.row(f)));
  }
  return a;
}

std::pair<Eigen::MatrixX3d, Eigen::MatrixX3d> tangentFrames(
  const FaceBases& bases, const Eigen::MatrixX3d& U, const Eigen::MatrixX3d& V)
{
  const Eigen::Index nf = bases.normal.rows();
  if (U.rows() != nf || (V.rows() != 0 && V.rows() != nf))
  {
    throw std::invalid_argument("tangentFrames: sizes do not match");
  }
  std::pair<Eigen::MatrixX3d, Eigen::MatrixX3d> frames(U, Eigen::MatrixX3d(nf, 3));
  for (Eigen::Index f = 0; f < nf; ++f)
  {
    const Eigen::Vector3d n = bases.normal.row(f);
    Eigen::Vector3d x = U.row(f);
    x -= x.dot(n) * n;
    frames.first.row(f) = x.allFinite() && x.norm() > 0.0 ? Eigen::RowVector3d(x.normalized())
                                                          : Eigen::RowVector3d(bases.b1.row(f));
    const bool given = V.rows() != 0 && V.row(f).allFinite();
    frames.second.row(f) = given ? Eigen::RowVector3d(V.row(f))
                                 : Eigen::RowVector3d(n.cross(frames.first.row(f).transpose()));
  }
  return frames;
}

Eigen::MatrixX3d angleVectors(const FaceBases& bases, const Eigen::VectorXd& angles)
{
  Eigen::MatrixX3d U(angles.size(), 3);
  for (Eigen::Index f = 0; f < angles.size(); ++f)
  {
    U.row(f) = std::cos(angles[f]) * bases.b1.row(f) + std::sin(angles[f]) * bases.b2.row(f);
  }
  return U;
}

Eigen::MatrixX3d computeTransport(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const FaceBases& bases)
{
  const int nf = static_cast<int>(F.rows());
  Eigen::MatrixX3d T = Eigen::MatrixX3d::Zero(nf, 3);
  forEachNeighbor(topo, [&](int f, int k, int g) {
    // The shared edge, as one 3D vector, measured in both bases: unfolding g onto f about the
    // edge keeps the edge fixed, so angles shift by the difference.
    const Eigen::Vector3d e = V.row(F(f, (k + 1) % 3)) - V.row(F(f, k));
    const double af = std::atan2(e.dot(bases.b2.row(f)), e.dot(bases.b1.row(f)));
    const double ag = std::atan2(e.dot(bases.b2.row(g)), e.dot(bases.b1.row(g)));
    T(f, k) = wrapAngle(af - ag);
  });
  return T;
}

Eigen::MatrixX3d cornerAngles(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F)
{
  Eigen::MatrixX3d A(F.rows(), 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Eigen::Vector3d p = V.row(F(f, k));
      const Eigen::Vector3d a = V.row(F(f, (k + 1) % 3)) - p.transpose();
      const Eigen::Vector3d b = V.row(F(f, (k + 2) % 3)) - p.transpose();
      A(f, k) = std::atan2(a.cross(b).norm(), a.dot(b));
    }
  }
  return A;
}

Eigen::VectorXd angleDefects(
  const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const MeshTopology& topo)
{
  const Eigen::MatrixX3d A = cornerAngles(V, F);
  Eigen::VectorXd K(V.rows());
  for (Eigen::Index v = 0; v < V.rows(); ++v)
  {
    K[v] = topo.boundaryVertex[v] ? Pi : 2.0 * Pi;
  }
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      K[F(f, k)] -= A(f, k);
    }
  }
  for (int v : topo.unreferencedVertices)
  {
    K[v] = 0.0;
  }
  return K;
}

void rotateFrames(
  const FaceBases& bases, const Eigen::VectorXd& alpha, Eigen::MatrixX3d& U, Eigen::MatrixX3d& V)
{
  for (Eigen::Index f = 0; f < alpha.size(); ++f)
  {
    const Eigen::Vector3d n = bases.normal.row(f);
    const double c = std::cos(alpha[f]), s = std::sin(alpha[f]);
    const Eigen::Vector3d u = U.row(f), v = V.row(f);
    U.row(f) = (c * u + s * n.cross(u)).transpose();
    V.row(f) = (c * v + s * n.cross(v)).transpose();
  }
}

double surfaceArea(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F)
{
  double area = 0.0;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    area += triangleArea(V, F, f);
  }
  return area;
}

std::vector<double> componentAreas(
  const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const MeshTopology& topo)
{
  std::vector<double> area(topo.numComponents(), 0.0);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    area[topo.faceComponent[f]] += triangleArea(V, F, f);
  }
  return area;
}

std::vector<int> edgeNetworks(const MeshTopology& topo, const std::vector<char>& flagged)
{
  const int ne = topo.numEdges();
  std::vector<int> parent(ne), firstAt(topo.numVertices, -1);
  for (int e = 0; e < ne; ++e)
  {
    parent[e] = e;
  }
  for (int e = 0; e < ne; ++e)
  {
    for (int j = 0; flagged[e] && j < 2; ++j)
    {
      int& other = firstAt[topo.edges(e, j)];
      other = other < 0 ? e : other;
      unite(parent, other, e);
    }
  }
  for (int e = 0; e < ne; ++e)
  {
    parent[e] = findRoot(parent, e);
  }
  return parent;
}

namespace
{

/// Per edge, the angle between its two triangles' normals (0 on a boundary or non-manifold edge).
std::vector<double> edgeBends(const MeshTopology& topo, const FaceBases& bases)
{
  std::vector<double> bend(topo.numEdges(), 0.0);
  for (int e = 0; e < topo.numEdges(); ++e)
  {
    if (topo.edgeFaceCount[e] == 2)
    {
      const double c =
        bases.normal.row(topo.edgeFaces(e, 0)).dot(bases.normal.row(topo.edgeFaces(e, 1)));
      bend[e] = std::acos(std::clamp(c, -1.0, 1.0));
    }
  }
  return bend;
}

/// How much the surface beside a sharp edge e bends across it: over the other edges of e's two
/// triangles that are not sharp themselves, the largest angle between the normals on either side
/// of them, seen along e (both normals projected onto the plane normal to e, so that a crease
/// that curves, like the rim of a faceted cylinder, has smooth sides).
double sideBend(const MeshTopology& topo, const FaceBases& bases, const std::vector<double>& bend,
  double feature, int e)
{
  const Eigen::Vector3d cross =
    bases.normal.row(topo.edgeFaces(e, 0)).cross(bases.normal.row(topo.edgeFaces(e, 1)));
  if (cross.norm() < 1e-12)
  {
    return 0.0; // folded flat: a fin's edge is a crease
  }
  const Eigen::Vector3d t = cross.normalized();
  double side = 0.0;
  for (int i = 0; i < 2; ++i)
  {
    const int f = topo.edgeFaces(e, i);
    for (int k = 0; k < 3; ++k)
    {
      const int o = topo.faceEdges(f, k);
      if (o < 0 || o == e || bend[o] > feature || topo.edgeFaceCount[o] != 2)
      {
        continue;
      }
      const int g = topo.edgeFaces(o, 0) == f ? topo.edgeFaces(o, 1) : topo.edgeFaces(o, 0);
      const Eigen::Vector3d nf = bases.normal.row(f), ng = bases.normal.row(g);
      const Eigen::Vector3d a = nf - nf.dot(t) * t, b = ng - ng.dot(t) * t;
      side = std::max(side, std::atan2(a.cross(b).norm(), a.dot(b)));
    }
  }
  return side;
}

}

std::vector<char> sharpEdges(const MeshTopology& topo, const FaceBases& bases, double featureAngle,
  int minimumLength, double smoothSideFraction)
{
  const double feature = featureAngle * 3.14159265358979323846 / 180.0;
  const int ne = topo.numEdges();
  const std::vector<double> bend = edgeBends(topo, bases);
  std::vector<char> sharp(ne, 0), smoothSides(ne, 0);
  for (int e = 0; e < ne; ++e)
  {
    sharp[e] = bend[e] > feature;
    smoothSides[e] =
      sharp[e] && sideBend(topo, bases, bend, feature, e) <= smoothSideFraction * bend[e];
  }
  // A network is a crease where it is long enough and at least half of its edges have smooth
  // sides; decided per network, so that a corner's few rough edges do not cut a crease apart.
  const std::vector<int> network = edgeNetworks(topo, sharp);
  std::vector<int> size(ne, 0), smooth(ne, 0);
  for (int e = 0; e < ne; ++e)
  {
    size[network[e]] += sharp[e];
    smooth[network[e]] += smoothSides[e];
  }
  for (int e = 0; e < ne; ++e)
  {
    const int n = network[e];
    sharp[e] = sharp[e] && size[n] >= minimumLength && 2 * smooth[n] >= size[n];
  }
  return sharp;
}
}
