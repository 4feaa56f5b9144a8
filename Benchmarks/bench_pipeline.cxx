// quadcover_bench: seconds and peak memory of the pipeline's stages (curvature, smoothing,
// matchings, parameterization, quad extraction), as a Markdown table.
//
//   quadcover_bench [--shared DIR] [--max-triangles N] [--repeat K] [--quads N] [--out FILE.md]
//
// Cases: the shared meshes, the same refined by Loop subdivision (x4 triangles per level) up to
// --max-triangles, and generated tori of about 10k, 100k and 1M triangles.
//
// Each case runs in a child process so that its peak resident memory (getrusage ru_maxrss of
// the child: reading or generating the mesh included) is its own. Seconds are the best of K
// runs of the stage on an already loaded surface.

#include "TestSurfaceFiles.h"

#include "vtkCurvatureFrames.h"
#include "vtkFrameSmoother.h"
#include "vtkLoopSubdivisionFilter.h"
#include "vtkMatchingBuilder.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkQuadCoverEigen.h"
#include "vtkQuadCoverSolver.h"
#include "vtkQuadExtractor.h"

#include "Surfaces.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
struct Case
{
  std::string name;
  std::string file; // empty: a generated torus
  int nu = 0, nv = 0;
  int subdivisions = 0; // Loop subdivision levels applied to the file's surface
};
constexpr int Stages = 5;

vtkSmartPointer<vtkPolyData> Torus(int nu, int nv)
{
  const quadcover::Surface s = quadcover::makeTorus(1.0, 0.4, nu, nv);
  return vtkQuadCoverEigen::ToPolyData(s.V, s.F);
}

