#include "FrameSmoother.h"

#include "SparseSolver.h"
#include <Eigen/Geometry>

#include <cmath>
#include <complex>
#include <stdexcept>

namespace quadcover
{
namespace
{
constexpr double Pi = 3.14159265358979323846;

/// One inner edge: faces f < g, the frames' misalignment before rotation, the weight.
struct Link
{
  int f, g;
  double theta; // angle of f's frame minus g's carried into f's plane
  double rho;   // transport from g's basis into f's
  double w;     // (A_f + A_g) / 3
};

struct Problem
{
  std::vector<Link> links;
  Eigen::VectorXd area, weight;
  double lambda = 0.5;

  double energy(const Eigen::VectorXd& alpha) const
  {
    double smooth = 0.0, align = 0.0;
    for (const Link& l : links)
    {
      smooth += l.w * (1.0 - std::cos(4.0 * (l.theta + alpha[l.f] - alpha[l.g])));
    }
    for (Eigen::Index i = 0; i < alpha.size(); ++i)
    {
      align += area[i] * weight[i] * alpha[i] * alpha[i];
    }
    return lambda * smooth + (1.0 - lambda) * align;
  }
};
}

SmootherResult smoothFrames(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const FrameGeometry& geometry, const Eigen::MatrixX3d& frameU,
  const Eigen::MatrixX3d& frameV, const Eigen::VectorXd& weight, const SmootherOptions& options,
  const Progress& progress)
{
  progress.report(0.0);
  const int nf = static_cast<int>(F.rows());
  if (frameU.rows() != nf || frameV.rows() != nf || weight.size() != nf || topo.numFaces != nf)
  {
    throw std::invalid_argument("smoothFrames: one frame and one weight per triangle expected");
  }
  if (!frameU.allFinite() || !frameV.allFinite())
  {
    throw std::invalid_argument("smoothFrames: frames must be finite");
  }
  if (!(options.smoothingWeight >= 0.0 && options.smoothingWeight <= 1.0))
  {
    throw std::invalid_argument("smoothFrames: smoothing weight must lie in [0, 1]");
  }
  const Eigen::VectorXd phi = vectorAngles(geometry.bases, frameU);
  Problem P;
  P.lambda = options.smoothingWeight;
  P.area.resize(nf);
  for (int f = 0; f < nf; ++f)
  {
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    P.area[f] = 0.5 * (b - a).cross(c - a).norm();
  }
  P.weight = weight.unaryExpr([](double w) { return std::isfinite(w) && w > 0.0 ? w : 0.0; });

  SmootherResult R;
  R.constrained.assign(nf, 0);
  Eigen::VectorXd fixedAlpha = Eigen::VectorXd::Zero(nf);
  Eigen::VectorXd constraintLength = Eigen::VectorXd::Zero(nf);
  auto hold = [&](int f, int k) {
    const double len = (V.row(F(f, (k + 1) % 3)) - V.row(F(f, k))).norm();
    if (len > constraintLength[f])
    {
      constraintLength[f] = len;
      R.constrained[f] = 1;
      fixedAlpha[f] = wrapQuarter(geometry.edgeAngle(f, k) - phi[f]);
    }
  };
  // Sharp edges, kept only in chains of at least minimumFeatureLength edges.
  const std::vector<char> sharp =
    sharpEdges(topo, geometry.bases, options.featureAngle, options.minimumFeatureLength);
  for (const char e : sharp)
  {
    R.featureEdges += e;
  }
  for (int f = 0; f < nf; ++f)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int g = topo.faceNeighbors(f, k);
      const int e = topo.faceEdges(f, k);
      if (g < 0)
      {
        if (e >= 0 && topo.edgeFaceCount[e] == 1)
        {
          R.boundaryEdges += 1;
          if (options.alignToBoundary)
          {
            hold(f, k);
          }
        }
        continue;
      }
      if (sharp[e] && options.alignToFeatures)
      {
        hold(f, k);
      }
      if (f < g)
      {
        const double rho = geometry.transport(f, k);
        P.links.push_back(
          { f, g, wrapAngle(phi[f] - phi[g] - rho), rho, (P.area[f] + P.area[g]) / 3.0 });
      }
    }
  }

  // Unknowns: the free triangles.
  std::vector<int> unknown(nf, -1);
  int n = 0;
  for (int f = 0; f < nf; ++f)
  {
    if (R.constrained[f])
    {
      ++R.numConstrained;
    }
    else
    {
      unknown[f] = n++;
    }
  }
  const double lambda = P.lambda;

  // The majorizer's matrix: 16 lambda w per link (graph Laplacian) + 2 (1 - lambda) A w, plus a
  // small proximal term that keeps it definite where nothing else does (it only adds a positive
  // term to the bound, so the energy still never rises).
  Eigen::SparseMatrix<double> H;
  Eigen::VectorXd diagonal = Eigen::VectorXd::Zero(n);
  {
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(4 * P.links.size() + n);
    for (const Link& l : P.links)
    {
      const double c = 16.0 * lambda * l.w;
      const int a = unknown[l.f], b = unknown[l.g];
      if (a >= 0)
        diagonal[a] += c;
      if (b >= 0)
        diagonal[b] += c;
      if (a >= 0 && b >= 0)
      {
        t.emplace_back(a, b, -c);
        t.emplace_back(b, a, -c);
      }
    }
    for (int f = 0; f < nf; ++f)
    {
      if (unknown[f] >= 0)
      {
        diagonal[unknown[f]] += 2.0 * (1.0 - lambda) * P.area[f] * P.weight[f];
      }
    }
    const double mean = n > 0 ? diagonal.sum() / n : 0.0;
    for (int i = 0; i < n; ++i)
    {
      diagonal[i] += 1e-9 * mean + 1e-300;
      t.emplace_back(i, i, diagonal[i]);
    }
    H.resize(n, n);
    H.setFromTriplets(t.begin(), t.end());
  }
  SpdSolver<double> mm;
  if (n > 0)
  {
    mm.compute(H);
    if (mm.info() != Eigen::Success)
    {
      throw std::runtime_error("smoothFrames: factorization failed");
    }
  }

  // Rounding in E is relative to the size of its terms, not to E (which may be ~0).
  double energyScale = 1e-300;
  for (const Link& l : P.links)
  {
    energyScale += lambda * l.w;
  }
  energyScale += (1.0 - lambda) * (P.area.array() * P.weight.array()).sum();
  int rejected = 0;
  auto descend = [&](Eigen::VectorXd alpha, std::vector<double>& history, int& iterations) {
    double E = P.energy(alpha);
    history.assign(1, E);
    iterations = 0;
    Eigen::VectorXd grad(n);
    for (int it = 0; it < options.maximumNumberOfIterations && n > 0; ++it)
    {
      grad.setZero();
      for (const Link& l : P.links)
      {
        const double s = 4.0 * lambda * l.w * std::sin(4.0 * (l.theta + alpha[l.f] - alpha[l.g]));
        if (unknown[l.f] >= 0)
          grad[unknown[l.f]] += s;
        if (unknown[l.g] >= 0)
          grad[unknown[l.g]] -= s;
      }
      for (int f = 0; f < nf; ++f)
      {
        if (unknown[f] >= 0)
          grad[unknown[f]] += 2.0 * (1.0 - lambda) * P.area[f] * P.weight[f] * alpha[f];
      }
      const Eigen::VectorXd step = mm.solve(-grad);
      auto advance = [&](double scale) {
        Eigen::VectorXd x = alpha;
        for (int f = 0; f < nf; ++f)
        {
          if (unknown[f] >= 0)
            x[f] += scale * step[unknown[f]];
        }
        return x;
      };
      Eigen::VectorXd next = advance(1.0);
      double En = P.energy(next);
      // The bound's step is safe but often short where the energy is flat: try longer ones and
      // keep the lowest (only energies below En are taken, so the descent stays monotone).
      for (double scale = 2.0; scale <= 8.0; scale *= 2.0)
      {
        Eigen::VectorXd longer = advance(scale);
        const double El = P.energy(longer);
        if (!(El < En))
          break;
        next.swap(longer);
        En = El;
      }
      if (!(En <= E))
      {
        // The bound guarantees descent: only rounding at the minimum gets here.
        rejected += En - E > 1e-12 * energyScale || !std::isfinite(En);
        break;
      }
      ++iterations;
      alpha = next;
      history.push_back(En);
      const bool done = E - En <= options.convergenceTolerance * std::max(E, 1e-300);
      E = En;
      if (done)
      {
        break;
      }
    }
    return alpha;
  };

  // Run 1: from the input (constrained triangles turned onto their edges).
  Eigen::VectorXd start = Eigen::VectorXd::Zero(nf);
  for (int f = 0; f < nf; ++f)
  {
    start[f] = R.constrained[f] ? fixedAlpha[f] : 0.0;
  }
  std::vector<double> history;
  int iterations = 0;
  Eigen::VectorXd alpha = descend(start, history, iterations);
  R.energyBefore = history.front();
  R.energyHistory = history;
  R.iterations = iterations;

  // Run 2: from the smoothest four-fold field blended with the alignment (complex u = e^{4 i psi}):
  // lambda/2 sum w |u_f - c u_g|^2 + (1 - lambda)/16 sum A w |u_f - q_f|^2, u fixed where held.
  if (options.globalStart && lambda > 0.0 && n > 0)
  {
    using C = std::complex<double>;
    std::vector<Eigen::Triplet<C>> t;
    Eigen::VectorXcd b = Eigen::VectorXcd::Zero(n);
    Eigen::VectorXd diag = Eigen::VectorXd::Zero(n), mass = Eigen::VectorXd::Zero(n);
    auto fixedU = [&](int f) { return std::polar(1.0, 4.0 * (phi[f] + fixedAlpha[f])); };
    double alignTotal = 0.0, smoothTotal = 0.0;
    for (const Link& l : P.links)
    {
      const double c = 0.5 * lambda * l.w;
      smoothTotal += c;
      const C rot = std::polar(1.0, 4.0 * l.rho); // u_g carried into f's basis
      const int a = unknown[l.f], bb = unknown[l.g];
      if (a >= 0)
        diag[a] += c;
      if (bb >= 0)
        diag[bb] += c;
      if (a >= 0 && bb >= 0)
      {
        t.emplace_back(a, bb, -c * rot);
        t.emplace_back(bb, a, -c * std::conj(rot));
      }
      else if (a >= 0)
      {
        b[a] += c * rot * fixedU(l.g);
      }
      else if (bb >= 0)
      {
        b[bb] += c * std::conj(rot) * fixedU(l.f);
      }
    }
    for (int f = 0; f < nf; ++f)
    {
      if (unknown[f] < 0)
        continue;
      const double s = (1.0 - lambda) / 16.0 * P.area[f] * P.weight[f];
      diag[unknown[f]] += s;
      alignTotal += s;
      b[unknown[f]] += s * std::polar(1.0, 4.0 * phi[f]);
      mass[unknown[f]] = P.area[f];
    }
    // Two candidate starts: the aligned solution of the system above, and, when no frame is
    // held and the alignment is weak, the smoothest field itself (the eigenvector of the smallest
    // eigenvalue, by inverse iteration begun from the aligned solution, so that within the
    // smoothest fields it keeps what alignment it can). A weak alignment term (a sphere) can mix
    // several near-smoothest fields into one with extra singularities; the eigenvector cannot.
    const double meanDiag = diag.sum() / n, meanMass = mass.sum() / n;
    const bool aligned = R.numConstrained > 0 || alignTotal > 1e-9 * smoothTotal;
    const double shift = 1e-6 * meanDiag / std::max(meanMass, 1e-300);
    auto factor = [&](double sigma, SpdSolver<C>& solver) -> bool {
      std::vector<Eigen::Triplet<C>> all = t;
      // The floor keeps the matrix definite where a triangle has neither links nor area (an
      // isolated zero-area triangle), which would otherwise drop the start for the whole mesh.
      for (int i = 0; i < n; ++i)
      {
        all.emplace_back(i, i, C(diag[i] + sigma * mass[i] + 1e-9 * meanDiag + 1e-300, 0.0));
      }
      Eigen::SparseMatrix<C> A(n, n);
      A.setFromTriplets(all.begin(), all.end());
      solver.compute(A);
      return solver.info() == Eigen::Success;
    };
    std::vector<Eigen::VectorXcd> starts;
    Eigen::VectorXcd u0 = Eigen::VectorXcd::Zero(n);
    for (int f = 0; f < nf; ++f)
    {
      if (unknown[f] >= 0)
        u0[unknown[f]] = std::polar(1.0, 4.0 * phi[f]);
    }
    // One factorization serves both: the shift is far below the smallest nonzero eigenvalue's
    // scale, so the aligned solution barely feels it.
    SpdSolver<C> solver;
    if (factor(shift, solver))
    {
      if (aligned)
      {
        u0 = solver.solve(b);
        starts.push_back(u0);
      }
      // The smoothest field matters where the curvature says little (a sphere's is noise:
      // ratio 3e-4 of the two terms before lambda weighs them); on the shared meshes (ratios
      // 0.08-0.12) the aligned start always won or tied, so the inverse iteration's dozen solves
      // are spared there. The ratio leaves lambda out: it asks how much the curvature says, not
      // how much it is listened to (with lambda in, every mesh fell below the bar at 0.95).
      const bool weakCurvature =
        lambda >= 1.0 || alignTotal / (1.0 - lambda) < 0.02 * smoothTotal / lambda;
      if (R.numConstrained == 0 && weakCurvature)
      {
        Eigen::VectorXcd u = u0;
        for (int it = 0; it < 40; ++it)
        {
          Eigen::VectorXcd next = solver.solve((mass.cast<C>().array() * u.array()).matrix());
          const double norm = std::sqrt((mass.array() * next.array().abs2()).sum());
          if (!(norm > 0.0) || !std::isfinite(norm))
            break;
          next /= norm;
          // Settled (up to a global phase, which does not matter for the cross field)?
          const C overlap = (mass.cast<C>().array() * u.array().conjugate() * next.array()).sum();
          u = next;
          // At least a dozen rounds: leftovers of higher modes, however small, add pairs of
          // singularities where the field is weak.
          if (it >= 12 && 1.0 - std::abs(overlap) < 1e-10)
            break;
        }
        starts.push_back(u);
      }
    }
    for (const Eigen::VectorXcd& u : starts)
    {
      const double largest = u.size() ? u.cwiseAbs().maxCoeff() : 0.0;
      Eigen::VectorXd global = start;
      for (int f = 0; f < nf; ++f)
      {
        const int i = unknown[f];
        if (i >= 0 && std::abs(u[i]) > 1e-12 * largest && std::isfinite(std::abs(u[i])))
        {
          global[f] = wrapQuarter(std::arg(u[i]) / 4.0 - phi[f]);
        }
      }
      std::vector<double> globalHistory;
      int globalIterations = 0;
      const Eigen::VectorXd candidate = descend(global, globalHistory, globalIterations);
      if (globalHistory.back() < R.energyHistory.back())
      {
        alpha = candidate;
        R.energyHistory = globalHistory;
        R.iterations = globalIterations;
        R.fromGlobalStart = true;
      }
    }
  }

  R.rejectedSteps = rejected;
  R.rotation = alpha;
  R.energyAfter = R.energyHistory.back();
  R.frameU = frameU;
  R.frameV = frameV;
  rotateFrames(geometry.bases, alpha, R.frameU, R.frameV);
  return R;
}

}
