#!/usr/bin/python3
"""QuadCover against Instant Meshes and QuadriFlow, side by side: the quads' quality.

  peers_quality.py [--data DIR] [--peers DIR] [--quadcover BIN] [--meshes a,b] [--quads N]
                   [--creases DEG] [--sharp DEG]

Every shared mesh (or those listed) is remeshed at about --quads quads by each tool, run as
peers_speed.py runs them (Instant Meshes `-v QUADS/4 -d -b`, QuadriFlow `-f QUADS`, QuadCover
with its defaults and --target-quad-count QUADS), and each output is measured against the input
by the shared evaluator (../shared/tools/quadeval.py): interior irregular vertices, edge-length
and angle RSD, Hausdorff distance in % of the diagonal, faces against the input's normal, χ (the
input's in the first column), and the share of the input's crease points (dihedral angle of
--creases DEG or more, 40 unless given; 0 leaves the column out) that lie on a crease of the quads
(`quadeval.py --creases`; "—" for a mesh without such creases). The last rows give each tool's
medians over the meshes where every tool gave a mesh. --sharp DEG runs the peers with their own
crease options, Instant Meshes `-c DEG` and QuadriFlow `-sharp`, and QuadCover twice, as it is
and with `--feature-lines` (its creases on grid lines). A run that fails, leaves no output or
takes over --timeout seconds shows as "failed" (the evaluator's own failure as "not measured",
with its message on stderr).
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


def measure(evaluator, out, mesh=None, creases=0.0):
    """The evaluator's figures of one output (against mesh, with the crease figures when creases
    is above 0), or None (its message on stderr)."""
    done = subprocess.run([sys.executable, evaluator, out, "--json"] +
                          (["--ref", mesh] if mesh else []) +
                          (["--creases", str(creases)] if mesh and creases > 0 else []),
                          capture_output=True, text=True)
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


def crease_cell(r):
    """The share of crease points kept, in %, or "—" without crease points."""
    share = r.get("crease_kept_share")
    return "—" if not r.get("crease_samples") or share is None else "%.0f%%" % (100 * share)


def row(name, chi, tool, r, why="failed", creases=False):
    if r is None:
        return "| %s (%s) | %s | %s | | | | | |%s" % (name, chi, tool, why,
                                                      " |" if creases else "")
    return "| %s (%s) | %s | %d | %.1f | %.1f | %.2f | %d | %d |" % (
        (name, chi, tool) + tuple(r[k] for k in KEYS)) + (
        " %s |" % crease_cell(r) if creases else "")


def tool_commands(args, mesh, scratch):
    """The runs of one mesh by tool name: as peers_speed.py runs them, or with --sharp each
    tool's crease options (and QuadCover both ways)."""
    tools = commands(args, mesh, scratch)
    if args.sharp <= 0:
        return tools
    return {
        "QuadCover": tools["QuadCover"],
        "QuadCover --feature-lines": tools["QuadCover"] + ["--feature-lines"],
        "Instant Meshes -c %g" % args.sharp: tools["Instant Meshes"] + ["-c", "%g" % args.sharp],
        "QuadriFlow -sharp": tools["QuadriFlow"] + ["-sharp"],
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    tool_arguments(parser)
    parser.add_argument("--evaluator",
                        default=os.path.join(HERE, "..", "..", "shared", "tools", "quadeval.py"))
    parser.add_argument("--timeout", type=float, default=600.0)
    parser.add_argument("--creases", type=float, default=40.0)
    parser.add_argument("--sharp", type=float, default=0.0)
    args = parser.parse_args()
    args.quadriflow = True
    evaluator = args.evaluator
    for tool in (args.quadcover, os.path.join(args.peers, "instant-meshes"),
                 os.path.join(args.peers, "quadriflow"), evaluator):
        if not os.path.exists(tool):
            sys.exit("peers_quality.py: error: not found: " + tool)
    names = ["QuadCover", "Instant Meshes", "QuadriFlow"]
    if args.sharp > 0:
        names = ["QuadCover", "QuadCover --feature-lines", "Instant Meshes -c %g" % args.sharp,
                 "QuadriFlow -sharp"]
    creases = args.creases > 0
    print("| mesh (input χ) | tool | irregular | RSD edge % | RSD angle % | Hausdorff % | "
          "flip | χ |" + (" creases |" if creases else ""))
    print("|---|---|---:|---:|---:|---:|---:|---:|" + ("---:|" if creases else ""))
    found = {n: {} for n in names}
    with tempfile.TemporaryDirectory() as scratch:
        for name, mesh in shared_meshes(args, "peers_quality.py"):
            figures = measure(evaluator, mesh)
            chi = figures["euler"] if figures else "?"
            for tool, command in tool_commands(args, mesh, scratch).items():
                out = run(command, args.timeout)
                r = measure(evaluator, out, mesh, args.creases) if out else None
                if r is not None:
                    found[tool][name] = r
                print(row(name, chi, tool, r, "failed" if out is None else "not measured",
                          creases), flush=True)
    common = [m for m in found["QuadCover"] if all(m in found[n] for n in names)]
    if not common:
        return
    print()
    print("Medians over the %d meshes all %s remeshed:" %
          (len(common), {3: "three", 4: "four"}.get(len(names), str(len(names)))))
    print()
    print("| tool | irregular | RSD edge % | RSD angle % | Hausdorff % |")
    print("|---|---:|---:|---:|---:|")
    for n in names:
        med = [statistics.median(found[n][m][k] for m in common) for k in KEYS[:4]]
        print("| %s | %.0f | %.1f | %.1f | %.2f |" % tuple([n] + med))


if __name__ == "__main__":
    main()
