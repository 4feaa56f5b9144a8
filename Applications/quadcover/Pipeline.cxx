#include "Pipeline.h"

#include "vtkCommand.h"
#include "vtkPolyData.h"
#include "vtkQuadCoverErrorObserver.h"

#include <chrono>
#include <cstdio>
#include <iostream>

namespace quadcover_app
{
namespace
{
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
    filter->Update();
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
      return errors->GetError();
    }
  }
  return "";
}
}
