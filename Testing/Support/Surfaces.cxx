#include "Surfaces.h"

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <map>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

namespace quadcover
{
namespace
{
constexpr double Pi = 3.14159265358979323846;

/// Uniform in [0, 1) from the standardized mt19937 sequence (portable across libraries).
double uniform(std::mt19937& rng)
{
  return static_cast<double>(rng()) / 4294967296.0;
}

/// Fills F with two triangles per quad of an (nu x nv) grid, periodic in u and/or v.
/// flip: reverse the orientation; diagonals: per-quad choice (empty = always a-c).
void gridFaces(Eigen::MatrixX3i& F, int nu, int nv, bool periodicU, bool periodicV, bool flip,
  const std::vector<char>& diagonals)
{
  const int cu = periodicU ? nu : nu - 1;
  const int cv = periodicV ? nv : nv - 1;
  F.resize(2 * cu * cv, 3);
  auto id = [&](int i, int j) { return (i % nu) * nv + (j % nv); };
  int t = 0;
  for (int i = 0; i < cu; ++i)
  {
    for (int j = 0; j < cv; ++j)
    {
      int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (flip)
      {
        std::swap(b, d);
      }
      const bool other = !diagonals.empty() && diagonals[i * cv + j];
      if (!other)
      {
        F.row(t++) << a, b, c;
        F.row(t++) << a, c, d;
      }
      else
      {
        F.row(t++) << a, b, d;
        F.row(t++) << b, c, d;
      }
    }
  }
}
}

Surface makeTorus(double R, double r, int nu, int nv)
{
  if (!(R > r && r > 0.0) || nu < 3 || nv < 3)
  {
    throw std::invalid_argument("makeTorus: need R > r > 0 and at least 3 segments");
  }
  Surface s;
  s.name = "torus";
  s.V.resize(nu * nv, 3);
  s.kappa.resize(nu * nv, 2);
  s.direction1.resize(nu * nv, 3);
  for (int i = 0; i < nu; ++i)
  {
    for (int j = 0; j < nv; ++j)
    {
      const double u = 2.0 * Pi * i / nu, v = 2.0 * Pi * j / nv;
      const int id = i * nv + j;
      s.V.row(id) << (R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
        r * std::sin(v);
      s.kappa.row(id) << 1.0 / r, std::cos(v) / (R + r * std::cos(v));
      s.direction1.row(id) << -std::sin(v) * std::cos(u), -std::sin(v) * std::sin(u), std::cos(v);
    }
  }
  gridFaces(s.F, nu, nv, true, true, false, {});
  return s;
}

double meanEdgeLength(const Surface& s)
{
  double edges = 0.0;
  for (Eigen::Index f = 0; f < s.F.rows(); ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      edges += (s.V.row(s.F(f, k)) - s.V.row(s.F(f, (k + 1) % 3))).norm();
    }
  }
  return edges / std::max<double>(3.0 * s.F.rows(), 1.0);
}

Surface withNoise(const Surface& s, double noise, unsigned seed)
{
  const double sigma = noise * meanEdgeLength(s);
  std::mt19937 rng(seed);
  Surface out;
  out.name = s.name + " with noise";
  out.V = s.V;
  out.F = s.F;
  for (Eigen::Index i = 0; i < out.V.rows(); ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      const double r = std::sqrt(-2.0 * std::log(1.0 - uniform(rng)));
      out.V(i, j) += sigma * r * std::cos(2.0 * Pi * uniform(rng));
    }
  }
  return out;
}

