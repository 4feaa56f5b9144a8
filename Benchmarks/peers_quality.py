#!/usr/bin/python3
"""QuadCover against Instant Meshes and QuadriFlow, side by side: the quads' quality.

  peers_quality.py [--data DIR] [--peers DIR] [--quadcover BIN] [--meshes a,b] [--quads N]

Every shared mesh (or those listed) is remeshed at about --quads quads by each tool, run as
peers_speed.py runs them (Instant Meshes `-v QUADS/4 -d -b`, QuadriFlow `-f QUADS`, QuadCover
with its defaults and --target-quad-count QUADS), and each output is measured against the input
by the shared evaluator (../shared/tools/quadeval.py): interior irregular vertices, edge-length
and angle RSD, Hausdorff distance in % of the diagonal, faces against the input's normal, χ (the
input's in the first column). The last rows give each tool's medians over the meshes where all
three gave a mesh. A run that fails, leaves no output or takes over --timeout seconds shows as
"failed" (the evaluator's own failure as "not measured", with its message on stderr).
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile

from peers_speed import HERE, commands, shared_meshes, tool_arguments

KEYS = ("irregular_interior", "rsd_edge_pct", "rsd_angle_pct", "hausdorff_pct_diag",
        "faces_against_ref_normal", "euler")


def measure(evaluator, out, mesh=None):
    """The evaluator's figures of one output (against mesh), or None (its message on stderr)."""
    done = subprocess.run([sys.executable, evaluator, out, "--json"] +
                          (["--ref", mesh] if mesh else []), capture_output=True, text=True)
    if done.returncode != 0:
        print("peers_quality.py: the evaluator failed on %s: %s" % (out, done.stderr.strip()),
              file=sys.stderr)
        return None
    return json.loads(done.stdout)


def run(command, timeout):
    """The output file of one run of a tool, or None when it failed or left none."""
    out = command[command.index("-o") + 1]
    if os.path.exists(out):
        os.remove(out)
    try:
        done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                              timeout=timeout)
    except subprocess.TimeoutExpired:
        return None
    if done.returncode != 0 or not os.path.exists(out) or os.path.getsize(out) == 0:
        return None
    return out


def row(name, chi, tool, r, why="failed"):
    if r is None:
        return "| %s (%s) | %s | %s | | | | | |" % (name, chi, tool, why)
    return "| %s (%s) | %s | %d | %.1f | %.1f | %.2f | %d | %d |" % (
        (name, chi, tool) + tuple(r[k] for k in KEYS))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    tool_arguments(parser)
    parser.add_argument("--evaluator",
                        default=os.path.join(HERE, "..", "..", "shared", "tools", "quadeval.py"))
    parser.add_argument("--timeout", type=float, default=600.0)
    args = parser.parse_args()
    args.quadriflow = True
    evaluator = args.evaluator
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
        for name, mesh in shared_meshes(args, "peers_quality.py"):
            figures = measure(evaluator, mesh)
            chi = figures["euler"] if figures else "?"
            for tool, command in commands(args, mesh, scratch).items():
                out = run(command, args.timeout)
                r = measure(evaluator, out, mesh) if out else None
                if r is not None:
                    found[tool][name] = r
                print(row(name, chi, tool, r, "failed" if out is None else "not measured"),
                      flush=True)
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
