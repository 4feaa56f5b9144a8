// vtkQuadCoverEigen.h (private): copies between vtkPolyData/vtkDataArray and the core's Eigen
// matrices, the core's progress forwarded to an algorithm, and a stage's checked input. Not
// wrapped or installed (Eigen types must stay out of the public, wrapped headers); the tests
// and benchmarks use it too.
#ifndef vtkQuadCoverEigen_h
#define vtkQuadCoverEigen_h

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include "MeshTopology.h"
#include "Progress.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <initializer_list>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace vtkQuadCoverEigen
{
/// #V x 3 point coordinates.
inline Eigen::MatrixX3d Points(vtkPolyData* pd)
{
  const vtkIdType n = pd->GetNumberOfPoints();
  Eigen::MatrixX3d V(n, 3);
  double p[3];
  for (vtkIdType i = 0; i < n; ++i)
  {
    pd->GetPoint(i, p);
    V.row(i) << p[0], p[1], p[2];
  }
  return V;
}

/// #F x 3 from the polys of a polydata holding only triangles (checked by the caller).
inline Eigen::MatrixX3i Triangles(vtkPolyData* pd)
{
  vtkCellArray* polys = pd->GetPolys();
  Eigen::MatrixX3i F(polys->GetNumberOfCells(), 3);
  vtkNew<vtkIdList> ids;
  vtkIdType f = 0;
  for (polys->InitTraversal(); polys->GetNextCell(ids);)
  {
    for (int k = 0; k < 3; ++k)
    {
      F(f, k) = static_cast<int>(ids->GetId(k));
    }
    ++f;
  }
  return F;
}

/// A new surface of double points V and triangles F.
inline vtkSmartPointer<vtkPolyData> ToPolyData(const Eigen::MatrixX3d& V, const Eigen::MatrixX3i& F)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(V.rows());
  for (Eigen::Index i = 0; i < V.rows(); ++i)
  {
    points->SetPoint(i, V(i, 0), V(i, 1), V(i, 2));
  }
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(F.rows(), 3 * F.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f)
  {
    const vtkIdType ids[3] = { F(f, 0), F(f, 1), F(f, 2) };
    polys->InsertNextCell(3, ids);
  }
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(points);
  pd->SetPolys(polys);
  return pd;
}

/**
 * The attributes of `given` carried onto `refined`, a refinement of it by midpoints
 * (quadcover::refineCoarseComponents, refineLongEdges): point data copied for given's points
 * (refined's first ones) and interpolated at each added point from its weights on them (a
 * midpoint of midpoints weighs the original points), cell data copied from each triangle's
 * parent.
 */
inline void CarryRefinedAttributes(vtkPolyData* given,
  const std::vector<std::array<int, 2>>& midpoints, const std::vector<int>& parent,
  vtkPolyData* refined)
{
  const vtkIdType nv = given->GetNumberOfPoints();
  std::vector<std::map<vtkIdType, double>> weights(midpoints.size());
  auto weightsOf = [&](int p) {
    return p < nv ? std::map<vtkIdType, double>{ { p, 1.0 } } : weights[p - nv];
  };
  vtkNew<vtkPointData> pointData;
  pointData->InterpolateAllocate(given->GetPointData(), nv + vtkIdType(midpoints.size()));
  for (vtkIdType p = 0; p < nv; ++p)
  {
    pointData->CopyData(given->GetPointData(), p, p);
  }
  vtkNew<vtkIdList> ids;
  std::vector<double> w;
  for (std::size_t i = 0; i < midpoints.size(); ++i)
  {
    for (const int end : midpoints[i])
    {
      for (const auto& [p, x] : weightsOf(end))
      {
        weights[i][p] += 0.5 * x;
      }
    }
    ids->Reset();
    w.clear();
    for (const auto& [p, x] : weights[i])
    {
      ids->InsertNextId(p);
      w.push_back(x);
    }
    pointData->InterpolatePoint(given->GetPointData(), nv + vtkIdType(i), ids, w.data());
  }
  vtkNew<vtkCellData> cellData;
  cellData->CopyAllocate(given->GetCellData(), vtkIdType(parent.size()));
  for (std::size_t t = 0; t < parent.size(); ++t)
  {
    cellData->CopyData(given->GetCellData(), parent[t], vtkIdType(t));
  }
  refined->GetPointData()->ShallowCopy(pointData);
  refined->GetCellData()->ShallowCopy(cellData);
}

/// A new array of type ArrayT (vtkDoubleArray unless given) named `name` with the rows of M as
/// tuples.
template<typename ArrayT = vtkDoubleArray, typename Derived>
vtkSmartPointer<ArrayT> ToArray(const Eigen::MatrixBase<Derived>& M, const char* name)
{
  auto a = vtkSmartPointer<ArrayT>::New();
  a->SetName(name);
  a->SetNumberOfComponents(static_cast<int>(M.cols()));
  a->SetNumberOfTuples(M.rows());
  for (Eigen::Index i = 0; i < M.rows(); ++i)
  {
    for (Eigen::Index j = 0; j < M.cols(); ++j)
    {
      a->SetTypedComponent(
        i, static_cast<int>(j), static_cast<typename ArrayT::ValueType>(M(i, j)));
    }
  }
  return a;
}

