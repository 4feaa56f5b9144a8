"""hostile_cases.py: the hostile inputs, each with the outcome quadcover owes it.

Every case is a function that writes its input file into a folder and returns its path; CASES
maps its name to (the function, the expectation). An expectation is either
  Refused("phrase"): exit 1 and one line on stderr that contains the phrase (case ignored), or
  Quads(components, euler[, irregular]): exit 0 and a valid quad mesh with that many connected
  components and that Euler characteristic (an int, or a tuple of the values allowed), and with
  at most `irregular` inner irregular vertices where that is given.

    hostile_cases.py FOLDER [NAME ...]   writes the inputs (all of them without names)
"""
import math
import os
import random
import struct
import sys

import hostile_meshes as m


class Refused:
    def __init__(self, phrase):
        self.phrase = phrase


class Quads:
    def __init__(self, components, euler, irregular=None):
        self.components = components
        self.euler = euler
        self.irregular = irregular


def _write(folder, name, data):
    path = os.path.join(folder, name)
    with open(path, "wb" if isinstance(data, bytes) else "w") as f:
        f.write(data)
    return path


def _obj_text(mesh, number="%.9g"):
    points, faces = mesh
    return "".join("v " + " ".join(number % x for x in p) + "\n" for p in points) + \
        "".join("f " + " ".join(str(i + 1) for i in f) + "\n" for f in faces)


def _garbage(seed, size=4096):
    """Random bytes, the same every run (no text format could take them for its own)."""
    rng = random.Random(seed)
    return bytes(rng.randrange(256) for _ in range(size))


SPHERE = m.icosphere(2)


def empty(ext):
    return lambda folder: _write(folder, "empty" + ext, b"")


def garbage(ext):
    return lambda folder: _write(folder, "garbage" + ext, _garbage(ext))


def binary_named(ext):
    # a well-formed binary STL, named as a text format
    return lambda folder: _write(folder, "binary" + ext, m.stl_binary(SPHERE))


def nonfinite_obj(folder):
    return _write(folder, "nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n")


def nonfinite_off(folder):
    return _write(folder, "inf.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 inf 0\n3 0 1 2\n")


def nonfinite_ply(folder):
    points, faces = SPHERE
    points = list(points)
    points[7] = (float("inf"), 0.0, 0.0)
    return _write(folder, "inf.ply", m.ply_bytes((points, faces), binary=False))


def nonfinite_vtp(folder):
    points, faces = SPHERE
    points = list(points)
    points[3] = (0.0, float("nan"), 0.0)
    path = os.path.join(folder, "nan.vtp")
    m.write_vtp(path, (points, faces))
    return path


def scaled_vtp(name, factor):
    def make(folder):
        path = os.path.join(folder, name)
        m.write_vtp(path, m.scaled(SPHERE, factor))
        return path
    return make


def scaled_obj(name, factor):
    return lambda folder: _write(folder, name, _obj_text(m.scaled(SPHERE, factor), "%.17g"))


TRIANGLE_OBJ = "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
TRIANGLE_OFF = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n"


def huge_ply(folder):
    # double-precision coordinates near 1e150, which VTK's PLY reader would store as float
    head = m.ply_header("ascii", 3, 1).replace(b"float", b"double")
    body = b"0 0 0\n1e150 0 0\n0 1e150 0\n3 0 1 2\n"
    return _write(folder, "huge.ply", head + body)


def bad_index_ply(index):
    def make(folder):
        head = m.ply_header("ascii", 3, 1)
        body = b"0 0 0\n1 0 0\n0 1 0\n3 0 1 %d\n" % index
        return _write(folder, "index%d.ply" % index, head + body)
    return make


