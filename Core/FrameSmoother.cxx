// FrameSmoother.cxx: smoothing and curvature alignment of a frame field by a majorized descent,
// run from the input and from the globally optimal fields.
#include "FrameSmoother.h"

#include "Parallel.h"
#include "SparseSolver.h"
#include <Eigen/Geometry>

#include <atomic>
#include <cmath>
#include <complex>
#include <limits>
#include <optional>
#include <stdexcept>

namespace quadcover
{
namespace
{
using Complex = std::complex<double>;

/// One inner edge: faces f < g, the frames' misalignment before rotation, the weight.
struct Link
{
  int f, g;
  double rho;   // transport from g's basis into f's
  double w;     // (A_f + A_g) / 3
  Complex turn; // e^{4 i theta}, theta the angle of f's frame minus g's carried into f's plane
};

/// e^{4 i alpha} per triangle: with them a link's cos 4(theta + alpha_f - alpha_g) and its sine
/// are the parts of turn z_f conj(z_g), a product instead of a cosine per link (linkPhasor).
Eigen::VectorXcd phasors(const Eigen::VectorXd& alpha)
{
  Eigen::VectorXcd z(alpha.size());
  for (Eigen::Index i = 0; i < alpha.size(); ++i)
  {
    z[i] = std::polar(1.0, 4.0 * alpha[i]);
  }
  return z;
}

/// turn z_f conj(z_g) of link l, written out (std::complex's product checks for infinities).
inline Complex linkPhasor(const Link& l, const Eigen::VectorXcd& z)
{
  const Complex a = z[l.f], b = z[l.g];
  const double re = a.real() * b.real() + a.imag() * b.imag();
  const double im = a.imag() * b.real() - a.real() * b.imag();
  return { l.turn.real() * re - l.turn.imag() * im, l.turn.real() * im + l.turn.imag() * re };
}

struct Problem
{
  std::vector<Link> links;
  Eigen::VectorXd area, weight;
  double lambda = 0.5;

