// quadcover_bench: seconds and peak memory of the pipeline's stages (curvature, smoothing,
// matchings so far), as a Markdown table.
//
//   quadcover_bench [--shared DIR] [--max-triangles N] [--repeat K] [--out FILE.md]
//
// Each case runs in a child process so that its peak resident memory (getrusage ru_maxrss of
// the child: reading or generating the mesh included) is its own. Seconds are the best of K
// runs of the stage on an already loaded surface.
#include "QuadCoverIO.h"

#include "vtkCurvatureFrames.h"
#include "vtkFrameSmoother.h"
#include "vtkMatchingBuilder.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkQuadCoverEigen.h"

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
};

vtkSmartPointer<vtkPolyData> Torus(int nu, int nv)
{
  const quadcover::Surface s = quadcover::makeTorus(1.0, 0.4, nu, nv);
  return vtkQuadCoverEigen::ToPolyData(s.V, s.F);
}

/// Child: load, run the stage `repeat` times with `threads`, print "triangles seconds".
int RunCase(const Case& c, int threads, int repeat, int fd)
{
  vtkSmartPointer<vtkPolyData> surface;
  if (c.file.empty())
  {
    surface = Torus(c.nu, c.nv);
  }
  else
  {
    std::string error;
    vtkSmartPointer<vtkPolyData> raw = QuadCoverIO::ReadSurface(c.file, error);
    QuadCoverIO::Repairs repairs;
    surface = raw ? QuadCoverIO::PrepareSurface(raw, repairs, error) : nullptr;
    if (!surface)
    {
      return 1;
    }
  }
  // Best of `repeat` runs of the whole chain, per stage.
  double best[3] = { 1e300, 1e300, 1e300 };
  for (int r = 0; r < repeat; ++r)
  {
    vtkNew<vtkCurvatureFrames> frames;
    frames->SetInputData(surface);
    frames->SetNumberOfThreads(threads);
    vtkNew<vtkFrameSmoother> smoother;
    smoother->SetInputConnection(frames->GetOutputPort());
    vtkNew<vtkMatchingBuilder> matching;
    matching->SetInputConnection(smoother->GetOutputPort());
    vtkAlgorithm* const stages[3] = { frames, smoother, matching };
    for (int s = 0; s < 3; ++s)
    {
      const auto t0 = std::chrono::steady_clock::now();
      stages[s]->Update();
      best[s] = std::min(
        best[s], std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
  }
  char line[160];
  const int n = std::snprintf(line, sizeof line, "%lld %.6f %.6f %.6f\n",
    static_cast<long long>(surface->GetNumberOfPolys()), best[0], best[1], best[2]);
  return write(fd, line, n) == n ? 0 : 1;
}
}

int main(int argc, char* argv[])
{
  std::string shared, out;
  long long maxTriangles = 1000000;
  int repeat = 3;
  std::string command = "quadcover_bench";
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    command += " " + a;
    if (i + 1 < argc && a == "--shared")
      shared = argv[++i], command += std::string(" ") + argv[i];
    else if (i + 1 < argc && a == "--max-triangles")
      maxTriangles = std::atoll(argv[++i]), command += std::string(" ") + argv[i];
    else if (i + 1 < argc && a == "--repeat")
      repeat = std::max(1, std::atoi(argv[++i])), command += std::string(" ") + argv[i];
    else if (i + 1 < argc && a == "--out")
      out = argv[++i], command += std::string(" ") + argv[i];
    else
    {
      std::fprintf(stderr,
        "usage: quadcover_bench [--shared DIR] [--max-triangles N] [--repeat K] [--out FILE]\n");
      return 2;
    }
  }

  std::vector<Case> cases;
  if (!shared.empty())
  {
    for (const char* name :
      { "bunny-lowres", "spot", "teapot", "fandisk", "cheburashka", "rocker-arm" })
    {
      const std::string file = shared + "/" + name + ".obj";
      if (std::ifstream(file).good())
      {
        cases.push_back({ name, file });
      }
    }
  }
  // Tori of about 10k, 100k and 1M triangles (2 nu nv, nu = 2 nv).
  for (long long target : { 10000LL, 100000LL, 1000000LL })
  {
    if (target <= maxTriangles)
    {
      const int nv = static_cast<int>(std::lround(std::sqrt(target / 4.0)));
      cases.push_back({ "torus " + std::to_string(target / 1000) + "k", "", 2 * nv, nv });
    }
  }

  std::ostringstream table;
  table << "| surface | triangles | threads | curvature s | smooth s | matching s | total s | "
           "peak RSS MiB |\n"
        << "|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Case& c : cases)
  {
    for (int threads : { 1, 2 })
    {
      int fds[2];
      if (pipe(fds) != 0)
      {
        return 1;
      }
      const pid_t pid = fork();
      if (pid == 0)
      {
        close(fds[0]);
        _exit(RunCase(c, threads, repeat, fds[1]));
      }
      close(fds[1]);
      char buf[128] = { 0 };
      const ssize_t got = read(fds[0], buf, sizeof buf - 1);
      close(fds[0]);
      int status = 0;
      struct rusage usage;
      wait4(pid, &status, 0, &usage);
      long long triangles = 0;
      double seconds[3] = { 0, 0, 0 };
      if (got <= 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0 ||
        std::sscanf(buf, "%lld %lf %lf %lf", &triangles, &seconds[0], &seconds[1], &seconds[2]) !=
          4)
      {
        std::fprintf(stderr, "quadcover_bench: case %s failed\n", c.name.c_str());
        continue;
      }
      char row[256];
      std::snprintf(row, sizeof row, "| %s | %lld | %d | %.4f | %.4f | %.4f | %.4f | %.0f |\n",
        c.name.c_str(), triangles, threads, seconds[0], seconds[1], seconds[2],
        seconds[0] + seconds[1] + seconds[2], usage.ru_maxrss / 1024.0);
      table << row;
      std::fputs(row, stderr);
    }
  }
  std::ostringstream doc;
  doc << "Command: `" << command << "` (Release build, best of " << repeat << " runs)\n\n"
      << table.str();
  if (out.empty())
  {
    std::fputs(doc.str().c_str(), stdout);
  }
  else
  {
    std::ofstream(out) << doc.str();
  }
  return 0;
}
