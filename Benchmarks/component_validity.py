#!/usr/bin/python3
"""Which components of a remesh are wrong?  component_validity.py QUADS INPUT [--write DIR]

Splits INPUT (the repaired surface, as `quadcover IN -o REF.vtp --stage repair` writes it) into
its connected components, assigns every connected piece of QUADS to the component nearest to its
first quads, and prints per component its triangles, Euler characteristic and boundary loops
against those of the pieces on it (a component is right when exactly one piece with its χ and
loops lies on it). With --write, each component goes to DIR/cNN.vtp, to be remeshed alone.
"""
import os
import sys
from collections import defaultdict

import vtk

sys.path.insert(0, os.path.dirname(__file__))
from validity import components, faces, join_points, read  # noqa: E402


def pieces(F):
    """The faces of F grouped by connected piece (through shared points)."""
    find, _ = join_points(F)
    groups = defaultdict(list)
    for f in F:
        groups[find(f[0])].append(f)
    return list(groups.values())


def main():
    out, ref = sys.argv[1], sys.argv[2]
    write = sys.argv[sys.argv.index("--write") + 1] if "--write" in sys.argv else None
    conn = vtk.vtkPolyDataConnectivityFilter()
    conn.SetInputData(read(ref))
    conn.SetExtractionModeToAllRegions()
    conn.ColorRegionsOn()  # VTK 9.1: point data RegionId only
    conn.Update()
    surface = conn.GetOutput()
    region = surface.GetPointData().GetArray("RegionId")
    count = conn.GetNumberOfExtractedRegions()
    triangles = defaultdict(list)
    for f in faces(surface):
        triangles[int(region.GetValue(f[0]))].append(f)
    locator = vtk.vtkStaticCellLocator()
    locator.SetDataSet(surface)
    locator.BuildLocator()
    quads = read(out)
    found = defaultdict(list)
    for piece in pieces(faces(quads)):
        votes = defaultdict(int)
        for f in piece[:50]:
            centre = [sum(quads.GetPoint(v)[i] for v in f) / len(f) for i in range(3)]
            closest, cell = [0.0] * 3, vtk.reference(0)
            locator.FindClosestPoint(centre, closest, cell, vtk.reference(0), vtk.reference(0.0))
            votes[int(region.GetValue(surface.GetCell(cell.get()).GetPointId(0)))] += 1
        found[max(votes, key=votes.get)].append((components(piece)[0], len(piece)))
    wrong = []
    for c in range(count):
        want = components(triangles[c])[0]
        got = sorted(found.get(c, []))
        ok = len(got) == 1 and got[0][0] == want
        wrong += [] if ok else [c]
        print("%s component %d: %d triangles, (chi, loops) %s; pieces ((chi, loops), quads): %s" % (
            "  " if ok else "XX", c, len(triangles[c]), want, got))
    print("wrong:", wrong)
    if write:
        os.makedirs(write, exist_ok=True)
        for c in range(count):
            keep = vtk.vtkThreshold()
            keep.SetInputData(surface)
            keep.SetInputArrayToProcess(0, 0, 0, 0, "RegionId")  # a point array: all points in
            keep.SetAllScalars(1)
            keep.SetLowerThreshold(c - 0.5)
            keep.SetUpperThreshold(c + 0.5)
            polys = vtk.vtkGeometryFilter()
            polys.SetInputConnection(keep.GetOutputPort())
            writer = vtk.vtkXMLPolyDataWriter()
            writer.SetFileName(os.path.join(write, "c%02d.vtp" % c))
            writer.SetInputConnection(polys.GetOutputPort())
            writer.Write()


if __name__ == "__main__":
    main()