  /// E at alpha, z = phasors(alpha).
  double energy(const Eigen::VectorXd& alpha, const Eigen::VectorXcd& z) const
  {
    double smooth = 0.0, align = 0.0;
    for (const Link& l : links)
    {
      smooth += l.w * (1.0 - linkPhasor(l, z).real());
    }
    for (Eigen::Index i = 0; i < alpha.size(); ++i)
    {
      align += area[i] * weight[i] * alpha[i] * alpha[i];
    }
    return lambda * smooth + (1.0 - lambda) * align;
  }
};

/// What every run shares: the energy, the input frames' angles, the held frames and the
/// numbering of the free ones.
struct Smoothing
{
  Problem P;
  Eigen::VectorXd phi;        ///< #F angles of the input frames
  Eigen::VectorXd fixedAlpha; ///< #F the turn that puts a held frame onto its edge
  std::vector<int> unknown;   ///< #F index of the triangle's unknown, -1 where its frame is held
  int n = 0;                  ///< number of unknowns
};

void checkInputs(const Eigen::MatrixX3i& F, const MeshTopology& topo,
  const Eigen::MatrixX3d& frameU, const Eigen::MatrixX3d& frameV, const Eigen::VectorXd& weight,
  const SmootherOptions& options)
{
  const Eigen::Index nf = F.rows();
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
  if (!(options.coherenceRadius >= 0.0 && std::isfinite(options.coherenceRadius)))
  {
    throw std::invalid_argument("smoothFrames: coherence radius must be finite and at least 0");
  }
}

/// The energy's terms (areas, weights, a link per inner edge) and the frames held along
/// boundaries and sharp edges: R's constrained, featureEdges and boundaryEdges, s.fixedAlpha.
void setUpProblem(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F, const MeshTopology& topo,
  const FrameGeometry& geometry, const Eigen::VectorXd& weight, const SmootherOptions& options,
  Smoothing& s, SmootherResult& R)
{
  const int nf = static_cast<int>(F.rows());
  Problem& P = s.P;
  P.lambda = options.smoothingWeight;
  P.area.resize(nf);
  for (int f = 0; f < nf; ++f)
  {
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    P.area[f] = 0.5 * (b - a).cross(c - a).norm();
  }
  P.weight = weight.unaryExpr([](double w) { return std::isfinite(w) && w > 0.0 ? w : 0.0; });

  R.constrained.assign(nf, 0);
  s.fixedAlpha = Eigen::VectorXd::Zero(nf);
  Eigen::VectorXd constraintLength = Eigen::VectorXd::Zero(nf);
  auto hold = [&](int f, int k) {
    const double len = (V.row(F(f, (k + 1) % 3)) - V.row(F(f, k))).norm();
    if (len > constraintLength[f])
    {
      constraintLength[f] = len;
      R.constrained[f] = 1;
      s.fixedAlpha[f] = wrapQuarter(geometry.edgeAngle(f, k) - s.phi[f]);
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
        const double theta = wrapAngle(s.phi[f] - s.phi[g] - rho);
        P.links.push_back(
          { f, g, rho, (P.area[f] + P.area[g]) / 3.0, std::polar(1.0, 4.0 * theta) });
      }
    }
  }
}

/// The unknowns: the free triangles, in order (R.numConstrained counts the others).
void numberUnknowns(Smoothing& s, SmootherResult& R)
{
  const int nf = static_cast<int>(R.constrained.size());
  s.unknown.assign(nf, -1);
  s.n = 0;
  for (int f = 0; f < nf; ++f)
  {
    if (R.constrained[f])
    {
      ++R.numConstrained;
    }
    else
    {
      s.unknown[f] = s.n++;
    }
  }
}

/// Adds a link's term c |x_a - turn x_b|^2 to a system over the unknowns (a, b: the link's ends'
/// unknowns, -1 where held): c to the diagonal at each free end (kept apart, the caller adds the
/// diagonal's triplets), and -c turn, -c conj(turn) between two free ends.
template<typename Scalar>
void addLink(Eigen::VectorXd& diagonal, std::vector<Eigen::Triplet<Scalar>>& t, int a, int b,
  double c, const Scalar& turn)
{
  if (a >= 0)
    diagonal[a] += c;
  if (b >= 0)
    diagonal[b] += c;
  if (a >= 0 && b >= 0)
  {
    t.emplace_back(a, b, -c * turn);
    t.emplace_back(b, a, -c * Eigen::numext::conj(turn));
  }
}

/// What the run from the input shares with the runs from the global starts when it runs beside
/// them (descendFromStarts).
struct Beside
{
  /// the global runs' lowest end once they have ended (+infinity before, and when there is none)
  std::atomic<double> bar{ std::numeric_limits<double>::infinity() };
  std::atomic<bool> stop{ false };  ///< set when the global runs end by an exception (a cancel)
  std::atomic<int> iterations{ 0 }; ///< the run's iterations so far, for its progress
};

/**
 * The descent: each iteration minimizes a quadratic upper bound of E (1 - cos is bounded by its
 * second-order expansion with curvature 1), so E never increases. The bound's matrix, 16 lambda
 * w per link (a graph Laplacian) + 2 (1 - lambda) A w, does not change: it is factored once for
 * every run.
 */
class Descent
{
public:
  /// Factors the bound's matrix (progress: before and after the factorization).
  Descent(const Smoothing& s, const SmootherOptions& options, const Progress& progress)
    : S(s)
    , Options(options)
  {
    this->factor(progress);
    // Rounding in E is relative to the size of its terms, not to E (which may be ~0).
    const Problem& P = s.P;
    for (const Link& l : P.links)
    {
      EnergyScale += P.lambda * l.w;
    }
    EnergyScale += (1.0 - P.lambda) * (P.area.array() * P.weight.array()).sum();
  }

