#!/usr/bin/python3
"""Is a change more robust? Builds side by side over a sweep of quad counts.

    /usr/bin/python3 Benchmarks/count_sweep.py BIN [BIN...] [--shared DIR] [--meshes a,b,...]
        [--counts 900,1000,...] [--jobs N] [-- QUADCOVER OPTIONS...]

Runs each quadcover binary (an installed copy of each build, or a script that runs one) on every
mesh at every quad count, and prints per binary the map's defects summed over all runs (points
wound unlike the field, triangles left flipped), the median, mean and largest Hausdorff distance
of the quads (quadcover's own figure, % of the diagonal), how many runs are above 4%, and the
median edge-length RSD; then per mesh the Hausdorff distance of each binary at each count. One
mesh at one count is chaotic (a map's defects move with any change); the sums over the sweep are
what to compare. Two runs at a time by default.
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
    a = parser.parse_args(args)
    meshes = a.meshes.split(",")
    counts = [int(c) for c in a.counts.split(",")]
    work = tempfile.mkdtemp(prefix="count_sweep_")

    def run(job):
        b, mesh, quads = job
        stats = os.path.join(work, "%d_%s_%d.json" % (b, mesh, quads))
        subprocess.run([a.binaries[b], os.path.join(a.shared, mesh + ".obj"),
                        "-o", stats[:-5] + ".vtp", "--target-quad-count", str(quads),
                        "--stats", stats] + options, capture_output=True, check=False)
        if not os.path.exists(stats):
            return job, None
        with open(stats, encoding="utf-8") as f:
            d = json.load(f)
        return job, (d["param"]["winding_errors"], d["param"]["flipped_triangles"][2],
                     d["quads"]["hausdorff_distance"][0], 100 * d["quads"]["edge_length_rsd"])

    jobs = [(b, m, q) for m in meshes for q in counts for b in range(len(a.binaries))]
    with ThreadPoolExecutor(a.jobs) as pool:
        found = dict(pool.map(run, jobs))
    for b, binary in enumerate(a.binaries):
        rows = [found[(b, m, q)] for m in meshes for q in counts if found[(b, m, q)]]
        failed = sum(1 for m in meshes for q in counts if not found[(b, m, q)])
        h = [r[2] for r in rows]
        print("%s: windings %d, flipped %d, Hausdorff median %.2f mean %.2f max %.2f, above 4%%: %d,"
              " edge RSD median %.1f%%, failed %d" % (
                  binary, sum(r[0] for r in rows), sum(r[1] for r in rows), statistics.median(h),
                  statistics.mean(h), max(h), sum(x > 4 for x in h),
                  statistics.median(r[3] for r in rows), failed))
    for m in meshes:
        cells = []
        for q in counts:
            values = [found[(b, m, q)] for b in range(len(a.binaries))]
            cells.append("%d: %s" % (q, " / ".join("%.1f" % v[2] if v else "failed" for v in values)))
        print("%s  %s" % (m, ", ".join(cells)))


if __name__ == "__main__":
    main()
