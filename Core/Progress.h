// Progress.h: how far a long computation is, and a way to stop it.
#ifndef quadcover_Progress_h
#define quadcover_Progress_h

#include <algorithm>
#include <functional>
#include <memory>
#include <stdexcept>
#include <utility>

namespace quadcover
{
/// Thrown by Progress::report when the callback asks the computation to stop. What the
/// computation was filling, or changing in place (relaxQuads' mesh), is then incomplete; its
/// read-only inputs are untouched.
class Cancelled : public std::runtime_error
{
public:
  Cancelled()
    : std::runtime_error("cancelled")
  {}
};

/**
 * Where a long computation (smoothFrames, optimizeBranchPoints, computeParameterization,
 * extractQuads, ...) says how far it is, as a fraction in [0, 1]. The default one reports to
 * nobody. The callback receives the fraction mapped into this object's share [begin, end] of the
 * caller's whole and returns false to stop the computation: report() then throws Cancelled.
 * Report only from the thread that called the computation.
 */
class Progress
{
public:
  using Callback = std::function<bool(double)>;

  Progress() = default;
  explicit Progress(Callback callback)
    : callback_(std::make_shared<const Callback>(std::move(callback)))
  {}

  /// Reports `fraction` of this object's share done.
  /// @throws Cancelled when the callback returns false
  void report(double fraction) const
  {
    if (callback_ && *callback_ &&
      !(*callback_)(begin_ + (end_ - begin_) * std::clamp(fraction, 0.0, 1.0)))
    {
      throw Cancelled();
    }
  }

  /// The part [from, to] (fractions of this object's share) for a step of the computation.
  Progress part(double from, double to) const
  {
    Progress p = *this;
    p.begin_ = begin_ + (end_ - begin_) * std::clamp(from, 0.0, 1.0);
    p.end_ = begin_ + (end_ - begin_) * std::clamp(to, 0.0, 1.0);
    return p;
  }

private:
  std::shared_ptr<const Callback> callback_;
  double begin_ = 0.0;
  double end_ = 1.0;
};
}

#endif
