// Eliminator.h: internal to Core: integer-preserving elimination of homogeneous linear
// constraints, for the unknowns of the integer-grid map (Parameterization.cxx).
#ifndef quadcover_Eliminator_h
#define quadcover_Eliminator_h

#include <utility>
#include <vector>

namespace quadcover
{
namespace param
{
/// A linear combination of unknowns, sorted by unknown, without zero coefficients.
using Expr = std::vector<std::pair<int, double>>;

/// Sorts e by unknown, adds up the coefficients of each unknown and drops those near 0.
void normalize(Expr& e);

/**
 * Eliminates homogeneous linear constraints sum a_j x_j = 0 one at a time, expressing one
 * unknown (the pivot) through the others. Pivots are chosen so that integer unknowns stay
 * integer: a constraint with a real unknown is solved for a real one; a constraint among
 * integer unknowns only is solved for one with coefficient +-1, so it becomes an integer
 * combination of the others. When no such unknown exists the pivot is counted (nonUnitPivots).
 */
class Eliminator
{
public:
  /// A new unknown; returns its index.
  int add(bool integer);
  int size() const { return static_cast<int>(IsInteger.size()); }
  bool isInteger(int x) const { return IsInteger[x] != 0; }
  bool isEliminated(int x) const { return Eliminated[x] != 0; }

  /// The unknown as a combination of unknowns not eliminated (path-compressed).
  const Expr& resolve(int x);

  /**
   * The unknown with every eliminated real unknown replaced, integer ones (eliminated or not)
   * kept: short, where the full resolution of a seam's translation may sum over every branch
   * point beyond it. Call once all constraints are in.
   */
  const Expr& resolveReals(int x);

  /// The combination in unknowns not eliminated.
  Expr resolve(const Expr& e);

  /// Adds the constraint c = 0, eliminating one of its unknowns.
  void constrain(const Expr& c);

  int Constraints = 0;
  int NonUnitPivots = 0;

private:
  /// The index in e of the unknown to eliminate (see the class comment).
  int choosePivot(const Expr& e);

  std::vector<char> IsInteger;
  std::vector<char> Eliminated;
  std::vector<Expr> Substitute; ///< the pivot's expression when it was eliminated
  std::vector<Expr> Full;       ///< the same in unknowns not eliminated (path-compressed)
  std::vector<Expr> Partial;    ///< resolveReals
  std::vector<char> PartialDone;
  Expr Identity;
};
}
}

#endif