  /// Descends from alpha (#F) until an iteration gains less than the convergence tolerance.
  /// A run that can no longer reach `bar` (the lowest end of the runs before it) is given up:
  /// when its energy is above the bar by more than Hopeless times what its last Window
  /// iterations gained (each iteration gains about as much as the one before or less, up to the
  /// jumps of a singularity moving; on the shared meshes the runs from the input end 2.8 times
  /// (armadillo) to 1.5 times (spot) above the global start's end, after 60 to 130 iterations). Its
  /// end is then above the bar, so it loses as it would have. The runs from the input that won (the
  /// teapot, and the knot with the smoothest field) were below the bar after 4 iterations,
  /// and the losers, given up after 10 iterations' gains, ran 15 to 38 iterations (armadillo
  /// 28, a fifth of its smoothing time); after 4 iterations' gains they run half as many, on
  /// the shared and generated meshes with both smoothing weights, and end as before.
  /// The bar may become known while the run goes on (beside: the runs before it on another
  /// thread): a run is given up as soon as any of its iterations so far meets the test
  /// (givenUp), so that where it stops does not change what it returns to a caller that tests
  /// its history again. It also stops when beside's stop is set.
  /// @param[out] history E at the start and after every iteration
  /// @param[out] rejected whether it ended on a step that raised the energy by more than rounding
  Eigen::VectorXd run(Eigen::VectorXd alpha, std::vector<double>& history, int& iterations,
    bool& rejected, const Progress& progress, Beside* beside = nullptr) const
  {
    rejected = false;
    Eigen::VectorXcd z = phasors(alpha);
    double E = S.P.energy(alpha, z);
    history.assign(1, E);
    iterations = 0;
    Eigen::VectorXd grad(S.n);
    // Accelerated (Nesterov's momentum, at most MaximumMomentum, restarted whenever a step from
    // the extrapolated point does not lower the energy): each step is the bound's from
    // y = alpha + beta (alpha - previous), kept only when it ends below alpha's energy, so the
    // descent stays monotone. At 6,500 quads: armadillo 44 -> 22 iterations, rocker-arm 45 ->
    // 25, lion 45 -> 31, to the same energies within 3e-4.
    Eigen::VectorXd previous = alpha, y = alpha;
    double t = 1.0;
    for (int it = 0; iterations < Options.maximumNumberOfIterations && S.n > 0; ++it)
    {
      progress.report(static_cast<double>(iterations) / Options.maximumNumberOfIterations);
      const double tNext = 0.5 * (1.0 + std::sqrt(1.0 + 4.0 * t * t));
      const double beta = std::min(MaximumMomentum, (t - 1.0) / tNext);
      if (it > 0)
      {
        y = alpha + beta * (alpha - previous);
        z = phasors(y); // afresh: products of products would drift off the unit circle
      }
      this->gradient(z, y, grad);
      const Eigen::VectorXd step = Solver.solveConcurrently(-grad);
      double En = 0.0;
      Eigen::VectorXd next = this->longestStep(y, z, step, En);
      if (!(En <= E) && beta > 0.0)
      {
        t = 1.0; // restart: the next step from alpha itself
        previous = alpha;
        continue;
      }
      if (!(En <= E))
      {
        // The bound guarantees descent from alpha: only rounding at the minimum gets here.
        rejected = En - E > 1e-12 * EnergyScale || !std::isfinite(En);
        break;
      }
      t = tNext;
      ++iterations;
      previous.swap(alpha);
      alpha.swap(next);
      history.push_back(En);
      bool done = E - En <= Options.convergenceTolerance * std::max(E, 1e-300);
      if (done && beta > 0.0)
      {
        // a step carried by momentum may gain little where a plain one gains more: converged
        // only when a plain step says so
        done = false;
        t = 1.0;
        previous = alpha;
      }
      E = En;
      if (beside)
      {
        beside->iterations.store(iterations);
      }
      if (done || (beside && (beside->stop.load() || givenUp(history, beside->bar.load()))))
      {
        break;
      }
    }
    return alpha;
  }

  /// Whether a run of this history is given up against bar (run): at some iteration k, its
  /// energy above the bar by more than Hopeless times what the Window iterations before gained.
  static bool givenUp(const std::vector<double>& history, double bar)
  {
    for (std::size_t k = Window; k < history.size(); ++k)
    {
      if (history[k] - bar > Hopeless * (history[k - Window] - history[k]))
      {
        return true;
      }
    }
    return false;
  }

private:
  /// The bound's matrix, plus a small proximal term that keeps it definite where nothing else
  /// does (it only adds a positive term to the bound, so the energy still never rises).
  void factor(const Progress& progress)
  {
    const Problem& P = S.P;
    const int n = S.n, nf = static_cast<int>(S.unknown.size());
    const double lambda = P.lambda;
    Eigen::VectorXd diagonal = Eigen::VectorXd::Zero(n);
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(4 * P.links.size() + n);
    for (const Link& l : P.links)
    {
      addLink(diagonal, t, S.unknown[l.f], S.unknown[l.g], 16.0 * lambda * l.w, 1.0);
    }
    for (int f = 0; f < nf; ++f)
    {
      if (S.unknown[f] >= 0)
      {
        diagonal[S.unknown[f]] += 2.0 * (1.0 - lambda) * P.area[f] * P.weight[f];
      }
    }
    const double mean = n > 0 ? diagonal.sum() / n : 0.0;
    for (int i = 0; i < n; ++i)
    {
      diagonal[i] += 1e-9 * mean + 1e-300;
      t.emplace_back(i, i, diagonal[i]);
    }
    Eigen::SparseMatrix<double> H(n, n);
    H.setFromTriplets(t.begin(), t.end());
    std::vector<Eigen::Triplet<double>>().swap(t); // not kept beside the factor
    progress.report(0.2);
    if (n > 0)
    {
      Solver.compute(H);
      if (Solver.info() != Eigen::Success)
      {
        throw std::runtime_error("smoothFrames: factorization failed");
      }
    }
    progress.report(1.0);
  }

