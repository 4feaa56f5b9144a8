#!/usr/bin/python3
"""Is a quad mesh a valid remesh of its input?  validity.py QUADS INPUT [--json]

Compares the components of QUADS with those of INPUT (the repaired input surface, as
`quadcover IN -o REF.vtp --stage repair` writes it): per component the Euler characteristic and
the number of boundary loops, as multisets, and counts the points of QUADS where faces touch in
separate fans (pinched points). Uses ../shared/tools/quadeval.py (the independent ruler) for the
faces against the input's normal, non-manifold and misoriented edges.
"""
import json
import os
import subprocess
import sys
from collections import defaultdict

import vtk
from vtk.util.numpy_support import vtk_to_numpy


def read(path):
    r = vtk.vtkXMLPolyDataReader() if path.endswith(".vtp") else vtk.vtkOBJReader()
    r.SetFileName(path)
    r.Update()
    return r.GetOutput()


def faces(pd):
    polys = pd.GetPolys()
    if polys.GetNumberOfCells() == 0:
        return []
    conn = vtk_to_numpy(polys.GetConnectivityArray()).tolist()
    offs = vtk_to_numpy(polys.GetOffsetsArray()).tolist()
    return [conn[offs[i]:offs[i + 1]] for i in range(len(offs) - 1)]


class Sets:
    """Disjoint sets of hashable items (union-find with path halving); an item joins when first
    met, as a set of its own."""

    def __init__(self):
        self.parent = {}

    def find(self, a):
        parent = self.parent
        while parent.setdefault(a, a) != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    def union(self, a, b):
        ra, rb = self.find(a), self.find(b)
        if ra != rb:
            self.parent[ra] = rb


def join_points(F):
    """(find, parent): the points of F joined through the faces (union-find); find(p) is the
    root of p's connected piece, parent has every point."""
    pieces = Sets()
    for f in F:
        for v in f[1:]:
            pieces.union(f[0], v)
    return pieces.find, pieces.parent


def components(F):
    """Per connected component (through shared points): (Euler characteristic, boundary loops)."""
    find, parent = join_points(F)
    edges = defaultdict(int)
    for f in F:
        for k in range(len(f)):
            a, b = f[k], f[(k + 1) % len(f)]
            edges[(min(a, b), max(a, b))] += 1
    comp = defaultdict(lambda: [0, 0, 0])  # V, E, F
    for v in parent:
        comp[find(v)][0] += 1
    for (a, b) in edges:
        comp[find(a)][1] += 1
    for f in F:
        comp[find(f[0])][2] += 1
    loops = defaultdict(int)
    boundary = Sets()
    for (a, b), n in edges.items():
        if n == 1:
            boundary.union(a, b)
    for v in boundary.parent:
        if boundary.find(v) == v:
            loops[find(v)] += 1
    return sorted((c[0] - c[1] + c[2], loops[r]) for r, c in comp.items())


def pinched_points(F):
    """Points whose faces fall into several fans (joined only through the point: two pieces, or
    two boundary loops, touching there); a manifold mesh has none. quadeval.py checks the edges
    only."""
    around = defaultdict(list)
    for i, f in enumerate(F):
        for k, v in enumerate(f):
            around[v].append((i, f[(k + 1) % len(f)], f[k - 1]))
    pinched = 0
    for v, corners in around.items():
        fans, first = Sets(), {}
        for i, after, before in corners:
            for w in (after, before):
                if w != v:
                    fans.union(i, first.setdefault(w, i))
        pinched += len({fans.find(i) for i, _, _ in corners}) > 1
    return pinched


def main():
    out, ref = sys.argv[1], sys.argv[2]
    quads, surface = faces(read(out)), faces(read(ref))
    qc, sc = components(quads), components(surface)
    ruler = os.path.join(os.path.dirname(__file__), "..", "..", "shared", "tools", "quadeval.py")
    q = json.loads(subprocess.run(["/usr/bin/python3", ruler, out, "--ref", ref, "--json"],
                                  check=True, capture_output=True, text=True).stdout)
    res = {
        "non_quads": q["non_quads"], "faces": q["faces"],
        "nonmanifold_edges": q["nonmanifold_edges"], "misoriented_edges": q["misoriented_edges"],
        "pinched_points": pinched_points(quads),
        "against_normal": q["faces_against_ref_normal"], "hausdorff_pct": q["hausdorff_pct_diag"],
        "components": [len(qc), len(sc)], "chi": [sum(c[0] for c in qc), sum(c[0] for c in sc)],
        "loops": [sum(c[1] for c in qc), sum(c[1] for c in sc)],
        "irregular": q["irregular_interior"], "rsd_edge": q["rsd_edge_pct"],
    }
    res["valid"] = (q["faces"] > 0 and q["non_quads"] == 0 and q["nonmanifold_edges"] == 0
                    and q["misoriented_edges"] == 0 and res["pinched_points"] == 0
                    and q["faces_against_ref_normal"] == 0 and qc == sc)
    print(json.dumps(res))


if __name__ == "__main__":
    main()