Surface makeIcosphere(double radius, int level)
{
  if (!(radius > 0.0) || level < 0 || level > 9)
  {
    throw std::invalid_argument("makeIcosphere: need radius > 0 and level in [0, 9]");
  }
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> P = { { -1, t, 0 }, { 1, t, 0 }, { -1, -t, 0 }, { 1, -t, 0 },
    { 0, -1, t }, { 0, 1, t }, { 0, -1, -t }, { 0, 1, -t }, { t, 0, -1 }, { t, 0, 1 },
    { -t, 0, -1 }, { -t, 0, 1 } };
  std::vector<std::array<int, 3>> T = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 },
    { 0, 10, 11 }, { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 },
    { 3, 4, 2 }, { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 },
    { 8, 6, 7 }, { 9, 8, 1 } };
  for (auto& p : P)
  {
    p.normalize();
  }
  for (int l = 0; l < level; ++l)
  {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = mid.find(key);
      if (it != mid.end())
      {
        return it->second;
      }
      P.push_back((P[a] + P[b]).normalized());
      const int id = static_cast<int>(P.size()) - 1;
      mid.emplace(key, id);
      return id;
    };
    std::vector<std::array<int, 3>> next;
    next.reserve(4 * T.size());
    for (const auto& f : T)
    {
      const int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
      next.push_back({ f[0], ab, ca });
      next.push_back({ f[1], bc, ab });
      next.push_back({ f[2], ca, bc });
      next.push_back({ ab, bc, ca });
    }
    T.swap(next);
  }
  Surface s;
  s.name = "sphere";
  s.V.resize(P.size(), 3);
  for (size_t i = 0; i < P.size(); ++i)
  {
    s.V.row(i) = radius * P[i].transpose();
  }
  s.F.resize(T.size(), 3);
  for (size_t i = 0; i < T.size(); ++i)
  {
    s.F.row(i) << T[i][0], T[i][1], T[i][2];
  }
  s.kappa.setConstant(P.size(), 2, 1.0 / radius);
  s.direction1.setZero(P.size(), 3); // umbilic everywhere
  return s;
}

Surface makeCylinder(double r, double h, int nAround, int nAlong)
{
  if (!(r > 0.0 && h > 0.0) || nAround < 3 || nAlong < 1)
  {
    throw std::invalid_argument("makeCylinder: need r, h > 0, nAround >= 3, nAlong >= 1");
  }
  Surface s;
  s.name = "cylinder";
  const int nv = nAlong + 1;
  s.V.resize(nAround * nv, 3);
  s.kappa.resize(nAround * nv, 2);
  s.direction1.resize(nAround * nv, 3);
  for (int i = 0; i < nAround; ++i)
  {
    const double a = 2.0 * Pi * i / nAround;
    for (int j = 0; j < nv; ++j)
    {
      const int id = i * nv + j;
      s.V.row(id) << r * std::cos(a), r * std::sin(a), -0.5 * h + h * j / nAlong;
      s.kappa.row(id) << 1.0 / r, 0.0;
      s.direction1.row(id) << -std::sin(a), std::cos(a), 0.0;
    }
  }
  gridFaces(s.F, nAround, nv, true, false, false, {});
  return s;
}

Surface makeSaddle(double a, double size, int n)
{
  if (!(a > 0.0 && size > 0.0) || n < 1)
  {
    throw std::invalid_argument("makeSaddle: need a, size > 0 and n >= 1");
  }
  Surface s;
  s.name = "saddle";
  const int m = n + 1;
  s.V.resize(m * m, 3);
  s.kappa.resize(m * m, 2);
  s.direction1.resize(m * m, 3);
  for (int i = 0; i < m; ++i)
  {
    for (int j = 0; j < m; ++j)
    {
      const double x = -size + 2.0 * size * i / n, y = -size + 2.0 * size * j / n;
      const int id = i * m + j;
      s.V.row(id) << x, y, (x * x - y * y) / (2.0 * a);
      // Monge patch: first and second fundamental forms with the upward normal.
      const double fx = x / a, fy = -y / a, fxx = 1.0 / a, fyy = -1.0 / a;
      const double W = std::sqrt(1.0 + fx * fx + fy * fy);
      Eigen::Matrix2d I, II;
      I << 1.0 + fx * fx, fx * fy, fx * fy, 1.0 + fy * fy;
      II << fxx / W, 0.0, 0.0, fyy / W;
      // Positive where the surface bends away from the normal: minus the usual convention.
      Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> es(-II, I);
      const Eigen::Vector2d k = es.eigenvalues(); // ascending
      const Eigen::Vector2d d = es.eigenvectors().col(1);
      const Eigen::Vector3d d3 =
        Eigen::Vector3d(d.x(), d.y(), fx * d.x() + fy * d.y()).normalized();
      s.kappa.row(id) << k[1], k[0];
      s.direction1.row(id) = d3.transpose();
    }
  }
  gridFaces(s.F, m, m, false, false, false, {});
  return s;
}

