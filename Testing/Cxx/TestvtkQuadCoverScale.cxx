// Every stage at any size: vtkQuadCoverAlgorithm computes on a surface of a size out of the
// ordinary scaled by a power of two to about unit size, and converts back whatever has units. A
// surface of unit size and its copies scaled by 2^-400 and 2^400 (where squared lengths
// underflow or overflow) must give the same outputs, those with units scaled by the same power:
// exactly, since the core sees the same bits.
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCurvatureFrames.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFrameSmoother.h"
#include "vtkMatchingBuilder.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkQuadCoverArrayNames.h"
#include "vtkQuadCoverEigen.h"
#include "vtkQuadCoverErrorObserver.h"
#include "vtkQuadCoverSolver.h"
#include "vtkQuadCoverSurfaceRepair.h"
#include "vtkQuadExtractor.h"

#include "Surfaces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{
namespace names = vtkQuadCoverArrayNames;

/// The arrays with units: their dimension in length (every other array is dimensionless).
const std::map<std::string, int> Dimension = { { names::PrincipalCurvatures, -1 },
  { names::CurvatureRadius, 1 }, { names::SmoothingEnergy, 2 }, { names::EdgeLength, 1 } };

/// The six stages on a rounded cube whose largest side is in [1, 2), scaled by 2^exponent, with
/// the quads' edge length 0.08 * 2^exponent; a second solver cuts the surface open along its
/// seams.
struct ScaledChain
{
  vtkNew<vtkQuadCoverSurfaceRepair> repair;
  vtkNew<vtkCurvatureFrames> curvature;
  vtkNew<vtkFrameSmoother> smoother;
  vtkNew<vtkMatchingBuilder> matching;
  vtkNew<vtkQuadCoverSolver> solver;
  vtkNew<vtkQuadCoverSolver> splitSolver;
  vtkNew<vtkQuadExtractor> extractor;
  vtkNew<vtkQuadCoverErrorObserver> errors;

  explicit ScaledChain(int exponent)
  {
    quadcover::Surface s = quadcover::makeRoundedCube(0.3, 12);
    const double side = (s.V.colwise().maxCoeff() - s.V.colwise().minCoeff()).maxCoeff();
    const int e = exponent - std::ilogb(side); // 2^-ilogb(side) brings it into [1, 2)
    s.V = s.V.unaryExpr([e](double x) { return std::ldexp(x, e); });
    repair->SetInputData(vtkQuadCoverEigen::ToPolyData(s.V, s.F));
    curvature->SetInputConnection(repair->GetOutputPort());
    smoother->SetInputConnection(curvature->GetOutputPort());
    matching->SetInputConnection(smoother->GetOutputPort());
    solver->SetInputConnection(matching->GetOutputPort());
    solver->SetTargetEdgeLength(std::ldexp(0.08, exponent));
    splitSolver->SetInputConnection(matching->GetOutputPort());
    splitSolver->SetTargetEdgeLength(std::ldexp(0.08, exponent));
    splitSolver->SplitSeamsOn();
    extractor->SetInputConnection(solver->GetOutputPort());
    extractor->SetRelaxationIterations(3);
    for (vtkAlgorithm* a : std::initializer_list<vtkAlgorithm*>{
           repair, curvature, smoother, matching, solver, splitSolver, extractor })
    {
      errors->Attach(a);
    }
  }

  /// Every output, named.
  std::vector<std::pair<std::string, vtkPolyData*>> Outputs()
  {
    extractor->Update();
    splitSolver->Update();
    return { { "repair", repair->GetOutput() }, { "curvature", curvature->GetOutput() },
      { "smoother", smoother->GetOutput() }, { "matching", matching->GetOutput() },
      { "branch points", matching->GetBranchPointsOutput() }, { "solver", solver->GetOutput() },
      { "split solver", splitSolver->GetOutput() }, { "extractor", extractor->GetOutput() } };
  }
};

