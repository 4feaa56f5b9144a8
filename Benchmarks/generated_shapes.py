#!/usr/bin/python3
"""Twenty-four generated surfaces for measuring robustness on shapes outside the shared set.

    /usr/bin/python3 Benchmarks/generated_shapes.py OUTDIR

Writes OUTDIR/NAME.obj for: vase (a surface of revolution with a thin neck), spiral (a conic
spiral tube narrowing to a point, open at its wide end), superellipsoid and supertoroid
(exponents 0.25: rounded boxes), gear (20 teeth around a hole, extruded), thinring (an annulus
0.02 thick), urchin (a sphere with six spikes), wavysheet (an open wavy square) and helixtube (a
long capped helical tube of radius 0.05); since 2026-12-06 (6) also gyroid (a gyroid cut by a
ball, genus 13) and perforated (a slab with 16 round holes), both by marching cubes, blobs (seven
metaballs), noisysphere (1% radial noise), nested (a sphere with another of half its radius
inside, turned inward), thinshell (the same 1% apart: the walls of a hollow ball) and
longtriangles (a closed cylinder of 300 sides and one ring); since 2026-12-06 (7) also holey (a
sphere with 25 round holes cut out along its triangles: jagged boundaries, as a scan's), noisyblobs
(blobs with noise of 0.3 edge lengths at every point), spindle (a torus whose tube passes through
its axis: self-intersecting, nearly pinched there), crossing (two spheres through each other, two
components), terrain (an open wavy heightfield), sawtooth (a flat disk whose boundary zigzags),
cone (512 sides: its apex on 512 triangles, its cap one polygon) and mixedbox (a box whose top is
a fine grid and whose other sides are a few long triangles). `Benchmarks/count_sweep.py ...
--meshes OUTDIR/vase.obj,...` measures them (Benchmarks/README.md).
"""
import os
import sys
from collections import Counter

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def write(out, name, V, F):
    with open(os.path.join(out, name + ".obj"), "w") as f:
        for p in V:
            f.write("v %.9g %.9g %.9g\n" % tuple(p))
        for t in F:
            f.write("f %d %d %d\n" % tuple(np.asarray(t) + 1))


def from_polydata(pd):
    """Triangulated, points merged: (V, F)."""
    t = vtk.vtkTriangleFilter()
    t.SetInputData(pd)
    c = vtk.vtkCleanPolyData()
    c.SetInputConnection(t.GetOutputPort())
    c.SetTolerance(1e-9)
    c.Update()
    p = c.GetOutput()
    V = vtk_to_numpy(p.GetPoints().GetData()).astype(float)
    F = vtk_to_numpy(p.GetPolys().GetData()).reshape(-1, 4)[:, 1:]
    return V, F


def parametric(function, u, v):
    source = vtk.vtkParametricFunctionSource()
    source.SetParametricFunction(function)
    source.SetUResolution(u)
    source.SetVResolution(v)
    source.Update()
    return from_polydata(source.GetOutput())


def revolve(radius, height, nu, nv):
    """A closed surface of revolution, poles at t = 0 and pi."""
    V = [[0, 0, height(0.0)]]
    F = []
    ts = np.linspace(0, np.pi, nv + 1)[1:-1]
    for t in ts:
        for j in range(nu):
            a = 2 * np.pi * j / nu
            V.append([radius(t) * np.cos(a), radius(t) * np.sin(a), height(t)])
    V.append([0, 0, height(np.pi)])
    last = len(V) - 1

    def idx(i, j):
        return 1 + i * nu + (j % nu)

    for j in range(nu):
        F.append([0, idx(0, j), idx(0, j + 1)])
    for i in range(len(ts) - 1):
        for j in range(nu):
            F.append([idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)])
            F.append([idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)])
    for j in range(nu):
        F.append([last, idx(len(ts) - 1, j + 1), idx(len(ts) - 1, j)])
    return np.array(V), np.array(F)


