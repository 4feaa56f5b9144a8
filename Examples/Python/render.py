#!/usr/bin/env python3
"""Render a QuadCover result to a PNG: the surface coloured by a cell array, with the guidance
frame field drawn as a small cross (FrameU, FrameV) at every triangle's centre, and (after the
matching stage) the singular points as balls: red for positive index, blue for negative.
A surface with texture coordinates (the solver's --split-seams output) is drawn with a
checkerboard of one square per grid cell instead of the frames, so the parameter lines show. A
quad mesh (the extractor's output, with point data Valence) is drawn with its edges, and its
irregular vertices as balls: red for valence 3, blue for 5, yellow for any other.

    render.py INPUT.vtp -o OUTPUT.png [--array FrameWeight] [--no-frames] [--size 1400x1000]
              [--azimuth DEG] [--elevation DEG]

Needs a display; on a headless machine run it under `xvfb-run -a` (Debian: xvfb, xauth).
"""
import argparse
import sys

import vtk
from vtk.util import numpy_support

import numpy as np


def read(path):
    if path.endswith(".vtp"):
        reader = vtk.vtkXMLPolyDataReader()
    elif path.endswith(".vtk"):
        reader = vtk.vtkPolyDataReader()
    else:
        sys.exit("render.py: error: expected a .vtp or .vtk file, got " + path)
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    if data.GetNumberOfPoints() == 0:
        sys.exit("render.py: error: no points in " + path)
    return data


def frame_segments(surface, names, scale):
    """Line segments c - s*u .. c + s*u at each triangle centre c for each named frame vector
    (FrameU and FrameV draw the whole cross: a four-fold field may swap U and V between
    neighbours without turning), lifted off the surface."""
    frames = [surface.GetCellData().GetArray(n) for n in names]
    frames = [f for f in frames if f is not None]
    if not frames:
        return None
    points = numpy_support.vtk_to_numpy(surface.GetPoints().GetData()).astype(float)
    polys = numpy_support.vtk_to_numpy(surface.GetPolys().GetData())
    # VTK 9 exports the legacy layout: 3 i j k 3 i j k ...
    tri = polys.reshape(-1, 4)[:, 1:]
    a, b, c = points[tri[:, 0]], points[tri[:, 1]], points[tri[:, 2]]
    centre = (a + b + c) / 3.0
    normal = np.cross(b - a, c - a)
    normal /= np.maximum(np.linalg.norm(normal, axis=1), 1e-300)[:, None]
    lift = 0.05 * scale * normal
    ends = np.empty((2 * len(tri) * len(frames), 3))
    for j, frame in enumerate(frames):
        u = numpy_support.vtk_to_numpy(frame).astype(float)
        part = ends[2 * len(tri) * j: 2 * len(tri) * (j + 1)]
        part[0::2] = centre - scale * u + lift
        part[1::2] = centre + scale * u + lift
    pts = vtk.vtkPoints()
    pts.SetData(numpy_support.numpy_to_vtk(ends, deep=True))
    lines = vtk.vtkCellArray()
    conn = np.arange(len(ends), dtype=np.int64)
    offsets = np.arange(0, len(ends) + 1, 2, dtype=np.int64)
    lines.SetData(numpy_support.numpy_to_vtkIdTypeArray(offsets, deep=True),
                  numpy_support.numpy_to_vtkIdTypeArray(conn, deep=True))
    segments = vtk.vtkPolyData()
    segments.SetPoints(pts)
    segments.SetLines(lines)
    return segments


def add_irregular_vertices(renderer, surface, valence):
    """Balls at the vertices of valence other than 4 (inner) and 2 or 3 (boundary)."""
    values = numpy_support.vtk_to_numpy(valence)
    points = numpy_support.vtk_to_numpy(surface.GetPoints().GetData())
    edges = vtk.vtkFeatureEdges()
    edges.SetInputData(surface)
    edges.BoundaryEdgesOn()
    edges.FeatureEdgesOff()
    edges.ManifoldEdgesOff()
    edges.NonManifoldEdgesOff()
    edges.Update()
    boundary = set()
    locator = vtk.vtkPointLocator()
    locator.SetDataSet(surface)
    locator.BuildLocator()
    bpts = edges.GetOutput().GetPoints()
    for i in range(bpts.GetNumberOfPoints() if bpts else 0):
        boundary.add(locator.FindClosestPoint(bpts.GetPoint(i)))
    bounds = surface.GetBounds()
    diagonal = float(np.linalg.norm([bounds[1] - bounds[0], bounds[3] - bounds[2],
                                     bounds[5] - bounds[4]]))
    groups = {3: (0.85, 0.1, 0.1), 5: (0.1, 0.25, 0.9)}
    chosen = {}
    for v, k in enumerate(values):
        regular = k in (2, 3) if v in boundary else k == 4
        if not regular:
            chosen.setdefault(int(k) if int(k) in groups else 0, []).append(v)
    for k, ids in chosen.items():
        add_balls(renderer, points[ids], 0.006 * diagonal, groups.get(k, (0.95, 0.8, 0.1)))