/// "" when `scaled` holds `unit`'s values times 2^(dimension * exponent), exactly; else the first
/// difference.
std::string CompareArray(vtkDataArray* unit, vtkDataArray* scaled, int dimension, int exponent)
{
  if (!scaled || unit->GetNumberOfTuples() != scaled->GetNumberOfTuples() ||
    unit->GetNumberOfComponents() != scaled->GetNumberOfComponents())
  {
    return "missing, or of another shape";
  }
  for (vtkIdType i = 0; i < unit->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < unit->GetNumberOfComponents(); ++c)
    {
      const double want = std::ldexp(unit->GetComponent(i, c), dimension * exponent);
      const double got = scaled->GetComponent(i, c);
      if (!(got == want || (std::isnan(got) && std::isnan(want))))
      {
        std::ostringstream out;
        out.precision(17);
        out << "tuple " << i << " component " << c << ": " << got << ", expected " << want;
        return out.str();
      }
    }
  }
  return "";
}

/// Expects `scaled` to be `unit` with its points and the arrays of Dimension scaled by 2^exponent
/// (to their dimension), all else equal; the names of the arrays with units go to `seen`.
void ExpectScaled(vtkPolyData* unit, vtkPolyData* scaled, int exponent, std::set<std::string>& seen)
{
  ASSERT_GT(unit->GetNumberOfPoints(), 0);
  ASSERT_EQ(scaled->GetNumberOfPoints(), unit->GetNumberOfPoints());
  EXPECT_EQ(
    CompareArray(unit->GetPoints()->GetData(), scaled->GetPoints()->GetData(), 1, exponent), "")
    << "points";
  ASSERT_EQ(scaled->GetNumberOfCells(), unit->GetNumberOfCells());
  using Cells = vtkCellArray* (*)(vtkPolyData*);
  for (const Cells cells : { Cells([](vtkPolyData* p) { return p->GetVerts(); }),
         Cells([](vtkPolyData* p) { return p->GetPolys(); }) })
  {
    EXPECT_EQ(CompareArray(
                cells(unit)->GetConnectivityArray(), cells(scaled)->GetConnectivityArray(), 0, 0),
      "")
      << "cells";
  }
  using Data = vtkFieldData* (*)(vtkPolyData*);
  for (const Data data : { Data([](vtkPolyData* p) -> vtkFieldData* { return p->GetPointData(); }),
         Data([](vtkPolyData* p) -> vtkFieldData* { return p->GetCellData(); }),
         Data([](vtkPolyData* p) { return p->GetFieldData(); }) })
  {
    vtkFieldData* u = data(unit);
    vtkFieldData* s = data(scaled);
    EXPECT_EQ(u->GetNumberOfArrays(), s->GetNumberOfArrays());
    for (int i = 0; i < u->GetNumberOfArrays(); ++i)
    {
      vtkDataArray* a = u->GetArray(i);
      if (!a || !a->GetName())
      {
        continue;
      }
      const auto unitful = Dimension.find(a->GetName());
      const int dimension = unitful == Dimension.end() ? 0 : unitful->second;
      if (dimension != 0)
      {
        seen.insert(a->GetName());
      }
      EXPECT_EQ(CompareArray(a, s->GetArray(a->GetName()), dimension, exponent), "")
        << a->GetName();
    }
  }
}
}

TEST(vtkQuadCoverScale, EveryStageGivesTheSameOutputsAtAnySizeInItsUnits)
{
  ScaledChain unit(0);
  const auto reference = unit.Outputs();
  ASSERT_EQ(unit.errors->GetError(), "");
  ASSERT_GT(unit.matching->GetBranchPointsOutput()->GetNumberOfPoints(), 0);
  for (const int exponent : { -400, 400 })
  {
    ScaledChain scaled(exponent);
    const auto outputs = scaled.Outputs();
    ASSERT_EQ(scaled.errors->GetError(), "") << "2^" << exponent;
    std::set<std::string> seen;
    for (std::size_t i = 0; i < outputs.size(); ++i)
    {
      SCOPED_TRACE(outputs[i].first + " at 2^" + std::to_string(exponent));
      ExpectScaled(reference[i].second, outputs[i].second, exponent, seen);
    }
    // every array with units was there to compare
    EXPECT_EQ(seen.size(), Dimension.size());
  }
}