def extrude(V2, F2, thickness):
    """A closed slab from a planar triangulation (counter-clockwise) of points V2 (n x 2 or 3)."""
    n = len(V2)
    flat = np.c_[V2[:, :2], np.zeros(n)]
    V = np.vstack([flat + [0, 0, thickness], flat])
    F = [t for t in F2] + [t[::-1] + n for t in F2]
    edges = Counter()
    for t in F2:
        for k in range(3):
            edges[(t[k], t[(k + 1) % 3])] += 1
    for (a, b) in edges:
        if (b, a) not in edges:  # a boundary edge a -> b: a wall down to the bottom
            F.append([b, a, a + n])
            F.append([b, a + n, b + n])
    return V, np.array(F)


def vase():
    return revolve(lambda t: np.sin(t) * (0.55 + 0.45 * np.cos(3 * t)) + 0.02 * np.sin(t),
                   lambda t: -3 * np.cos(t), 96, 240)


def spiral():
    s = vtk.vtkParametricConicSpiral()
    s.SetA(0.2)
    s.SetB(1)
    s.SetC(0.1)
    s.SetN(2)
    return parametric(s, 300, 60)


def super_shape(function):
    function.SetN1(0.25)
    function.SetN2(0.25)
    return parametric(function, 160, 160)


def delaunay_inside(points, loops):
    """The Delaunay triangulation of vtkPoints `points` in the plane z = 0 inside the polygons
    `loops` (lists of point ids; a hole's loop clockwise)."""
    cloud = vtk.vtkPolyData()
    cloud.SetPoints(points)
    polys = vtk.vtkCellArray()
    for ids in loops:
        polygon = vtk.vtkPolygon()
        polygon.GetPointIds().SetNumberOfIds(len(ids))
        for i, v in enumerate(ids):
            polygon.GetPointIds().SetId(i, v)
        polys.InsertNextCell(polygon)
    bounds = vtk.vtkPolyData()
    bounds.SetPoints(points)
    bounds.SetPolys(polys)
    delaunay = vtk.vtkDelaunay2D()
    delaunay.SetInputData(cloud)
    delaunay.SetSourceData(bounds)
    delaunay.Update()
    return delaunay.GetOutput()


def gear():
    n = 20
    outline = []
    for k in range(n):
        for a, r in ((0, 1.0), (0.18, 1.0), (0.28, 1.2), (0.42, 1.2), (0.52, 1.0)):
            angle = 2 * np.pi * (k + a) / n
            outline.append((r * np.cos(angle), r * np.sin(angle)))
    m = len(outline)
    hole = [(0.35 * np.cos(2 * np.pi * k / 40), 0.35 * np.sin(2 * np.pi * k / 40))
            for k in range(40)]
    inner = []
    for r in np.linspace(0.45, 0.95, 6):
        for k in range(int(60 * r)):
            a = 2 * np.pi * k / int(60 * r) + r
            inner.append((r * np.cos(a), r * np.sin(a)))
    points = vtk.vtkPoints()
    for x, y in outline + hole + inner:
        points.InsertNextPoint(x, y, 0)
    face = delaunay_inside(points, (list(range(m)), [m + 39 - i for i in range(40)]))
    Vf = vtk_to_numpy(face.GetPoints().GetData()).astype(float)
    Ff = vtk_to_numpy(face.GetPolys().GetData()).reshape(-1, 4)[:, 1:]

    def up(t):
        a, b, c = Vf[t]
        return np.cross(b - a, c - a)[2] > 0

    Ff = np.array([t if up(t) else t[::-1] for t in Ff])
    V, F = extrude(Vf, Ff, 0.3)
    slab = vtk.vtkPolyData()
    pts = vtk.vtkPoints()
    for p in V:
        pts.InsertNextPoint(*p)
    cells = vtk.vtkCellArray()
    for t in F:
        cells.InsertNextCell(3)
        for i in t:
            cells.InsertCellPoint(int(i))
    slab.SetPoints(pts)
    slab.SetPolys(cells)
    subdivided = vtk.vtkLinearSubdivisionFilter()
    subdivided.SetInputData(slab)
    subdivided.SetNumberOfSubdivisions(2)
    subdivided.Update()
    return from_polydata(subdivided.GetOutput())


