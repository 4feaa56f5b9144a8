// The catalogue of generated test surfaces shared by the core tests.
#ifndef quadcover_TestSurfaces_h
#define quadcover_TestSurfaces_h

#include "Surfaces.h"

#include <stdexcept>
#include <string>

namespace quadcover
{
/// Moderate resolutions: every core test over the catalogue stays well under a second.
inline Surface testSurface(const std::string& name)
{
  if (name == "torus")
    return makeTorus(1.0, 0.4, 96, 48);
  if (name == "sphere")
    return makeIcosphere(1.0, 4);
  if (name == "cylinder")
    return makeCylinder(0.5, 2.0, 48, 40);
  if (name == "saddle")
    return makeSaddle(1.0, 0.5, 40);
  if (name == "knot")
    return makeKnotTube(2, 3, 1.0, 0.4, 0.12, 240, 20, 0.3, 0.03, 7);
  if (name == "roundedcube")
    return makeRoundedCube(0.3, 20);
  throw std::invalid_argument("unknown test surface " + name);
}
}

#endif
