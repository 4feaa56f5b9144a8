// QuadOverlaps.h: removeOverlappingQuads with progress reports, for extractQuads (internal to
// Core).
#ifndef quadcover_QuadOverlaps_h
#define quadcover_QuadOverlaps_h

#include "Progress.h"

#include <array>
#include <vector>

namespace quadcover
{
/// removeOverlappingQuads (QuadExtraction.h), reporting through its three passes over the quads.
int removeOverlappingQuads(
  std::vector<std::array<int, 4>>& quads, std::vector<int>& owner, const Progress& progress);
}

#endif