def thin_ring():
    nu, nr = 180, 12
    V = []
    for i in range(nr + 1):
        r = 0.5 + 0.5 * i / nr
        for j in range(nu):
            a = 2 * np.pi * j / nu
            V.append([r * np.cos(a), r * np.sin(a)])
    F = []
    for i in range(nr):
        for j in range(nu):
            a, b = i * nu + j, i * nu + (j + 1) % nu
            F += [[a, b, b + nu], [a, b + nu, a + nu]]
    return extrude(np.array(V), np.array(F), 0.02)


def urchin():
    sphere = vtk.vtkSphereSource()
    sphere.SetThetaResolution(200)
    sphere.SetPhiResolution(200)
    sphere.Update()
    V, F = from_polydata(sphere.GetOutput())
    V = V / np.linalg.norm(V, axis=1)[:, None]
    dirs = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1.0]])
    dirs = dirs + 0.3 * np.array([[0, 1, 0.2]])
    dirs /= np.linalg.norm(dirs, axis=1)[:, None]
    bump = np.zeros(len(V))
    for d in dirs:
        bump += 1.2 * np.exp(-(1 - V @ d) / 0.01)
    return V * (1 + bump)[:, None], F


def wavy_sheet():
    n = 120
    xs = np.linspace(-1, 1, n)
    X, Y = np.meshgrid(xs, xs)
    V = np.c_[X.ravel(), Y.ravel(), (0.25 * np.sin(3 * X) * np.cos(2 * Y)).ravel()]
    F = []
    for i in range(n - 1):
        for j in range(n - 1):
            a = i * n + j
            F += [[a, a + 1, a + n + 1], [a, a + n + 1, a + n]]
    return V, np.array(F)


def helix_tube():
    spline = vtk.vtkParametricSpline()
    points = vtk.vtkPoints()
    for t in np.linspace(0, 6 * np.pi, 200):
        points.InsertNextPoint(np.cos(t), np.sin(t), 0.15 * t)
    spline.SetPoints(points)
    source = vtk.vtkParametricFunctionSource()
    source.SetParametricFunction(spline)
    source.SetUResolution(1000)
    tube = vtk.vtkTubeFilter()
    tube.SetInputConnection(source.GetOutputPort())
    tube.SetRadius(0.05)
    tube.SetNumberOfSides(24)
    tube.CappingOn()
    tube.Update()
    return from_polydata(tube.GetOutput())


def implicit(f, bounds, n):
    """The zero level set of f(X, Y, Z) on an n^3 grid over bounds ((lo, hi) per axis): a
    triangulation with the slivers that marching cubes leaves."""
    from vtk.util.numpy_support import numpy_to_vtk

    image = vtk.vtkImageData()
    image.SetDimensions(n, n, n)
    image.SetOrigin(*(lo for lo, _ in bounds))
    image.SetSpacing(*((hi - lo) / (n - 1) for lo, hi in bounds))
    axes = [np.linspace(lo, hi, n) for lo, hi in bounds]
    Z, Y, X = np.meshgrid(axes[2], axes[1], axes[0], indexing="ij")
    values = numpy_to_vtk(f(X, Y, Z).ravel().astype(np.float64), deep=1)
    values.SetName("f")
    image.GetPointData().SetScalars(values)
    contour = vtk.vtkFlyingEdges3D()
    contour.SetInputData(image)
    contour.SetValue(0, 0.0)
    contour.ComputeNormalsOff()
    contour.Update()
    return from_polydata(contour.GetOutput())


def gyroid():
    """A gyroid cut by a ball: genus 13, closed."""
    return implicit(lambda X, Y, Z: np.maximum(
        np.sin(X) * np.cos(Y) + np.sin(Y) * np.cos(Z) + np.sin(Z) * np.cos(X) - 0.3,
        X ** 2 + Y ** 2 + Z ** 2 - 36.0), [(-6.5, 6.5)] * 3, 120)


def perforated():
    """A slab 0.6 thick with a 4 x 4 grid of round holes: genus 16."""
    def f(X, Y, Z):
        slab = np.maximum(np.abs(Z) - 0.3, np.maximum(np.abs(X) - 4.0, np.abs(Y) - 4.0))
        holes = np.full(X.shape, np.inf)
        for cx in (-3, -1, 1, 3):
            for cy in (-3, -1, 1, 3):
                holes = np.minimum(holes, np.hypot(X - cx, Y - cy) - 0.6)
        return np.maximum(slab, -holes)
    return implicit(f, [(-4.5, 4.5), (-4.5, 4.5), (-1, 1)], 140)