def truncated_binary_ply(folder):
    data = m.ply_bytes(SPHERE, binary=True)
    return _write(folder, "truncated_binary.ply", data[:len(data) * 2 // 3])


def truncated_ascii_ply(folder):
    data = m.ply_bytes(SPHERE, binary=False)
    return _write(folder, "truncated_ascii.ply", data[:len(data) * 2 // 3])


def huge_header_ply(folder):
    # the header claims 1e9 vertices; the file is 251 bytes
    head = m.ply_header("binary_little_endian", 10 ** 9, 1)
    data = head + struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
    data += struct.pack("<B3i", 3, 0, 1, 2)
    data = data.ljust(251, b"\0")[:251]
    return _write(folder, "huge_header.ply", data)


def truncated_binary_stl(folder):
    # the header says 1056 triangles, 10 are there
    points, faces = SPHERE
    return _write(folder, "truncated_binary.stl", m.stl_binary((points, faces[:10]), 1056))


def ascii_stl(folder):
    # a whole sphere as ASCII STL, its points repeated per facet (the reader joins them)
    return _write(folder, "sphere_ascii.stl", m.stl_ascii(SPHERE))


def bad_number_stl(folder):
    text = m.stl_ascii(SPHERE)
    at = text.find("vertex", len(text) // 2) + len("vertex ")
    return _write(folder, "bad_number.stl", text[:at] + "1.0x" + text[at + 1:])


def truncated_ascii_stl(folder):
    text = m.stl_ascii(SPHERE)
    cut = text.find("vertex", len(text) // 2)  # in the middle of a facet
    return _write(folder, "truncated_ascii.stl", text[:cut + 10])


def truncated_obj(folder):
    # the faces sorted from the top down, cut in the middle of a face line 70% through: what
    # is left is a cap of the sphere (a disk), its last face cut short to two indices
    points, faces = SPHERE
    faces = sorted(faces, key=lambda f: -sum(points[i][2] for i in f))
    text = _obj_text((points, faces))
    face_lines = text.index("\nf ")
    cut = text.index("\nf ", face_lines + int(0.7 * (len(text) - face_lines)))
    second = text.index(" ", text.index(" ", cut + 3) + 1)
    return _write(folder, "truncated.obj", text[:second])


def truncated_vtp(folder):
    path = os.path.join(folder, "whole.vtp")
    m.write_vtp(path, SPHERE)
    with open(path, "rb") as f:
        data = f.read()
    os.remove(path)
    return _write(folder, "truncated.vtp", data[:len(data) // 2])


def vertices_only(folder):
    return _write(folder, "vertices.obj", _obj_text((SPHERE[0], [])))


def lines_only(folder):
    path = os.path.join(folder, "lines.obj")
    m.write_obj(path, (SPHERE[0], []), lines=[(i, i + 1) for i in range(40)])
    return path


def polygon_100(folder):
    points = [(math.cos(2 * math.pi * i / 100), math.sin(2 * math.pi * i / 100), 0.0)
              for i in range(100)]
    return _write(folder, "polygon100.obj", _obj_text((points, [tuple(range(100))])))


def sliver_strip(folder):
    # a unit square as one strip of 400 needles, each 1 long and 0.005 wide
    n = 200
    points = [(i / n, 0.0, 0.0) for i in range(n + 1)] + [(i / n, 1.0, 0.0) for i in range(n + 1)]
    faces = []
    for i in range(n):
        faces += [(i, i + 1, n + 2 + i), (i, n + 2 + i, n + 1 + i)]
    return _write(folder, "slivers.obj", _obj_text((points, faces)))


def sliver_washer(folder):
    # a flat washer (radii 0.3 and 1, thickness 0.1) as a CAD export meshes it: each face one
    # band of triangles from rim to rim, 13 grid edges long at 3,000 quads (refined before the map)
    n = 48
    points, faces = [], []
    for z in (0.0, 0.1):
        for r in (1.0, 0.3):
            points += [(r * math.cos(2 * math.pi * i / n), r * math.sin(2 * math.pi * i / n), z)
                       for i in range(n)]
    ring = [k * n for k in range(4)]  # bottom outer, bottom inner, top outer, top inner

    def band(a, b, flip):
        for i in range(n):
            j = (i + 1) % n
            for t in ((a + i, a + j, b + j), (a + i, b + j, b + i)):
                faces.append(t[::-1] if flip else t)
    band(ring[0], ring[1], True)   # bottom, facing down
    band(ring[2], ring[3], False)  # top, facing up
    band(ring[0], ring[2], False)  # outer wall, facing out
    band(ring[1], ring[3], True)   # inner wall, facing the hole
    return _write(folder, "washer.obj", _obj_text((points, faces)))


def duplicate_triangles(folder):
    points, faces = SPHERE
    return _write(folder, "duplicates.obj", _obj_text((points, faces + faces)))


def degenerate_next_to_sphere(folder):
    # beside the sphere, on a line of 12 points (and a 13th at the first one's place): triangles
    # with a repeated point, one with two points at one place, and six with three points on the
    # line (distinct, but of zero area)
    points, faces = SPHERE
    n = len(points)
    points = list(points) + [(3.0 + 0.1 * i, 0.0, 0.0) for i in range(12)] + [(3.0, 0.0, 0.0)]
    extra = [(0, 0, 1), (2, 3, 3), (0, 12, 1)] + [(i, i + 1, i + 2) for i in range(4, 10)]
    return _write(folder, "degenerate.obj",
                  _obj_text((points, faces + [tuple(n + i for i in f) for f in extra])))


def stray_collinear_triangle(folder):
    points, faces = SPHERE
    n = len(points)
    points = list(points) + [(3.0, 0.0, 0.0), (4.0, 0.0, 0.0), (5.0, 0.0, 0.0)]
    return _write(folder, "collinear.obj", _obj_text((points, faces + [(n, n + 1, n + 2)])))


def collinear_fans(folder):
    # a T-junction repaired as CAD exports do: six edges of a sphere each get five points on them
    # (written with 17 digits: on it to round-off), the triangle on one side split from its far
    # corner, the one on the
    # other side fanned from the edge's end into a row of caps (triangles of zero area, a corner
    # on the longest edge), which left one map unable to be factored
    points, faces = m.icosphere(3)
    points, faces = list(points), list(faces)
    face_of = {(f[k], f[(k + 1) % 3]): i for i, f in enumerate(faces) for k in range(3)}
    used = set()
    for start in range(0, len(faces), 211):
        a, b, c = faces[start]
        other = face_of[(b, a)]
        d = next(p for p in faces[other] if p not in (a, b))
        if used & {a, b, c, d}:
            continue
        used |= {a, b, c, d}
        chain = [a]
        for j in range(1, 6):
            chain.append(len(points))
            points.append(tuple(x + j / 6 * (y - x) for x, y in zip(points[a], points[b])))
        chain.append(b)
        faces[other] = None
        faces += [(chain[j + 1], chain[j], d) for j in range(len(chain) - 1)]
        faces += [(a, chain[j], chain[j + 1]) for j in range(1, len(chain) - 1)]
    faces = [f for f in faces if f is not None]
    return _write(folder, "collinear_fans.obj", _obj_text((points, faces), "%.17g"))


def faces_meshed_apart(folder):
    # a box whose six faces were meshed one by one (4 to 8 squares a side, as some CAD exports
    # do): the seams' points do not match, every other point of a seam is a T-junction; before
    # they were closed it came out as six separate squares
    points, faces = [], []
    sides = [((0, 0, 0), (0, 1, 0), (1, 0, 0)), ((0, 0, 1), (1, 0, 0), (0, 1, 0)),
             ((0, 0, 0), (1, 0, 0), (0, 0, 1)), ((0, 1, 0), (0, 0, 1), (1, 0, 0)),
             ((0, 0, 0), (0, 0, 1), (0, 1, 0)), ((1, 0, 0), (0, 1, 0), (0, 0, 1))]
    for (o, u, v), n in zip(sides, (4, 6, 5, 3, 8, 7)):
        base = len(points)
        points += [tuple(o[k] + u[k] * i / n + v[k] * j / n for k in range(3))
                   for j in range(n + 1) for i in range(n + 1)]
        for j in range(n):
            for i in range(n):
                a = base + j * (n + 1) + i
                faces += [(a, a + 1, a + n + 2), (a, a + n + 2, a + n + 1)]
    return _write(folder, "faces_meshed_apart.obj", _obj_text((points, faces)))


def hemispheres_meshed_apart(folder):
    # a sphere whose hemispheres were meshed apart, 32 and 64 points on the equator: the lower
    # side's extra points lie 0.5% of the diameter off the upper side's chords (a curved seam's
    # crack); it came out as two hemispheres
    points, faces = [], []
    for side, n in ((1, 32), (-1, 64)):
        base = len(points)
        for k in range(8):
            lat = side * math.pi / 2 * k / 8
            points += [(math.cos(lat) * math.cos(2 * math.pi * i / n),
                        math.cos(lat) * math.sin(2 * math.pi * i / n), math.sin(lat))
                       for i in range(n)]
        points.append((0.0, 0.0, float(side)))
        pole = len(points) - 1
        for k in range(8):
            for i in range(n):
                a, b = base + k * n + i, base + k * n + (i + 1) % n
                tris = [(a, b, pole)] if k == 7 else [(a, b, b + n), (a, b + n, a + n)]
                faces += [t if side > 0 else t[::-1] for t in tris]
    return _write(folder, "hemispheres.obj", _obj_text((points, faces), "%.17g"))


def sliver_lens(folder):
    # a thin lens whose tips are single triangles of about 10 degrees: no grid cell of its map gave
    # a quad at any count
    return _write(folder, "lens.obj", _obj_text(m.lens()))


def lens_beside_sphere(folder):
    # the lens, a tenth of the sphere's size, beside it: its component gave no quad and was lost
    points, faces = m.lens(length=0.2)
    points = [(x + 3.0, y, z) for x, y, z in points]
    return _write(folder, "lens_sphere.obj", _obj_text(m.merge(SPHERE, (points, faces))))


def noisy_sphere(folder):
    # a sphere of 5,120 triangles whose points carry noise of half a mean edge length, as a raw
    # scan: smoothed by the repair, its 500 quads have about 10 irregular vertices (left rough,
    # 292, and its field a singularity at nearly every other point)
    points, faces = m.icosphere(4)
    edge = sum(math.dist(points[f[k]], points[f[k - 1]]) for f in faces for k in range(3)) / \
        (3 * len(faces))
    rng = random.Random(11)
    noisy = [tuple(x + rng.gauss(0.0, 0.5 * edge) for x in p) for p in points]
    return _write(folder, "noisy_sphere.obj", _obj_text((noisy, faces)))


def cube_12(folder):
    return _write(folder, "cube.obj", _obj_text(m.box()))


def coarse_cone(folder):
    return _write(folder, "cone.obj", _obj_text(m.cone()))


def needle_sphere(folder):
    # 4 rings of 200 needles, 10 degrees from pole to pole and under 2 across
    return _write(folder, "needles.obj", _obj_text(m.uv_sphere(4, 200)))


def seamed_torus(folder):
    path = os.path.join(folder, "seamed_torus.vtp")  # double precision: the round-off survives
    m.write_vtp(path, m.seamed_torus())
    return path


def genus_5(folder):
    return _write(folder, "genus5.obj", _obj_text(m.genus(5)))


def _spheres(folder, name, count, subdivisions):
    """`count` icospheres of radii 0.01 .. 10 in equal ratios, side by side along x."""
    spheres, x = [], 0.0
    for k in range(count):
        r = 0.01 * 1000 ** (k / (count - 1))
        spheres.append(m.icosphere(subdivisions, r, (x + r, 0.0, 0.0)))
        x += 2 * r + 0.5
    path = os.path.join(folder, name)
    m.write_vtp(path, m.merge(*spheres))
    return path


def twenty_spheres(folder):
    return _spheres(folder, "twenty_spheres.vtp", 20, 2)


def fine_spheres(folder):
    # 24 spheres of 5,120 triangles, radii 0.01 .. 10: 122,880 triangles, more than the default
    # simplification leaves (100,000 at 500 quads); the small spheres' share of the triangles by
    # area is far below 256 and they must stay whole
    return _spheres(folder, "fine_spheres.vtp", 24, 4)


def nonmanifold_edge(folder):
    # three triangles on the edge (0, 1)
    text = "v 0 0 0\nv 1 0 0\nv 0.5 1 0\nv 0.5 -0.5 0.8\nv 0.5 -0.5 -0.8\n"
    return _write(folder, "three_on_an_edge.obj", text + "f 1 2 3\nf 2 1 4\nf 1 2 5\n")


def boxes_sharing_an_edge(folder):
    # [0,1]^3 and [1,2]x[1,2]x[0,1] share the edge x = y = 1
    points, faces = m.voxels({(0, 0, 0), (1, 1, 0)}, 4)
    return _write(folder, "two_boxes.obj", _obj_text((points, faces)))


def spheres_touching(folder):
    # the sphere and its mirror image through its point 0, sharing that point (the mirror
    # turns the triangles inside out, so their order is reversed too)
    points, faces = SPHERE
    top = points[0]
    shifted = [tuple(2 * t - x for t, x in zip(top, p)) for p in points]
    both = list(points) + shifted[1:]
    remap = [0] + list(range(len(points), len(points) + len(points) - 1))
    return _write(folder, "touching.obj",
                  _obj_text((both, faces + [tuple(remap[i] for i in f[::-1]) for f in faces])))


def _box_with_fin(name, tip):
    # a square fin standing on the box's top edge y = 1, z = 1, its far edge at (x, tip[0], tip[1])
    def make(folder):
        points, faces = m.box(n=4)
        points = list(points)
        edge = [i for i, p in enumerate(points) if abs(p[1] - 1) < 1e-9 and abs(p[2] - 1) < 1e-9]
        edge.sort(key=lambda i: points[i][0])
        top = []
        for i in edge:
            top.append(len(points))
            points.append((points[i][0], tip[0], tip[1]))
        for k in range(len(edge) - 1):
            faces += [(edge[k], edge[k + 1], top[k + 1]), (edge[k], top[k + 1], top[k])]
        return _write(folder, name, _obj_text((points, faces)))
    return make


fin_on_a_box = _box_with_fin("fin.obj", (1.0, 1.5))
# leaning into the box: around the edge the fin lies between the box's two faces, on the
# solid's side
fin_into_a_box = _box_with_fin("fin_into.obj", (0.4, 0.7))


def moebius(folder):
    return _write(folder, "moebius.obj", _obj_text(m.moebius()))


def _text(name, text):
    return lambda folder: _write(folder, name, text)


CASES = {
    "empty_obj": (empty(".obj"), Refused("the file is empty")),
    "empty_off": (empty(".off"), Refused("the file is empty")),
    "empty_ply": (empty(".ply"), Refused("the file is empty")),
    "empty_stl": (empty(".stl"), Refused("the file is empty")),
    "empty_vtp": (empty(".vtp"), Refused("the file is empty")),
    "garbage_obj": (garbage(".obj"), Refused("not a text OBJ file")),
    "garbage_off": (garbage(".off"), Refused("not a text OFF file")),
    "garbage_ply": (garbage(".ply"), Refused("not a PLY file")),
    "garbage_stl": (garbage(".stl"), Refused("binary STL")),
    "garbage_vtp": (garbage(".vtp"), Refused("cannot read")),
    "binary_obj": (binary_named(".obj"), Refused("not a text OBJ file")),
    "binary_off": (binary_named(".off"), Refused("not a text OFF file")),
    "nan_obj": (nonfinite_obj, Refused("non-finite")),
    "inf_off": (nonfinite_off, Refused("non-finite")),
    "inf_ply": (nonfinite_ply, Refused("NaN or infinite")),
    "nan_vtp": (nonfinite_vtp, Refused("NaN or infinite")),
    "tiny_vtp": (scaled_vtp("tiny.vtp", 1e-160), Quads(1, 2)),
    "huge_vtp": (scaled_vtp("huge.vtp", 1e150), Quads(1, 2)),
    "tiny_obj": (scaled_obj("tiny.obj", 1e-160), Quads(1, 2)),
    "huge_obj": (scaled_obj("huge.obj", 1e150), Quads(1, 2)),
    "huge_ply": (huge_ply, Refused("single precision")),
    "bad_index_obj": (_text("index.obj", TRIANGLE_OBJ + "f 1 2 9\n"), Refused("refers to vertex 9")),
    "negative_index_obj": (_text("negative.obj", TRIANGLE_OBJ + "f -1 -2 -9\n"),
                           Refused("refers to vertex -9")),
    # the most negative 64-bit index: its negation overflows
    "lowest_index_obj": (_text("lowest.obj", TRIANGLE_OBJ + "f 1 2 -9223372036854775808\n"),
                         Refused("refers to vertex -9223372036854775808")),
    "short_vertex_obj": (_text("short.obj", "v 0 0\n" + TRIANGLE_OBJ + "f 2 3 4\n"),
                         Refused("line 1 has a vertex of fewer than three coordinates")),
    "word_index_obj": (_text("word.obj", TRIANGLE_OBJ + "f 1 2 x/1\n"),
                       Refused("line 4 has a vertex index that is not a number")),
    # the error shows 32 characters of a long token, and an index beyond 64 bits is no vertex
    "long_token_obj": (_text("long.obj", TRIANGLE_OBJ + "f 1 2 " + 5000 * "x" + "\n"),
                       Refused("not a number (" + 32 * "x" + "...)")),
    "huge_index_obj": (_text("huge_index.obj", TRIANGLE_OBJ + "f 1 2 99999999999999999999\n"),
                       Refused("refers to vertex 99999999999999999999, which does not exist")),
    "bad_index_off": (_text("index.off", TRIANGLE_OFF + "3 0 1 7\n"), Refused("refers to vertex 7")),
    "negative_index_off": (_text("negative.off", TRIANGLE_OFF + "3 0 1 -2\n"),
                           Refused("refers to vertex -2")),
    "bad_index_ply": (bad_index_ply(70000), Refused("refers to point 70000")),
    "negative_index_ply": (bad_index_ply(-3), Refused("refers to point -3")),
    "truncated_binary_ply": (truncated_binary_ply, Refused("cut short")),
    "truncated_ascii_ply": (truncated_ascii_ply, Refused("cut short")),
    "huge_header_ply": (huge_header_ply, Refused("more than the file")),
    "truncated_binary_stl": (truncated_binary_stl, Refused("1056 triangles")),
    "truncated_ascii_stl": (truncated_ascii_stl, Refused("ends in the middle of a facet")),
    "ascii_stl": (ascii_stl, Quads(1, 2)),
    "bad_number_stl": (bad_number_stl, Refused("a vertex needs three numbers")),
    "truncated_obj": (truncated_obj, Refused("cut short")),
    "truncated_vtp": (truncated_vtp, Refused("cannot read")),
    "vertices_only": (vertices_only, Refused("no polygons")),
    "lines_only": (lines_only, Refused("no polygons")),
    "polygon_100": (polygon_100, Quads(1, 1)),
    "sliver_strip": (sliver_strip, Quads(1, 1)),
    "sliver_washer": (sliver_washer, Quads(1, 0)),
    "duplicate_triangles": (duplicate_triangles, Quads(1, 2)),
    "degenerate_next_to_sphere": (degenerate_next_to_sphere, Quads(1, 2)),
    "stray_collinear_triangle": (stray_collinear_triangle, Quads(1, 2)),
    "collinear_fans": (collinear_fans, Quads(1, 2)),
    "faces_meshed_apart": (faces_meshed_apart, Quads(1, 2)),
    "hemispheres_meshed_apart": (hemispheres_meshed_apart, Quads(1, 2)),
    "sliver_lens": (sliver_lens, Quads(1, 1)),
    "lens_beside_sphere": (lens_beside_sphere, Quads(2, 3)),
    "noisy_sphere": (noisy_sphere, Quads(1, 2, irregular=40)),
    "cube_12": (cube_12, Quads(1, 2)),
    "coarse_cone": (coarse_cone, Quads(1, 2)),
    "needle_sphere": (needle_sphere, Quads(1, 2)),
    "seamed_torus": (seamed_torus, Quads(1, 0)),
    "genus_5": (genus_5, Quads(1, -8)),
    "twenty_spheres": (twenty_spheres, Quads(20, 40)),
    "fine_spheres": (fine_spheres, Quads(24, 48)),
    # cut apart: one pair of the three stays joined or none does; every piece is a disk
    "nonmanifold_edge": (nonmanifold_edge, Quads((2, 3), (2, 3))),
    "boxes_sharing_an_edge": (boxes_sharing_an_edge, Quads(2, 4)),
    "spheres_touching": (spheres_touching, Quads(2, 4)),
    "fin_on_a_box": (fin_on_a_box, Quads(2, 3)),
    "fin_into_a_box": (fin_into_a_box, Quads(2, 3)),
    "moebius": (moebius, Refused("orientable")),
}


def main(argv):
    folder = argv[1]
    os.makedirs(folder, exist_ok=True)
    for name in argv[2:] or sorted(CASES):
        print(CASES[name][0](folder))


if __name__ == "__main__":
    main(sys.argv)
