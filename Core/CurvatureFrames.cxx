// CurvatureFrames.cxx: triangle normals, curvature tensors from the normal cycle, and the
// curvature frames they give.
#include "CurvatureFrames.h"

#include "DegenerateTriangles.h"
#include "Parallel.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace quadcover
{

Eigen::MatrixX3d computeFaceNormals(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, std::vector<char>* degenerate)
{
  const int nf = static_cast<int>(F.rows());
  Eigen::MatrixX3d raw(nf, 3); // cross products: direction and twice the area
  std::vector<char> bad(nf, 0);
  for (int f = 0; f < nf; ++f)
  {
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    raw.row(f) = (b - a).cross(c - a).transpose();
    bad[f] = isDegenerateTriangle(a, b, c);
  }
  Eigen::MatrixX3d N(nf, 3);
  for (int f = 0; f < nf; ++f)
  {
    if (!bad[f])
    {
      N.row(f) = raw.row(f).normalized();
      continue;
    }
    Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
    for (int k = 0; k < 3; ++k)
    {
      const int v = F(f, k);
      for (int i = topo.ringOffsets[v]; i < topo.ringOffsets[v + 1]; ++i)
      {
        const int g = topo.ringFaces[i];
        if (!bad[g])
        {
          sum += raw.row(g);
        }
      }
    }
    const double len = sum.norm();
    N.row(f) = len > 0.0 ? (sum / len).eval() : Eigen::RowVector3d::Zero();
  }
  if (degenerate)
  {
    degenerate->swap(bad);
  }
  return N;
}

double medianEdgeLength(const Eigen::MatrixX3d& V, const MeshTopology& topo)
{
  const int ne = topo.numEdges();
  if (ne == 0)
  {
    return 0.0;
  }
  std::vector<double> lengths(ne);
  for (int e = 0; e < ne; ++e)
  {
    lengths[e] = (V.row(topo.edges(e, 0)) - V.row(topo.edges(e, 1))).norm();
  }
  std::nth_element(lengths.begin(), lengths.begin() + ne / 2, lengths.end());
  return lengths[ne / 2];
}

namespace
{
using Tensor = Eigen::Matrix<double, 6, 1>; // xx yy zz xy xz yz

Tensor outer(const Eigen::Vector3d& e, double w)
{
  Tensor t;
  t << w * e.x() * e.x(), w * e.y() * e.y(), w * e.z() * e.z(), w * e.x() * e.y(),
    w * e.x() * e.z(), w * e.y() * e.z();
  return t;
}

double quadratic(const Tensor& t, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return t[0] * a.x() * b.x() + t[1] * a.y() * b.y() + t[2] * a.z() * b.z() +
    t[3] * (a.x() * b.y() + a.y() * b.x()) + t[4] * (a.x() * b.z() + a.z() * b.x()) +
    t[5] * (a.y() * b.z() + a.z() * b.y());
}

void checkInputs(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const MeshTopology& topo,
  const CurvatureOptions& options)
{
  if (topo.numFaces != F.rows() || topo.numVertices != V.rows())
  {
    throw std::invalid_argument("computeCurvatureField: topology does not match the mesh");
  }
  if (!V.allFinite())
  {
    throw std::invalid_argument("computeCurvatureField: non-finite point coordinates");
  }
  if (!(options.neighborhoodRadius >= 0.0) || !std::isfinite(options.neighborhoodRadius))
  {
    throw std::invalid_argument("computeCurvatureField: radius must be finite and >= 0");
  }
}

/// Per-edge contribution beta |e| e e^T, beta > 0 where the edge is convex (#E; zero on edges
/// without two triangles, with a degenerate one, or of zero length).
std::vector<Tensor> edgeTensors(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const Eigen::MatrixX3d& N, const std::vector<char>& degenerate)
{
  const int ne = topo.numEdges();
  std::vector<Tensor> edgeTensor(ne, Tensor::Zero());
  for (int e = 0; e < ne; ++e)
  {
    if (topo.edgeFaceCount[e] != 2)
    {
      continue;
    }
    const int f0 = topo.edgeFaces(e, 0), f1 = topo.edgeFaces(e, 1);
    if (degenerate[f0] || degenerate[f1])
    {
      continue; // a borrowed normal says nothing about the bend across this edge
    }
    const Eigen::Vector3d n0 = N.row(f0), n1 = N.row(f1);
    // Orient the edge as it runs in f0.
    const int k0 = topo.edgeCorners(e, 0) % 3;
    const int from = F(f0, k0), to = F(f0, (k0 + 1) % 3);
    Eigen::Vector3d d = V.row(to) - V.row(from);
    const double len = d.norm();
    if (len == 0.0)
    {
      continue;
    }
    d /= len;
    const double beta = std::atan2(n0.cross(n1).dot(d), n0.dot(n1));
    edgeTensor[e] = outer(d, beta * len);
  }
  return edgeTensor;
}

/// What each triangle brings to a neighbourhood: half the tensors of its edges, its area, and
/// where it is (its centroid).
struct FaceSums
{
  std::vector<Tensor> tensor; ///< #F
  Eigen::VectorXd area;       ///< #F
  Eigen::MatrixX3d centroid;  ///< #F x 3
};

FaceSums faceSums(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const MeshTopology& topo,
  const std::vector<Tensor>& edgeTensor)
{
  const int nf = static_cast<int>(F.rows());
  FaceSums S;
  S.tensor.resize(nf);
  S.area.resize(nf);
  S.centroid.resize(nf, 3);
  for (int f = 0; f < nf; ++f)
  {
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    S.area[f] = 0.5 * (b - a).cross(c - a).norm();
    S.centroid.row(f) = ((a + b + c) / 3.0).transpose();
    Tensor t = Tensor::Zero();
    for (int k = 0; k < 3; ++k)
    {
      const int e = topo.faceEdges(f, k);
      if (e >= 0)
      {
        t += 0.5 * edgeTensor[e];
      }
    }
    S.tensor[f] = t;
  }
  return S;
}

/// Sums the tensors and areas of the triangles around one, breadth-first over edge neighbours
/// whose centroid lies closer than the radius; one per worker thread, its scratch reused.
class NeighborhoodSummer
{
public:
  NeighborhoodSummer(const MeshTopology& topo, const FaceSums& sums, double r2, size_t cap)
    : Topo(topo)
    , Sums(sums)
    , R2(r2)
    , Cap(cap)
    , Stamp(r2 > 0.0 ? topo.numFaces : 0, -1)
  {}

  /// The tensor summed around f and divided by the area summed (as is where that area is 0).
  /// @return whether the neighbourhood was cut at the cap
  bool sum(int f, Tensor& H)
  {
    H = Sums.tensor[f];
    double A = Sums.area[f];
    bool truncated = false;
    if (R2 > 0.0)
    {
      Queue.clear();
      Queue.push_back(f);
      Stamp[f] = f;
      const Eigen::RowVector3d cf = Sums.centroid.row(f);
      for (size_t q = 0; q < Queue.size() && Queue.size() < Cap; ++q)
      {
        const int g = Queue[q];
        for (int k = 0; k < 3 && Queue.size() < Cap; ++k)
        {
          const int h = Topo.faceNeighbors(g, k);
          if (h < 0 || Stamp[h] == f)
          {
            continue;
          }
          Stamp[h] = f;
          if ((Sums.centroid.row(h) - cf).squaredNorm() < R2)
          {
            H += Sums.tensor[h];
            A += Sums.area[h];
            Queue.push_back(h);
          }
        }
      }
      truncated = Queue.size() >= Cap;
    }
    if (A > 0.0)
    {
      H /= A;
    }
    return truncated;
  }

private:
  const MeshTopology& Topo;
  const FaceSums& Sums;
  const double R2;
  const size_t Cap;
  std::vector<int> Stamp; // per-block visit marks
  std::vector<int> Queue;
};

/// Curvatures, directions, frame and weight of triangle f with unit normal n from its
/// neighbourhood's tensor H.
void setPrincipalFrame(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, int f,
  const Eigen::Vector3d& n, const Tensor& H, CurvatureField& out)
{
  // Tangent basis from the longest edge (any tangent if it is parallel to n).
  Eigen::Vector3d t1 = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k)
  {
    const Eigen::Vector3d e = V.row(F(f, (k + 1) % 3)) - V.row(F(f, k));
    t1 = e.squaredNorm() > t1.squaredNorm() ? e : t1;
  }
  t1 -= t1.dot(n) * n;
  if (!(t1.squaredNorm() > 1e-24 * std::max(1.0, V.row(F(f, 0)).squaredNorm())))
  {
    t1 = n.unitOrthogonal();
  }
  t1.normalize();
  const Eigen::Vector3d t2 = n.cross(t1);
  // The edge tensor's value along t is the curvature across t: rotate by 90 degrees.
  const double h11 = quadratic(H, t1, t1), h12 = quadratic(H, t1, t2), h22 = quadratic(H, t2, t2);
  const double a = h22, b = -h12, c = h11; // curvature tensor [[a b][b c]] in (t1, t2)
  const double mean = 0.5 * (a + c);
  const double dev = std::sqrt(0.25 * (a - c) * (a - c) + b * b);
  const double k1 = mean + dev, k2 = mean - dev;
  const double theta = 0.5 * std::atan2(2.0 * b, a - c);
  const Eigen::Vector3d d1 = std::cos(theta) * t1 + std::sin(theta) * t2;
  const Eigen::Vector3d d2 = n.cross(d1);
  out.curvatures(f, 0) = k1;
  out.curvatures(f, 1) = k2;
  out.direction1.row(f) = d1.transpose();
  out.direction2.row(f) = d2.transpose();
  out.frameU.row(f) = d2.transpose();
  out.frameV.row(f) = n.cross(d2).transpose();
  const double norm = std::sqrt(k1 * k1 + k2 * k2);
  out.weight[f] = norm > 0.0 ? std::abs(k1 - k2) / norm : 0.0;
}

/// Triangle f has no normal at all (an isolated degenerate triangle): nothing to say there.
void setZeroFrame(int f, CurvatureField& out)
{
  out.curvatures.row(f).setZero();
  out.direction1.row(f).setZero();
  out.direction2.row(f).setZero();
  out.frameU.row(f).setZero();
  out.frameV.row(f).setZero();
  out.weight[f] = 0.0;
}

void resizeFrames(int nf, CurvatureField& out)
{
  out.curvatures.resize(nf, 2);
  out.direction1.resize(nf, 3);
  out.direction2.resize(nf, 3);
  out.frameU.resize(nf, 3);
  out.frameV.resize(nf, 3);
  out.weight.resize(nf);
}
}

