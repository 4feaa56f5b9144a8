// quadcover: run the QuadCover pipeline on a surface file, up to a chosen stage.
//
//   quadcover INPUT -o OUTPUT [--stage NAME] [--stats FILE.json] [-v] [stage options]
//
// Exit status: 0 success, 1 the input or a stage failed (one line on stderr), 2 bad usage.
#include "QuadCoverIO.h"

#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkCurvatureFrames.h"
#include "vtkDataArray.h"
#include "vtkFrameSmoother.h"
#include "vtkLogger.h"
#include "vtkMatchingBuilder.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkQuadCoverArrayNames.h"
#include "vtkQuadCoverSolver.h"
#include "vtkQuadExtractor.h"
#include "vtkSmartPointer.h"
#include "vtkStringOutputWindow.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace
{
const char* const StageNames[] = { "curvature", "smooth", "matching", "param", "quads" };
const char* const StageFilters[] = { "vtkCurvatureFrames", "vtkFrameSmoother", "vtkMatchingBuilder",
  "vtkQuadCoverSolver", "vtkQuadExtractor" };
const int BuiltStages = 5;

/// A numeric option of one stage: its flag, meaning, range and default, all but the flag and
/// meaning taken from the filter it sets (its vtkSetClampMacro range and initial value).
struct NumberOption
{
  int stage;
  const char* flag;
  const char* meaning;
  double low, high, value;
  bool whole;
};

void Usage(std::ostream& os, const std::vector<NumberOption>& numbers)
{
  os << "usage: quadcover INPUT -o OUTPUT [--stage STAGE] [--stats FILE.json] [-v] [options]\n"
        "\n"
        "Runs the QuadCover pipeline on a triangle surface up to STAGE and writes the result.\n"
        "  INPUT            .obj .ply .stl .vtp or .vtk surface\n"
        "  -o OUTPUT        .vtp or .vtk (all arrays kept), .obj or .ply (geometry only)\n"
        "  --stage STAGE    curvature|smooth|matching|param|quads (default: quads)\n"
        "  --stats FILE     write a JSON summary: input size, repairs, seconds per stage, and\n"
        "                   what each stage counts\n"
        "  -v, --verbose    seconds per stage, and VTK's own messages (progress shows\n"
        "                   whenever stderr is a terminal)\n";
  const char* const flags[] = {
    "  --no-input-frames  ignore a FrameU cell array on the input; use curvature frames\n",
    "  --no-features      do not hold frames along sharp edges\n"
    "  --no-boundary-alignment  do not hold frames along the boundary\n",
    "  --no-branch-optimization  keep the smallest-angle matchings\n"
    "  --edge-count-cost  every edge counts once in the merge cost (not by its length)\n",
    "  --no-pure-quads    only seam translations integer (branch points may lie mid-cell)\n"
    "  --rounding MODE    greedy|simple|none (default greedy)\n"
    "  --split-seams      write the surface cut open along the seams, with UV texture\n"
    "                     coordinates (view it with a checkerboard texture)\n",
    "  --no-hausdorff     skip the Hausdorff distance to the input\n"
    "  --no-quad-repair   leave quads with a corner turned inside out as extracted\n",
  };
  for (int stage = 0; stage < BuiltStages; ++stage)
  {
    os << StageNames[stage] << " (" << StageFilters[stage] << "):\n";
    for (const NumberOption& n : numbers)
    {
      if (n.stage == stage)
      {
        char line[200];
        std::snprintf(line, sizeof line, "  %-18s %s, %g..%g (default %g)\n", n.flag, n.meaning,
          n.low, n.high, n.value);
        os << line;
      }
    }
    os << flags[stage];
  }
  os << "\n"
        "Repaired silently: polygons and strips triangulated, vertex/line cells dropped, exactly\n"
        "coincident points merged, triangles with a repeated point removed, triangles\n"
        "reoriented to agree with their neighbours, and a vertex where separate fans of\n"
        "triangles touch split into one copy per fan (see --stats for the counts).\n"
        "Refused: missing, unreadable or empty files, unknown extensions, no polygons, point\n"
        "ids out of range, NaN or infinite coordinates, non-manifold edges, surfaces whose\n"
        "triangles all have zero area.\n";
}

int Fail(const std::string& message)
{
  std::cerr << "quadcover: error: " << message << "\n";
  return 1;
}

int UsageError(const std::string& message)
{
  std::cerr << "quadcover: " << message << " (see quadcover --help)\n";
  return 2;
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

std::string JsonString(const std::string& s)
{
  std::string out = "\"";
  for (char c : s)
  {
    if (c == '"' || c == '\\')
    {
      out += '\\';
      out += c;
    }
    else if (static_cast<unsigned char>(c) < 0x20)
    {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    }
    else
    {
      out += c;
    }
  }
  return out + "\"";
}
}

int main(int argc, char* argv[])
{
  std::string input, output, stage, statsPath;
  bool verbose = false, useInputFrames = true, features = true, boundary = true,
       optimizeBranches = true;
  // The filters first: their defaults and ranges are the options'.
  vtkNew<vtkCurvatureFrames> curvature;
  vtkNew<vtkFrameSmoother> smoother;
  vtkNew<vtkMatchingBuilder> matching;
  vtkNew<vtkQuadCoverSolver> solver;
  vtkNew<vtkQuadExtractor> extractor;
  bool pureQuads = true, splitSeams = false, hausdorff = true, lengthScaledCost = true,
       quadRepair = true;
  int rounding = solver->GetRoundingMode();
  std::vector<NumberOption> numbers = {
    { 0, "--radius R", "neighbourhood radius in median edge lengths",
      curvature->GetNeighborhoodRadiusMinValue(), curvature->GetNeighborhoodRadiusMaxValue(),
      curvature->GetNeighborhoodRadius(), false },
    { 0, "--threads N", "worker threads, 0 = all cores", 0.0,
      double(curvature->GetNumberOfThreadsMaxValue()), double(curvature->GetNumberOfThreads()),
      true },
    { 1, "--smoothing L", "lambda: smoothness against curvature alignment",
      smoother->GetSmoothingWeightMinValue(), smoother->GetSmoothingWeightMaxValue(),
      smoother->GetSmoothingWeight(), false },
    { 1, "--iterations N", "at most N iterations per run",
      double(smoother->GetMaximumNumberOfIterationsMinValue()),
      double(smoother->GetMaximumNumberOfIterationsMaxValue()),
      double(smoother->GetMaximumNumberOfIterations()), true },
    { 1, "--feature-angle D", "edges sharper than D degrees are features",
      smoother->GetFeatureAngleMinValue(), smoother->GetFeatureAngleMaxValue(),
      smoother->GetFeatureAngle(), false },
    { 2, "--branch-weight L", "cost of a singular point in radians",
      matching->GetBranchPointWeightMinValue(), matching->GetBranchPointWeightMaxValue(),
      matching->GetBranchPointWeight(), false },
    { 3, "--target-quads N", "about N quads (when no --edge-length)",
      double(solver->GetTargetQuadCountMinValue()), double(solver->GetTargetQuadCountMaxValue()),
      double(solver->GetTargetQuadCount()), true },
    { 3, "--edge-length L", "quad edge length in world units, 0 = from --target-quads",
      solver->GetTargetEdgeLengthMinValue(), solver->GetTargetEdgeLengthMaxValue(),
      solver->GetTargetEdgeLength(), false },
    { 3, "--boundary-tolerance D", "boundary edges within D degrees of a frame lie on grid lines",
      solver->GetBoundaryToleranceMinValue(), solver->GetBoundaryToleranceMaxValue(),
      solver->GetBoundaryTolerance(), false },
    { 3, "--untangle N", "rounds of untangling per flipped neighbourhood",
      double(solver->GetMaximumUntangleRoundsMinValue()),
      double(solver->GetMaximumUntangleRoundsMaxValue()),
      double(solver->GetMaximumUntangleRounds()), true },
    { 4, "--relax N", "sweeps of tangential relaxation of the quads",
      double(extractor->GetRelaxationIterationsMinValue()),
      double(extractor->GetRelaxationIterationsMaxValue()),
      double(extractor->GetRelaxationIterations()), true },
  };
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    NumberOption* number = nullptr;
    for (NumberOption& n : numbers)
    {
      const std::string flag = n.flag;
      number = a == flag.substr(0, flag.find(' ')) ? &n : number;
    }
    const bool takesText =
      a == "-o" || a == "--output" || a == "--stage" || a == "--stats" || a == "--rounding";
    if ((number || takesText) && i + 1 >= argc)
    {
      return UsageError(a + " needs a value");
    }
    if (a == "-h" || a == "--help")
    {
      Usage(std::cout, numbers);
      return 0;
    }
    else if (a == "-v" || a == "--verbose")
      verbose = true;
    else if (a == "-o" || a == "--output")
      output = argv[++i];
    else if (a == "--stage")
      stage = argv[++i];
    else if (a == "--stats")
      statsPath = argv[++i];
    else if (number)
    {
      const char* v = argv[++i];
      char* end = nullptr;
      const double x = std::strtod(v, &end);
      // Range first: converting an out-of-range double to int is undefined.
      if (end == v || *end != '\0' || !(x >= number->low && x <= number->high) ||
        (number->whole && x != std::floor(x)))
      {
        return UsageError("invalid value '" + std::string(v) + "' for " + a);
      }
      number->value = x;
    }
    else if (a == "--no-input-frames")
      useInputFrames = false;
    else if (a == "--no-features")
      features = false;
    else if (a == "--no-boundary-alignment")
      boundary = false;
    else if (a == "--no-branch-optimization")
      optimizeBranches = false;
    else if (a == "--edge-count-cost")
      lengthScaledCost = false;
    else if (a == "--pure-quads")
      pureQuads = true;
    else if (a == "--no-pure-quads")
      pureQuads = false;
    else if (a == "--split-seams")
      splitSeams = true;
    else if (a == "--no-hausdorff")
      hausdorff = false;
    else if (a == "--no-quad-repair")
      quadRepair = false;
    else if (a == "--rounding")
    {
      const std::string mode = argv[++i];
      if (mode == "greedy")
        rounding = vtkQuadCoverSolver::ROUNDING_GREEDY;
      else if (mode == "simple")
        rounding = vtkQuadCoverSolver::ROUNDING_SIMPLE;
      else if (mode == "none")
        rounding = vtkQuadCoverSolver::ROUNDING_NONE;
      else
        return UsageError("invalid value '" + mode + "' for --rounding (greedy, simple, none)");
    }
    else if (!a.empty() && a[0] == '-' && a != "-")
      return UsageError("unknown option " + a);
    else if (input.empty())
      input = a;
    else
      return UsageError("more than one input file given ('" + input + "', '" + a + "')");
  }
  if (input.empty())
  {
    return UsageError("no input file given");
  }
  if (output.empty())
  {
    return UsageError("no output file given (-o OUTPUT)");
  }
  if (!QuadCoverIO::CanWrite(output))
  {
    return UsageError("cannot write '" + output + "': unknown extension (use .vtp .vtk .obj .ply)");
  }
  int lastStage = BuiltStages - 1;
  if (!stage.empty())
  {
    int found = -1;
    for (int s = 0; s < 5; ++s)
    {
      found = stage == StageNames[s] ? s : found;
    }
    if (found < 0)
    {
      return UsageError(
        "unknown stage '" + stage + "' (stages: curvature, smooth, matching, param, quads)");
    }
    if (found >= BuiltStages)
    {
      return UsageError("stage '" + stage + "' (" + StageFilters[found] + ") is not built yet");
    }
    lastStage = found;
  }

  if (!verbose)
  {
    // Keep VTK's stray messages off the terminal. (GlobalWarningDisplayOff would also stop the
    // ErrorEvents the observers below turn into one-line errors.)
    vtkNew<vtkStringOutputWindow> quiet;
    vtkOutputWindow::SetInstance(quiet);
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF); // VTK 9 logs errors here too
  }
  const bool showProgress = isatty(STDERR_FILENO) != 0; // a log file gets no \r updates
  vtkNew<ProgressPrinter> progress;
  struct Timing
  {
    std::string name;
    double seconds;
  };
  std::vector<Timing> timings;
  auto clock = [] { return std::chrono::steady_clock::now(); };
  auto since = [](std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  };

  // Read and repair.
  auto t0 = clock();
  std::string error;
  vtkSmartPointer<vtkPolyData> raw = QuadCoverIO::ReadSurface(input, error);
  if (!raw)
  {
    return Fail(error);
  }
  QuadCoverIO::Repairs repairs;
  vtkSmartPointer<vtkPolyData> surface = QuadCoverIO::PrepareSurface(raw, repairs, error);
  if (!surface)
  {
    return Fail("'" + input + "': " + error);
  }
  timings.push_back({ "read", since(t0) });

  // The pipeline, stage by stage.
  curvature->SetInputData(surface);
  curvature->SetNeighborhoodRadius(numbers[0].value);
  curvature->SetNumberOfThreads(static_cast<int>(numbers[1].value));
  curvature->SetUseInputFrames(useInputFrames);
  smoother->SetInputConnection(curvature->GetOutputPort());
  smoother->SetSmoothingWeight(numbers[2].value);
  smoother->SetMaximumNumberOfIterations(static_cast<int>(numbers[3].value));
  smoother->SetFeatureAngle(numbers[4].value);
  smoother->SetAlignToFeatures(features);
  smoother->SetAlignToBoundary(boundary);
  matching->SetInputConnection(smoother->GetOutputPort());
  matching->SetOptimizeBranchPoints(optimizeBranches);
  matching->SetLengthScaledCost(lengthScaledCost);
  matching->SetBranchPointWeight(numbers[5].value);
  solver->SetInputConnection(matching->GetOutputPort());
  solver->SetTargetQuadCount(static_cast<int>(numbers[6].value));
  solver->SetTargetEdgeLength(numbers[7].value);
  solver->SetBoundaryTolerance(numbers[8].value);
  solver->SetMaximumUntangleRounds(static_cast<int>(numbers[9].value));
  solver->SetPureQuads(pureQuads);
  solver->SetRoundingMode(rounding);
  solver->SetSplitSeams(splitSeams);
  extractor->SetInputConnection(solver->GetOutputPort());
  extractor->SetComputeHausdorffDistance(hausdorff);
  extractor->SetRepairInvertedQuads(quadRepair);
  extractor->SetRelaxationIterations(static_cast<int>(numbers[10].value));
  vtkAlgorithm* const pipeline[] = { curvature, smoother, matching, solver, extractor };
  vtkPolyData* result = nullptr;
  for (int s = 0; s <= lastStage; ++s)
  {
    vtkAlgorithm* filter = pipeline[s];
    vtkNew<QuadCoverIO::ErrorObserver> errors;
    errors->Attach(filter);
    if (showProgress)
    {
      progress->Stage = StageNames[s];
      filter->AddObserver(vtkCommand::ProgressEvent, progress);
    }
    t0 = clock();
    filter->Update();
    progress->Finish();
    timings.push_back({ StageNames[s], since(t0) });
    for (const std::string& w : errors->Warnings())
    {
      std::cerr << "quadcover: warning: " << w << "\n";
    }
    if (!errors->Error().empty())
    {
      return Fail("'" + input + "': " + errors->Error());
    }
    result = vtkPolyData::SafeDownCast(filter->GetOutputDataObject(0));
  }

  t0 = clock();
  if (!QuadCoverIO::WriteSurface(result, output, error))
  {
    return Fail(error);
  }
  timings.push_back({ "write", since(t0) });

  if (verbose)
  {
    std::fprintf(stderr, "quadcover: %lld points, %lld triangles\n",
      static_cast<long long>(surface->GetNumberOfPoints()),
      static_cast<long long>(surface->GetNumberOfPolys()));
    for (const Timing& t : timings)
    {
      std::fprintf(stderr, "  %-10s %8.3f s\n", t.name.c_str(), t.seconds);
    }
  }

  if (!statsPath.empty())
  {
    namespace names = vtkQuadCoverArrayNames;
    auto field = [](vtkAlgorithm* a, const char* name, int i) {
      vtkDataArray* x =
        vtkPolyData::SafeDownCast(a->GetOutputDataObject(0))->GetFieldData()->GetArray(name);
      return x && i < x->GetNumberOfTuples() * x->GetNumberOfComponents()
        ? x->GetComponent(i / x->GetNumberOfComponents(), i % x->GetNumberOfComponents())
        : 0.0;
    };
    std::ostringstream js;
    js << "{\n  \"input\": {\"file\": " << JsonString(input)
       << ", \"points\": " << raw->GetNumberOfPoints() << ", \"cells\": " << raw->GetNumberOfCells()
       << "},\n";
    js << "  \"surface\": {\"points\": " << surface->GetNumberOfPoints()
       << ", \"triangles\": " << surface->GetNumberOfPolys() << "},\n";
    js << "  \"repairs\": {\"merged_points\": " << repairs.mergedPoints
       << ", \"removed_cells\": " << repairs.removedCells
       << ", \"triangulated_polygons\": " << repairs.triangulatedPolygons
       << ", \"flipped_triangles\": " << repairs.flippedTriangles
       << ", \"split_vertices\": " << repairs.splitVertices << "},\n";
    js << "  \"stage\": " << JsonString(StageNames[lastStage]) << ",\n";
    js << "  \"seconds\": {";
    for (size_t i = 0; i < timings.size(); ++i)
    {
      js << (i ? ", " : "") << JsonString(timings[i].name) << ": " << timings[i].seconds;
    }
    js << "}";
    {
      vtkDataArray* w = curvature->GetOutput()->GetCellData()->GetArray(names::FrameWeight);
      double mean = 0.0;
      for (vtkIdType c = 0; w && c < w->GetNumberOfTuples(); ++c)
      {
        mean += w->GetTuple1(c) / w->GetNumberOfTuples();
      }
      js << ",\n  \"curvature\": {\"radius\": " << field(curvature, names::CurvatureRadius, 0)
         << ", \"mean_frame_weight\": " << mean << "}";
    }
    if (lastStage >= 1)
    {
      vtkDataArray* held = smoother->GetOutput()->GetCellData()->GetArray(names::FrameConstrained);
      double count = 0;
      for (vtkIdType c = 0; held && c < held->GetNumberOfTuples(); ++c)
      {
        count += held->GetTuple1(c);
      }
      js << ",\n  \"smooth\": {\"energy_before\": " << field(smoother, names::SmoothingEnergy, 0)
         << ", \"energy_after\": " << field(smoother, names::SmoothingEnergy, 1)
         << ", \"iterations\": " << field(smoother, names::SmoothingIterations, 0)
         << ", \"held_triangles\": " << count << "}";
    }
    if (lastStage >= 2)
    {
      // Singularities by index (inner points) and the Poincare-Hopf sum over all points.
      vtkPolyData* m = matching->GetOutput();
      vtkDataArray* index = m->GetPointData()->GetArray(names::SingularityIndex);
      double sum = 0.0;
      for (vtkIdType p = 0; index && p < index->GetNumberOfTuples(); ++p)
      {
        sum += index->GetTuple1(p);
      }
      js << ",\n  \"matching\": {\"singularities\": " << field(matching, names::SingularityCount, 0)
         << ", \"branch_points_before\": " << field(matching, names::BranchPointCount, 0)
         << ", \"branch_points_after\": " << field(matching, names::BranchPointCount, 1)
         << ", \"matching_cost_before\": " << field(matching, names::MatchingCost, 0)
         << ", \"matching_cost_after\": " << field(matching, names::MatchingCost, 1)
         << ", \"index_sum\": " << sum << ", \"singularities_by_index\": {";
      vtkDataArray* table = m->GetFieldData()->GetArray(names::SingularityHistogram);
      for (vtkIdType i = 0; table && i < table->GetNumberOfTuples(); ++i)
      {
        char key[32];
        std::snprintf(key, sizeof key, "%g", table->GetComponent(i, 0));
        js << (i ? ", " : "") << JsonString(key) << ": " << table->GetComponent(i, 1);
      }
      js << "}}";
    }
    if (lastStage >= 3)
    {
      js << ",\n  \"param\": {\"grid_size\": " << field(solver, names::GridScale, 0)
         << ", \"seam_edges\": " << field(solver, names::SeamEdgeCount, 0)
         << ", \"branch_points\": " << field(solver, names::BranchPointsOnGrid, 0)
         << ", \"branch_points_on_grid\": " << field(solver, names::BranchPointsOnGrid, 1)
         << ", \"flipped_continuous\": " << field(solver, names::FlippedTriangles, 0)
         << ", \"flipped_rounded\": " << field(solver, names::FlippedTriangles, 1)
         << ", \"flipped\": " << field(solver, names::FlippedTriangles, 2)
         << ", \"winding_errors\": " << field(solver, names::WindingErrors, 0)
         << ", \"energy_continuous\": " << field(solver, names::ParameterizationEnergy, 0)
         << ", \"energy_rounded\": " << field(solver, names::ParameterizationEnergy, 1)
         << ", \"energy\": " << field(solver, names::ParameterizationEnergy, 2)
         << ", \"seam_translation_error\": " << field(solver, names::SeamTranslationError, 0)
         << ", \"solve_seconds\": [";
      vtkDataArray* solves = solver->GetOutput()->GetFieldData()->GetArray(names::SolveSeconds);
      for (vtkIdType i = 0; solves && i < solves->GetNumberOfTuples(); ++i)
      {
        js << (i ? ", " : "") << solves->GetTuple1(i);
      }
      js << "]}";
    }
    if (lastStage >= 4)
    {
      vtkPolyData* q = extractor->GetOutput();
      js << ",\n  \"quads\": {\"vertices\": " << q->GetNumberOfPoints()
         << ", \"faces\": " << q->GetNumberOfPolys()
         << ", \"quad_share\": " << field(extractor, names::QuadShare, 0)
         << ", \"irregular_inner\": " << field(extractor, names::IrregularVertices, 0)
         << ", \"irregular_boundary\": " << field(extractor, names::IrregularVertices, 1)
         << ", \"edge_length_rsd\": " << field(extractor, names::EdgeLengthRSD, 0)
         << ", \"angle_rsd\": " << field(extractor, names::AngleRSD, 0)
         << ", \"scaled_jacobian_min\": " << field(extractor, names::ScaledJacobianStatistics, 0)
         << ", \"scaled_jacobian_mean\": " << field(extractor, names::ScaledJacobianStatistics, 1)
         << ", \"non_manifold_edges\": " << field(extractor, names::NonManifoldEdges, 0)
         << ", \"euler_characteristic\": " << field(extractor, names::EulerCharacteristic, 0)
         << ", \"boundary_loops\": " << field(extractor, names::BoundaryLoops, 0)
         << ", \"hausdorff_percent\": " << field(extractor, names::HausdorffDistance, 0)
         << ", \"inverted_quads_extracted\": " << field(extractor, names::InvertedQuads, 0)
         << ", \"inverted_quads\": " << field(extractor, names::InvertedQuads, 1)
         << ", \"dropped_cells\": "
         << field(extractor, names::DroppedCells, 0) + field(extractor, names::DroppedCells, 1) +
          field(extractor, names::DroppedCells, 2)
         << "}";
    }
    js << "\n}\n";
    std::ofstream out(statsPath);
    out << js.str();
    if (!out.good())
    {
      return Fail("cannot write '" + statsPath + "'");
    }
  }
  return 0;
}