  /// dE/dalpha over the unknowns at alpha, z = phasors(alpha).
  void gradient(const Eigen::VectorXcd& z, const Eigen::VectorXd& alpha, Eigen::VectorXd& grad) const
  {
    const Problem& P = S.P;
    const double lambda = P.lambda;
    grad.setZero();
    for (const Link& l : P.links)
    {
      const double s = 4.0 * lambda * l.w * linkPhasor(l, z).imag();
      if (S.unknown[l.f] >= 0)
        grad[S.unknown[l.f]] += s;
      if (S.unknown[l.g] >= 0)
        grad[S.unknown[l.g]] -= s;
    }
    for (int f = 0; f < static_cast<int>(S.unknown.size()); ++f)
    {
      if (S.unknown[f] >= 0)
        grad[S.unknown[f]] += 2.0 * (1.0 - lambda) * P.area[f] * P.weight[f] * alpha[f];
    }
  }

  /// alpha moved by scale times step on the unknowns.
  Eigen::VectorXd advance(
    const Eigen::VectorXd& alpha, const Eigen::VectorXd& step, double scale) const
  {
    Eigen::VectorXd x = alpha;
    for (int f = 0; f < static_cast<int>(S.unknown.size()); ++f)
    {
      if (S.unknown[f] >= 0)
        x[f] += scale * step[S.unknown[f]];
    }
    return x;
  }

  /// The bound's step is safe but often short where the energy is flat: try longer ones and
  /// keep the lowest (only energies below the bound step's are taken, so the descent stays
  /// monotone). z = phasors(alpha); the longer steps' phasors are z times the step's squared,
  /// squared again. @param[out] En the energy where it ends
  Eigen::VectorXd longestStep(const Eigen::VectorXd& alpha, const Eigen::VectorXcd& z,
    const Eigen::VectorXd& step, double& En) const
  {
    Eigen::VectorXd next = this->advance(alpha, step, 1.0);
    Eigen::VectorXcd turn = phasors(next - alpha);
    En = S.P.energy(next, (z.array() * turn.array()).matrix());
    for (double scale = 2.0; scale <= 8.0; scale *= 2.0)
    {
      Eigen::VectorXd longer = this->advance(alpha, step, scale);
      turn = turn.cwiseProduct(turn);
      const double El = S.P.energy(longer, (z.array() * turn.array()).matrix());
      if (!(El < En))
        break;
      next.swap(longer);
      En = El;
    }
    return next;
  }

  static constexpr std::size_t Window = 4;
  static constexpr double Hopeless = 5.0;
  /// The momentum's cap: above 0.8 cheburashka and the teapot (at 6,500 quads) ended in other
  /// minima, higher ones, and armadillo took 32 iterations instead of 19 (22 with the plain
  /// step deciding convergence).
  static constexpr double MaximumMomentum = 0.7;
  const Smoothing& S;
  const SmootherOptions& Options;
  /// simplicial: one factorization, 40 to 60 solves (armadillo: 0.6 s less than supernodal)
  SpdSolver<double> Solver{ Factorization::Simplicial };
  double EnergyScale = 1e-300;
};

/**
 * The smoothest four-fold field blended with the alignment, in u = e^{4 i psi} per free triangle:
 *   lambda/2 sum w |u_f - c u_g|^2 + (1 - lambda)/16 sum A w |u_f - q_f|^2, u fixed where held.
 */
struct GlobalSystem
{
  /// the matrix without its diagonal (room for it kept), until factor() takes it
  std::vector<Eigen::Triplet<Complex>> t;
  Eigen::VectorXcd b;
  Eigen::VectorXd diag, mass;
  double alignTotal = 0.0, smoothTotal = 0.0;

