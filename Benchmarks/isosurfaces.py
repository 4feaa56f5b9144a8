#!/usr/bin/python3
"""Isosurfaces as visualization pipelines make them: vtkFlyingEdges3D on sampled scalar fields,
cut by the volume's faces. Their triangles are the marching cubes' (slivers, fans at the
voxels' corners), their pieces at the volume's faces are thin slivers with sharp tips, and
their saddles leave necks far thinner than the rest.

    /usr/bin/python3 Benchmarks/isosurfaces.py OUTDIR

Writes OUTDIR/NAME.obj:
- iso_blobs: the sum of 60 Gaussians (radii 0.02-0.12, centres 0.1 or more inside the cube) on
  a 96^3 grid, level 0.5 (3 components, 105k triangles, cut by the volume; necks at saddles);
- iso_cut: the sum of 400 such Gaussians on a 128^3 grid, level 0.3 (3 components, 58k
  triangles; two sliver pieces where blobs touch the volume's edges, one with tips of 10
  degrees);
- iso_bubbles: the largest of 150 Gaussians of radii 0.008-0.04 on a 100^3 grid, level 0.6 (135
  small closed components, 32k triangles);
- iso_noise: white noise smoothed by a Gaussian of 2 voxels on a 48^3 grid, level 0.05 (25
  components, high genus, cut by the volume, 48k triangles).
Each field has its own seed. `Benchmarks/validity_table.sh` with `GENERATED=OUTDIR` measures them
(Benchmarks/README.md, 2026-12-07).
"""
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy

from generated_shapes import write_all


def grid(n):
    x = np.linspace(0.0, 1.0, n)
    return np.meshgrid(x, x, x, indexing="ij")


def blobs(n, count, seed, rmin, rmax, combine, margin):
    """Gaussians centred at random at least `margin` inside the unit cube, summed (combine np.add)
    or the largest (np.maximum)."""
    rng = np.random.default_rng(seed)
    X, Y, Z = grid(n)
    f = np.zeros_like(X)
    for _ in range(count):
        c = rng.uniform(margin, 1.0 - margin, 3)
        r = rng.uniform(rmin, rmax)
        f = combine(f, np.exp(-((X - c[0]) ** 2 + (Y - c[1]) ** 2 + (Z - c[2]) ** 2) / (2 * r * r)))
    return f


def smoothed(f, sigma):
    """f smoothed by a Gaussian of sigma samples along each axis in turn, truncated at 4 sigma,
    the samples mirrored at the ends (as scipy.ndimage.gaussian_filter does)."""
    r = int(4.0 * sigma + 0.5)
    w = np.exp(-0.5 * (np.arange(-r, r + 1) / sigma) ** 2)
    w /= w.sum()
    for axis in range(f.ndim):
        pad = [(0, 0)] * f.ndim
        pad[axis] = (r, r)
        g = np.pad(f, pad, mode="symmetric")
        n = f.shape[axis]
        f = sum(w[k] * np.take(g, np.arange(k, k + n), axis=axis) for k in range(2 * r + 1))
    return f


def noise(n, seed, sigma):
    rng = np.random.default_rng(seed)
    return smoothed(rng.normal(size=(n, n, n)), sigma)


def isosurface(f, level):
    """(V, F) of the level set of f sampled on the unit cube."""
    n = f.shape[0]
    image = vtk.vtkImageData()
    image.SetDimensions(n, n, n)
    image.SetSpacing(1.0 / (n - 1), 1.0 / (n - 1), 1.0 / (n - 1))
    values = numpy_to_vtk(f.ravel(order="F"), deep=1)
    values.SetName("f")
    image.GetPointData().SetScalars(values)
    contour = vtk.vtkFlyingEdges3D()
    contour.SetInputData(image)
    contour.SetValue(0, level)
    contour.ComputeNormalsOff()
    contour.Update()
    out = contour.GetOutput()
    V = vtk_to_numpy(out.GetPoints().GetData()).astype(float)
    F = vtk_to_numpy(out.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    return V, F


SURFACES = {
    "iso_blobs": lambda: isosurface(blobs(96, 60, 1, 0.02, 0.12, np.add, 0.1), 0.5),
    "iso_cut": lambda: isosurface(blobs(128, 400, 3, 0.02, 0.12, np.add, 0.1), 0.3),
    "iso_bubbles": lambda: isosurface(blobs(100, 150, 5, 0.008, 0.04, np.maximum, 0.05), 0.6),
    "iso_noise": lambda: isosurface(noise(48, 4, 2.0), 0.05),
}


def main(argv):
    if len(argv) != 2:
        sys.exit(__doc__)
    write_all(argv[1], SURFACES)


if __name__ == "__main__":
    main(sys.argv)
