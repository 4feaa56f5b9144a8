#!/usr/bin/env python3
"""A surface file in, a quad mesh out, with QuadCover's filters chained in Python.

    remesh.py INPUT OUTPUT [--quads N]

INPUT may be any surface vtkQuadCoverReader takes (.obj .off .ply .stl .vtp .vtk), straight from
a scanner or a CAD export: vtkQuadCoverSurfaceRepair merges its duplicate points, orients it and
splits non-manifold vertices first. Run with Debian's /usr/bin/python3 and PYTHONPATH pointing at
the quadcover package (build/lib/python3/dist-packages in a build tree).
"""
import argparse
import sys

from quadcover import (vtkCurvatureFrames, vtkFrameSmoother, vtkMatchingBuilder,
                       vtkQuadCoverErrorObserver, vtkQuadCoverReader, vtkQuadCoverSolver,
                       vtkQuadCoverSurfaceRepair, vtkQuadCoverWriter, vtkQuadExtractor)


def remesh(path, quads=3000):
    """The quad mesh of the surface in `path` (a vtkPolyData), or SystemExit with the error."""
    reader = vtkQuadCoverReader()
    reader.SetFileName(path)
    stages = [reader, vtkQuadCoverSurfaceRepair(), vtkCurvatureFrames(), vtkFrameSmoother(),
              vtkMatchingBuilder(), vtkQuadCoverSolver(), vtkQuadExtractor()]
    errors = vtkQuadCoverErrorObserver()
    for upstream, stage in zip(stages, stages[1:]):
        stage.SetInputConnection(upstream.GetOutputPort())
    for stage in stages:
        errors.Attach(stage)
    stages[5].SetTargetQuadCount(quads)
    stages[-1].Update()
    if errors.GetError():
        sys.exit("remesh.py: " + errors.GetError())
    return stages[-1].GetOutput()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("input")
    parser.add_argument("output")
    parser.add_argument("--quads", type=int, default=3000)
    args = parser.parse_args()
    mesh = remesh(args.input, args.quads)
    writer = vtkQuadCoverWriter()
    writer.SetFileName(args.output)
    writer.SetInputData(mesh)
    errors = vtkQuadCoverErrorObserver()
    errors.Attach(writer)
    writer.Write()
    if errors.GetError():
        sys.exit("remesh.py: " + errors.GetError())
    fd = mesh.GetFieldData()
    print("%d quads, %d irregular inner vertices, edge-length RSD %.3f, Euler characteristic %d" % (
        mesh.GetNumberOfCells(), fd.GetArray("IrregularVertices").GetValue(0),
        fd.GetArray("EdgeLengthRSD").GetValue(0), fd.GetArray("EulerCharacteristic").GetValue(0)))


if __name__ == "__main__":
    main()