  explicit GlobalSystem(const Smoothing& s)
    : b(Eigen::VectorXcd::Zero(s.n))
    , diag(Eigen::VectorXd::Zero(s.n))
    , mass(Eigen::VectorXd::Zero(s.n))
  {
    const Problem& P = s.P;
    const double lambda = P.lambda;
    t.reserve(2 * P.links.size() + static_cast<std::size_t>(s.n));
    auto fixedU = [&](int f) { return std::polar(1.0, 4.0 * (s.phi[f] + s.fixedAlpha[f])); };
    for (const Link& l : P.links)
    {
      const double c = 0.5 * lambda * l.w;
      smoothTotal += c;
      const Complex rot = std::polar(1.0, 4.0 * l.rho); // u_g carried into f's basis
      const int a = s.unknown[l.f], bb = s.unknown[l.g];
      addLink(diag, t, a, bb, c, rot);
      if (a >= 0 && bb < 0)
      {
        b[a] += c * rot * fixedU(l.g);
      }
      else if (a < 0 && bb >= 0)
      {
        b[bb] += c * std::conj(rot) * fixedU(l.f);
      }
    }
    for (int f = 0; f < static_cast<int>(s.unknown.size()); ++f)
    {
      if (s.unknown[f] < 0)
        continue;
      const double w = (1.0 - lambda) / 16.0 * P.area[f] * P.weight[f];
      diag[s.unknown[f]] += w;
      alignTotal += w;
      b[s.unknown[f]] += w * std::polar(1.0, 4.0 * s.phi[f]);
      mass[s.unknown[f]] = P.area[f];
    }
  }

  double meanDiagonal() const { return diag.sum() / diag.size(); }