/// Child: load, run the stages `repeat` times with `threads`, print "triangles seconds...".
int RunCase(const Case& c, int threads, int repeat, int quads, int fd)
{
  vtkSmartPointer<vtkPolyData> surface;
  if (c.file.empty())
  {
    surface = Torus(c.nu, c.nv);
  }
  else
  {
    std::string error;
    surface = ReadRepaired(c.file, error);
    if (!surface)
    {
      return 1;
    }
    if (c.subdivisions > 0)
    {
      vtkNew<vtkLoopSubdivisionFilter> loop;
      loop->SetInputData(surface);
      loop->SetNumberOfSubdivisions(c.subdivisions);
      loop->Update();
      surface = loop->GetOutput();
    }
  }
  // Best of `repeat` runs of the whole chain, per stage.
  double best[Stages] = { 1e300, 1e300, 1e300, 1e300, 1e300 };
  for (int r = 0; r < repeat; ++r)
  {
    vtkNew<vtkCurvatureFrames> frames;
    frames->SetInputData(surface);
    frames->SetNumberOfThreads(threads);
    vtkNew<vtkQuadCoverSolver> solver;
    solver->SetTargetQuadCount(quads);
    const vtkSmartPointer<vtkAlgorithm> stages[Stages] = { frames.Get(),
      vtkSmartPointer<vtkFrameSmoother>::New(), vtkSmartPointer<vtkMatchingBuilder>::New(),
      solver.Get(), vtkSmartPointer<vtkQuadExtractor>::New() };
    for (int s = 0; s < Stages; ++s)
    {
      if (s > 0)
      {
        stages[s]->SetInputConnection(stages[s - 1]->GetOutputPort());
      }
      const auto t0 = std::chrono::steady_clock::now();
      stages[s]->Update();
      best[s] = std::min(
        best[s], std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
  }
  char line[160];
  const int n = std::snprintf(line, sizeof line, "%lld %.6f %.6f %.6f %.6f %.6f\n",
    static_cast<long long>(surface->GetNumberOfPolys()), best[0], best[1], best[2], best[3],
    best[4]);
  return write(fd, line, n) == n ? 0 : 1;
}

struct Settings
{
  std::string shared, out;
  long long maxTriangles = 1000000;
  int repeat = 3;
  int quads = 3000;
  std::string command = "quadcover_bench";
};

/// The arguments; false on bad usage.
bool Parse(int argc, char* argv[], Settings& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    o.command += " " + a;
    if (i + 1 >= argc)
      return false;
    const std::string value = argv[++i];
    o.command += " " + value;
    if (a == "--shared")
      o.shared = value;
    else if (a == "--max-triangles")
      o.maxTriangles = std::atoll(value.c_str());
    else if (a == "--repeat")
      o.repeat = std::max(1, std::atoi(value.c_str()));
    else if (a == "--quads")
      o.quads = std::max(1, std::atoi(value.c_str()));
    else if (a == "--out")
      o.out = value;
    else
      return false;
  }
  return true;
}

/// The shared meshes, the two largest refined (4^k times the triangles, up to maxTriangles),
/// and tori of about 10k, 100k and 1M triangles.
std::vector<Case> Cases(const Settings& o)
{
  std::vector<Case> cases;
  for (const char* name :
    { "bunny-lowres", "spot", "teapot", "fandisk", "cheburashka", "rocker-arm" })
  {
    const std::string file = o.shared + "/" + name + ".obj";
    if (!o.shared.empty() && std::ifstream(file).good())
    {
      cases.push_back({ name, file });
    }
  }
  for (const auto& [name, triangles] :
    { std::pair<const char*, long long>{ "spot", 5856 }, { "rocker-arm", 20088 } })
  {
    const std::string file = o.shared + "/" + name + ".obj";
    long long count = triangles;
    for (int level = 1; level <= 4 && !o.shared.empty() && std::ifstream(file).good(); ++level)
    {
      count *= 4;
      if (count <= o.maxTriangles)
      {
        cases.push_back(
          { std::string(name) + " x" + std::to_string(1 << (2 * level)), file, 0, 0, level });
      }
    }
  }
  for (long long target : { 10000LL, 100000LL, 1000000LL }) // 2 nu nv triangles, nu = 2 nv
  {
    if (target <= o.maxTriangles)
    {
      const int nv = static_cast<int>(std::lround(std::sqrt(target / 4.0)));
      cases.push_back({ "torus " + std::to_string(target / 1000) + "k", "", 2 * nv, nv });
    }
  }
  return cases;
}

/// Runs one case in a child process; its table row, or "" when it failed.
std::string RunInChild(const Case& c, int threads, const Settings& o)
{
  int fds[2];
  if (pipe(fds) != 0)
  {
    return "";
  }
  const pid_t pid = fork();
  if (pid == 0)
  {
    close(fds[0]);
    _exit(RunCase(c, threads, o.repeat, o.quads, fds[1]));
  }
  close(fds[1]);
  char buf[128] = { 0 };
  const ssize_t got = read(fds[0], buf, sizeof buf - 1);
  close(fds[0]);
  int status = 0;
  struct rusage usage;
  wait4(pid, &status, 0, &usage);
  long long triangles = 0;
  double t[Stages] = { 0, 0, 0, 0, 0 };
  if (got <= 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0 ||
    std::sscanf(buf, "%lld %lf %lf %lf %lf %lf", &triangles, &t[0], &t[1], &t[2], &t[3], &t[4]) !=
      6)
  {
    return "";
  }
  char row[256];
  std::snprintf(row, sizeof row,
    "| %s | %lld | %d | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %.0f |\n", c.name.c_str(),
    triangles, threads, t[0], t[1], t[2], t[3], t[4], t[0] + t[1] + t[2] + t[3] + t[4],
    usage.ru_maxrss / 1024.0);
  return row;
}
}

int main(int argc, char* argv[])
{
  Settings o;
  if (!Parse(argc, argv, o))
  {
    std::fprintf(stderr,
      "usage: quadcover_bench [--shared DIR] [--max-triangles N] [--repeat K] "
      "[--quads N] [--out FILE]\n");
    return 2;
  }
  std::ostringstream table;
  table << "| surface | triangles | threads | curvature s | smooth s | matching s | param s | "
           "quads s | total s | peak RSS MiB |\n"
        << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Case& c : Cases(o))
  {
    for (int threads : { 1, 2 })
    {
      const std::string row = RunInChild(c, threads, o);
      if (row.empty())
      {
        std::fprintf(stderr, "quadcover_bench: case %s failed\n", c.name.c_str());
        continue;
      }
      table << row;
      std::fputs(row.c_str(), stderr);
    }
  }
  std::ostringstream doc;
  doc << "Command: `" << o.command << "` (Release build, best of " << o.repeat << " runs)\n\n"
      << table.str();
  if (o.out.empty())
  {
    std::fputs(doc.str().c_str(), stdout);
  }
  else
  {
    std::ofstream(o.out) << doc.str();
  }
  return 0;
}