def add_balls(renderer, centres, radius, colour):
    """Balls of one colour at the given points."""
    pts = vtk.vtkPoints()
    for c in centres:
        pts.InsertNextPoint(*c)
    cloud = vtk.vtkPolyData()
    cloud.SetPoints(pts)
    ball = vtk.vtkSphereSource()
    ball.SetRadius(radius)
    ball.SetThetaResolution(16)
    ball.SetPhiResolution(12)
    glyphs = vtk.vtkGlyph3D()
    glyphs.SetInputData(cloud)
    glyphs.SetSourceConnection(ball.GetOutputPort())
    glyph_mapper = vtk.vtkPolyDataMapper()
    glyph_mapper.SetInputConnection(glyphs.GetOutputPort())
    glyph_mapper.ScalarVisibilityOff()
    glyph_actor = vtk.vtkActor()
    glyph_actor.SetMapper(glyph_mapper)
    glyph_actor.GetProperty().SetColor(*colour)
    renderer.AddActor(glyph_actor)


def flipped_triangles(surface):
    """The triangles whose CornerUV image is flipped or degenerate, or None."""
    corner_uv = surface.GetCellData().GetArray("CornerUV")
    if corner_uv is None:
        return None
    uv = numpy_support.vtk_to_numpy(corner_uv).astype(float)
    e1 = uv[:, 2:4] - uv[:, 0:2]
    e2 = uv[:, 4:6] - uv[:, 0:2]
    chosen = np.nonzero(e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0] <= 0)[0]
    if len(chosen) == 0:
        return None
    ids = vtk.vtkIdTypeArray()
    ids.SetNumberOfTuples(len(chosen))
    for i, c in enumerate(chosen):
        ids.SetValue(i, int(c))
    node = vtk.vtkSelectionNode()
    node.SetFieldType(vtk.vtkSelectionNode.CELL)
    node.SetContentType(vtk.vtkSelectionNode.INDICES)
    node.SetSelectionList(ids)
    selection = vtk.vtkSelection()
    selection.AddNode(node)
    extract = vtk.vtkExtractSelection()
    extract.SetInputData(0, surface)
    extract.SetInputData(1, selection)
    geometry = vtk.vtkGeometryFilter()
    geometry.SetInputConnection(extract.GetOutputPort())
    geometry.Update()
    return geometry.GetOutput()


