#!/usr/bin/python3
"""Is a change more robust? Builds side by side over a sweep of quad counts.

    /usr/bin/python3 Benchmarks/count_sweep.py BIN [BIN...] [--shared DIR] [--meshes a,b,...]
        [--counts 900,1000,...] [--jobs N] [--evaluate] [-- QUADCOVER OPTIONS...]

Runs each quadcover binary (an installed copy of each build, or a script that runs one) on every
mesh at every quad count, and prints per binary the map's defects summed over all runs (points
wound unlike the field, triangles left flipped), the median, mean and largest Hausdorff distance
of the quads (quadcover's own figure, % of the diagonal), how many runs are above 4%, and the
median edge-length RSD, and the seconds the stages took (their sum, the median run, the
slowest runs); then per mesh the Hausdorff distance of each binary at each count. One
mesh at one count is chaotic (a map's defects move with any change); the sums over the sweep are
what to compare. Two runs at a time by default. A mesh named with an extension
(`--meshes /tmp/armadillo4.vtp,spot`) is that file, not one of the shared meshes: refined or
generated surfaces. `--evaluate` also measures every output with the shared evaluator
(`../shared/tools/quadeval.py OUT --ref IN`) and prints per binary the faces against the input's
normal summed over the sweep and the runs whose quads' Euler characteristic is not the input's
(as the evaluator reads the input: a file that repeats its points along seams, as the teapot's
does, reads with another one).
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor

MESHES = ["cheburashka", "armadillo", "lion", "decimated-knight", "bunny-lowres", "fandisk", "spot",
          "rocker-arm", "teapot", "fertility"]
COUNTS = [900, 1000, 1200, 1500, 2000, 3000, 4500]
QUADEVAL = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "shared", "tools",
                        "quadeval.py")


def main():
    args = sys.argv[1:]
    options = args[args.index("--") + 1:] if "--" in args else []
    args = args[:args.index("--")] if "--" in args else args
    parser = argparse.ArgumentParser()
    parser.add_argument("binaries", nargs="+")
    parser.add_argument("--shared", default="../shared/data")
    parser.add_argument("--meshes", default=",".join(MESHES))
    parser.add_argument("--counts", default=",".join(str(c) for c in COUNTS))
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--evaluate", action="store_true")
    a = parser.parse_args(args)
    meshes = a.meshes.split(",")
    counts = [int(c) for c in a.counts.split(",")]
    work = tempfile.mkdtemp(prefix="count_sweep_")

    def path_of(mesh):
        return mesh if os.path.splitext(mesh)[1] else os.path.join(a.shared, mesh + ".obj")

    def evaluate(out, mesh):
        """(faces against the input's normal, Euler characteristic) of the quads in `out`."""
        if not os.path.exists(out):
            return None
        r = subprocess.run(["/usr/bin/python3", QUADEVAL, out, "--ref", path_of(mesh)],
                           capture_output=True, text=True, check=False).stdout
        d = dict(line.split(None, 1) for line in r.splitlines() if line.strip())
        return int(d["faces_against_ref_normal"]), int(d["euler"])

    def run(job):
        b, mesh, quads = job
        stats = os.path.join(work, "%d_%s_%d.json" % (b, os.path.basename(mesh), quads))
        out = stats[:-5] + ".vtp"
        subprocess.run([a.binaries[b], path_of(mesh), "-o", out, "--target-quad-count",
                        str(quads), "--stats", stats] + options, capture_output=True, check=False)
        if not os.path.exists(stats):
            return job, None
        with open(stats, encoding="utf-8") as f:
            d = json.load(f)
        return job, (d["param"]["winding_errors"], d["param"]["flipped_triangles"][2],
                     d["quads"]["hausdorff_distance"][0], 100 * d["quads"]["edge_length_rsd"],
                     evaluate(out, mesh) if a.evaluate else None, sum(d["seconds"].values()))

    jobs = [(b, m, q) for m in meshes for q in counts for b in range(len(a.binaries))]
    with ThreadPoolExecutor(a.jobs) as pool:
        found = dict(pool.map(run, jobs))
    # the inputs' own Euler characteristic, as the evaluator reads them (once: the evaluator
    # also measures their distance to themselves)
    input_euler = {m: evaluate(path_of(m), m)[1] for m in meshes} if a.evaluate else {}
    for b, binary in enumerate(a.binaries):
        rows = [found[(b, m, q)] for m in meshes for q in counts if found[(b, m, q)]]
        failed = sum(1 for m in meshes for q in counts if not found[(b, m, q)])
        h = [r[2] for r in rows]
        print("%s: windings %d, flipped %d, Hausdorff median %.2f mean %.2f max %.2f, above 4%%: %d,"
              " edge RSD median %.1f%%, failed %d" % (
                  binary, sum(r[0] for r in rows), sum(r[1] for r in rows), statistics.median(h),
                  statistics.mean(h), max(h), sum(x > 4 for x in h),
                  statistics.median(r[3] for r in rows), failed))
        timed = sorted(((found[(b, m, q)][5], m, q) for m in meshes for q in counts
                        if found[(b, m, q)]), reverse=True)
        print("  seconds (the stages', %d runs at a time): total %.1f, median %.2f, over 5 s: %d,"
              " slowest %s" % (a.jobs, sum(t[0] for t in timed), statistics.median(t[0] for t in timed),
                               sum(t[0] > 5 for t in timed), ", ".join(
                                   "%s at %d %.1f" % (os.path.basename(m), q, t)
                                   for t, m, q in timed[:5])))
        if a.evaluate:
            judged = [(m, found[(b, m, q)][4]) for m in meshes for q in counts
                      if found[(b, m, q)] and found[(b, m, q)][4]]
            print("  faces against the input's normal %d (in %d runs), Euler characteristic not the"
                  " input's in %d runs" % (sum(e[0] for _, e in judged),
                                          sum(e[0] > 0 for _, e in judged),
                                          sum(e[1] != input_euler[m] for m, e in judged)))
    for m in meshes:
        cells = []
        for q in counts:
            values = [found[(b, m, q)] for b in range(len(a.binaries))]
            cells.append("%d: %s" % (q, " / ".join("%.1f" % v[2] if v else "failed" for v in values)))
        print("%s  %s" % (os.path.basename(m), ", ".join(cells)))


if __name__ == "__main__":
    main()
