// QuadOverlaps.cxx: removeOverlappingQuads, the clean-up of the quads a folded map overlaps.
#include "QuadOverlaps.h"

#include "QuadExtraction.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>
#include <vector>

namespace quadcover
{

int removeOverlappingQuads(std::vector<std::array<int, 4>>& quads, std::vector<int>& owner)
{
  return removeOverlappingQuads(quads, owner, Progress());
}

int removeOverlappingQuads(
  std::vector<std::array<int, 4>>& quads, std::vector<int>& owner, const Progress& progress)
{
  if (owner.size() != quads.size())
  {
    throw std::invalid_argument("removeOverlappingQuads: one owner per quad expected");
  }
  // three passes over the quads (each a sixteenth at a time): repeats, edges, the manifold rest
  const std::size_t stride = std::max<std::size_t>(1, quads.size() / 16);
  auto tick = [&](int pass, std::size_t i) {
    if (i % stride == 0)
    {
      progress.report((pass + static_cast<double>(i) / quads.size()) / 3.0);
    }
  };
  // repeats: the same cell from another triangle holding its centre; the first one stays
  std::vector<std::pair<std::array<int, 4>, int>> cells(quads.size());
  for (std::size_t i = 0; i < quads.size(); ++i)
  {
    tick(0, i);
    std::array<int, 4> key = quads[i];
    std::rotate(key.begin(), std::min_element(key.begin(), key.end()), key.end());
    cells[i] = { key, static_cast<int>(i) };
  }
  std::sort(cells.begin(), cells.end());
  std::vector<char> keep(quads.size(), 1);
  for (std::size_t j = 1; j < cells.size(); ++j)
  {
    if (cells[j].first == cells[j - 1].first)
    {
      keep[cells[j].second] = 0;
    }
  }
  // the kept quads' edges, directed and not, sorted to be counted
  std::vector<std::pair<int, int>> directed, undirected;
  directed.reserve(4 * quads.size());
  undirected.reserve(4 * quads.size());
  for (std::size_t i = 0; i < quads.size(); ++i)
  {
    tick(1, i);
    for (int k = 0; k < 4 && keep[i]; ++k)
    {
      const int a = quads[i][k], b = quads[i][(k + 1) % 4];
      directed.emplace_back(a, b);
      undirected.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(directed.begin(), directed.end());
  std::sort(undirected.begin(), undirected.end());
  const auto count = [](const std::vector<std::pair<int, int>>& list, std::pair<int, int> e) {
    const auto range = std::equal_range(list.begin(), list.end(), e);
    return range.second - range.first;
  };
  int removed = 0;
  std::vector<std::array<int, 4>> kept;
  std::vector<int> keptOwner;
  for (std::size_t i = 0; i < quads.size(); ++i)
  {
    tick(2, i);
    for (int k = 0; k < 4 && keep[i]; ++k)
    {
      const int a = quads[i][k], b = quads[i][(k + 1) % 4];
      if (count(directed, { a, b }) > 1 ||
        count(undirected, { std::min(a, b), std::max(a, b) }) > 2)
      {
        keep[i] = 0;
        ++removed;
      }
    }
    if (keep[i])
    {
      kept.push_back(quads[i]);
      keptOwner.push_back(owner[i]);
    }
  }
  quads.swap(kept);
  owner.swap(keptOwner);
  progress.report(1.0);
  return removed;
}

}
