// Eliminator.cxx: integer-preserving elimination of homogeneous linear constraints.
#include "Eliminator.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>

namespace quadcover
{
namespace param
{
void normalize(Expr& e)
{
  std::sort(e.begin(), e.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::size_t out = 0;
  for (std::size_t i = 0; i < e.size();)
  {
    double sum = 0.0;
    const int var = e[i].first;
    for (; i < e.size() && e[i].first == var; ++i)
    {
      sum += e[i].second;
    }
    if (std::abs(sum) > 1e-12)
    {
      e[out++] = { var, sum };
    }
  }
  e.resize(out);
}

int Eliminator::add(bool integer)
{
  IsInteger.push_back(integer);
  Eliminated.push_back(0);
  Substitute.emplace_back();
  Full.emplace_back();
  Partial.emplace_back();
  PartialDone.push_back(0);
  return static_cast<int>(IsInteger.size()) - 1;
}

const Expr& Eliminator::resolve(int x)
{
  if (!Eliminated[x])
  {
    Identity = { { x, 1.0 } };
    return Identity;
  }
  Expr& e = Full[x];
  bool stale = false;
  for (const auto& t : e)
  {
    stale = stale || Eliminated[t.first];
  }
  if (stale)
  {
    Expr out;
    const Expr copy = e;
    for (const auto& t : copy)
    {
      if (!Eliminated[t.first])
      {
        out.push_back(t);
      }
      else
      {
        const Expr& sub = resolve(t.first);
        for (const auto& s : sub)
        {
          out.emplace_back(s.first, s.second * t.second);
        }
      }
    }
    normalize(out);
    Full[x] = std::move(out);
  }
  return Full[x];
}

const Expr& Eliminator::resolveReals(int x)
{
  if (!Eliminated[x] || IsInteger[x])
  {
    Identity = { { x, 1.0 } };
    return Identity;
  }
  if (!PartialDone[x])
  {
    Expr out;
    for (const auto& t : Substitute[x])
    {
      if (Eliminated[t.first] && !IsInteger[t.first])
      {
        const Expr sub = resolveReals(t.first);
        for (const auto& u : sub)
        {
          out.emplace_back(u.first, u.second * t.second);
        }
      }
      else
      {
        out.push_back(t);
      }
    }
    normalize(out);
    Partial[x] = std::move(out);
    PartialDone[x] = 1;
  }
  return Partial[x];
}

Expr Eliminator::resolve(const Expr& e)
{
  Expr out;
  for (const auto& t : e)
  {
    const Expr& sub = resolve(t.first);
    for (const auto& s : sub)
    {
      out.emplace_back(s.first, s.second * t.second);
    }
  }
  normalize(out);
  return out;
}

int Eliminator::choosePivot(const Expr& e)
{
  int pivot = -1;
  for (std::size_t i = 0; i < e.size(); ++i) // a real unknown, the largest coefficient
  {
    if (!IsInteger[e[i].first] && (pivot < 0 || std::abs(e[i].second) >= std::abs(e[pivot].second)))
    {
      pivot = static_cast<int>(i);
    }
  }
  if (pivot < 0) // integers only: one with coefficient +-1, the newest
  {
    for (std::size_t i = 0; i < e.size(); ++i)
    {
      if (std::abs(std::abs(e[i].second) - 1.0) < 1e-9)
      {
        pivot = static_cast<int>(i);
      }
    }
  }
  if (pivot < 0)
  {
    ++NonUnitPivots;

    for (std::size_t i = 0; i < e.size(); ++i)
    {
      if (pivot < 0 || std::abs(e[i].second) > std::abs(e[pivot].second))
      {
        pivot = static_cast<int>(i);
      }
    }
  }
  return pivot;
}

void Eliminator::constrain(const Expr& c)
{
  ++Constraints;
  Expr e = resolve(c);
  if (e.empty())
  {
    return; // implied by earlier constraints
  }
  // Integer coefficients with a common divisor (2 (x + y - z) = 0, as the cycles around the
  // branch points of a sphere add up to): divide it out, so a coefficient +-1 appears.
  long divisor = 0;
  for (const auto& t : e)
  {
    const double rounded = std::round(t.second);
    divisor = std::abs(t.second - rounded) < 1e-9 && divisor >= 0
      ? std::gcd(divisor, std::abs(static_cast<long>(rounded)))
      : -1;
  }
  if (divisor > 1)
  {
    for (auto& t : e)
    {
      t.second /= static_cast<double>(divisor);
    }
  }
  const int pivot = choosePivot(e);
  const int x = e[pivot].first;
  const double a = e[pivot].second;
  Expr sub;
  for (std::size_t i = 0; i < e.size(); ++i)
  {
    if (static_cast<int>(i) != pivot)
    {
      sub.emplace_back(e[i].first, -e[i].second / a);
    }
  }
  Eliminated[x] = 1;
  Full[x] = sub;
  Substitute[x] = std::move(sub);
}
}
}