def checkerboard(pixels=64):
    """A 2 x 2 checkerboard texture: with (u, v) in grid units and repeat on, one square per grid
    cell, with thin dark lines on the integer grid lines."""
    size = 2 * pixels
    image = np.empty((size, size, 3), dtype=np.uint8)
    cells = (np.arange(size) // pixels)
    light = (cells[:, None] + cells[None, :]) % 2 == 0
    image[light] = (235, 235, 225)
    image[~light] = (175, 195, 225)
    line = (np.arange(size) % pixels) < 2
    image[line[:, None] | line[None, :]] = (40, 40, 40)
    data = vtk.vtkImageData()
    data.SetDimensions(size, size, 1)
    data.GetPointData().SetScalars(numpy_support.numpy_to_vtk(image.reshape(-1, 3), deep=True))
    texture = vtk.vtkTexture()
    texture.SetInputData(data)
    texture.RepeatOn()
    texture.InterpolateOn()
    texture.MipmapOn()
    return texture


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("input")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--array", default="FrameWeight", help="cell array for the colours")
    parser.add_argument("--no-frames", action="store_true", help="do not draw the frames")
    parser.add_argument("--frame-u-only", action="store_true",
                        help="draw FrameU alone, not the whole cross")
    parser.add_argument("--no-singularities", action="store_true",
                        help="do not draw the singular points")
    parser.add_argument("--size", default="1400x1000")
    parser.add_argument("--azimuth", type=float, default=30.0)
    parser.add_argument("--elevation", type=float, default=25.0)
    args = parser.parse_args()

    surface = read(args.input)
    width, height = (int(x) for x in args.size.split("x"))

    renderer = vtk.vtkRenderer()
    renderer.SetBackground(1.0, 1.0, 1.0)

    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputData(surface)
    colours = surface.GetCellData().GetArray(args.array)
    if colours is not None and colours.GetNumberOfComponents() == 1:
        mapper.SetScalarModeToUseCellFieldData()
        mapper.SelectColorArray(args.array)
        mapper.SetScalarRange(colours.GetRange())
        lut = vtk.vtkLookupTable()
        lut.SetHueRange(0.6, 0.0)
        lut.SetSaturationRange(0.45, 0.45)
        lut.Build()
        mapper.SetLookupTable(lut)
        mapper.ScalarVisibilityOn()
        bar = vtk.vtkScalarBarActor()
        bar.SetLookupTable(lut)
        bar.SetTitle(args.array)
        bar.SetNumberOfLabels(3)
        bar.SetWidth(0.08)
        bar.SetHeight(0.4)
        bar.GetTitleTextProperty().SetColor(0.1, 0.1, 0.1)
        bar.GetLabelTextProperty().SetColor(0.1, 0.1, 0.1)
        renderer.AddActor2D(bar)
    else:
        mapper.ScalarVisibilityOff()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(0.85, 0.85, 0.8)
    textured = surface.GetPointData().GetTCoords() is not None
    valence = surface.GetPointData().GetArray("Valence")
    if valence is not None:
        mapper.ScalarVisibilityOff()
        for a in renderer.GetActors2D():
            renderer.RemoveActor2D(a)
        actor.GetProperty().SetColor(0.92, 0.92, 0.88)
        actor.GetProperty().EdgeVisibilityOn()
        actor.GetProperty().SetEdgeColor(0.15, 0.15, 0.2)
        actor.GetProperty().SetLineWidth(1.0)
        add_irregular_vertices(renderer, surface, valence)
    if textured:
        # the texture holds 2 x 2 cells: texture coordinates (u, v) / 2
        uv = numpy_support.vtk_to_numpy(surface.GetPointData().GetTCoords()).astype(float)
        half = numpy_support.numpy_to_vtk(0.5 * uv, deep=True)
        half.SetName("HalfUV")
        surface.GetPointData().SetTCoords(half)
        mapper.ScalarVisibilityOff()
        for a in renderer.GetActors2D():
            renderer.RemoveActor2D(a)
        actor.SetTexture(checkerboard())
        actor.GetProperty().SetColor(1.0, 1.0, 1.0)
    renderer.AddActor(actor)
    flipped = flipped_triangles(surface)
    if flipped is not None:
        flipped_mapper = vtk.vtkPolyDataMapper()
        flipped_mapper.SetInputData(flipped)
        flipped_mapper.ScalarVisibilityOff()
        flipped_actor = vtk.vtkActor()
        flipped_actor.SetMapper(flipped_mapper)
        flipped_actor.GetProperty().SetColor(0.9, 0.1, 0.1)
        renderer.AddActor(flipped_actor)

    if not args.no_frames and not textured and valence is None:
        # Segment half-length: 40% of the mean edge length, from the mean triangle area.
        quality = vtk.vtkCellSizeFilter()
        quality.SetInputData(surface)
        quality.ComputeAreaOn()
        quality.Update()
        areas = numpy_support.vtk_to_numpy(quality.GetOutput().GetCellData().GetArray("Area"))
        edge = float(np.sqrt(4.0 * max(float(np.mean(areas)), 1e-300) / np.sqrt(3.0)))
        segments = frame_segments(surface, ["FrameU"] if args.frame_u_only
                                  else ["FrameU", "FrameV"], 0.35 * edge)
        if segments is not None:
            seg_mapper = vtk.vtkPolyDataMapper()
            seg_mapper.SetInputData(segments)
            seg_actor = vtk.vtkActor()
            seg_actor.SetMapper(seg_mapper)
            seg_actor.GetProperty().SetColor(0.05, 0.05, 0.05)
            seg_actor.GetProperty().SetLineWidth(1.5)
            seg_actor.GetProperty().LightingOff()
            renderer.AddActor(seg_actor)

    index = surface.GetPointData().GetArray("SingularityIndex")
    if index is not None and not args.no_singularities:
        values = numpy_support.vtk_to_numpy(index)
        points = numpy_support.vtk_to_numpy(surface.GetPoints().GetData())
        bounds = surface.GetBounds()
        diagonal = float(np.linalg.norm([bounds[1] - bounds[0], bounds[3] - bounds[2],
                                         bounds[5] - bounds[4]]))
        # Inner singularities are multiples of 1/4; boundary points carry fractional leftovers.
        quarter = np.abs(4.0 * values - np.round(4.0 * values)) < 1e-6
        for sign, colour in ((1, (0.85, 0.1, 0.1)), (-1, (0.1, 0.25, 0.9))):
            chosen = np.nonzero(quarter & (sign * values > 1e-9))[0]
            if len(chosen) > 0:
                add_balls(renderer, points[chosen], 0.008 * diagonal, colour)

    camera = renderer.GetActiveCamera()
    renderer.ResetCamera()
    camera.Azimuth(args.azimuth)
    camera.Elevation(args.elevation)
    camera.OrthogonalizeViewUp()
    renderer.ResetCamera()
    camera.Zoom(1.3)

    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(width, height)
    window.SetMultiSamples(8)
    window.Render()

    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(args.output)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


if __name__ == "__main__":
    main()
