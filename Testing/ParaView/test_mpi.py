"""The plugin on two MPI ranks: `mpiexec -n 2 pvbatch test_mpi.py PLUGIN SCRATCH_DIR`.

- A multiblock of two surfaces is remeshed one block per rank (ProcessIdScalars tells which rank
  made each block), every block all quads with chi 2, the block names kept.
- A single surface, which its source splits over the ranks (ParaView's Sphere: half on each), is
  remeshed whole once (on the rank of piece 0), never piece by piece: one closed all-quad mesh.
Exits non-zero with a line per failure.
"""
import os
import sys

from paraview import servermanager
from paraview.simple import (LoadPlugin, OpenDataFile, ProcessIdScalars, Sphere, Triangulate,
                             UpdatePipeline)
from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet, vtkMultiBlockDataSet
from vtkmodules.vtkFiltersCore import vtkTriangleFilter
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataWriter

from meshchecks import check, check_quads, finish

plugin, scratch = sys.argv[1], sys.argv[2]


def sphere(radius, center):
    source = vtkSphereSource()
    source.SetRadius(radius)
    source.SetCenter(*center)
    source.SetThetaResolution(40)
    source.SetPhiResolution(40)
    triangles = vtkTriangleFilter()
    triangles.SetInputConnection(source.GetOutputPort())
    triangles.Update()
    return triangles.GetOutput()


def ranks_of(mesh):
    ids = mesh.GetPointData().GetArray("ProcessId")
    return {int(ids.GetValue(i)) for i in range(ids.GetNumberOfTuples())} if ids else set()


os.makedirs(scratch, exist_ok=True)
# the inputs, written here (this script runs on rank 0; the readers run on every rank)
blocks = vtkMultiBlockDataSet()
for b, (radius, center) in enumerate([(1.0, (0, 0, 0)), (2.0, (6, 0, 0))]):
    blocks.SetBlock(b, sphere(radius, center))
    blocks.GetMetaData(b).Set(vtkCompositeDataSet.NAME(), "sphere%d" % b)
writer = vtkXMLMultiBlockDataWriter()
writer.SetFileName(os.path.join(scratch, "two.vtm"))
writer.SetInputData(blocks)
writer.Write()

ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
check(ranks == 2, "%d ranks, not 2 (run under mpiexec -n 2)" % ranks)
LoadPlugin(plugin, ns=globals())  # on the server: every rank

remesh = QuadCoverRemesh(Input=OpenDataFile(os.path.join(scratch, "two.vtm")))  # noqa: F821
remesh.TargetQuadCount = 300
tagged = ProcessIdScalars(Input=remesh)
UpdatePipeline(proxy=tagged)
result = servermanager.Fetch(tagged)
# Fetch gathers each rank's multiblock as one block of a multiblock; each holds its own blocks
made_by = {}
leaves = result.NewIterator()
leaves.InitTraversal()
while not leaves.IsDoneWithTraversal():
    block = leaves.GetCurrentDataObject()
    meta = leaves.GetCurrentMetaData()
    name = meta.Get(vtkCompositeDataSet.NAME()) if meta.Has(vtkCompositeDataSet.NAME()) else None
    check(block.IsA("vtkPolyData"), "block %s is a %s" % (name, block.GetClassName()))
    if block.IsA("vtkPolyData") and block.GetNumberOfCells() > 0:
        check(name not in made_by, "block %s made twice" % name)
        check_quads(block, "block %s" % name)
        made_by[name] = ranks_of(block)
    leaves.GoToNextItem()
print("blocks made by ranks", made_by)
check(set(made_by) == {"sphere0", "sphere1"}, "blocks %s, not sphere0 and sphere1" % sorted(made_by))
check(sorted(map(sorted, made_by.values())) == [[0], [1]],
      "the two blocks were made by ranks %s, not one each" % made_by)

# ParaView's sphere source gives each rank a piece (half the sphere on 2 ranks)
whole = QuadCoverRemesh(Input=Triangulate(Input=Sphere(ThetaResolution=40,  # noqa: F821
                                                       PhiResolution=40)))
whole.TargetQuadCount = 300
tagged = ProcessIdScalars(Input=whole)
UpdatePipeline(proxy=tagged)
mesh = servermanager.Fetch(tagged)
check(mesh.IsA("vtkPolyData"), "one surface in, %s out" % mesh.GetClassName())
if mesh.IsA("vtkPolyData"):
    check_quads(mesh, "the surface split over the ranks")
    check(ranks_of(mesh) == {0}, "the surface was remeshed on ranks %s" % ranks_of(mesh))

finish("mpi")