def blobs():
    """Seven metaballs of radii 0.4 to 1.4 melted into one surface."""
    rng = np.random.default_rng(3)
    centres, radii = rng.uniform(-2, 2, (7, 3)), rng.uniform(0.4, 1.4, 7)

    def f(X, Y, Z):
        s = np.zeros(X.shape)
        for c, r in zip(centres, radii):
            s += r ** 2 / ((X - c[0]) ** 2 + (Y - c[1]) ** 2 + (Z - c[2]) ** 2 + 1e-9)
        return 1.0 - s
    return implicit(f, [(-4, 4)] * 3, 110)


def sphere_source():
    s = vtk.vtkSphereSource()
    s.SetThetaResolution(120)
    s.SetPhiResolution(60)
    s.Update()
    return from_polydata(s.GetOutput())


def noisy_sphere():
    """A sphere with 1% of radial noise at every point, as a scan."""
    V, F = sphere_source()
    return V * (1 + 0.01 * np.random.default_rng(3).standard_normal((len(V), 1))), F


def two_spheres(inner_scale):
    """A sphere and, inside it, the same scaled and turned inward: two components."""
    V, F = sphere_source()
    return np.vstack([V, inner_scale * V]), np.vstack([F, F[:, ::-1] + len(V)])


def long_triangles():
    """A closed cylinder of 300 sides and one ring: triangles 300 times longer than wide."""
    c = vtk.vtkCylinderSource()
    c.SetResolution(300)
    c.SetHeight(3.0)
    c.CappingOn()
    c.Update()
    return from_polydata(c.GetOutput())


def holey():
    """A sphere with 25 round holes cut out along its triangles (some overlapping): the jagged
    boundaries of a scan's holes."""
    s = vtk.vtkSphereSource()
    s.SetThetaResolution(200)
    s.SetPhiResolution(100)
    s.Update()
    V, F = from_polydata(s.GetOutput())
    centres = np.random.default_rng(5).standard_normal((25, 3))
    centres /= np.linalg.norm(centres, axis=1)[:, None]
    mid = V[F].mean(axis=1)
    mid /= np.linalg.norm(mid, axis=1)[:, None]
    keep = np.ones(len(F), bool)
    for k, c in enumerate(centres):
        keep &= mid @ c < np.cos(0.08 + 0.04 * (k % 3))
    F = F[keep]
    used = np.unique(F)
    renumber = -np.ones(len(V), int)
    renumber[used] = np.arange(len(used))
    return V[used], renumber[F]


def noisy_blobs():
    """The blobs with noise of 0.3 mean edge lengths at every point, as a rough scan."""
    V, F = blobs()
    edge = np.linalg.norm(V[F[:, 0]] - V[F[:, 1]], axis=1).mean()
    return V + 0.3 * edge * np.random.default_rng(4).standard_normal(V.shape), F


def spindle():
    """A torus whose tube (radius 0.8) passes through its axis (ring radius 0.6): it intersects
    itself, and its points nearly meet where the tube crosses the axis."""
    torus = vtk.vtkParametricTorus()
    torus.SetRingRadius(0.6)
    torus.SetCrossSectionRadius(0.8)
    return parametric(torus, 80, 40)


def crossing():
    """Two spheres of radius 0.5 whose centres lie 0.5 apart: two components through each other."""
    V, F = sphere_source()
    return np.vstack([V, V + [0.5, 0.0, 0.0]]), np.vstack([F, F + len(V)])


def terrain():
    """An open heightfield of five waves on a 120 x 120 grid."""
    n = 120
    x, y = np.meshgrid(np.linspace(0, 1, n), np.linspace(0, 1, n))
    rng = np.random.default_rng(7)
    z = np.zeros_like(x)
    for k in range(1, 6):
        a, b, phase = rng.uniform(-1, 1, 3) * 3 * 2 ** k
        z += 0.15 / 2 ** k * np.sin(a * x + b * y + phase)
    V = np.c_[x.ravel(), y.ravel(), z.ravel()]
    v = (np.arange(n - 1)[:, None] * n + np.arange(n - 1)[None, :]).ravel()
    F = np.vstack([np.c_[v, v + 1, v + n + 1], np.c_[v, v + n + 1, v + n]])
    return V, F