/// Adds a field-data array `name` of type ArrayT holding `values` (one component).
template<typename ArrayT>
void AddField(vtkFieldData* fd, const char* name, const std::vector<double>& values)
{
  vtkNew<ArrayT> a;
  a->SetName(name);
  for (double v : values)
  {
    a->InsertNextTuple1(v);
  }
  fd->AddArray(a);
}

/// #tuples x #components of any data array.
inline Eigen::MatrixXd FromArray(vtkDataArray* a)
{
  Eigen::MatrixXd M(a->GetNumberOfTuples(), a->GetNumberOfComponents());
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    for (int j = 0; j < a->GetNumberOfComponents(); ++j)
    {
      M(i, j) = a->GetComponent(i, j);
    }
  }
  return M;
}

/// #tuples x 3 from a 3-component array.
inline Eigen::MatrixX3d FromArray3(vtkDataArray* a)
{
  return FromArray(a);
}

/// Throws "NAME is not a number" for the first of the properties that is NaN: vtkSetClampMacro
/// lets NaN through (it compares false with both bounds), from Python or ParaView as from C++.
inline void RequireNumbers(std::initializer_list<std::pair<const char*, double>> properties)
{
  for (const auto& [name, value] : properties)
  {
    if (std::isnan(value))
    {
      throw std::invalid_argument(std::string(name) + " is not a number");
    }
  }
}

/// A Core progress that forwards to `algorithm`'s UpdateProgress, mapped into [begin, end] and
/// at most once per 1%, and stops the computation (quadcover::Cancelled) once AbortExecute is
/// set.
inline quadcover::Progress CoreProgress(vtkAlgorithm* algorithm, double begin, double end)
{
  auto last = std::make_shared<double>(-1.0);
  return quadcover::Progress([algorithm, begin, end, last](double fraction) {
    const double p = begin + (end - begin) * fraction;
    if (p >= *last + 0.01 || (fraction >= 1.0 && p > *last))
    {
      *last = p;
      algorithm->UpdateProgress(p);
    }
    return !algorithm->GetAbortExecute();
  });
}
}

/**
 * A stage's input once vtkQuadCoverAlgorithm has checked it (see its InputRequirement): the
 * surface of triangles (the input itself when it held nothing else) and the core's view of it.
 *
 * V is the input's points times 2^ScaleExponent (vtkQuadCoverInput::UnitScaleExponent): 0 for
 * an ordinary size, else the power of two that brings the surface to about unit size, so that a
 * surface of 1e-160 or 1e150 has lengths, areas and curvatures well inside double's range and
 * the core's tolerances see what they were made for. Scaling by a power of two is exact, and so
 * is the way back: a stage passes lengths given by the user through InCoreUnits and everything
 * it writes that has units (points, lengths, areas, curvatures) through InWorldUnits; what is
 * dimensionless (directions, angles, (u, v), ratios, counts) is the same either way. polyData
 * keeps the input's own points.
 */
struct vtkQuadCoverSurface
{
  vtkSmartPointer<vtkPolyData> polyData;
  Eigen::MatrixX3d V;           ///< #V x 3, scaled (not filled for ANY_POLYDATA)
  Eigen::MatrixX3i F;           ///< #F x 3
  quadcover::MeshTopology topo; ///< buildTopology(F, #V)
  int ScaleExponent = 0;        ///< V = the input's points * 2^ScaleExponent
  vtkIdType NumberOfTriangles() const { return this->F.rows(); }

  /// A quantity of the dimension length^power computed on V, in the input's units (power 1:
  /// lengths and points, 2: areas, -1: curvatures).
  double InWorldUnits(double x, int power = 1) const
  {
    return std::ldexp(x, -power * this->ScaleExponent);
  }
  /// The same for every entry of a matrix.
  template<typename Derived>
  Eigen::MatrixXd InWorldUnits(const Eigen::MatrixBase<Derived>& M, int power = 1) const
  {
    return M.unaryExpr([this, power](double x) { return this->InWorldUnits(x, power); });
  }
  /// A quantity of the dimension length^power in the input's units (a property the user set), in
  /// the units of V.
  double InCoreUnits(double x, int power = 1) const
  {
    return std::ldexp(x, power * this->ScaleExponent);
  }
  /// The same for every entry of a matrix.
  template<typename Derived>
  Eigen::MatrixXd InCoreUnits(const Eigen::MatrixBase<Derived>& M, int power = 1) const
  {
    return M.unaryExpr([this, power](double x) { return this->InCoreUnits(x, power); });
  }
};

#endif
// VTK-HeaderTest-Exclude: vtkQuadCoverEigen.h