Surface makeKnotTube(int p, int q, double R, double rKnot, double tube, int nAlong, int nAround,
  double jitter, double noise, unsigned seed)
{
  if (!(R > rKnot && rKnot > 0.0 && tube > 0.0) || nAlong < 3 || nAround < 3 ||
    !(jitter >= 0.0 && jitter < 0.5) || !(noise >= 0.0))
  {
    throw std::invalid_argument("makeKnotTube: invalid parameters");
  }
  auto curve = [&](double t) {
    const double rr = R + rKnot * std::cos(q * t);
    return Eigen::Vector3d(rr * std::cos(p * t), rr * std::sin(p * t), rKnot * std::sin(q * t));
  };
  std::mt19937 rng(seed);
  Surface s;
  s.name = "knot";
  const int n = nAlong * nAround;
  s.V.resize(n, 3);
  s.kappa.resize(n, 2);
  s.direction1.resize(n, 3);
  const double hd = 1e-4;
  for (int i = 0; i < nAlong; ++i)
  {
    for (int j = 0; j < nAround; ++j)
    {
      const double di = jitter > 0.0 ? jitter * (2.0 * uniform(rng) - 1.0) : 0.0;
      const double dj = jitter > 0.0 ? jitter * (2.0 * uniform(rng) - 1.0) : 0.0;
      const double dn = noise > 0.0 ? noise * tube * (2.0 * uniform(rng) - 1.0) : 0.0;
      const double t = 2.0 * Pi * (i + di) / nAlong;
      const double phi = 2.0 * Pi * (j + dj) / nAround;
      const Eigen::Vector3d c = curve(t);
      const Eigen::Vector3d c1 = (curve(t + hd) - curve(t - hd)) / (2.0 * hd);
      const Eigen::Vector3d c2 = (curve(t + hd) - 2.0 * c + curve(t - hd)) / (hd * hd);
      const Eigen::Vector3d T = c1.normalized();
      const Eigen::Vector3d N = (c2 - c2.dot(T) * T).normalized();
      const Eigen::Vector3d B = T.cross(N);
      const Eigen::Vector3d out = std::cos(phi) * N + std::sin(phi) * B;
      const int id = i * nAround + j;
      s.V.row(id) = (c + (tube + dn) * out).transpose();
      s.direction1.row(id) = (-std::sin(phi) * N + std::cos(phi) * B).transpose();
      // Normal curvature along the curve of a tube: kappa_c cos(phi) / (1 - tube kappa_c cos(phi))
      // measured toward the centre line, i.e. bending towards -out: negative of that here.
      const double kc = c1.cross(c2).norm() / std::pow(c1.norm(), 3);
      const double kAlong = -kc * std::cos(phi) / (1.0 - tube * kc * std::cos(phi));
      s.kappa.row(id) << 1.0 / tube, kAlong;
    }
  }
  std::vector<char> diagonals;
  if (jitter > 0.0)
  {
    diagonals.resize(static_cast<size_t>(n));
    for (auto& d : diagonals)
    {
      d = uniform(rng) < 0.5 ? 1 : 0;
    }
  }
  // The (along, around) grid runs clockwise seen from outside: flip it.
  gridFaces(s.F, nAlong, nAround, true, true, true, diagonals);
  return s;
}