def sawtooth():
    """A flat disk whose boundary zigzags between radii 1 and 0.8 (60 teeth), Delaunay
    triangulated over 2,000 random points."""
    m = 120
    t = np.linspace(0, 2 * np.pi, m, endpoint=False)
    r = np.where(np.arange(m) % 2 == 0, 1.0, 0.8)
    points = vtk.vtkPoints()
    for ti, ri in zip(t, r):
        points.InsertNextPoint(ri * np.cos(ti), ri * np.sin(ti), 0.0)
    for p in np.random.default_rng(2).uniform(-1, 1, (2000, 2)):
        if np.hypot(*p) < 0.78:
            points.InsertNextPoint(p[0], p[1], 0.0)
    return from_polydata(delaunay_inside(points, [list(range(m))]))


def cone():
    """A closed cone of 512 sides: its apex on 512 triangles, its cap one polygon triangulated."""
    c = vtk.vtkConeSource()
    c.SetResolution(512)
    c.SetHeight(1.5)
    c.SetRadius(0.6)
    c.CappingOn()
    c.Update()
    return from_polydata(c.GetOutput())


def mixed_box():
    """A unit box whose top is a 100 x 100 grid and whose four sides are fans of long triangles
    from the top's edges down to the bottom's corners (the bottom two triangles)."""
    n = 100
    top = lambda i, j: i * (n + 1) + j
    V = [[i / n, j / n, 1.0] for i in range(n + 1) for j in range(n + 1)]
    F = []
    for i in range(n):
        for j in range(n):
            F += [[top(i, j), top(i + 1, j), top(i + 1, j + 1)],
                  [top(i, j), top(i + 1, j + 1), top(i, j + 1)]]
    b = len(V)
    V += [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]
    F += [[b, b + 2, b + 1], [b, b + 3, b + 2]]

    def side(edge, b0, b1):
        for k in range(n):
            F.append([b0 if k < n // 2 else b1, edge[k + 1], edge[k]])
        F.append([b0, b1, edge[n // 2]])
    side([top(i, 0) for i in range(n + 1)], b, b + 1)
    side([top(n, j) for j in range(n + 1)], b + 1, b + 2)
    side([top(i, n) for i in range(n, -1, -1)], b + 2, b + 3)
    side([top(0, j) for j in range(n, -1, -1)], b + 3, b)
    return np.array(V, float), np.array(F)


SHAPES = {
    "vase": vase,
    "spiral": spiral,
    "superellipsoid": lambda: super_shape(vtk.vtkParametricSuperEllipsoid()),
    "supertoroid": lambda: super_shape(vtk.vtkParametricSuperToroid()),
    "gear": gear,
    "thinring": thin_ring,
    "urchin": urchin,
    "wavysheet": wavy_sheet,
    "helixtube": helix_tube,
    "gyroid": gyroid,
    "perforated": perforated,
    "blobs": blobs,
    "noisysphere": noisy_sphere,
    "nested": lambda: two_spheres(0.5),
    "thinshell": lambda: two_spheres(0.99),
    "longtriangles": long_triangles,
    "holey": holey,
    "noisyblobs": noisy_blobs,
    "spindle": spindle,
    "crossing": crossing,
    "terrain": terrain,
    "sawtooth": sawtooth,
    "cone": cone,
    "mixedbox": mixed_box,
}


def write_all(out, shapes):
    """Each of `shapes` (name: a function giving (V, F)) to OUT/NAME.obj."""
    os.makedirs(out, exist_ok=True)
    for name, make in shapes.items():
        V, F = make()
        write(out, name, V, F)
        print("%s.obj: %d points, %d triangles" % (name, len(V), len(F)))


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    write_all(sys.argv[1], SHAPES)


if __name__ == "__main__":
    main()
