// SurfaceLocator.h: the point of a triangle surface closest to any point in space (a uniform grid
// of the triangles' boxes), and the closest points on a segment and on a triangle.
#ifndef quadcover_SurfaceLocator_h
#define quadcover_SurfaceLocator_h

#include <Eigen/Core>

#include <limits>
#include <stdexcept>
#include <vector>

namespace quadcover
{

/// The point of segment (a, b) closest to p.
Eigen::Vector3d closestOnSegment(
  const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b);

/// The point of triangle (a, b, c) closest to p (of its edges where it is degenerate).
Eigen::Vector3d closestOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
  const Eigen::Vector3d& b, const Eigen::Vector3d& c);

/**
 * Finds the closest point of a triangle surface to any point in space, over all its triangles
 * (whatever their component): a uniform grid of cells of about the mean edge length, each listing
 * the triangles whose bounding box meets it, searched in growing shells of cells. Triangles of
 * zero area are left out (their points lie on their neighbours' edges). Deterministic: ties go
 * to the lowest triangle index.
 */
class SurfaceLocator
{
public:
  struct Hit
  {
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    int triangle = -1; ///< -1 when the surface has no triangle of positive area
    double distance = std::numeric_limits<double>::infinity();
  };

  /// @param[in] V #V x 3 points @param[in] F #F x 3 triangles (indices checked by the caller)
  SurfaceLocator(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F);

  /// The closest point of the surface to p, its triangle and distance.
  Hit closest(const Eigen::Vector3d& p) const;

  /// The triangles (of positive area) whose closest point to p lies within `slack` of the
  /// closest one's distance: the candidates for "the" closest triangle where there are ties
  /// (a point above a crease, or where two components cross), in index order.
  std::vector<int> nearlyClosest(const Eigen::Vector3d& p, double slack) const;

  /// Labels the triangles with their components (#F, MeshTopology::faceComponent), for
  /// component(); without labels every triangle is in component -1. Throws
  /// std::invalid_argument unless there is one label a triangle.
  void setComponents(const Eigen::VectorXi& faceComponent)
  {
    if (faceComponent.size() != F_.rows())
    {
      throw std::invalid_argument("SurfaceLocator::setComponents: one label a triangle is needed");
    }
    components_ = faceComponent;
  }
  /// The component of triangle t (-1 when the triangles are not labelled).
  int component(int t) const { return components_.size() > 0 ? components_[t] : -1; }
  /// The unit normal of triangle t (zero for a triangle of zero area).
  Eigen::Vector3d normal(int t) const { return normals_.row(t).transpose(); }

  int numTriangles() const { return static_cast<int>(F_.rows()); }

  /// The point of triangle t closest to p.
  Eigen::Vector3d closestIn(int t, const Eigen::Vector3d& p) const;

  /// A lower bound of the distance from p to triangle t (its bounding sphere's), cheap.
  double lowerBound(int t, const Eigen::Vector3d& p) const
  {
    return (p - centres_.row(t).transpose()).norm() - radii_[t];
  }

  /// Whether triangle t lies farther from p than `bound` by its bounding sphere, without a
  /// square root: true only where lowerBound(t, p) > bound would be too, with room for rounding
  /// (so that a search pruned by it measures the same triangles or a few more, and finds the
  /// same).
  bool beyond(int t, const Eigen::Vector3d& p, double bound) const
  {
    const double reach = bound + radii_[t];
    return (p - centres_.row(t).transpose()).squaredNorm() > reach * reach * (1.0 + 1e-12);
  }

private:
  Eigen::Vector3i cellOf(const Eigen::Vector3d& p) const;
  int cellIndex(int x, int y, int z) const { return (z * size_[1] + y) * size_[0] + x; }
  /// Calls visit(t) for every triangle listed in the cells of Chebyshev distance `ring` from
  /// `centre`; false when the ring lies wholly outside the grid.
  template <typename Visit>
  bool visitRing(const Eigen::Vector3i& centre, int ring, Visit&& visit) const;
  /// A lower bound of the distance from p to any triangle not listed within `ring` of centre.
  double beyondRing(const Eigen::Vector3d& p, const Eigen::Vector3i& centre, int ring) const;

  const Eigen::MatrixX3d& V_;
  const Eigen::MatrixX3i& F_;
  Eigen::MatrixX3d normals_;
  Eigen::MatrixX3d centres_; ///< #F x 3: the centroids
  Eigen::VectorXd radii_;    ///< #F: the centroids' largest distance to a corner
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  double cell_ = 1.0;
  Eigen::Vector3i size_ = Eigen::Vector3i::Ones();
  Eigen::VectorXi components_; ///< #F, or empty: see setComponents
  std::vector<int> offsets_;   ///< per cell + 1: where its triangles start in triangles_
  std::vector<int> triangles_; ///< the triangles of each cell, one cell after the other
};

}

#endif
