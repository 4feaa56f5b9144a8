#!/usr/bin/python3
"""The quality issue's table: every shared mesh remeshed at QUADS quads, measured by the shared
evaluator (../shared/tools/quadeval.py), beside QuadriFlow's irregular count from the peers' table.

    /usr/bin/python3 Benchmarks/evenness_table.py [--shared DIR] [--quads N]
        [--quadcover BIN] [--creases DEG] [--meshes a,b,...] [-- QUADCOVER OPTIONS...]

Prints one Markdown row per mesh (irregular inner vertices, edge-length and angle RSD, Hausdorff
distance in % of the diagonal, faces against the input's normal, χ against the input's), then the
medians over the meshes that have a QuadriFlow figure (the truck has none: QuadriFlow fails on
it) and the meshes that miss the per-mesh bars (edge RSD above 14%, irregular vertices not below
QuadriFlow's). With --creases DEG a last column gives the share of the input's crease points
(dihedral angle of DEG or more) that lie on a crease of the quads (`quadeval.py --creases`).
--meshes runs only the meshes listed. Run after `bash Scripts/build.sh`; all meshes take about a
minute on 2 cores.
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile

MESHES = ["3holes", "armadillo", "bumpy-cube", "bunny-lowres", "cheburashka", "decimated-knight",
          "fandisk", "fertility", "lion", "rocker-arm", "screwdriver", "spot", "teapot", "truck"]


def quadriflow_irregular(shared):
    """QuadriFlow's interior irregular vertices per mesh, from the peers' README table."""
    found = {}
    readme = os.path.join(shared, "..", "peers", "README.md")
    if os.path.exists(readme):
        with open(readme, encoding="utf-8") as lines:
            table = lines.read().splitlines()
        for line in table:
            m = re.match(r"\| (\S+) \(-?\d+\) \| QuadriFlow \| (\d+) \|", line)
            if m:
                found[m.group(1)] = int(m.group(2))
    return found


def main():
    args = sys.argv[1:]
    options = args[args.index("--") + 1:] if "--" in args else []
    args = args[:args.index("--")] if "--" in args else args
    parser = argparse.ArgumentParser()
    parser.add_argument("--shared", default="../shared/data")
    parser.add_argument("--quads", type=int, default=6500)
    parser.add_argument("--quadcover", default="build/bin/quadcover")
    parser.add_argument("--creases", type=float, default=0.0)
    parser.add_argument("--meshes", default=",".join(MESHES))
    a = parser.parse_args(args)
    evaluator = os.path.join(a.shared, "..", "tools", "quadeval.py")
    if not os.path.exists(evaluator):
        sys.exit("evenness_table.py: no evaluator at %s" % evaluator)
    peer = quadriflow_irregular(a.shared)
    crease = ["--creases", str(a.creases)] if a.creases > 0 else []
    print("| mesh | irregular (QuadriFlow) | RSD edge % | RSD angle % | Hausdorff % | flip | χ |" +
          (" creases kept |" if crease else ""))
    print("|---|---:|---:|---:|---:|---:|---:|" + ("---:|" if crease else ""))
    rows = {}
    with tempfile.TemporaryDirectory() as tmp:
        for name in a.meshes.split(","):
            mesh = os.path.join(a.shared, name + ".obj")
            if not os.path.exists(mesh):
                print("| %s | not found: %s |" % (name, mesh) + " |" * (5 if not crease else 6))
                continue
            out = os.path.join(tmp, name + ".vtp")
            run = subprocess.run([a.quadcover, mesh, "-o", out, "--target-quad-count",
                                  str(a.quads)] + options, capture_output=True, text=True)
            columns = " |" * (6 if not crease else 7)  # the empty cells after the message
            if run.returncode != 0 or not os.path.exists(out):
                last = (run.stderr.strip().splitlines() or ["no output"])[-1]
                print("| %s | quadcover failed: %s |" % (name, last) + columns[2:])
                continue
            figures = subprocess.run([sys.executable, evaluator, out, "--ref", mesh, "--json"] +
                                     crease, capture_output=True, text=True)
            if figures.returncode != 0:
                print("| %s | the evaluator failed |" % name + columns[2:])
                continue
            r = json.loads(figures.stdout)
            rows[name] = r
            kept = r.get("crease_kept_share")
            print("| %s | %d (%s) | %.1f | %.1f | %.2f | %d | %d |" % (
                name, r["irregular_interior"], peer.get(name, "—"), r["rsd_edge_pct"],
                r["rsd_angle_pct"], r["hausdorff_pct_diag"], r["faces_against_ref_normal"],
                r["euler"]) + ((" %s |" % ("—" if kept is None else "%.0f%%" % (100 * kept)))
                               if crease else ""))
    ranked = {n: r for n, r in rows.items() if n in peer}
    if not ranked:
        return
    def median(key):
        return statistics.median(r[key] for r in ranked.values())
    print()
    print("Medians over %d meshes: irregular %.0f, edge RSD %.1f%%, angle RSD %.1f%%, "
          "Hausdorff %.2f%%" % (len(ranked), median("irregular_interior"),
                                median("rsd_edge_pct"), median("rsd_angle_pct"),
                                median("hausdorff_pct_diag")))
    missed = [n for n, r in ranked.items()
              if r["rsd_edge_pct"] > 14 or r["irregular_interior"] >= peer[n]]
    print("Edge RSD above 14%% or irregular not below QuadriFlow's: %s" %
          (", ".join(missed) if missed else "none"))


if __name__ == "__main__":
    main()
