#!/usr/bin/python3
"""Six shared scans with holes cut out along their triangles: a family of scans with holes, whose
boundaries step along the triangles and whose holes sometimes nearly meet.

    /usr/bin/python3 Benchmarks/holed_scans.py SHARED_DIR OUTDIR

Writes OUTDIR/NAME_h.obj for spot (8 holes), bunny (bunny-lowres, 6), armadillo (10), fertility
(8), rocker (rocker-arm, 6) and cheb (cheburashka, 12): around triangles chosen at random, every
triangle whose centre lies within r of the chosen one's is removed, r a fraction of the diagonal
(spot 0.04, bunny 0.05, armadillo 0.02, fertility and rocker 0.03, cheb 0.02) times a factor
drawn from [0.5, 1.5]; each surface has its own seed. `Benchmarks/validity_table.sh` with
`GENERATED=OUTDIR` measures them (Benchmarks/README.md, 2026-12-06 (9)).
"""
import os
import sys

import numpy as np

# name, shared mesh, holes, radius over the diagonal, seed
SCANS = [
    ("spot_h", "spot", 8, 0.04, 1),
    ("bunny_h", "bunny-lowres", 6, 0.05, 2),
    ("armadillo_h", "armadillo", 10, 0.02, 3),
    ("fertility_h", "fertility", 8, 0.03, 4),
    ("rocker_h", "rocker-arm", 6, 0.03, 5),
    ("cheb_h", "cheburashka", 12, 0.02, 6),
]


def read_obj(path):
    """Points and triangles (polygons fanned) of an OBJ file."""
    V, F = [], []
    with open(path) as f:
        for line in f:
            t = line.split()
            if not t:
                continue
            if t[0] == "v":
                V.append([float(x) for x in t[1:4]])
            elif t[0] == "f":
                idx = [int(x.split("/")[0]) for x in t[1:]]
                F.extend([idx[0] - 1, idx[k] - 1, idx[k + 1] - 1] for k in range(1, len(idx) - 1))
    return np.array(V), np.array(F)


def cut_holes(V, F, holes, fraction, seed):
    """The surface without the triangles whose centres lie within a radius of `holes` random
    triangles' centres, its unused points dropped."""
    diagonal = np.linalg.norm(V.max(0) - V.min(0))
    rng = np.random.default_rng(seed)
    middle = V[F].mean(1)
    keep = np.ones(len(F), bool)
    for c in rng.choice(len(F), holes, replace=False):
        radius = fraction * diagonal * rng.uniform(0.5, 1.5)
        keep &= np.linalg.norm(middle - middle[c], axis=1) > radius
    F = F[keep]
    used = np.unique(F)
    renumber = -np.ones(len(V), int)
    renumber[used] = np.arange(len(used))
    return V[used], renumber[F]


def main():
    shared, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    for name, mesh, holes, fraction, seed in SCANS:
        V, F = cut_holes(*read_obj(os.path.join(shared, mesh + ".obj")), holes, fraction, seed)
        with open(os.path.join(out, name + ".obj"), "w") as o:
            for v in V:
                o.write("v %.9g %.9g %.9g\n" % tuple(v))
            for f in F:
                o.write("f %d %d %d\n" % tuple(f + 1))


if __name__ == "__main__":
    main()
