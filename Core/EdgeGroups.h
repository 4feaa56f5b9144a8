// EdgeGroups.h: internal to Core: the corners of a triangle mesh grouped by the edge they start
// (the repair's pairing of sheets, its search for T-junctions).
#ifndef quadcover_EdgeGroups_h
#define quadcover_EdgeGroups_h

#include <Eigen/Core>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace quadcover
{
/// The corners 3f+k of every edge, grouped: edge k of face f runs F(f,k) -> F(f,k+1).
struct EdgeGroups
{
  std::vector<int> corners; ///< sorted by the edge's point pair, then by corner
  std::vector<int> offsets; ///< group g is corners[offsets[g] .. offsets[g+1])
};

inline int tail(const Eigen::MatrixX3i& F, int c)
{
  return F(c / 3, c % 3);
}

inline int head(const Eigen::MatrixX3i& F, int c)
{
  return F(c / 3, (c % 3 + 1) % 3);
}

inline EdgeGroups groupEdges(const Eigen::MatrixX3i& F)
{
  const int nc = 3 * static_cast<int>(F.rows());
  // (the edge's point pair as one number, the corner), sorted: contiguous keys sort several
  // times faster than keys looked up in F at every comparison
  std::vector<std::pair<std::uint64_t, int>> keyed(nc);
  for (int c = 0; c < nc; ++c)
  {
    const int p = tail(F, c), q = head(F, c);
    const auto low = static_cast<std::uint64_t>(static_cast<std::uint32_t>(std::min(p, q)));
    const auto high = static_cast<std::uint64_t>(static_cast<std::uint32_t>(std::max(p, q)));
    keyed[c] = { (low << 32) | high, c };
  }
  std::sort(keyed.begin(), keyed.end());
  EdgeGroups groups;
  groups.corners.resize(nc);
  for (int i = 0; i < nc; ++i)
  {
    groups.corners[i] = keyed[i].second;
    if (i == 0 || keyed[i].first != keyed[i - 1].first)
    {
      groups.offsets.push_back(i);
    }
  }
  groups.offsets.push_back(nc);
  return groups;
}

}

#endif
