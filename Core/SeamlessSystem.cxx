// SeamlessSystem.cxx: the linear system of the integer-grid map: unknowns per sector, the
// constraints of the cut and the boundary eliminated, columns and symbols, the energy.
#include "ParameterizationSteps.h"

#include "DegenerateTriangles.h"
#include "FrameField.h"
#include "NearbyPoints.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace quadcover
{
namespace param
{
namespace
{
/// z_B - i^r z_A - t_e = 0 at both ends of every cut edge (f = side A, g = side B), with a new
/// integer translation t_e per cut edge.
void constrainTransitions(
  const Inputs& in, const Parameterization& out, Eliminator& elim, const Progress& progress)
{
  const MeshTopology& topo = in.topo;
  const int nV = in.numVertices();
  std::vector<std::vector<int>> cutAt(nV);
  std::vector<int> translation(topo.numEdges(), -1);
  for (int e = 0; e < topo.numEdges(); ++e)
  {
    if (out.cut.onCut[e])
    {
      translation[e] = elim.add(true);
      elim.add(true);
      cutAt[topo.edges(e, 0)].push_back(e);
      cutAt[topo.edges(e, 1)].push_back(e);
    }
  }
  for (int p = 0; p < nV; ++p)
  {
    reportEvery(progress, p, nV);
    for (const int e : cutAt[p])
    {
      const int c0 = topo.edgeCorners(e, 0);
      const int f = c0 / 3;
      const int g = topo.edgeCorners(e, 1) / 3;
      const int r = out.combedMatching(f, c0 % 3);
      const int a = sectorOf(in.F, out, f, p);
      const int b = sectorOf(in.F, out, g, p);
      // i^r (uA + i vA): r = 0: (uA, vA), 1: (-vA, uA), 2: (-uA, -vA), 3: (vA, -uA)
      const int reU = (r % 2 == 0) ? 2 * a : 2 * a + 1;
      const double reS = (r == 0 || r == 3) ? 1.0 : -1.0;
      const int imU = (r % 2 == 0) ? 2 * a + 1 : 2 * a;
      const double imS = (r == 0 || r == 1) ? 1.0 : -1.0;
      elim.constrain({ { 2 * b, 1.0 }, { reU, -reS }, { translation[e], -1.0 } });
      elim.constrain({ { 2 * b + 1, 1.0 }, { imU, -imS }, { translation[e] + 1, -1.0 } });
    }
  }
}

/// Which coordinate of boundary edge e (corner k of face f) is constant along it: 1 (v) for an
/// edge along the combed frame's u direction, 0 (u) for one along v (within the boundary
/// tolerance), -1 for neither.
int constantCoordinate(
  const Inputs& in, const Field& field, const Parameterization& out, int f, int k, double tolerance)
{
  const Eigen::Vector3d d = in.V.row(in.F(f, (k + 1) % 3)) - in.V.row(in.F(f, k));
  const double alpha = std::atan2(
    d.dot(in.geometry.bases.b2.row(f).transpose()), d.dot(in.geometry.bases.b1.row(f).transpose()));
  double delta = wrapAngle(alpha - field.theta[f] - out.comb[f] * Pi / 2);
  // delta modulo pi in (-pi/2, pi/2]: near 0 along u (v constant), near +-pi/2 along v
  if (delta > Pi / 2)
  {
    delta -= Pi;
  }
  else if (delta <= -Pi / 2)
  {
    delta += Pi;
  }
  if (std::abs(delta) <= tolerance)
  {
    return 1;
  }
  if (Pi / 2 - std::abs(delta) <= tolerance)
  {
    return 0;
  }
  return -1;
}

/// The sharp edges (featureLines) of the crease networks at least MinimumFeatureLineLength grid
/// edges long (a network: sharp edges joined at their points). A shorter one is left to the field
/// alone: put on an integer line, a crease of a grid edge or two pulls the grid around it.
std::vector<char> featureLines(const Inputs& in, double edgeLength)
{
  constexpr double MinimumFeatureLineLength = 4.0;
  const MeshTopology& topo = in.topo;
  if (!in.options.featureLines)
  {
    return std::vector<char>(topo.numEdges(), 0);
  }
  std::vector<char> sharp = sharpEdges(
    topo, in.geometry.bases, in.options.featureAngle, in.options.minimumFeatureLength);
  const std::vector<int> network = edgeNetworks(topo, sharp);
  std::vector<double> length(topo.numEdges(), 0.0);
  for (int e = 0; e < topo.numEdges(); ++e)
  {
    if (sharp[e])
    {
      length[network[e]] += (in.V.row(topo.edges(e, 0)) - in.V.row(topo.edges(e, 1))).norm();
    }
  }
  for (int e = 0; e < topo.numEdges(); ++e)
  {
    sharp[e] = sharp[e] && length[network[e]] >= MinimumFeatureLineLength * edgeLength;
  }
  return sharp;
}

/// In grid edges, how long a straight run of a boundary loop must be for its edges to be put on
/// grid lines. On a jagged boundary (a hole cut along the triangles of a scan) the frames follow
/// every step, and lines on steps shorter than a grid edge, each a quarter turned from the next,
/// put the steps' points on grid points, several within one cell, and fold the map: a sphere with
/// 25 such holes at 3,000 quads kept 106 flipped triangles after 14 s of untangling, with this
/// 1 in 2 s (0.5: 66 in 5 s).
constexpr double MinimumBoundaryLineRun = 1.0;

/// In grid edges: a boundary edge this near an edge of another loop stays on its line however
/// short its run, so that the rounding keeps the two loops apart (lines that face each other never
/// meet; free, the strip between two holes less than a cell or two wide is cut, and they become
/// one: the sphere with 25 holes lost 4 of its 22 loops at 1,000 quads).
constexpr double NearLoopReach = 1.5;

/// Per edge of topo, 1 on a boundary edge within `reach` of an edge of another boundary loop
/// (their middles).
std::vector<char> nearOtherLoops(const Inputs& in, double reach)
{
  const MeshTopology& topo = in.topo;
  std::vector<int> loopOf(in.numVertices(), -1);
  for (std::size_t l = 0; l < topo.boundaryLoops.size(); ++l)
  {
    for (const int p : topo.boundaryLoops[l])
    {
      loopOf[p] = static_cast<int>(l);
    }
  }
  std::vector<int> edges;
  std::vector<Eigen::Vector3d> middles;
  for (int e = 0; e < topo.numEdges(); ++e)
  {
    if (topo.edgeFaceCount[e] == 1)
    {
      edges.push_back(e);
      middles.push_back(
        0.5 * (in.V.row(topo.edges(e, 0)) + in.V.row(topo.edges(e, 1))).transpose());
    }
  }
  std::vector<char> near(topo.numEdges(), 0);
  const std::vector<std::vector<int>> candidates = nearbyPoints(middles, reach);
  for (std::size_t i = 0; i < edges.size(); ++i)
  {
    for (const int j : candidates[i])
    {
      if (loopOf[topo.edges(edges[i], 0)] != loopOf[topo.edges(edges[j], 0)] &&
        (middles[i] - middles[j]).norm() < reach)
      {
        near[edges[i]] = near[edges[j]] = 1;
      }
    }
  }
  return near;
}

/// Per point, the boundary edge that leaves it along its loop (as the loops run: from a point to
/// the next), -1 off the boundary.
std::vector<int> boundaryEdgeFrom(const Inputs& in)
{
  const MeshTopology& topo = in.topo;
  std::vector<int> edgeFrom(in.numVertices(), -1);
  for (int e = 0; e < topo.numEdges(); ++e)
  {
    if (topo.edgeFaceCount[e] == 1)
    {
      const int c0 = topo.edgeCorners(e, 0);
      edgeFrom[in.F(c0 / 3, c0 % 3)] = e;
    }
  }
  return edgeFrom;
}

/// Per edge of topo, 1 on a boundary edge that lies on a straight run of its loop shorter than
/// MinimumBoundaryLineRun grid edges and not near another loop (NearLoopReach): its edges are not
/// put on lines. A run is the stretch between two points where the loop turns by more than
/// 45 degrees; a loop without such points keeps its lines however short (a small round hole:
/// they keep it open).
std::vector<char> shortBoundaryRuns(const Inputs& in, double edgeLength)
{
  const MeshTopology& topo = in.topo;
  const double minimumLength = MinimumBoundaryLineRun * edgeLength;
  const std::vector<char> near = nearOtherLoops(in, NearLoopReach * edgeLength);
  std::vector<char> isShort(topo.numEdges(), 0);
  const std::vector<int> edgeFrom = boundaryEdgeFrom(in);
  const double cosTurn = std::cos(Pi / 4);
  for (const std::vector<int>& loop : topo.boundaryLoops)
  {
    const int n = static_cast<int>(loop.size());
    std::vector<Eigen::Vector3d> d(n);
    for (int i = 0; i < n; ++i)
    {
      d[i] = in.V.row(loop[(i + 1) % n]) - in.V.row(loop[i]);
    }
    std::vector<int> corners; // i: the loop turns at loop[i], between d[i - 1] and d[i]
    for (int i = 0; i < n; ++i)
    {
      const Eigen::Vector3d& before = d[(i + n - 1) % n];
      if (before.dot(d[i]) < cosTurn * before.norm() * d[i].norm())
      {
        corners.push_back(i);
      }
    }
    for (std::size_t j = 0; j < corners.size(); ++j)
    {
      const int first = corners[j];
      const int last = j + 1 < corners.size() ? corners[j + 1] : corners[0] + n;
      double length = 0.0;
      for (int i = first; i < last; ++i)
      {
        length += d[i % n].norm();
      }
      for (int i = first; i < last && length < minimumLength; ++i)
      {
        const int e = edgeFrom[loop[i % n]];
        if (e >= 0 && !near[e])
        {
          isShort[e] = 1;
        }
      }
    }
  }
  return isShort;
}

/// Per edge of topo, 1 on one of the two boundary edges at a tip of the boundary (an angle of
/// less than a quarter turn inside the surface) that would both go on lines of the same coordinate
/// through the tip (constantCoordinate, the same sector, neither on a `shortRun`): the shorter of
/// the two. Both on lines, the lines through the tip are one, and the two sides of the boundary
/// with them: the tip's fan and every triangle between the sides is squashed onto the line (an
/// isosurface cut by its volume's face leaves slivers whose tips are single triangles of about 10
/// degrees: no grid cell of their map gave a quad, at any count). Where a cut of the map ends at
/// the tip, its two sides lie in different sectors and are left as they are.
std::vector<char> boundaryTips(const Inputs& in, const Field& field, const Parameterization& out,
  double tolerance, const std::vector<char>& shortRun)
{
  const MeshTopology& topo = in.topo;
  std::vector<char> tip(topo.numEdges(), 0);
  const std::vector<int> edgeFrom = boundaryEdgeFrom(in);
  // the coordinate boundary edge e (corner c) would be on a line of, or -1 (off its run's line,
  // or neither)
  const auto lineOf = [&](int e, int c) {
    return shortRun[e] ? -1 : constantCoordinate(in, field, out, c / 3, c % 3, tolerance);
  };
  for (const std::vector<int>& loop : topo.boundaryLoops)
  {
    const int n = static_cast<int>(loop.size());
    for (int i = 0; i < n; ++i)
    {
      const int p = loop[i];
      const int before = edgeFrom[loop[(i + n - 1) % n]], after = edgeFrom[p];
      // the angle inside is pi less the point's defect
      if (n < 3 || before < 0 || after < 0 || !(in.geometry.defect[p] > Pi / 2))
      {
        continue;
      }
      const int a = topo.edgeCorners(before, 0), b = topo.edgeCorners(after, 0);
      const int ca = lineOf(before, a), cb = lineOf(after, b);
      if (ca >= 0 && ca == cb && sectorOf(in.F, out, a / 3, p) == sectorOf(in.F, out, b / 3, p))
      {
        const auto length = [&](int c) { return in.geometry.edgeLength(c / 3, c % 3); };
        tip[length(a) < length(b) ? before : after] = 1;
      }
    }
  }
  return tip;
}

/// Boundary edges, and sharp edges (featureLines), along a combed frame direction: the other
/// coordinate is an integer line. Returns per sector coordinate (2s + c) 1 where it is on a line.
std::vector<char> alignToLines(
  const Inputs& in, const Field& field, Parameterization& out, Eliminator& elim)
{
  const int nS = static_cast<int>(out.sectorPoint.size());
  std::vector<char> onLine(2 * static_cast<std::size_t>(nS), 0);
  const double tolerance = in.options.boundaryTolerance * Pi / 180.0;
  // the edge of face f opposite corner k + 2 on a line when it runs along a frame direction
  auto putOnLine = [&](int f, int k) {
    const int component = constantCoordinate(in, field, out, f, k, tolerance);
    if (component < 0)
    {
      return false;
    }
    const int line = elim.add(true);
    for (int end = 0; end < 2; ++end)
    {
      const int s = out.cornerSector[3 * f + (k + end) % 3];
      elim.constrain({ { 2 * s + component, 1.0 }, { line, -1.0 } });
      onLine[2 * s + component] = 1;
    }
    return true;
  };
  const std::vector<char> sharp = featureLines(in, out.edgeLength);
  // (out.edgeLength is the first grid's, before its correction by the map's area and any finer
  // grid, as for the feature lines)
  const std::vector<char> shortRun = in.options.alignToBoundary
    ? shortBoundaryRuns(in, out.edgeLength)
    : std::vector<char>(in.topo.numEdges(), 0);
  const std::vector<char> tip = in.options.alignToBoundary
    ? boundaryTips(in, field, out, tolerance, shortRun)
    : std::vector<char>(in.topo.numEdges(), 0);
  for (int e = 0; e < in.topo.numEdges(); ++e)
  {
    const bool boundary =
      in.topo.edgeFaceCount[e] == 1 && in.options.alignToBoundary && !shortRun[e] && !tip[e];
    const bool feature = in.topo.edgeFaceCount[e] == 2 && sharp[e];
    if (!boundary && !feature)
    {
      continue;
    }
    // an inner edge in one of its faces: the other face's sectors are the same off the cut, and
    // across it the transition (a grid symmetry) takes the line to a line; but only where the
    // other face's frame follows it too (else that face would be pulled onto the line)
    const int c0 = in.topo.edgeCorners(e, 0);
    if (feature)
    {
      const int c1 = in.topo.edgeCorners(e, 1);
      if (constantCoordinate(in, field, out, c1 / 3, c1 % 3, tolerance) < 0)
      {
        continue;
      }
    }
    if (putOnLine(c0 / 3, c0 % 3))
    {
      ++(boundary ? out.alignedBoundaryEdges : out.alignedFeatureEdges);
    }
  }
  return onLine;
}

/// One point per component fixed at (0, 0): the map is defined up to translation. The point is
/// one that is on the grid anyway (a branch point, else a boundary corner on two grid lines),
/// so that the fixing costs nothing; only without either is a regular point put on the grid.
void pinComponents(const Inputs& in, const Field& field, const std::vector<char>& onLine,
  const Parameterization& out, Eliminator& elim)
{
  std::vector<int> pin(in.topo.numComponents(), -1);
  std::vector<int> rank(in.topo.numComponents(), 3);
  for (int f = 0; f < in.numFaces(); ++f)
  {
    const int c = in.topo.faceComponent[f];
    for (int k = 0; k < 3 && c >= 0; ++k)
    {
      const int s = out.cornerSector[3 * f + k];
      const int r = field.branch[in.F(f, k)] ? 0 : (onLine[2 * s] && onLine[2 * s + 1] ? 1 : 2);
      if (r < rank[c])
      {
        rank[c] = r;
        pin[c] = s;
      }
    }
  }
  for (const int s : pin)
  {
    if (s >= 0)
    {
      elim.constrain({ { 2 * s, 1.0 } });
      elim.constrain({ { 2 * s + 1, 1.0 } });
    }
  }
}

/// P: symbols x columns, the identity on the real ones.
SparseMatrix symbolMatrix(int numReal, const std::vector<Expr>& symbolColumns, int numColumns)
{
  SparseMatrix P(numReal + static_cast<int>(symbolColumns.size()), numColumns);
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < numReal; ++j)
  {
    t.emplace_back(j, j, 1.0);
  }
  for (std::size_t k = 0; k < symbolColumns.size(); ++k)
  {
    for (const auto& c : symbolColumns[k])
    {
      t.emplace_back(numReal + static_cast<int>(k), c.first, c.second);
    }
  }
  P.setFromTriplets(t.begin(), t.end());
  return P;
}

/**
 * Builds the energy's rows, 4 per triangle: sqrt(A) (grad u - U'/h, grad v - V'/h) in the
 * triangle's basis, D's rows over symbols and rhs; H = P^T (D^T D) P, its lower triangle, with
 * D^T D assembled from each row's outer product (much faster than the sparse product) and
 * written in columns entry by entry (lowerInColumns).
 */
class EnergyAssembly
{
public:
  EnergyAssembly(
    const Inputs& in, const Field& field, const Parameterization& out, SeamlessSystem& sys)
    : in_(in)
    , field_(field)
    , out_(out)
    , sys_(sys)
    , scale_(1.0 / out.edgeLength)
  {
    const int nF = in.numFaces();
    sys.faceArea = Eigen::VectorXd::Zero(nF);
    sys.rhs = Eigen::VectorXd::Zero(4 * static_cast<Eigen::Index>(nF));
    triplets_.reserve(static_cast<std::size_t>(nF) * 14);
    hessian_.reserve(std::min(static_cast<std::size_t>(nF) * 26, 2 * FirstHessianSum));
    hessianSum_.resize(sys.P.rows(), sys.P.rows());
  }

  /// The rows of face f (none for a degenerate one).
  void addFace(int f)
  {
    Eigen::Vector2d p[3];
    const Eigen::Vector3d b1 = in_.geometry.bases.b1.row(f).transpose();
    const Eigen::Vector3d b2 = in_.geometry.bases.b2.row(f).transpose();
    for (int k = 0; k < 3; ++k)
    {
      const Eigen::Vector3d d = in_.V.row(in_.F(f, k)) - in_.V.row(in_.F(f, 0));
      p[k] = Eigen::Vector2d(d.dot(b1), d.dot(b2));
    }
    const double twiceArea =
      (p[1] - p[0]).x() * (p[2] - p[0]).y() - (p[1] - p[0]).y() * (p[2] - p[0]).x();
    if (!(twiceArea > 0) || // left out where degenerate, as the frames leave it out
      isDegenerateTriangle(in_.V.row(in_.F(f, 0)), in_.V.row(in_.F(f, 1)), in_.V.row(in_.F(f, 2))))
    {
      return;
    }
    const double cell = sys_.cell(f);
    totalArea_ += 0.5 * twiceArea / (cell * cell);
    sys_.faceArea[f] = 0.5 * twiceArea;
    const double w = std::sqrt(0.5 * twiceArea);
    const double target = scale_ / cell;
    const double angle = field_.theta[f] + out_.comb[f] * Pi / 2;
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    sys_.rhs[4 * f + 0] = w * target * c;  // grad u . x = U'.x
    sys_.rhs[4 * f + 1] = w * target * s;  // grad u . y
    sys_.rhs[4 * f + 2] = w * target * -s; // grad v . x = V'.x
    sys_.rhs[4 * f + 3] = w * target * c;  // grad v . y
    for (int r = 0; r < 4; ++r)
    {
      row_[r].clear();
    }
    for (int k = 0; k < 3; ++k)
    {
      const Eigen::Vector2d edge = p[(k + 2) % 3] - p[(k + 1) % 3];
      const Eigen::Vector2d grad = Eigen::Vector2d(-edge.y(), edge.x()) * (w / twiceArea);
      const int sector = out_.cornerSector[3 * f + k];
      for (int uv = 0; uv < 2; ++uv)
      {
        for (const auto& t : sys_.sectorExpr[2 * sector + uv])
        {
          row_[2 * uv].emplace_back(t.first, grad.x() * t.second);
          row_[2 * uv + 1].emplace_back(t.first, grad.y() * t.second);
        }
      }
    }
    addRows(f);
    if (hessian_.size() >= sumAt_)
    {
      sumHessian();
    }
  }

  /// D, H and the energy's scale from the rows added.
  void finish()
  {
    const int numSymbols = static_cast<int>(sys_.P.rows());
    sys_.D.resize(4 * static_cast<Eigen::Index>(in_.numFaces()), numSymbols);
    sys_.D.setFromTriplets(triplets_.begin(), triplets_.end());
    triplets_.clear();
    triplets_.shrink_to_fit();
    sumHessian();
    std::vector<Eigen::Triplet<double>>().swap(hessian_);
    sys_.H = lowerInColumns(hessianSum_);
    hessianSum_ = SparseMatrix();
    sys_.energyNorm = 2.0 * scale_ * scale_ * std::max(totalArea_, 1e-300);
  }

private:
  /// The outer products (lower triangle) of D's rows kept as triplets, one per product, are
  /// summed into hessianSum_ when there are as many as it has entries (at least
  /// FirstHessianSum): the triplets of a whole surface took most of the map's peak memory
  /// (fandisk: 37 of 52 MB), and summing each batch costs the sum's entries, so that the whole
  /// costs a few times its final size.
  static constexpr std::size_t FirstHessianSum = std::size_t(1) << 18;

  void sumHessian()
  {
    SparseMatrix batch(hessianSum_.rows(), hessianSum_.cols());
    batch.setFromTriplets(hessian_.begin(), hessian_.end());
    hessian_.clear();
    if (hessianSum_.nonZeros() == 0)
    {
      hessianSum_ = std::move(batch);
    }
    else
    {
      hessianSum_ = SparseMatrix(hessianSum_ + batch);
    }
    sumAt_ = std::max(FirstHessianSum, static_cast<std::size_t>(hessianSum_.nonZeros()));
  }

  /// The lower triangle of P^T S P from S's (over symbols): P is the identity on the real
  /// symbols, so that only the rows and columns of the integer symbols (I) need products, and
  /// those are few: H = S_rr + P_I^T S_Ir + (P_I^T S_Ir)^T + P_I^T S_II P_I. P^T S P as a
  /// product of the whole S made S whole and two products of its size, the map's peak memory
  /// (peak RSS: armadillo 272 -> 246 MB, rocker-arm 88 -> 81, fandisk 70 -> 64; the same
  /// outputs, byte for byte).
  SparseMatrix lowerInColumns(const SparseMatrix& S) const
  {
    const int nr = sys_.numReal, ni = static_cast<int>(S.rows()) - nr, n = sys_.numColumns();
    const SparseMatrix PI = sys_.P.bottomRows(ni);
    const SparseMatrix C = PI.transpose() * SparseMatrix(S.bottomLeftCorner(ni, nr));
    const SparseMatrix SII =
      SparseMatrix(S.bottomRightCorner(ni, ni)).selfadjointView<Eigen::Lower>();
    const SparseMatrix G = PI.transpose() * SII * PI;
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(static_cast<std::size_t>(S.nonZeros() + C.nonZeros() + G.nonZeros()));
    for (int j = 0; j < nr; ++j)
    {
      for (SparseMatrix::InnerIterator it(S, j); it; ++it)
      {
        if (it.row() < nr)
        {
          t.emplace_back(static_cast<int>(it.row()), j, it.value());
        }
      }
    }
    for (int j = 0; j < nr; ++j)
    {
      // C(a, j) and its mirror C(a, j) at (j, a): the lower one of the two, twice on the diagonal
      for (SparseMatrix::InnerIterator it(C, j); it; ++it)
      {
        const int a = static_cast<int>(it.row());
        t.emplace_back(std::max(a, j), std::min(a, j), a == j ? 2.0 * it.value() : it.value());
      }
    }
    for (int j = 0; j < n; ++j)
    {
      for (SparseMatrix::InnerIterator it(G, j); it; ++it)
      {
        if (it.row() >= j)
        {
          t.emplace_back(static_cast<int>(it.row()), j, it.value());
        }
      }
    }
    SparseMatrix H(n, n);
    H.setFromTriplets(t.begin(), t.end());
    return H;
  }

  /// D's rows of face f, and their outer products (lower triangle) into D^T D.
  void addRows(int f)
  {
    for (int r = 0; r < 4; ++r)
    {
      for (const auto& a : row_[r])
      {
        triplets_.emplace_back(4 * f + r, a.first, a.second);
        for (const auto& b : row_[r])
        {
          if (b.first <= a.first)
          {
            hessian_.emplace_back(a.first, b.first, a.second * b.second);
          }
        }
      }
    }
  }

  const Inputs& in_;
  const Field& field_;
  const Parameterization& out_;
  SeamlessSystem& sys_;
  const double scale_;
  double totalArea_ = 0.0;
  std::vector<Eigen::Triplet<double>> triplets_;
  std::vector<Eigen::Triplet<double>> hessian_;
  SparseMatrix hessianSum_;
  std::size_t sumAt_ = FirstHessianSum;
  Expr row_[4];
};
}

Eliminator constrainUnknowns(
  const Inputs& in, const Field& field, Parameterization& out, const Progress& progress)
{
  Eliminator elim;
  const int nS = static_cast<int>(out.sectorPoint.size());
  for (int s = 0; s < nS; ++s)
  {
    const bool integer = in.options.pureQuads && field.branch[out.sectorPoint[s]];
    elim.add(integer); // u = 2s
    elim.add(integer); // v = 2s + 1
  }
  constrainTransitions(in, out, elim, progress.part(0.0, 0.9));
  const std::vector<char> onLine = alignToLines(in, field, out, elim);
  pinComponents(in, field, onLine, out, elim);
  out.constraints = elim.Constraints;
  out.nonUnitPivots = elim.NonUnitPivots;
  progress.report(1.0);
  return elim;
}

SeamlessSystem numberUnknowns(Eliminator& elim, Parameterization& out)
{
  SeamlessSystem sys;
  // Columns: real unknowns first, then integer ones.
  std::vector<int> column(elim.size(), -1);
  for (int x = 0; x < elim.size(); ++x)
  {
    if (!elim.isEliminated(x) && !elim.isInteger(x))
    {
      column[x] = sys.numReal++;
    }
  }
  for (int x = 0; x < elim.size(); ++x)
  {
    if (!elim.isEliminated(x) && elim.isInteger(x))
    {
      column[x] = sys.numReal + sys.numInteger++;
    }
  }
  out.unknowns = sys.numColumns();
  out.integerUnknowns = sys.numInteger;
  // Symbols: the real unknowns, then the integer unknowns in the order the sectors meet them.
  const int nS = static_cast<int>(out.sectorPoint.size());
  std::vector<int> symbolOf(elim.size(), -1);
  sys.sectorExpr.resize(2 * nS);
  for (int x = 0; x < 2 * nS; ++x)
  {
    sys.sectorExpr[x] = elim.resolveReals(x);
    for (auto& t : sys.sectorExpr[x])
    {
      if (!elim.isInteger(t.first))
      {
        t.first = column[t.first];
        continue;
      }
      if (symbolOf[t.first] < 0)
      {
        symbolOf[t.first] = sys.numReal + static_cast<int>(sys.symbolColumns.size());
        Expr e = elim.resolve(t.first);
        for (auto& c : e)
        {
          c.first = column[c.first];
        }
        sys.symbolColumns.push_back(std::move(e));
      }
      t.first = symbolOf[t.first];
    }
  }
  sys.P = symbolMatrix(sys.numReal, sys.symbolColumns, sys.numColumns());
  return sys;
}

void assembleEnergy(const Inputs& in, const Field& field, const Parameterization& out,
  SeamlessSystem& sys, const Progress& progress)
{
  EnergyAssembly assembly(in, field, out, sys);
  const int nF = in.numFaces();
  const Progress rows = progress.part(0.0, 0.4);
  for (int f = 0; f < nF; ++f)
  {
    reportEvery(rows, f, nF);
    assembly.addFace(f);
  }
  progress.report(0.4);
  assembly.finish();
  progress.report(1.0);
}

Eigen::MatrixX2d SeamlessSystem::uv(const Eigen::VectorXd& columns) const
{
  const Eigen::VectorXd x = P * columns;
  const int nS = static_cast<int>(sectorExpr.size() / 2);
  Eigen::MatrixX2d uv(nS, 2);
  for (int s = 0; s < nS; ++s)
  {
    for (int c = 0; c < 2; ++c)
    {
      uv(s, c) = sectorValue(x, s, c);
    }
  }
  return uv;
}

std::vector<int> flippedFaces(
  const Eigen::MatrixX2d& uv, const std::vector<int>& cornerSector, const Eigen::VectorXd& faceArea)
{
  std::vector<int> flipped;
  const int nF = static_cast<int>(cornerSector.size() / 3);
  for (int f = 0; f < nF; ++f)
  {
    if (faceArea[f] > 0.0 && !(twiceUVArea(uv, cornerSector, f) > 0))
    {
      flipped.push_back(f);
    }
  }
  return flipped;
}
}
}
