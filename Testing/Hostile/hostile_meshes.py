"""hostile_meshes.py: the surfaces the hostile cases are made of, and writers for every format
quadcover reads.

A mesh is (points, faces): a list of (x, y, z) and a list of tuples of 0-based point ids. The
writers are written out by hand (no numpy, VTK only for .vtp) so that a case can say exactly
which bytes a file holds, and can cut it wherever it likes.
"""
import math
import struct


# ---- surfaces ----
def icosphere(subdivisions=2, radius=1.0, center=(0.0, 0.0, 0.0)):
    """A sphere from an icosahedron cut into 4 triangles per level (2 levels: 320 triangles)."""
    t = (1.0 + math.sqrt(5.0)) / 2.0
    points = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
              (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
             (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
             (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    points = [_unit(p) for p in points]
    for _ in range(subdivisions):
        middle = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                middle[key] = len(points)
                points.append(_unit(tuple((x + y) / 2 for x, y in zip(points[a], points[b]))))
            return middle[key]

        finer = []
        for a, b, c in faces:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            finer += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = finer
    return [tuple(c + radius * x for c, x in zip(center, p)) for p in points], faces


def _unit(p):
    n = math.sqrt(sum(x * x for x in p))
    return tuple(x / n for x in p)


def box(lo=(0.0, 0.0, 0.0), hi=(1.0, 1.0, 1.0), n=1):
    """The surface of an axis-aligned box, each side an n x n grid of squares cut in two."""
    return voxels({(0, 0, 0)}, n, lo, hi)


def voxels(cells, n=1, lo=(0.0, 0.0, 0.0), hi=None):
    """The outer surface of a union of unit cubes (integer cells (i, j, k)), each square side
    an n x n grid cut into triangles, wound outwards. Cubes must not meet along an edge only
    (the surface would not be a manifold there). The cubes are scaled to fit lo..hi when hi is
    given, else sit at lo with side 1."""
    index, points, faces = {}, [], []

    def point(q):
        if q not in index:
            index[q] = len(points)
            points.append(q)
        return index[q]

    for c in cells:
        for axis in range(3):
            for side in (0, 1):
                nb = list(c)
                nb[axis] += 1 if side else -1
                if tuple(nb) in cells:
                    continue
                _voxel_side(c, axis, side, n, point, faces)
    span = [h - l for l, h in zip(lo, hi)] if hi else [1.0, 1.0, 1.0]
    return [tuple(l + s * x / n for l, s, x in zip(lo, span, p)) for p in points], faces


def _voxel_side(c, axis, side, n, point, faces):
    """Triangles of one side of cube c, in grid units of 1/n, wound with the normal outwards."""
    u, v = (axis + 1) % 3, (axis + 2) % 3

    def corner(i, j):
        q = [0, 0, 0]
        q[axis] = n * (c[axis] + side)
        q[u] = n * c[u] + i
        q[v] = n * c[v] + j
        return point(tuple(q))

    for i in range(n):
        for j in range(n):
            a, b, d, e = corner(i, j), corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1)
            # (u, v, axis) is right-handed, so counter-clockwise in (u, v) faces +axis
            faces += [(a, b, d), (a, d, e)] if side else [(a, d, b), (a, e, d)]


def genus(holes, n=2):
    """A slab of 2*holes+1 x 3 x 1 cubes with `holes` square holes through it: genus `holes`."""
    cells = {(i, j, 0) for i in range(2 * holes + 1) for j in range(3)}
    cells -= {(2 * h + 1, 1, 0) for h in range(holes)}
    return voxels(cells, n)


def cone(around=64, height=2.0, radius=1.0):
    """A closed cone as VTK's cone source makes it: a fan of long needles around the tip, and the
    base one polygon of `around` sides (the repair triangulates it)."""
    points = [(0.0, 0.0, height)]
    faces = []
    for i in range(around):
        a = 2 * math.pi * i / around
        points.append((radius * math.cos(a), radius * math.sin(a), 0.0))
        faces.append((0, 1 + i, 1 + (i + 1) % around))
    faces.append(tuple(range(around, 0, -1)))
    return points, faces


def uv_sphere(rings, segments, radius=1.0):
    """A sphere of latitude rings and longitude segments, closed by a fan at each pole: with
    many more segments than rings, a sphere of needles."""
    points = [(0.0, 0.0, -radius), (0.0, 0.0, radius)]
    for j in range(1, rings):
        t = math.pi * j / rings
        for i in range(segments):
            a = 2 * math.pi * i / segments
            points.append((radius * math.sin(t) * math.cos(a), radius * math.sin(t) * math.sin(a),
                           -radius * math.cos(t)))
    ring = lambda j, i: 2 + (j - 1) * segments + i % segments
    faces = []
    for i in range(segments):
        faces.append((0, ring(1, i + 1), ring(1, i)))
        faces.append((1, ring(rings - 1, i), ring(rings - 1, i + 1)))
        for j in range(1, rings - 1):
            faces += [(ring(j, i), ring(j, i + 1), ring(j + 1, i + 1)),
                      (ring(j, i), ring(j + 1, i + 1), ring(j + 1, i))]
    return points, faces


def seamed_torus(n=40, radius=1.0, tube=0.4):
    """A torus as VTK's parametric sources make it: an (n + 1) x (n + 1) grid whose last row and
    column, computed at 2 pi, lie round-off (about 1e-16) away from the first's."""
    points = []
    for i in range(n + 1):
        for j in range(n + 1):
            u, v = 2 * math.pi * i / n, 2 * math.pi * j / n
            points.append(((radius + tube * math.cos(v)) * math.cos(u),
                           (radius + tube * math.cos(v)) * math.sin(u), tube * math.sin(v)))
    index = lambda i, j: i * (n + 1) + j
    faces = []
    for i in range(n):
        for j in range(n):
            faces += [(index(i, j), index(i + 1, j), index(i + 1, j + 1)),
                      (index(i, j), index(i + 1, j + 1), index(i, j + 1))]
    return points, faces


def lens(n=60, tip_degrees=10.0, length=2.0):
    """A flat lens between the arcs y = +-t (1 - x^2) (x in -1..1, scaled to `length`), t such
    that each tip is one triangle of a little less than tip_degrees, as n strips across it (an
    isosurface cut by its volume's face leaves such slivers)."""
    t = math.tan(math.radians(tip_degrees) / 2) / 2
    s = length / 2
    points = [(-s, 0.0, 0.0), (s, 0.0, 0.0)]
    upper, lower = [0], [0]
    for i in range(1, n):
        x = -1.0 + 2.0 * i / n
        y = t * (1 - x * x)
        upper.append(len(points))
        points.append((s * x, s * y, 0.0))
        lower.append(len(points))
        points.append((s * x, -s * y, 0.0))
    upper.append(1)
    lower.append(1)
    faces = [(0, lower[1], upper[1])]
    for i in range(1, n - 1):
        faces += [(lower[i], lower[i + 1], upper[i]), (upper[i], lower[i + 1], upper[i + 1])]
    faces.append((upper[n - 1], lower[n - 1], 1))
    return points, faces


def moebius(around=48, across=4, radius=1.0, width=0.3):
    """A Moebius strip: a band whose ends are glued after half a turn."""
    points = []
    for i in range(around):
        a = 2 * math.pi * i / around
        for j in range(across + 1):
            s = width * (2.0 * j / across - 1.0)
            r = radius + s * math.cos(a / 2)
            points.append((r * math.cos(a), r * math.sin(a), s * math.sin(a / 2)))
    faces = []
    for i in range(around):
        for j in range(across):
            a, b = i * (across + 1) + j, i * (across + 1) + j + 1
            if i + 1 < around:
                c, d = a + across + 1, b + across + 1
            else:  # the half turn: row 0 glued back to front
                c, d = across - j, across - j - 1
            faces += [(a, c, d), (a, d, b)]
    return points, faces


def merge(*meshes):
    """The meshes side by side in one point list (no points shared)."""
    points, faces = [], []
    for p, f in meshes:
        offset = len(points)
        points += list(p)
        faces += [tuple(i + offset for i in face) for face in f]
    return points, faces


def scaled(mesh, factor):
    return [tuple(factor * x for x in p) for p in mesh[0]], mesh[1]


# ---- writers ----
def write_obj(path, mesh, lines=(), number="%.9g"):
    points, faces = mesh
    with open(path, "w") as f:
        for p in points:
            f.write("v " + " ".join(number % x for x in p) + "\n")
        for face in faces:
            f.write("f " + " ".join(str(i + 1) for i in face) + "\n")
        for line in lines:
            f.write("l " + " ".join(str(i + 1) for i in line) + "\n")


def ply_header(fmt, vertices, faces):
    return ("ply\nformat %s 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
            "property float z\nelement face %d\nproperty list uchar int vertex_indices\n"
            "end_header\n" % (fmt, vertices, faces)).encode()


def ply_bytes(mesh, binary):
    points, faces = mesh
    head = ply_header("binary_little_endian" if binary else "ascii", len(points), len(faces))
    if binary:
        body = b"".join(struct.pack("<3f", *p) for p in points)
        body += b"".join(struct.pack("<B%di" % len(f), len(f), *f) for f in faces)
    else:
        body = "".join("%.9g %.9g %.9g\n" % p for p in points).encode()
        body += "".join("%d %s\n" % (len(f), " ".join(map(str, f))) for f in faces).encode()
    return head + body


def _normal(a, b, c):
    u = [y - x for x, y in zip(a, b)]
    v = [y - x for x, y in zip(a, c)]
    n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
    length = math.sqrt(sum(x * x for x in n)) or 1.0
    return tuple(x / length for x in n)


def stl_binary(mesh, claimed=None):
    """A binary STL; `claimed` puts another triangle count in its header."""
    points, faces = mesh
    out = [b"hostile binary STL".ljust(80, b"\0")]
    out.append(struct.pack("<I", len(faces) if claimed is None else claimed))
    for face in faces:
        p = [points[i] for i in face]
        out.append(struct.pack("<12fH", *_normal(*p), *p[0], *p[1], *p[2], 0))
    return b"".join(out)


def stl_ascii(mesh):
    points, faces = mesh
    text = ["solid hostile\n"]
    for face in faces:
        p = [points[i] for i in face]
        text.append("  facet normal %.6g %.6g %.6g\n    outer loop\n" % _normal(*p))
        text += ["      vertex %.9g %.9g %.9g\n" % q for q in p]
        text.append("    endloop\n  endfacet\n")
    return "".join(text) + "endsolid hostile\n"


def write_vtp(path, mesh, binary=True):
    """An XML PolyData file with double-precision points (appended, raw, or ASCII)."""
    from vtkmodules.vtkCommonCore import VTK_DOUBLE, vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

    points, faces = mesh
    pts = vtkPoints()
    pts.SetDataType(VTK_DOUBLE)
    for p in points:
        pts.InsertNextPoint(p)
    cells = vtkCellArray()
    for face in faces:
        cells.InsertNextCell(len(face), face)
    pd = vtkPolyData()
    pd.SetPoints(pts)
    pd.SetPolys(cells)
    w = vtkXMLPolyDataWriter()
    w.SetFileName(path)
    w.SetInputData(pd)
    if binary:
        w.SetDataModeToAppended()
        w.EncodeAppendedDataOff()
        w.SetCompressorTypeToNone()
    else:
        w.SetDataModeToAscii()
    if not w.Write():
        raise RuntimeError("cannot write " + path)
