// vtkQuadCoverEigen.h (private): copies between vtkPolyData/vtkDataArray and the core's Eigen
// matrices. Not wrapped or installed (Eigen types must stay out of the public, wrapped headers);
// the in-tree command line, tests and benchmarks use it too.
#ifndef vtkQuadCoverEigen_h
#define vtkQuadCoverEigen_h

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include "MeshTopology.h"
#include "vtkQuadCoverInput.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <initializer_list>
#include <string>

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

/// A new double array named `name` with the rows of M as tuples.
template<typename Derived>
vtkSmartPointer<vtkDoubleArray> ToArray(const Eigen::MatrixBase<Derived>& M, const char* name)
{
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(static_cast<int>(M.cols()));
  a->SetNumberOfTuples(M.rows());
  for (Eigen::Index i = 0; i < M.rows(); ++i)
  {
    for (Eigen::Index j = 0; j < M.cols(); ++j)
    {
      a->SetTypedComponent(i, static_cast<int>(j), M(i, j));
    }
  }
  return a;
}

/// Adds a field-data array `name` of type ArrayT holding `values` (one component).
template<typename ArrayT>
void AddField(vtkFieldData* fd, const char* name, std::initializer_list<double> values)
{
  vtkNew<ArrayT> a;
  a->SetName(name);
  for (double v : values)
  {
    a->InsertNextTuple1(v);
  }
  fd->AddArray(a);
}

/// #tuples x 3 from a 3-component array.
inline Eigen::MatrixX3d FromArray3(vtkDataArray* a)
{
  Eigen::MatrixX3d M(a->GetNumberOfTuples(), 3);
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      M(i, j) = a->GetComponent(i, j);
    }
  }
  return M;
}

/// "" when `a` has 3 components and one tuple per triangle (#F = nf), else the one-line reason:
/// "the input has no 3-component cell array NAME (HINT)".
inline std::string CheckCellArray3(
  vtkDataArray* a, vtkIdType nf, const char* name, const char* hint)
{
  if (a && a->GetNumberOfComponents() == 3 && a->GetNumberOfTuples() == nf)
  {
    return "";
  }
  return std::string("the input has no 3-component cell array ") + name + " (" + hint + ")";
}

/// A triangle surface as the core sees it.
struct Mesh
{
  Eigen::MatrixX3d V;
  Eigen::MatrixX3i F;
  quadcover::MeshTopology topo;
};

/// What a stage needs of the surface's connectivity.
enum class Needs
{
  ManifoldEdges,   ///< at most two triangles per edge, consistently oriented
  ManifoldSurface, ///< and every vertex's triangles one fan (ordered one-rings)
};

/**
 * The check every filter starts with: triangulates `input` into `surface` (see
 * vtkQuadCoverInput::Triangulate), copies it into `mesh` and checks its connectivity.
 * @return "" or a one-line reason; `warning` gets what was dropped or is doubtful.
 */
inline std::string Load(
  vtkPolyData* input, vtkPolyData* surface, Mesh& mesh, Needs needs, std::string& warning)
{
  std::string problem = vtkQuadCoverInput::Triangulate(input, surface, warning);
  if (!problem.empty())
  {
    return problem;
  }
  mesh.V = Points(surface);
  mesh.F = Triangles(surface);
  mesh.topo = quadcover::buildTopology(mesh.F, static_cast<int>(mesh.V.rows()));
  const quadcover::MeshTopology& T = mesh.topo;
  const bool vertices = needs == Needs::ManifoldSurface;
  if (!T.degenerateFaces.empty() || !T.nonManifoldEdges.empty() || !T.misorientedEdges.empty() ||
    (vertices && !T.nonManifoldVertices.empty()))
  {
    return "the surface has " + T.describeDefects() +
      "; merge duplicate points, remove non-manifold parts (split non-manifold vertices) and "
      "orient the triangles consistently first (the quadcover command line does all this)";
  }
  if (!T.nonManifoldVertices.empty())
  {
    warning += std::string(warning.empty() ? "" : "; ") +
      std::to_string(T.nonManifoldVertices.size()) +
      " non-manifold vertices (fans of triangles touching at one vertex); later stages need them "
      "split";
  }
  return "";
}
}

#endif
// VTK-HeaderTest-Exclude: vtkQuadCoverEigen.h