  /// Factors the matrix shifted by sigma times the mass; once: its entries go (they are not kept
  /// beside the factor).
  bool factor(double sigma, SpdSolver<Complex>& solver)
  {
    const int n = static_cast<int>(diag.size());
    const double meanDiag = this->meanDiagonal();
    // The floor keeps the matrix definite where a triangle has neither links nor area (an
    // isolated zero-area triangle), which would otherwise drop the start for the whole mesh.
    for (int i = 0; i < n; ++i)
    {
      t.emplace_back(i, i, Complex(diag[i] + sigma * mass[i] + 1e-9 * meanDiag + 1e-300, 0.0));
    }
    Eigen::SparseMatrix<Complex> A(n, n);
    A.setFromTriplets(t.begin(), t.end());
    std::vector<Eigen::Triplet<Complex>>().swap(t);
    solver.compute(A);
    return solver.info() == Eigen::Success;
  }
};

/// The eigenvector of the smallest eigenvalue of the factored system (mass-normalized), by
/// inverse iteration from u, one report per solve.
Eigen::VectorXcd smoothestField(const SpdSolver<Complex>& solver, const Eigen::VectorXd& mass,
  Eigen::VectorXcd u, const Progress& progress)
{
  const int rounds = 40;
  for (int it = 0; it < rounds; ++it)
  {
    progress.report(static_cast<double>(it) / rounds);
    Eigen::VectorXcd next = solver.solve((mass.cast<Complex>().array() * u.array()).matrix());
    const double norm = std::sqrt((mass.array() * next.array().abs2()).sum());
    if (!(norm > 0.0) || !std::isfinite(norm))
      break;
    next /= norm;
    // Settled (up to a global phase, which does not matter for the cross field)?
    const Complex overlap =
      (mass.cast<Complex>().array() * u.array().conjugate() * next.array()).sum();
    u = next;
    // At least a dozen rounds: leftovers of higher modes, however small, add pairs of
    // singularities where the field is weak.
    if (it >= 12 && 1.0 - std::abs(overlap) < 1e-10)
      break;
  }
  return u;
}

/**
 * The global candidate starts: the aligned solution of the global system, and, when no frame is
 * held and the alignment is weak, the smoothest field itself (the eigenvector of the smallest
 * eigenvalue, by inverse iteration begun from the aligned solution, so that within the smoothest
 * fields it keeps what alignment it can). A weak alignment term (a sphere) can mix several
 * near-smoothest fields into one with extra singularities; the eigenvector cannot. None when the
 * system cannot be factored.
 */
std::vector<Eigen::VectorXcd> globalStarts(
  const Smoothing& s, int numConstrained, const Progress& progress)
{
  GlobalSystem G(s);
  progress.report(0.05);
  const double lambda = s.P.lambda;
  const double meanDiag = G.meanDiagonal(), meanMass = G.mass.sum() / s.n;
  const bool aligned = numConstrained > 0 || G.alignTotal > 1e-9 * G.smoothTotal;
  const double shift = 1e-6 * meanDiag / std::max(meanMass, 1e-300);
  std::vector<Eigen::VectorXcd> starts;
  Eigen::VectorXcd u0 = Eigen::VectorXcd::Zero(s.n);
  for (int f = 0; f < static_cast<int>(s.unknown.size()); ++f)
  {
    if (s.unknown[f] >= 0)
      u0[s.unknown[f]] = std::polar(1.0, 4.0 * s.phi[f]);
  }
  // One factorization serves both: the shift is far below the smallest nonzero eigenvalue's
  // scale, so the aligned solution barely feels it.
  SpdSolver<Complex> solver{ Factorization::Automatic };
  if (!G.factor(shift, solver))
  {
    return starts;
  }
  progress.report(0.2);
  if (aligned)
  {
    u0 = solver.solve(G.b);
    starts.push_back(u0);
    progress.report(0.3);
  }
  // The smoothest field matters where the curvature says little (a sphere's is noise: ratio 3e-4
  // of the two terms before lambda weighs them); on the shared meshes (ratios 0.08-0.12) the
  // aligned start always won or tied, so the inverse iteration's dozen solves are spared there.
  // The ratio leaves lambda out: it asks how much the curvature says, not how much it is
  // listened to (with lambda in, every mesh fell below the bar at 0.95).
  const bool weakCurvature =
    lambda >= 1.0 || G.alignTotal / (1.0 - lambda) < 0.02 * G.smoothTotal / lambda;
  if (numConstrained == 0 && weakCurvature)
  {
    starts.push_back(smoothestField(solver, G.mass, u0, progress.part(0.3, 1.0)));
  }
  return starts;
}

/// The turns (#F) that carry the input frames onto the field u (held frames, and triangles
/// where u vanishes, keep their turn from `start`).
Eigen::VectorXd turnsToField(
  const Smoothing& s, const Eigen::VectorXcd& u, const Eigen::VectorXd& start)
{
  const double largest = u.size() ? u.cwiseAbs().maxCoeff() : 0.0;
  Eigen::VectorXd global = start;
  for (int f = 0; f < static_cast<int>(s.unknown.size()); ++f)
  {
    const int i = s.unknown[f];
    if (i >= 0 && std::abs(u[i]) > 1e-12 * largest && std::isfinite(std::abs(u[i])))
    {
      global[f] = wrapQuarter(std::arg(u[i]) / 4.0 - s.phi[f]);
    }
  }
  return global;
}

/// How far each input frame agrees with those around it, in [0, 1]: |c_f| with c the input's
/// four-fold field q = e^{4 i phi} diffused over about `radius` (one implicit step of the
/// connection Laplacian of the links: (M + t L) c = M q, t = 2 radius^2 / l^2 for the mean
/// edge length l). The links' weights are areas, so the step reaches about radius / l triangles
/// whatever their local size: a radius in mean edge lengths, not in distance, on a mesh whose
/// triangles vary in size. Incoherent directions (noise, umbilics, directions that turn within
/// the radius) average out towards 0. A system that cannot be factored (never seen) leaves 1.
Eigen::VectorXd frameCoherence(const Smoothing& s, double radius)
{
  const Problem& P = s.P;
  const int nf = static_cast<int>(P.area.size());
  Eigen::VectorXd coherence = Eigen::VectorXd::Ones(nf);
  const double meanArea = nf > 0 ? P.area.sum() / nf : 0.0;
  const double l2 = 4.0 / std::sqrt(3.0) * meanArea;
  if (!(radius > 0.0) || !(l2 > 0.0) || nf == 0)
  {
    return coherence;
  }
  const double t = 2.0 * radius * radius / l2;
  Eigen::VectorXd diag = Eigen::VectorXd::Zero(nf);
  std::vector<Eigen::Triplet<Complex>> triplets;
  triplets.reserve(2 * P.links.size() + nf);
  for (const Link& l : P.links)
  {
    addLink(diag, triplets, l.f, l.g, t * l.w, std::polar(1.0, 4.0 * l.rho));
  }
  Eigen::VectorXcd b(nf);
  for (int f = 0; f < nf; ++f)
  {
    const double m = P.area[f] + 1e-12 * meanArea;
    triplets.emplace_back(f, f, Complex(diag[f] + m, 0.0));
    b[f] = m * std::polar(1.0, 4.0 * s.phi[f]);
  }
  Eigen::SparseMatrix<Complex> A(nf, nf);
  A.setFromTriplets(triplets.begin(), triplets.end());
  std::vector<Eigen::Triplet<Complex>>().swap(triplets); // not kept beside the factor
  SpdSolver<Complex> solver{ Factorization::Automatic };
  solver.compute(A);
  if (solver.info() != Eigen::Success)
  {
    return coherence;
  }
  const Eigen::VectorXcd c = solver.solve(b);
  for (int f = 0; f < nf; ++f)
  {
    coherence[f] = std::min(1.0, std::abs(c[f]));
  }
  return coherence;
}

/// Multiplies each triangle's alignment weight by its frameCoherence (radius: a fraction of the
/// square root of the surface's area) to the power CoherencePower; returns the coherence (1
/// everywhere when the radius is 0).
Eigen::VectorXd weighByCoherence(Smoothing& s, double radius)
{
  // The power: the alignment fades fast below full agreement. Chosen on the shared meshes with
  // the smoothing weight 0.95 and no merges at 6,500 quads: 8 against 4 and 16 (medians of the
  // edge-length RSD 10.3% against 10.9 and 10.0, angle RSD 7.7% against 7.9 and 8.8).
  constexpr double CoherencePower = 8.0;
  const Eigen::VectorXd coherence = frameCoherence(s, radius * std::sqrt(s.P.area.sum()));
  for (Eigen::Index f = 0; f < coherence.size(); ++f)
  {
    s.P.weight[f] *= std::pow(coherence[f], CoherencePower);
  }
  return coherence;
}

/// Runs 2 and 3: descents from the global starts (Knoeppel et al. 2013, globalStarts); the
/// first with the lowest end goes into alpha and R (R.rejectedSteps counts their rejected steps).
/// Returns false when there is none.
bool descendFromGlobalStarts(const Smoothing& s, const Descent& descent,
  const std::vector<Eigen::VectorXcd>& starts, const Eigen::VectorXd& start, Eigen::VectorXd& alpha,
  SmootherResult& R, const Progress& progress)
{
  for (std::size_t i = 0; i < starts.size(); ++i)
  {
    const double from = static_cast<double>(i) / static_cast<double>(starts.size());
    const double to = static_cast<double>(i + 1) / static_cast<double>(starts.size());
    std::vector<double> globalHistory;
    int globalIterations = 0;
    bool rejected = false;
    const Eigen::VectorXd candidate = descent.run(turnsToField(s, starts[i], start), globalHistory,
      globalIterations, rejected, progress.part(from, to));
    R.rejectedSteps += rejected;
    if (i == 0 || globalHistory.back() < R.energyHistory.back())
    {
      alpha = candidate;
      R.energyHistory = globalHistory;
      R.iterations = globalIterations;
      R.fromGlobalStart = true;
    }
  }
  return !starts.empty();
}

/**
 * The global runs (2 and 3) and run 1 on two threads, each global run's end lowering the bar as
 * it comes: run 2 on this thread (reporting `global`), the other global runs in turn on the
 * other thread, and run 1 on whichever thread is free first; this thread then reports run 1's
 * progress on `input` until the other has ended, so that a cancel stops every run. The bar run 1
 * sees is the lowest end of the global runs ended so far, never below the final one: a run given
 * up against it is given up against the final bar too, and a run not given up ran to its end, so
 * whether run 1 wins and what it returns are as when it runs after them. The global runs' winner
 * is descendFromGlobalStarts' (the first with the lowest end). Before, run 1 went beside the
 * global runs, which ran one after the other: the urchin's smoothing (79k triangles, two global
 * starts) took 1.85 s against 1.64 s now (medians of five, Benchmarks/README.md).
 */
void descendBeside(const Smoothing& s, const Descent& descent,
  const std::vector<Eigen::VectorXcd>& starts, const Eigen::VectorXd& start,
  const SmootherOptions& options, const Progress& global, const Progress& input,
  Eigen::VectorXd& alpha, SmootherResult& R, Beside& beside, Eigen::VectorXd& fromInput,
  std::vector<double>& history, int& iterations, bool& rejected)
{
  const std::size_t n = starts.size();
  std::vector<Eigen::VectorXd> ends(n);
  std::vector<std::vector<double>> histories(n);
  std::vector<int> runIterations(n, 0);
  std::vector<char> runRejected(n, 0);
  Beside others; // the other thread's global runs: no bar, stopped by a cancel on this thread
  std::atomic<bool> inputTaken{ false };
  auto globalRun = [&](std::size_t i, const Progress& progress, Beside* own) {
    bool r = false;
    ends[i] = descent.run(
      turnsToField(s, starts[i], start), histories[i], runIterations[i], r, progress, own);
    runRejected[i] = r;
    double bar = beside.bar.load();
    while (histories[i].back() < bar && !beside.bar.compare_exchange_weak(bar, histories[i].back()))
    {}
  };
  auto inputRun = [&](const Progress& progress) {
    if (!inputTaken.exchange(true))
    {
      fromInput = descent.run(start, history, iterations, rejected, progress, &beside);
    }
  };
  auto stoppingAll = [&](auto&& work) {
    try
    {
      work();
    }
    catch (...)
    {
      others.stop.store(true);
      beside.stop.store(true);
      throw;
    }
  };
  const double most = std::max(1, options.maximumNumberOfIterations);
  runBothReporting(
    [&]() {
      stoppingAll([&]() {
        globalRun(0, global, nullptr);
        inputRun(input);
      });
    },
    [&]() {
      for (std::size_t i = 1; i < n; ++i)
      {
        globalRun(i, Progress(), &others);
      }
      inputRun(Progress());
    },
    [&]() { stoppingAll([&]() { input.report(beside.iterations.load() / most); }); },
    options.numberOfThreads);
  std::size_t won = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    R.rejectedSteps += runRejected[i];
    won = histories[i].back() < histories[won].back() ? i : won;
  }
  alpha.swap(ends[won]);
  R.energyHistory.swap(histories[won]);
  R.iterations = runIterations[won];
  R.fromGlobalStart = true;
}

