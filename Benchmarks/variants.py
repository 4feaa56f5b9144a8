#!/usr/bin/python3
"""Variants of every shared mesh but the truck, for the robustness sweeps: the surfaces people bring
are rarely as clean as the shared set, so each is written three more ways into OUTDIR:

    NAME_dec.vtp  decimated to 30% of its triangles (vtkQuadricDecimation, volume kept): coarse
    NAME_str.vtp  stretched three times along x: long thin parts, anisotropic triangles
    NAME_jit.vtp  each point moved in its tangent plane by up to a quarter of its mean edge length
                  (seeded): a noisy triangulation of the same shape

    /usr/bin/python3 Benchmarks/variants.py OUTDIR [--shared DIR]

Then run them like any surface, e.g. `quadcover OUTDIR/spot_str.vtp -o OUT.vtp
--target-quad-count 1000` and `Benchmarks/validity.py OUT.vtp REF.vtp` (REF from `--stage
repair`).
"""
import argparse
import glob
import os

import numpy as np
import vtk
from vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy


def read(path):
    reader = vtk.vtkOBJReader()
    reader.SetFileName(path)
    clean = vtk.vtkCleanPolyData()
    clean.SetInputConnection(reader.GetOutputPort())
    triangles = vtk.vtkTriangleFilter()
    triangles.SetInputConnection(clean.GetOutputPort())
    triangles.Update()
    return triangles.GetOutput()


def write(surface, path):
    writer = vtk.vtkXMLPolyDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(surface)
    writer.SetDataModeToBinary()
    writer.Write()


def with_points(surface, points):
    copy = vtk.vtkPolyData()
    copy.DeepCopy(surface)
    copy.GetPoints().SetData(numpy_to_vtk(points, deep=1))
    return copy


def decimated(surface):
    decimate = vtk.vtkQuadricDecimation()
    decimate.SetInputData(surface)
    decimate.SetTargetReduction(0.7)
    decimate.VolumePreservationOn()
    decimate.Update()
    return decimate.GetOutput()


def jittered(surface, random):
    normals = vtk.vtkPolyDataNormals()
    normals.SetInputData(surface)
    normals.SplittingOff()
    normals.ConsistencyOff()
    normals.AutoOrientNormalsOff()
    normals.Update()
    n = vtk_to_numpy(normals.GetOutput().GetPointData().GetNormals())
    points = vtk_to_numpy(surface.GetPoints().GetData()).astype(float)
    triangles = vtk_to_numpy(surface.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    ends = np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])
    # (an edge of two triangles counts twice, for both its points: the mean is the same)
    lengths = np.linalg.norm(points[ends[:, 0]] - points[ends[:, 1]], axis=1)
    total = np.zeros(len(points))
    count = np.zeros(len(points))
    for k in (0, 1):
        np.add.at(total, ends[:, k], lengths)
        np.add.at(count, ends[:, k], 1)
    mean = total / np.maximum(count, 1)
    step = random.normal(size=points.shape)
    step -= n * (step * n).sum(axis=1)[:, None]
    step /= np.maximum(np.linalg.norm(step, axis=1), 1e-12)[:, None]
    return points + step * (0.25 * mean * random.random(len(points)))[:, None]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("outdir")
    here = os.path.dirname(os.path.abspath(__file__))
    parser.add_argument("--shared", default=os.path.join(here, "..", "..", "shared", "data"))
    args = parser.parse_args()
    os.makedirs(args.outdir, exist_ok=True)
    random = np.random.default_rng(7)
    for path in sorted(glob.glob(os.path.join(args.shared, "*.obj"))):
        name = os.path.basename(path)[:-4]
        if name == "truck":
            continue  # a soup: its variants would say nothing more
        surface = read(path)
        write(decimated(surface), os.path.join(args.outdir, name + "_dec.vtp"))
        points = vtk_to_numpy(surface.GetPoints().GetData()).astype(float)
        points[:, 0] *= 3.0
        write(with_points(surface, points), os.path.join(args.outdir, name + "_str.vtp"))
        write(with_points(surface, jittered(surface, random)),
              os.path.join(args.outdir, name + "_jit.vtp"))
        print(name, surface.GetNumberOfCells())


if __name__ == "__main__":
    main()
