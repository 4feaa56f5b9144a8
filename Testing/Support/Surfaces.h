// Surfaces.h: surfaces the project generates for its tests, benchmarks and Data/, with their
// analytic principal curvatures where they are known.
#ifndef quadcover_Surfaces_h
#define quadcover_Surfaces_h

#include <Eigen/Core>

#include <string>
#include <vector>

namespace quadcover
{

/// A generated triangle surface. kappa and direction1 are per vertex, analytic values of the
/// exact (noise-free) surface at the vertex's parameters; empty when unknown.
struct Surface
{
  std::string name;
  Eigen::MatrixX3d V;          ///< #V x 3
  Eigen::MatrixX3i F;          ///< #F x 3, counterclockwise seen from outside
  Eigen::MatrixX2d kappa;      ///< #V x 2 (kappa1 >= kappa2), sign as in CurvatureField
  Eigen::MatrixX3d direction1; ///< #V x 3 unit direction of kappa1
};

/// Torus around the z axis, radii R > r, nu segments around z, nv around the tube.
Surface makeTorus(double R, double r, int nu, int nv);

/// Sphere from a subdivided icosahedron (20 * 4^level triangles).
Surface makeIcosphere(double radius, int level);

/// The mean length of s's triangles' edges (each inner edge counted from both sides; 0 without
/// triangles).
double meanEdgeLength(const Surface& s);

/// `s` with every coordinate of every point moved by a normal deviate of `noise` mean edge
/// lengths (Box-Muller on mt19937: the same surface on every platform), as a rough scan; its
/// curvatures dropped.
Surface withNoise(const Surface& s, double noise, unsigned seed);

/// Open cylinder around the z axis, height h centred at 0: two boundary loops.
Surface makeCylinder(double r, double h, int nAround, int nAlong);

/// Saddle z = (x^2 - y^2) / (2 a) over [-s, s]^2 with n x n quads (one boundary loop). Its
/// principal curvatures at the origin are +-1/a.
Surface makeSaddle(double a, double s, int n);

/// Tube of radius `tube` around the (p, q) torus knot with radii R, rKnot. With jitter > 0 the
/// parameter grid is displaced at random (jitter in cells, < 0.5) and every quad split along a
/// random diagonal; with noise > 0 every vertex moves along the tube's normal by a random amount
/// up to noise * tube. Deterministic for a given seed.
Surface makeKnotTube(int p, int q, double R, double rKnot, double tube, int nAlong, int nAround,
  double jitter, double noise, unsigned seed);

/// Axis-aligned cube [-1,1]^3 with edges rounded at radius `round` (0 <= round < 1; 0 gives the
/// sharp cube of the paper's Fig. 4): a closed
/// surface with flat faces, cylindrical edges and spherical corners, made by pushing an n x n
/// grid on each face of the cube onto the rounded surface.
Surface makeRoundedCube(double round, int n);

/// `count` separate closed surfaces in a row along x, spheres (icosphere level 2) and tori
/// (R = size, r = 0.35 size, 20 x 10) in turn, their sizes growing geometrically from rMin to
/// rMax, each 0.1 + 0.1 size away from the last: one file of components of very different sizes.
Surface makeComponents(int count, double rMin, double rMax);

// ---- the stress surfaces (StressSurfaces.cxx) ----

/// A closed surface of revolution around z from -length to length whose radius goes from `bulb`
/// to `neck` at the middle and back (a tube whose width varies, closed at the poles), with
/// nAround points on each of nAlong - 1 rings.
Surface makeDumbbell(double length, double bulb, double neck, int nAround, int nAlong);

/// The closed surface of a union of grid cells of size cellSize (the cells meet face to face, not
/// only along an edge), each face cut into squares of about `edge` and each square into two
/// triangles: a CAD-like part with convex and concave right-angle creases, of any genus.
Surface makeBlocks(
  const std::vector<Eigen::Vector3i>& cells, const Eigen::Vector3d& cellSize, double edge);

/// A box width x depth x thickness (makeBlocks of one cell): a plate thinner than a quad.
Surface makeThinPlate(double width, double depth, double thickness, double edge);

/// A square frame 2 x 2 x 0.02 around a 1 x 1 hole (makeBlocks; genus 1): a thin plate with a
/// hole, its rims walls lower than the quads.
Surface makeThinFrame(double edge);

/// A square frame with a hole, a wall along one side and a tab on it (makeBlocks; genus 1).
Surface makeBracket(double edge);

/// A turned part: the closed surface of revolution around z of a profile of points (r, z) from
/// the axis back to the axis (r = 0 at the first and last point only), sharp at every point of
/// the profile, so that its creases are circles and its flat steps annuli (curved creases, as on
/// a CAD part's turned features). Rings about `edge` apart along the profile, each of about
/// 2 pi r / edge points (at least 8), neighbouring rings zipped by angle.
Surface makeTurnedPart(const std::vector<Eigen::Vector2d>& profile, double edge);

/// A shaft of three steps (radii 1, 0.7, 0.4; makeTurnedPart).
Surface makeSteppedShaft(double edge);
}

#endif
