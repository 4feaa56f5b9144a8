// UnionFind.h: disjoint sets over 0..n-1 (path halving; the smaller root wins, so labels are
// deterministic).
#ifndef quadcover_UnionFind_h
#define quadcover_UnionFind_h

#include <algorithm>
#include <vector>

namespace quadcover
{
inline int findRoot(std::vector<int>& parent, int x)
{
  while (parent[x] != x)
  {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

inline void unite(std::vector<int>& parent, int a, int b)
{
  a = findRoot(parent, a);
  b = findRoot(parent, b);
  if (a != b)
  {
    parent[std::max(a, b)] = std::min(a, b);
  }
}
}

#endif