/**
 * Runs 2 and 3 (descendFromGlobalStarts, with `global` for their progress), then run 1, from the
 * input (`start`: held triangles turned onto their edges), given up once it cannot reach their
 * lowest end (the bar); on a tie it wins. With more than one thread and a global start, they run
 * on two threads instead (descendBeside: armadillo's run 1 took 13 of its iterations, 0.2 s, off
 * the smoothing's time), with the same outcome. The winner goes into alpha and R.
 */
void descendFromStarts(const Smoothing& s, const Descent& descent,
  const std::vector<Eigen::VectorXcd>& starts, const Eigen::VectorXd& start,
  const SmootherOptions& options, Eigen::VectorXd& alpha, SmootherResult& R, const Progress& global,
  const Progress& input)
{
  Beside beside;
  Eigen::VectorXd fromInput;
  std::vector<double> history;
  int iterations = 0;
  bool anyGlobal = !starts.empty(), rejected = false;
  if (threadCount(options.numberOfThreads) > 1 && anyGlobal)
  {
    descendBeside(s, descent, starts, start, options, global, input, alpha, R, beside, fromInput,
      history, iterations, rejected);
  }
  else
  {
    anyGlobal = descendFromGlobalStarts(s, descent, starts, start, alpha, R, global);
    if (anyGlobal)
    {
      beside.bar.store(R.energyHistory.back());
    }
    fromInput = descent.run(start, history, iterations, rejected, input, &beside);
  }
  R.energyBefore = history.front();
  const bool lost = anyGlobal && Descent::givenUp(history, beside.bar.load());
  R.rejectedSteps += rejected && !lost;
  if (!anyGlobal || (!lost && history.back() <= beside.bar.load()))
  {
    alpha.swap(fromInput);
    R.energyHistory.swap(history);
    R.iterations = iterations;
    R.fromGlobalStart = false;
  }
}
}

