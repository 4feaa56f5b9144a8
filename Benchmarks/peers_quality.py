#!/usr/bin/python3
"""QuadCover against Instant Meshes and QuadriFlow, side by side: the quads' quality.

  peers_quality.py [--data DIR] [--peers DIR] [--quadcover BIN] [--meshes a,b] [--quads N]

Every shared mesh (or those listed) is remeshed at about --quads quads by each tool, run as
peers_speed.py runs them (Instant Meshes `-v QUADS/4 -d -b`, QuadriFlow `-f QUADS`, QuadCover
with its defaults and --target-quad-count QUADS), and each output is measured against the input
by the shared evaluator (../shared/tools/quadeval.py): interior irregular vertices, edge-length
and angle RSD, Hausdorff distance in % of the diagonal, faces against the input's normal, χ (the
input's in the first column). The last rows give each tool's medians over the meshes where all
three gave a mesh. A run that fails or leaves no output shows as "failed".
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

from peers_speed import HERE, MESHES, commands

KEYS = ("irregular_interior", "rsd_edge_pct", "rsd_angle_pct", "hausdorff_pct_diag",
        "faces_against_ref_normal", "euler")


def measure(evaluator, out, mesh=None):
    """The evaluator's figures of one output (against mesh), or None."""
    done = subprocess.run([sys.executable, evaluator, out, "--json"] +
                          (["--ref", mesh] if mesh else []), capture_output=True, text=True)
    return json.loads(done.stdout) if done.returncode == 0 else None


def row(name, chi, tool, r):
    if r is None:
        return "| %s (%s) | %s | failed | | | | | |" % (name, chi, tool)
    return "| %s (%s) | %s | %d | %.1f | %.1f | %.2f | %d | %d |" % (
        (name, chi, tool) + tuple(r[k] for k in KEYS))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--data", default=os.path.join(HERE, "..", "..", "shared", "data"))
    parser.add_argument("--peers", default=os.path.join(HERE, "..", "..", "shared", "peers", "bin"))
    parser.add_argument("--quadcover", default=os.path.join(HERE, "..", "build", "bin", "quadcover"))
    parser.add_argument("--meshes", default=",".join(MESHES))
    parser.add_argument("--quads", type=int, default=6500)
    args = parser.parse_args()
    args.quadriflow = True
    evaluator = os.path.join(args.data, "..", "tools", "quadeval.py")
    for tool in (args.quadcover, os.path.join(args.peers, "instant-meshes"),
                 os.path.join(args.peers, "quadriflow"), evaluator):
        if not os.path.exists(tool):
            sys.exit("peers_quality.py: error: not found: " + tool)
    names = ["QuadCover", "Instant Meshes", "QuadriFlow"]
    print("| mesh (input χ) | tool | irregular | RSD edge % | RSD angle % | Hausdorff % | "
          "flip | χ |")
    print("|---|---|---:|---:|---:|---:|---:|---:|")
    found = {n: {} for n in names}
    with tempfile.TemporaryDirectory() as scratch:
        for name in args.meshes.split(","):
            mesh = os.path.join(args.data, name + ".obj")
            if not os.path.exists(mesh):
                print("peers_quality.py: skipped, not found: " + mesh, file=sys.stderr)
                continue
            chi = measure(evaluator, mesh)["euler"]
            for tool, command in commands(args, mesh, scratch).items():
                out = command[command.index("-o") + 1]
                done = subprocess.run(command, stdout=subprocess.DEVNULL,
                                      stderr=subprocess.DEVNULL)
                r = None
                if done.returncode == 0 and os.path.exists(out) and os.path.getsize(out) > 0:
                    r = measure(evaluator, out, mesh)
                    os.remove(out)
                if r is not None:
                    found[tool][name] = r
                print(row(name, chi, tool, r), flush=True)
    common = [m for m in found["QuadCover"] if all(m in found[n] for n in names)]
    if not common:
        return
    print()
    print("Medians over the %d meshes all three remeshed:" % len(common))
    print()
    print("| tool | irregular | RSD edge % | RSD angle % | Hausdorff % |")
    print("|---|---:|---:|---:|---:|")
    for n in names:
        med = [statistics.median(found[n][m][k] for m in common) for k in KEYS[:4]]
        print("| %s | %.0f | %.1f | %.1f | %.2f |" % tuple([n] + med))


if __name__ == "__main__":
    main()
