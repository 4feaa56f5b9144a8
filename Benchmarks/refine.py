#!/usr/bin/python3
"""A surface refined by Loop subdivision, for the runs at scale.  refine.py IN OUT.vtp LEVELS

Reads IN (.obj, .vtp or .ply), merges coincident points, triangulates, subdivides LEVELS times
(each level multiplies the triangles by 4) and writes OUT as VTK XML poly data; prints the
triangles written. E.g. ../shared/data/spot.obj refined 4 times has 1,499,136 triangles.
"""
import sys

import vtk


def refined(path, levels):
    """The surface in `path` (.obj, .vtp or .ply) merged, triangulated and subdivided `levels`
    times (none at 0), as the algorithm whose output holds it (updated)."""
    readers = {"obj": vtk.vtkOBJReader, "vtp": vtk.vtkXMLPolyDataReader, "ply": vtk.vtkPLYReader}
    kind = path.rsplit(".", 1)[-1].lower()
    if kind not in readers:
        sys.exit("refine.py: error: expected .obj, .vtp or .ply, got " + path)
    reader = readers[kind]()
    reader.SetFileName(path)
    clean = vtk.vtkCleanPolyData()
    clean.SetInputConnection(reader.GetOutputPort())
    last = vtk.vtkTriangleFilter()
    last.SetInputConnection(clean.GetOutputPort())
    if levels > 0:
        loop = vtk.vtkLoopSubdivisionFilter()
        loop.SetNumberOfSubdivisions(levels)
        loop.SetInputConnection(last.GetOutputPort())
        last = loop
    last.Update()
    return last


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__.strip().splitlines()[0])
    path, out, levels = sys.argv[1], sys.argv[2], int(sys.argv[3])
    loop = refined(path, levels)
    writer = vtk.vtkXMLPolyDataWriter()
    writer.SetInputConnection(loop.GetOutputPort())
    writer.SetFileName(out)
    if not writer.Write():
        sys.exit("refine.py: error: could not write " + out)
    print(loop.GetOutput().GetNumberOfPolys())


if __name__ == "__main__":
    main()
