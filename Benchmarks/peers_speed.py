#!/usr/bin/python3
"""QuadCover against Instant Meshes and QuadriFlow, side by side: wall time and peak memory.

  peers_speed.py [--data DIR] [--peers DIR] [--quadcover BIN] [--meshes a,b] [--levels 0,1]
                 [--runs N] [--quads N] [--no-quadriflow]

Every shared mesh (or those listed), as it is (level 0) and refined by Loop subdivision (level 1:
4 times the triangles, 2: 16, 3: 64), is remeshed at about --quads quads by each tool in turn,
run after run (so that the machine's drift hits every tool alike), --runs times; the table has
each tool's median wall time and peak resident memory (the whole process, /usr/bin/time), and
the ratios QuadCover / Instant Meshes. The peers run as the shared figures were made: Instant
Meshes `-v QUADS/4 -d -b` (pure quads: its count applies before its final subdivision),
QuadriFlow `-f QUADS`; QuadCover with its defaults and --target-quad-count QUADS, without the
Hausdorff distance it measures for its statistics (the peers measure nothing).
A run that fails or leaves no output shows as "failed".
Before the first run it waits (up to --settle seconds, default 120) until the one-minute load
average is below 0.5: right after a build or another benchmark, libgomp's dynamic adjustment
gives CHOLMOD's parallel loops fewer threads (the cores less the load average), and QuadCover
then reads slower (armadillo 3.9 against 3.5 s).
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

import vtk

from refine import refined

HERE = os.path.dirname(os.path.abspath(__file__))
MESHES = ("bunny-lowres spot fandisk rocker-arm cheburashka teapot armadillo bumpy-cube "
          "decimated-knight lion screwdriver 3holes fertility truck").split()


def write_obj(polydata, path):
    """Writes the triangles of polydata as OBJ (both peers read it)."""
    points = polydata.GetPoints()
    with open(path, "w") as f:
        for i in range(points.GetNumberOfPoints()):
            f.write("v %.9g %.9g %.9g\n" % points.GetPoint(i))
        ids = vtk.vtkIdList()
        polys = polydata.GetPolys()
        polys.InitTraversal()
        while polys.GetNextCell(ids):
            f.write("f " + " ".join(str(ids.GetId(k) + 1) for k in range(ids.GetNumberOfIds())) +
                    "\n")


def prepared(path, level, scratch):
    """The mesh as OBJ, refined `level` times (merged and triangulated first); its triangles."""
    last = refined(path, level)
    if level == 0:
        out = path  # the file itself: every tool reads what a user would give it
    else:
        out = os.path.join(scratch, "%s-%d.obj" % (os.path.basename(path)[:-4], level))
        write_obj(last.GetOutput(), out)
    return out, last.GetOutput().GetNumberOfPolys()


def timed(command, scratch):
    """(seconds, peak MB) of one run, or None when it failed."""
    stats = os.path.join(scratch, "time.txt")
    done = subprocess.run(["/usr/bin/time", "-f", "%e %M", "-o", stats] + command,
                          stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    output = command[command.index("-o") + 1]
    if done.returncode != 0 or not os.path.exists(output) or os.path.getsize(output) == 0:
        return None
    seconds, kilobytes = open(stats).read().split()[-2:]
    os.remove(output)
    return float(seconds), float(kilobytes) / 1024.0


def commands(args, mesh, scratch):
    out = os.path.join(scratch, "out")
    tools = {
        "QuadCover": [args.quadcover, mesh, "-o", out + ".vtp", "--target-quad-count",
                      str(args.quads), "--no-compute-hausdorff-distance"],
        "Instant Meshes": [os.path.join(args.peers, "instant-meshes"), mesh, "-o", out + ".obj",
                           "-v", str(args.quads // 4), "-d", "-b"],
    }
    if args.quadriflow:
        tools["QuadriFlow"] = [os.path.join(args.peers, "quadriflow"), "-i", mesh, "-o",
                               out + ".obj", "-f", str(args.quads)]
    return tools


def tool_arguments(parser):
    """The options peers_speed.py and peers_quality.py share: where the meshes, the peers and
    QuadCover are, which meshes, how many quads."""
    parser.add_argument("--data", default=os.path.join(HERE, "..", "..", "shared", "data"))
    parser.add_argument("--peers", default=os.path.join(HERE, "..", "..", "shared", "peers", "bin"))
    parser.add_argument("--quadcover", default=os.path.join(HERE, "..", "build", "bin", "quadcover"))
    parser.add_argument("--meshes", default=",".join(MESHES))
    parser.add_argument("--quads", type=int, default=6500)


def shared_meshes(args, script):
    """(name, path) of each mesh of --meshes in --data; one missing is said and skipped."""
    for name in args.meshes.split(","):
        path = os.path.join(args.data, name + ".obj")
        if os.path.exists(path):
            yield name, path
        else:
            print("%s: skipped, not found: %s" % (script, path), file=sys.stderr)


def wait_for_quiet(limit):
    """Waits until the one-minute load average is below 0.5, at most `limit` seconds; says so on
    stderr when it gives up."""
    start = time.monotonic()
    while os.getloadavg()[0] >= 0.5:
        if time.monotonic() - start >= limit:
            print("peers_speed.py: the load average is still %.2f after %.0f s; measuring anyway"
                  % (os.getloadavg()[0], limit), file=sys.stderr)
            return
        time.sleep(5)


def cell(values, fmt):
    return fmt % statistics.median(values) if values else "failed"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    tool_arguments(parser)
    parser.add_argument("--levels", default="0")
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--no-quadriflow", dest="quadriflow", action="store_false")
    parser.add_argument("--settle", type=float, default=120.0,
                        help="seconds to wait at most for a quiet machine first (0: none)")
    args = parser.parse_args()
    for tool in (args.quadcover, os.path.join(args.peers, "instant-meshes")):
        if not os.access(tool, os.X_OK):
            sys.exit("peers_speed.py: error: not found: " + tool)
    names = ["QuadCover", "Instant Meshes"] + (["QuadriFlow"] if args.quadriflow else [])
    wait_for_quiet(args.settle)
    print("| mesh | triangles | " + " | ".join(n + " s" for n in names) + " | " +
          " | ".join(n + " MB" for n in names) + " | time QC/IM | memory QC/IM |")
    print("|---|---:|" + "---:|" * (2 * len(names) + 2))
    with tempfile.TemporaryDirectory() as scratch:
        for name, path in shared_meshes(args, "peers_speed.py"):
            for level in (int(v) for v in args.levels.split(",")):
                mesh, triangles = prepared(path, level, scratch)
                runs = {n: [] for n in names}
                for _ in range(args.runs):
                    for n, command in commands(args, mesh, scratch).items():
                        result = timed(command, scratch)
                        if result:
                            runs[n].append(result)
                seconds = {n: [r[0] for r in runs[n]] for n in names}
                memory = {n: [r[1] for r in runs[n]] for n in names}
                qc, im = "QuadCover", "Instant Meshes"
                both = seconds[qc] and seconds[im]
                label = name + ("" if level == 0 else " x%d" % 4 ** level)
                print("| %s | %d | " % (label, triangles) +
                      " | ".join(cell(seconds[n], "%.2f") for n in names) + " | " +
                      " | ".join(cell(memory[n], "%.0f") for n in names) + " | " +
                      ("%.2f | %.2f |" % (statistics.median(seconds[qc]) / statistics.median(
                          seconds[im]), statistics.median(memory[qc]) / statistics.median(
                              memory[im])) if both else "— | — |"), flush=True)


if __name__ == "__main__":
    main()
