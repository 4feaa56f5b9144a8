"""Composite inputs from Python: each surface of a vtkMultiBlockDataSet or a
vtkPartitionedDataSetCollection is remeshed on its own (its own target quad count), and the
output keeps the input's structure and block names; the stage filters do the same.
"""
import sys

import vtk
from quadcover import (vtkCurvatureFrames, vtkFrameSmoother, vtkMatchingBuilder,
                       vtkQuadCoverErrorObserver, vtkQuadCoverRemesh, vtkQuadCoverSolver,
                       vtkQuadCoverSurfaceRepair, vtkQuadExtractor)

failures = []


def check(condition, text):
    if not condition:
        failures.append(text)
        print("FAIL:", text)


def sphere(radius):
    source = vtk.vtkSphereSource()
    source.SetRadius(radius)
    source.SetThetaResolution(30)
    source.SetPhiResolution(30)
    triangles = vtk.vtkTriangleFilter()
    triangles.SetInputConnection(source.GetOutputPort())
    triangles.Update()
    return triangles.GetOutput()


def check_surface(mesh, what, target):
    check(mesh is not None and mesh.IsA("vtkPolyData"), "%s: no surface" % what)
    if mesh is None or not mesh.IsA("vtkPolyData"):
        return
    sizes = {mesh.GetCell(c).GetNumberOfPoints() for c in range(mesh.GetNumberOfCells())}
    check(sizes == {4}, "%s: cells of %s points" % (what, sorted(sizes)))
    # its own target: a sphere of radius 0.01 gets as many quads as one of radius 100
    check(0.6 * target <= mesh.GetNumberOfCells() <= 1.4 * target,
          "%s: %d quads for a target of %d" % (what, mesh.GetNumberOfCells(), target))


def composite(kind):
    data = vtk.vtkMultiBlockDataSet() if kind == "multiblock" else \
        vtk.vtkPartitionedDataSetCollection()
    for i, radius in enumerate([0.01, 100.0]):
        if kind == "multiblock":
            data.SetBlock(i, sphere(radius))
        else:
            data.SetPartition(i, 0, sphere(radius))
        data.GetMetaData(i).Set(vtk.vtkCompositeDataSet.NAME(), "surface%d" % i)
    return data


def check_composite(out, kind, what, target):
    check(out is not None and out.GetClassName() == ("vtkMultiBlockDataSet" if kind == "multiblock"
                                                     else "vtkPartitionedDataSetCollection"),
          "%s: a %s out" % (what, out.GetClassName() if out else None))
    count = out.GetNumberOfBlocks() if kind == "multiblock" else out.GetNumberOfPartitionedDataSets()
    check(count == 2, "%s: %d blocks" % (what, count))
    for i in range(count):
        name = out.GetMetaData(i).Get(vtk.vtkCompositeDataSet.NAME())
        check(name == "surface%d" % i, "%s: block %d named %s" % (what, i, name))
        block = out.GetBlock(i) if kind == "multiblock" else out.GetPartition(i, 0)
        check_surface(block, "%s block %d" % (what, i), target)


for kind in ("multiblock", "partitioned"):
    remesh = vtkQuadCoverRemesh()
    remesh.SetInputData(composite(kind))
    remesh.SetTargetQuadCount(300)
    error = vtkQuadCoverErrorObserver.Run(remesh)
    check(error == "", "Remesh on a %s: %s" % (kind, error))
    check_composite(remesh.GetOutputDataObject(0), kind, "Remesh, " + kind, 300)

    stages = [vtkQuadCoverSurfaceRepair(), vtkCurvatureFrames(), vtkFrameSmoother(),
              vtkMatchingBuilder(), vtkQuadCoverSolver(), vtkQuadExtractor()]
    stages[0].SetInputData(composite(kind))
    for upstream, stage in zip(stages, stages[1:]):
        stage.SetInputConnection(upstream.GetOutputPort())
    stages[4].SetTargetQuadCount(300)
    error = vtkQuadCoverErrorObserver.Run(stages[-1])
    check(error == "", "the stages on a %s: %s" % (kind, error))
    check_composite(stages[-1].GetOutputDataObject(0), kind, "the stages, " + kind, 300)
    # the matching builder's branch points: a composite too, some on each sphere (chi 2)
    branch = stages[3].GetOutputDataObject(1)
    check(branch is not None and branch.IsA("vtkCompositeDataSet"),
          "branch points of a %s: %s" % (kind, branch.GetClassName() if branch else None))
    if branch is not None and branch.IsA("vtkCompositeDataSet"):
        leaves = branch.NewIterator()
        leaves.InitTraversal()
        counts = []
        while not leaves.IsDoneWithTraversal():
            counts.append(leaves.GetCurrentDataObject().GetNumberOfPoints())
            leaves.GoToNextItem()
        check(len(counts) == 2 and min(counts) > 0, "branch points by block: %s" % counts)

if failures:
    sys.exit("%d failures" % len(failures))
print("composite: all checks passed")
