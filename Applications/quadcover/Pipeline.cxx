#include "Pipeline.h"

#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkPolyData.h"
#include "vtkQuadCoverErrorObserver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <new>
#include <numeric>
#include <vector>

namespace quadcover_app
{
namespace
{
/// The number of connected components of the surface's polygons (joined through shared points).
long long ComponentCount(vtkPolyData* surface)
{
  std::vector<vtkIdType> parent(surface->GetNumberOfPoints());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](vtkIdType x) {
    while (parent[x] != x)
    {
      x = parent[x] = parent[parent[x]];
    }
    return x;
  };
  std::vector<char> used(parent.size(), 0);
  vtkCellArray* polys = surface->GetPolys();
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    for (vtkIdType k = 0; k < n; ++k)
    {
      used[ids[k]] = 1;
      const vtkIdType a = root(ids[0]), b = root(ids[k]);
      parent[std::max(a, b)] = std::min(a, b);
    }
  }
  long long count = 0;
  for (vtkIdType p = 0; p < static_cast<vtkIdType>(parent.size()); ++p)
  {
    count += used[p] && root(p) == p ? 1 : 0;
  }
  return count;
}

/// "Cannot ...: std::bad_alloc." (a filter's message for the exception, by its what()) as
/// "Cannot ...: out of memory."
std::string SayOutOfMemory(std::string error)
{
  const std::string what = ": std::bad_alloc.";
  if (error.size() >= what.size() &&
    error.compare(error.size() - what.size(), what.size(), what) == 0)
  {
    error.replace(error.size() - what.size(), what.size(), ": out of memory.");
  }
  return error;
}

/// Prints "stage  NN%" on one line of stderr while a filter runs.
class ProgressPrinter : public vtkCommand
{
public:
  static ProgressPrinter* New() { return new ProgressPrinter; }
  void Execute(vtkObject*, unsigned long, void* callData) override
  {
    const int percent = static_cast<int>(100.0 * *static_cast<double*>(callData));
    if (percent != this->Last)
    {
      this->Last = percent;
      std::fprintf(stderr, "\r%-10s %3d%%", this->Stage.c_str(), percent);
      std::fflush(stderr);
    }
  }
  void Finish()
  {
    if (this->Last >= 0)
    {
      std::fprintf(stderr, "\n");
    }
    this->Last = -1;
  }
  std::string Stage;
  int Last = -1;
};
}

const std::vector<std::string>& Pipeline::StageNames()
{
  static const std::vector<std::string> names = { "repair", "curvature", "smooth", "matching",
    "param", "quads" };
  return names;
}

int Pipeline::StageIndex(const std::string& name)
{
  for (std::size_t i = 0; i < StageNames().size(); ++i)
  {
    if (StageNames()[i] == name)
    {
      return static_cast<int>(i);
    }
  }
  return -1;
}

Pipeline::Pipeline()
{
  this->Curvature->SetInputConnection(this->Repair->GetOutputPort());
  this->Smoother->SetInputConnection(this->Curvature->GetOutputPort());
  this->Matching->SetInputConnection(this->Smoother->GetOutputPort());
  this->Solver->SetInputConnection(this->Matching->GetOutputPort());
  this->Extractor->SetInputConnection(this->Solver->GetOutputPort());
}

double Pipeline::MaximumQuadCount(long long triangles)
{
  return vtkQuadCoverSolver::MaximumQuadCount(static_cast<vtkIdType>(triangles));
}

std::string Pipeline::CheckQuadCount() const
{
  vtkPolyData* surface = this->Repair->GetOutput();
  const long long triangles = surface->GetNumberOfPolys();
  const double length = this->Solver->GetTargetEdgeLength();
  // each component's minimum comes on top of its share, at most
  const double quads = (length > 0.0 ? vtkQuadCoverSurfaceRepair::AreaInSquares(surface, length)
                                     : static_cast<double>(this->Solver->GetTargetQuadCount())) +
    static_cast<double>(this->Solver->GetMinimumComponentQuadCount()) *
      static_cast<double>(ComponentCount(surface));
  const double most = MaximumQuadCount(triangles);
  if (!(quads > most)) // NaN (a zero-area surface) is for the solver to refuse
  {
    return "";
  }
  char asked[96];
  if (length > 0.0)
    std::snprintf(asked, sizeof asked, "--target-edge-length %g gives about %.3g quads, which is",
      length, quads);
  else
    std::snprintf(asked, sizeof asked, "--target-quad-count %d gives about %.3g quads, which is",
      this->Solver->GetTargetQuadCount(), quads);
  char text[320];
  std::snprintf(text, sizeof text,
    "%s too many for this surface (about %.0f GB of memory); at most %.0f quads are taken "
    "(2000000, or 50 for each of its %lld triangles)",
    asked, std::ceil(quads * 0.6e3 / 1e9), most, triangles);
  return text;
}

vtkQuadCoverAlgorithm* Pipeline::Filter(int stage) const
{
  vtkQuadCoverAlgorithm* const filters[] = { this->Repair, this->Curvature, this->Smoother,
    this->Matching, this->Solver, this->Extractor };
  return filters[stage];
}

std::string Pipeline::Run(
  vtkPolyData* surface, int last, bool progress, std::vector<Timing>& timings)
{
  this->Repair->SetInputData(surface);
  if (this->AutomaticTriangleCount)
  {
    // a run that stops at the repair asks for the surface repaired, not simplified
    this->Repair->SetMaximumTriangleCount(last == 0
        ? 0
        : vtkQuadCoverSurfaceRepair::MaximumTriangleCountFor(
            surface, this->Solver->GetTargetQuadCount(), this->Solver->GetTargetEdgeLength()));
  }
  this->Extractor->SetSourceData(nullptr);
  vtkNew<ProgressPrinter> printer;
  for (int s = 0; s <= last; ++s)
  {
    vtkQuadCoverAlgorithm* filter = this->Filter(s);
    vtkNew<vtkQuadCoverErrorObserver> errors;
    errors->Attach(filter);
    unsigned long observer = 0;
    if (progress)
    {
      printer->Stage = StageNames()[s];
      observer = filter->AddObserver(vtkCommand::ProgressEvent, printer);
    }
    const auto start = std::chrono::steady_clock::now();
    try
    {
      filter->Update();
    }
    catch (const std::bad_alloc&)
    {
      // the filters catch their own; this is VTK's pipeline (copying the data between them)
      printer->Finish();
      return "Cannot run the " + StageNames()[s] + " stage: out of memory.";
    }
    printer->Finish();
    if (progress)
    {
      filter->RemoveObserver(observer);
    }
    timings.push_back({ StageNames()[s],
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() });
    for (int w = 0; w < errors->GetNumberOfWarnings(); ++w)
    {
      std::cerr << "quadcover: warning: " << errors->GetWarning(w) << "\n";
    }
    if (!errors->GetError().empty())
    {
      return SayOutOfMemory(errors->GetError());
    }
    if (s == 0 && vtkQuadCoverSurfaceRepair::Simplified(this->Repair->GetOutput()) &&
      !vtkQuadCoverSurfaceRepair::Smoothed(this->Repair->GetOutput()))
    {
      this->Extractor->SetSourceData(surface); // the quads onto the surface as it was given
    }
    const std::string tooMany = s == 0 && last >= StageIndex("param") ? this->CheckQuadCount() : "";
    if (!tooMany.empty())
    {
      return tooMany;
    }
  }
  return "";
}
}
