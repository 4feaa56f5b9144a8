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
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPolyData.h"
#include "vtkQuadCoverArrayNames.h"
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
/// The pipeline's stages in order; `available` is false until its issue is built.
struct StageInfo
{
  const char* name;
  const char* filter;
  bool available;
};
const StageInfo Stages[] = {
  { "curvature", "vtkCurvatureFrames", true },
  { "smooth", "vtkFrameSmoother", false },
  { "matching", "vtkMatchingBuilder", false },
  { "param", "vtkQuadCoverSolver", false },
  { "quads", "vtkQuadExtractor", false },
};

void Usage(std::ostream& os)
{
  os << "usage: quadcover INPUT -o OUTPUT [--stage STAGE] [--stats FILE.json] [-v]\n"
        "                 [--radius R] [--threads N] [--no-input-frames]\n"
        "\n"
        "Runs the QuadCover pipeline on a triangle surface up to STAGE and writes the result.\n"
        "  INPUT            .obj .ply .stl .vtp or .vtk surface\n"
        "  -o OUTPUT        .vtp or .vtk (all arrays kept), .obj or .ply (geometry only)\n"
        "  --stage STAGE    curvature|smooth|matching|param|quads (default: the last built one,\n"
        "                   now curvature)\n"
        "  --stats FILE     write a JSON summary: input size, repairs, seconds per stage, counts\n"
        "  -v, --verbose    seconds per stage, and VTK's own messages (progress shows\n"
        "                   whenever stderr is a terminal)\n"
        "  --radius R       curvature neighbourhood radius in median edge lengths, 0..20\n"
        "                   (default 2)\n"
        "  --threads N      worker threads, 0 = all cores (default 0)\n"
        "  --no-input-frames  ignore a FrameU cell array on the input; use curvature frames\n"
        "\n"
        "Repaired silently: exactly coincident points are merged, unused points dropped,\n"
        "polygons and strips triangulated, vertex/line cells and degenerate polygons removed,\n"
        "triangles reoriented to agree with their neighbours, and a vertex where separate fans of\n"
        "triangles touch split into one copy per fan (see --stats for the counts).\n"
        "Refused: missing, unreadable or empty files, unknown extensions, no polygons, NaN or\n"
        "infinite coordinates, non-manifold edges.\n";
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
  bool verbose = false, useInputFrames = true;
  double radius = 2.0;
  int threads = 0;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&](const char* what) -> const char* {
      if (i + 1 >= argc)
      {
        return nullptr;
      }
      (void)what;
      return argv[++i];
    };
    if (a == "-h" || a == "--help")
    {
      Usage(std::cout);
      return 0;
    }
    else if (a == "-v" || a == "--verbose")
    {
      verbose = true;
    }
    else if (a == "-o" || a == "--output" || a == "--stage" || a == "--stats" || a == "--radius" ||
      a == "--threads")
    {
      const char* v = value(a.c_str());
      if (!v)
      {
        return UsageError(a + " needs a value");
      }
      if (a == "-o" || a == "--output")
        output = v;
      else if (a == "--stage")
        stage = v;
      else if (a == "--stats")
        statsPath = v;
      else
      {
        char* end = nullptr;
        const double x = std::strtod(v, &end);
        // Range first: casting an out-of-range double to int is undefined.
        if (end == v || *end != '\0' || !(x >= 0.0) || (a == "--radius" && x > 20.0) ||
          (a == "--threads" && (x > 1024.0 || x != std::floor(x))))
        {
          return UsageError("invalid value '" + std::string(v) + "' for " + a);
        }
        if (a == "--radius")
          radius = x;
        else
          threads = static_cast<int>(x);
      }
    }
    else if (a == "--no-input-frames")
    {
      useInputFrames = false;
    }
    else if (!a.empty() && a[0] == '-' && a != "-")
    {
      return UsageError("unknown option " + a);
    }
    else if (input.empty())
    {
      input = a;
    }
    else
    {
      return UsageError("more than one input file given ('" + input + "', '" + a + "')");
    }
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
  int lastStage = -1;
  std::string built;
  for (int s = 0; s < 5; ++s)
  {
    if (Stages[s].available)
    {
      lastStage = s;
      built += (built.empty() ? "" : ", ") + std::string(Stages[s].name);
    }
  }
  if (!stage.empty())
  {
    int found = -1;
    for (int s = 0; s < 5; ++s)
    {
      found = stage == Stages[s].name ? s : found;
    }
    if (found < 0)
    {
      return UsageError(
        "unknown stage '" + stage + "' (stages: curvature, smooth, matching, param, quads)");
    }
    if (!Stages[found].available)
    {
      return UsageError(
        "stage '" + stage + "' (" + Stages[found].filter + ") is not built yet; built: " + built);
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
  vtkNew<vtkCurvatureFrames> curvature;
  curvature->SetInputData(surface);
  curvature->SetNeighborhoodRadius(radius);
  curvature->SetNumberOfThreads(threads);
  curvature->SetUseInputFrames(useInputFrames);
  std::vector<std::pair<std::string, vtkAlgorithm*>> pipeline = { { "curvature", curvature } };
  vtkPolyData* result = nullptr;
  for (int s = 0; s <= lastStage; ++s)
  {
    vtkAlgorithm* filter = pipeline[s].second;
    vtkNew<QuadCoverIO::ErrorObserver> errors;
    errors->Attach(filter);
    if (showProgress)
    {
      progress->Stage = pipeline[s].first;
      filter->AddObserver(vtkCommand::ProgressEvent, progress);
    }
    t0 = clock();
    filter->Update();
    progress->Finish();
    timings.push_back({ pipeline[s].first, since(t0) });
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
    js << "  \"stage\": " << JsonString(Stages[lastStage].name) << ",\n";
    js << "  \"seconds\": {";
    for (size_t i = 0; i < timings.size(); ++i)
    {
      js << (i ? ", " : "") << JsonString(timings[i].name) << ": " << timings[i].seconds;
    }
    js << "},\n";
    {
      vtkDataArray* w =
        curvature->GetOutput()->GetCellData()->GetArray(vtkQuadCoverArrayNames::FrameWeight);
      double mean = 0.0;
      for (vtkIdType c = 0; w && c < w->GetNumberOfTuples(); ++c)
      {
        mean += w->GetTuple1(c) / w->GetNumberOfTuples();
      }
      vtkDataArray* r =
        curvature->GetOutput()->GetFieldData()->GetArray(vtkQuadCoverArrayNames::CurvatureRadius);
      js << "  \"curvature\": {\"radius\": " << (r ? r->GetTuple1(0) : 0.0)
         << ", \"mean_frame_weight\": " << mean << "}\n";
    }
    js << "}\n";
    std::ofstream out(statsPath);
    out << js.str();
    if (!out.good())
    {
      return Fail("cannot write '" + statsPath + "'");
    }
  }
  return 0;
}