SmootherResult smoothFrames(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F,
  const MeshTopology& topo, const FrameGeometry& geometry, const Eigen::MatrixX3d& frameU,
  const Eigen::MatrixX3d& frameV, const Eigen::VectorXd& weight, const SmootherOptions& options,
  const Progress& progress)
{
  progress.report(0.0);
  checkInputs(F, topo, frameU, frameV, weight, options);
  SmootherResult R;
  Smoothing s;
  s.phi = vectorAngles(geometry.bases, frameU);
  setUpProblem(V, F, topo, geometry, weight, options, s, R);
  // at lambda 1 the alignment term is gone: nothing to weigh, no factorization
  R.coherence = weighByCoherence(s, s.P.lambda < 1.0 ? options.coherenceRadius : 0.0);
  numberUnknowns(s, R);
  progress.report(0.01);
  // The global starts and the descent's factorization do not depend on each other: on two
  // threads they run at once (the descent's reports nothing).
  const bool global = options.globalStart && s.P.lambda > 0.0 && s.n > 0;
  std::vector<Eigen::VectorXcd> starts;
  std::optional<Descent> descent;
  runBoth(
    [&]() {
      if (global)
      {
        starts = globalStarts(s, R.numConstrained, progress.part(0.01, 0.15));
      }
    },
    [&]() { descent.emplace(s, options, Progress()); }, options.numberOfThreads);

  Eigen::VectorXd start = Eigen::VectorXd::Zero(F.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    start[f] = R.constrained[f] ? s.fixedAlpha[f] : 0.0;
  }
  Eigen::VectorXd alpha;
  descendFromStarts(s, *descent, starts, start, options, alpha, R, progress.part(0.15, 0.6),
    progress.part(starts.empty() ? 0.15 : 0.6, 1.0));

  R.rotation = alpha;
  R.energyAfter = R.energyHistory.back();
  R.frameU = frameU;
  R.frameV = frameV;
  rotateFrames(geometry.bases, alpha, R.frameU, R.frameV);
  progress.report(1.0);
  return R;
}

}
