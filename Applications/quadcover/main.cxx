// quadcover: runs the QuadCover pipeline on a surface file, up to a chosen stage.
//
//   quadcover INPUT -o OUTPUT [--stage NAME] [--stats FILE.json] [-v] [stage options]
//
// Exit status: 0 done, 1 the input or a stage failed (one line on stderr, out of memory too),
// 2 bad usage.
#include "Options.h"
#include "Pipeline.h"
#include "Stats.h"

#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPolyData.h"
#include "vtkQuadCoverErrorObserver.h"
#include "vtkQuadCoverReader.h"
#include "vtkQuadCoverWriter.h"
#include "vtkStringOutputWindow.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <new>
#include <unistd.h>

namespace
{
using quadcover_app::Timing;

int Fail(const std::string& message)
{
  std::cerr << "quadcover: error: " << message << "\n";
  return 1;
}

double Since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Keeps VTK's stray messages off the terminal. (GlobalWarningDisplayOff would also stop the
/// ErrorEvents the observers turn into one-line errors.)
void QuietVTK()
{
  vtkNew<vtkStringOutputWindow> quiet;
  vtkOutputWindow::SetInstance(quiet);
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF); // VTK 9 logs errors here too
}

/// The run after the arguments: read, run the stages, write. `doing` says what it is doing,
/// for the message if memory runs out.
int Run(const quadcover_app::Request& request, quadcover_app::Pipeline& pipeline,
  const std::vector<quadcover_app::Option>& options, std::string& doing)
{
  std::vector<Timing> timings;
  auto start = std::chrono::steady_clock::now();
  doing = "read '" + request.input + "'";
  vtkNew<vtkQuadCoverReader> reader;
  reader->SetFileName(request.input.c_str());
  std::string error = vtkQuadCoverErrorObserver::Run(reader);
  if (!error.empty())
  {
    return Fail(error);
  }
  timings.push_back({ "read", Since(start) });

  doing = "run the stages on '" + request.input + "'";
  const int last = quadcover_app::Pipeline::StageIndex(request.stage);
  const bool progress = isatty(STDERR_FILENO) != 0; // a log file gets no \r updates
  error = pipeline.Run(reader->GetOutput(), last, progress, timings);
  if (!error.empty())
  {
    return Fail("'" + request.input + "': " + error);
  }

  start = std::chrono::steady_clock::now();
  doing = "write '" + request.output + "'";
  vtkNew<vtkQuadCoverWriter> writer;
  writer->SetFileName(request.output.c_str());
  writer->SetInputConnection(pipeline.Filter(last)->GetOutputPort());
  error = vtkQuadCoverErrorObserver::Run(writer);
  if (!error.empty())
  {
    return Fail(error);
  }
  timings.push_back({ "write", Since(start) });

  if (request.verbose)
  {
    vtkPolyData* surface = pipeline.Repair->GetOutput();
    std::fprintf(stderr, "quadcover: %lld points, %lld triangles\n",
      static_cast<long long>(surface->GetNumberOfPoints()),
      static_cast<long long>(surface->GetNumberOfPolys()));
    for (const Timing& t : timings)
    {
      std::fprintf(stderr, "  %-10s %8.3f s\n", t.name.c_str(), t.seconds);
    }
  }
  if (!request.stats.empty())
  {
    doing = "write '" + request.stats + "'";
    std::ofstream out(request.stats);
    out << quadcover_app::StatsJson(request, reader->GetOutput(), pipeline, last, timings, options);
    if (!out.good())
    {
      return Fail("cannot write '" + request.stats + "'");
    }
  }
  return 0;
}
}

int main(int argc, char* argv[])
{
#ifdef __GLIBC__
  // One malloc arena for all threads, before any starts: with one per thread (glibc's default),
  // what the pipeline's second thread frees stays in its own arena while the main thread's grows
  // to its peak beside it (peak memory: spot 53 -> 51 MB, rocker-arm 97 -> 88, armadillo 306 ->
  // 272, at the same speed; Benchmarks/README.md). The library leaves the process's allocator
  // to the program that loads it.
  mallopt(M_ARENA_MAX, 1);
#endif
  quadcover_app::Pipeline pipeline;
  const std::vector<quadcover_app::Option> options = quadcover_app::StageOptions(pipeline);
  quadcover_app::Request request;
  const std::string usage = quadcover_app::Parse(argc, argv, options, request);
  pipeline.AutomaticTriangleCount = std::find(request.given.begin(), request.given.end(),
                                      "maximum-triangle-count") == request.given.end();
  if (request.help)
  {
    quadcover_app::PrintUsage(std::cout, options);
    return 0;
  }
  if (!usage.empty())
  {
    std::cerr << "quadcover: " << usage << " (see quadcover --help)\n";
    return 2;
  }
  if (!request.verbose)
  {
    QuietVTK();
  }
  // The filters turn their exceptions into errors; what escapes is VTK's own readers, writers
  // and pipeline, or the --stats text: one line, not std::terminate's abort.
  std::string doing = "start";
  try
  {
    return Run(request, pipeline, options, doing);
  }
  catch (const std::bad_alloc&)
  {
    return Fail("cannot " + doing + ": out of memory");
  }
  catch (const std::exception& e)
  {
    return Fail("cannot " + doing + ": " + e.what());
  }
}