Surface makeRoundedCube(double round, int n)
{
  if (!(round >= 0.0 && round < 1.0) || n < 2)
  {
    throw std::invalid_argument("makeRoundedCube: need 0 <= round < 1 and n >= 2");
  }
  // Grid points on the cube's surface, shared along edges and corners through a map.
  std::map<std::array<int, 3>, int> index;
  std::vector<Eigen::Vector3d> P;
  auto vertex = [&](const std::array<int, 3>& g) {
    auto it = index.find(g);
    if (it != index.end())
    {
      return it->second;
    }
    P.emplace_back(-1.0 + 2.0 * g[0] / n, -1.0 + 2.0 * g[1] / n, -1.0 + 2.0 * g[2] / n);
    const int id = static_cast<int>(P.size()) - 1;
    index.emplace(g, id);
    return id;
  };
  std::vector<std::array<int, 3>> T;
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int side = 0; side < 2; ++side)
    {
      const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
      for (int i = 0; i < n; ++i)
      {
        for (int j = 0; j < n; ++j)
        {
          std::array<int, 4> q;
          const int di[4] = { 0, 1, 1, 0 }, dj[4] = { 0, 0, 1, 1 };
          for (int c = 0; c < 4; ++c)
          {
            std::array<int, 3> g;
            g[axis] = side * n;
            g[a1] = i + di[c];
            g[a2] = j + dj[c];
            q[c] = vertex(g);
          }
          // (a1, a2, axis) is right-handed: counterclockwise seen from +axis.
          if (side == 1)
          {
            T.push_back({ q[0], q[1], q[2] });
            T.push_back({ q[0], q[2], q[3] });
          }
          else
          {
            T.push_back({ q[0], q[2], q[1] });
            T.push_back({ q[0], q[3], q[2] });
          }
        }
      }
    }
  }
  Surface s;
  s.name = round > 0.0 ? "roundedcube" : "cube";
  s.V.resize(P.size(), 3);
  s.kappa.resize(P.size(), 2);
  s.direction1.setZero(P.size(), 3);
  const double inner = 1.0 - round;
  for (size_t i = 0; i < P.size(); ++i)
  {
    const Eigen::Vector3d p = P[i];
    const Eigen::Vector3d c = p.cwiseMax(-inner).cwiseMin(inner);
    const Eigen::Vector3d d = (p - c).normalized();
    s.V.row(i) = (round > 0.0 ? Eigen::Vector3d(c + round * d) : p).transpose();
    int clamped = 0, free = -1;
    for (int k = 0; k < 3; ++k)
    {
      if (std::abs(p[k]) > inner)
      {
        ++clamped;
      }
      else
      {
        free = k;
      }
    }
    if (clamped == 2)
    {
      Eigen::Vector3d axis = Eigen::Vector3d::Zero();
      axis[free] = 1.0;
      s.direction1.row(i) = axis.cross(d).normalized().transpose();
      s.kappa.row(i) << 1.0 / round, 0.0;
    }
    else if (clamped == 3)
    {
      s.kappa.row(i) << 1.0 / round, 1.0 / round;
    }
    else
    {
      s.kappa.row(i) << 0.0, 0.0;
    }
  }
  s.F.resize(T.size(), 3);
  for (size_t i = 0; i < T.size(); ++i)
  {
    s.F.row(i) << T[i][0], T[i][1], T[i][2];
  }
  return s;
}

Surface makeComponents(int count, double rMin, double rMax)
{
  Surface all;
  all.name = "components";
  double x = 0.0;
  for (int i = 0; i < count; ++i)
  {
    const double size = rMin * std::pow(rMax / rMin, count > 1 ? i / (count - 1.0) : 0.0);
    Surface part = i % 2 == 0 ? makeIcosphere(size, 2) : makeTorus(size, 0.35 * size, 20, 10);
    const double extent = i % 2 == 0 ? size : 1.35 * size;
    x += extent;
    part.V.col(0).array() += x;
    x += extent + 0.1 + 0.1 * size;
    const Eigen::Index v0 = all.V.rows(), f0 = all.F.rows();
    all.V.conservativeResize(v0 + part.V.rows(), 3);
    all.V.bottomRows(part.V.rows()) = part.V;
    all.F.conservativeResize(f0 + part.F.rows(), 3);
    all.F.bottomRows(part.F.rows()) = part.F.array() + static_cast<int>(v0);
  }
  return all;
}

}