CurvatureField computeCurvatureField(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const CurvatureOptions& options)
{
  checkInputs(V, F, topo, options);
  const int nf = static_cast<int>(F.rows());
  CurvatureField out;
  std::vector<char> degenerate;
  out.normals = computeFaceNormals(V, F, topo, &degenerate);
  out.degenerateFaces = static_cast<int>(std::count(degenerate.begin(), degenerate.end(), 1));
  out.medianEdgeLength = medianEdgeLength(V, topo);
  out.curvatureRadius = options.neighborhoodRadius * out.medianEdgeLength;
  const Eigen::MatrixX3d& N = out.normals;
  const FaceSums sums = faceSums(V, F, topo, edgeTensors(V, F, topo, N, degenerate));

  resizeFrames(nf, out);
  const double r2 = out.curvatureRadius * out.curvatureRadius;
  const int threads = threadCount(options.numberOfThreads);
  const size_t cap =
    options.maximumNeighborhood > 0 ? static_cast<size_t>(options.maximumNeighborhood) : size_t(-1);
  std::vector<int> truncated(std::max(1, threads), 0);
  parallelFor(nf, threads, [&](int begin, int end, int thread) {
    NeighborhoodSummer neighborhood(topo, sums, r2, cap);
    Tensor H;
    for (int f = begin; f < end; ++f)
    {
      truncated[thread] += neighborhood.sum(f, H) ? 1 : 0;
      const Eigen::Vector3d n = N.row(f);
      if (n.squaredNorm() == 0.0)
      {
        setZeroFrame(f, out);
      }
      else
      {
        setPrincipalFrame(V, F, f, n, H, out);
      }
    }
  });
  for (int t : truncated)
  {
    out.truncatedNeighborhoods += t;
  }
  for (int f = 0; f < nf; ++f)
  {
    out.zeroFrames += out.frameU.row(f).squaredNorm() == 0.0 ? 1 : 0;
  }
  return out;
}

int applyInputFrames(CurvatureField& field, const Eigen::MatrixX3d& frameU)
{
  const int nf = static_cast<int>(field.normals.rows());
  if (frameU.rows() != nf)
  {
    throw std::invalid_argument("applyInputFrames: one frame vector per triangle expected");
  }
  int kept = 0;
  for (int f = 0; f < nf; ++f)
  {
    const Eigen::Vector3d n = field.normals.row(f);
    Eigen::Vector3d u = frameU.row(f);
    if (u.allFinite())
    {
      u -= u.dot(n) * n;
    }
    const double len = u.allFinite() ? u.norm() : 0.0;
    // Below 1e-9 of the input length (or of 1) the projection carries no direction.
    const double inputLen = frameU.row(f).allFinite() ? frameU.row(f).norm() : 0.0;
    if (len > 1e-9 * std::max(1e-300, inputLen) && len > 0.0)
    {
      u /= len;
      field.frameU.row(f) = u.transpose();
      field.frameV.row(f) = n.cross(u).transpose();
    }
    else
    {
      ++kept;
    }
  }
  return kept;
}

}
