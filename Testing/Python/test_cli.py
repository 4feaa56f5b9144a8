"""The quadcover command line: exit status, one-line errors, arrays and --stats on success.

Needs QUADCOVER_CLI (the binary) and QUADCOVER_DATA (Data/); QUADCOVER_SHARED_DATA is optional.
"""
import json
import math
import os
import re
import subprocess
import tempfile
import unittest

import vtk

CLI = os.environ["QUADCOVER_CLI"]
DATA = os.environ["QUADCOVER_DATA"]
SHARED = os.environ.get("QUADCOVER_SHARED_DATA", "")

FRAME_ARRAYS = {"PrincipalCurvatures": 2, "PrincipalDirection1": 3, "PrincipalDirection2": 3,
                "FrameU": 3, "FrameV": 3, "FrameWeight": 1}


def run(*args):
    p = subprocess.run([CLI, *args], capture_output=True, text=True, timeout=300)
    return p.returncode, p.stdout, p.stderr


class CommandLine(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def write(self, name, text):
        path = os.path.join(self.dir, name)
        with open(path, "w") as f:
            f.write(text)
        return path

    def assert_one_line_error(self, args, rc, pattern):
        code, out, err = run(*args)
        self.assertEqual(code, rc, err)
        lines = err.strip().splitlines()
        self.assertEqual(len(lines), 1, "expected one line on stderr, got:\n" + err)
        self.assertRegex(lines[0], pattern)
        self.assertNotIn("Traceback", err)

    def check_frames(self, path):
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(path)
        reader.Update()
        out = reader.GetOutput()
        self.assertGreater(out.GetNumberOfCells(), 0)
        for name, comps in FRAME_ARRAYS.items():
            a = out.GetCellData().GetArray(name)
            self.assertIsNotNone(a, name)
            self.assertEqual(a.GetNumberOfComponents(), comps, name)
            self.assertEqual(a.GetNumberOfTuples(), out.GetNumberOfCells(), name)
        return out

    # ---- success ----
    def test_knot_with_stats(self):
        out = os.path.join(self.dir, "knot.vtp")
        stats = os.path.join(self.dir, "knot.json")
        code, _, err = run(os.path.join(DATA, "knot.obj"), "-o", out, "--stage", "curvature",
                           "--stats", stats, "-v")
        self.assertEqual(code, 0, err)
        self.assertIn("curvature", err)  # -v: seconds per stage
        pd = self.check_frames(out)
        with open(stats) as f:
            s = json.load(f)
        self.assertEqual(s["surface"]["triangles"], pd.GetNumberOfCells())
        self.assertEqual(s["surface"]["points"], pd.GetNumberOfPoints())
        self.assertEqual(s["stage"], "curvature")
        self.assertGreaterEqual(s["seconds"]["curvature"], 0.0)
        self.assertEqual(s["repair"]["merged_points"], 0)
        self.assertEqual(s["options"]["neighborhood_radius"], 2)
        self.assertIs(s["options"]["use_input_frames"], True)

    def test_matching_stage_on_the_sphere(self):
        # The sphere: 8 singularities of index +1/4, indices summing to 2.
        out = os.path.join(self.dir, "s.vtp")
        stats = os.path.join(self.dir, "s.json")
        code, _, err = run(os.path.join(DATA, "sphere.obj"), "-o", out, "--stage", "matching",
                           "--stats", stats)
        self.assertEqual(code, 0, err)
        with open(stats) as f:
            m = json.load(f)["matching"]
        self.assertEqual(m["singularity_count"], 8)
        self.assertEqual(m["singularity_histogram"], [[0.25, 8]])
        self.assertAlmostEqual(m["singularity_index_sum"], 2.0, places=9)
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(out)
        reader.Update()
        pd = reader.GetOutput()
        for name in ("Matching", "FrameRotation", "FrameConstrained"):
            self.assertIsNotNone(pd.GetCellData().GetArray(name), name)
        for name in ("LayerShift", "SingularityIndex"):
            self.assertIsNotNone(pd.GetPointData().GetArray(name), name)

    def test_param_stage_options_and_stats(self):
        # The param stage: a seamless map with the sphere's 8 branch points on the
        # grid, no flips, about --target-quad-count cells; the options reach the solver.
        out = os.path.join(self.dir, "s.vtp")
        stats = os.path.join(self.dir, "s.json")
        code, _, err = run(os.path.join(DATA, "sphere.obj"), "-o", out, "--stage", "param",
                           "--target-quad-count", "500", "--stats", stats)
        self.assertEqual(code, 0, err)
        with open(stats) as f:
            s = json.load(f)
        self.assertEqual(s["stage"], "param")
        p = s["param"]
        self.assertEqual(p["branch_points_on_grid"], [8, 8])
        self.assertEqual(p["flipped_triangles"][2], 0)
        self.assertLess(p["seam_translation_error"], 1e-6)
        self.assertGreater(p["seam_edge_count"], 0)
        self.assertGreaterEqual(len(p["solve_seconds"]), 1)
        area = 4 * math.pi * 0.99  # the icosphere is a little smaller than its sphere
        self.assertAlmostEqual(p["edge_length"], math.sqrt(area / 500), delta=0.01)
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(out)
        reader.Update()
        pd = reader.GetOutput()
        self.assertEqual(pd.GetCellData().GetArray("CornerUV").GetNumberOfComponents(), 6)
        self.assertEqual(pd.GetCellData().GetArray("Seam").GetNumberOfComponents(), 3)
        # --target-edge-length wins over --target-quad-count; --no-pure-quads and
        # --rounding-mode reach the filter
        code, _, err = run(os.path.join(DATA, "sphere.obj"), "-o", out, "--stage", "param",
                           "--target-edge-length=0.25",
                           "--no-pure-quads", "--rounding-mode", "simple", "--split-seams",
                           "--stats", stats)
        self.assertEqual(code, 0, err)
        with open(stats) as f:
            s = json.load(f)
        p = s["param"]
        self.assertEqual(p["edge_length"], 0.25)
        self.assertEqual(s["options"]["rounding_mode"], "simple")
        self.assertIs(s["options"]["pure_quads"], False)
        reader.Modified()
        reader.Update()
        pd = reader.GetOutput()
        self.assertIsNotNone(pd.GetPointData().GetTCoords())
        self.assertGreater(pd.GetNumberOfPoints(), 2562)  # cut open along the seams

    def test_built_in_options_take_their_value_after_an_equals_sign(self):
        # and the figures of one solve are a list all the same (rounding none: one solve)
        stats = os.path.join(self.dir, "e.json")
        code, _, err = run(os.path.join(DATA, "sphere.obj"),
                           "--output=" + os.path.join(self.dir, "e.vtp"), "--stage=param",
                           "--stats=" + stats, "--rounding-mode=none", "--target-quad-count=300")
        self.assertEqual(code, 0, err)
        with open(stats) as f:
            s = json.load(f)
        self.assertEqual(s["stage"], "param")
        self.assertEqual(s["options"]["rounding_mode"], "none")
        self.assertIsInstance(s["param"]["solve_seconds"], list)
        self.assertEqual(len(s["param"]["solve_seconds"]), 1)
        self.assertTrue(os.path.exists(os.path.join(self.dir, "e.vtp")))

    def test_quads_by_default_in_every_output_format(self):
        # The default stage: an all-quad, closed, manifold mesh of the sphere with its 8
        # valence-3 vertices, written as .obj, .ply, .vtk and .vtp.
        stats = os.path.join(self.dir, "q.json")
        for ext in (".vtp", ".obj", ".ply", ".vtk"):
            out = os.path.join(self.dir, "q" + ext)
            code, _, err = run(os.path.join(DATA, "sphere.obj"), "-o", out,
                               "--target-quad-count", "600", "--stats", stats)
            self.assertEqual(code, 0, err)
            with open(stats) as f:
                s = json.load(f)
            self.assertEqual(s["stage"], "quads")
            q = s["quads"]
            self.assertEqual(q["quad_share"], 1)
            self.assertEqual(q["irregular_vertices"], [8, 0])
            self.assertEqual(q["non_manifold_edges"], 0)
            self.assertEqual(q["euler_characteristic"], 2)
            self.assertEqual(q["boundary_loops"], 0)
            self.assertEqual(q["dropped_cells"], [0, 0, 0])
            self.assertLess(q["hausdorff_distance"][0], 2.0)
            reader = {".vtp": vtk.vtkXMLPolyDataReader, ".obj": vtk.vtkOBJReader,
                      ".ply": vtk.vtkPLYReader, ".vtk": vtk.vtkPolyDataReader}[ext]()
            reader.SetFileName(out)
            reader.Update()
            pd = reader.GetOutput()
            self.assertEqual(pd.GetNumberOfCells(), q["faces"], ext)
            sizes = {pd.GetCell(i).GetNumberOfPoints() for i in range(pd.GetNumberOfCells())}
            self.assertEqual(sizes, {4}, ext)

    def test_smoothing_options_reach_the_filter(self):
        # Without features the cube holds nothing; with them its edges are held.
        cube = os.path.join(DATA, "roundedcube.obj")
        held = {}
        for flag in ([], ["--no-align-to-features", "--no-align-to-boundary"]):
            stats = os.path.join(self.dir, "c.json")
            code, _, err = run(cube, "-o", os.path.join(self.dir, "c.vtp"), "--stage", "smooth",
                               "--feature-angle", "10", "--smoothing-weight", "0.8", "--stats", stats,
                               *flag)
            self.assertEqual(code, 0, err)
            with open(stats) as f:
                held[bool(flag)] = json.load(f)["smooth"]["constrained_frame_count"]
        self.assertGreater(held[False], 0)
        self.assertEqual(held[True], 0)

    def test_boundary_options_reach_both_filters(self):
        # --no-align-to-boundary: the smoother holds no frame along the cylinder's circles and
        # the solver puts no boundary edge on a grid line; --boundary-tolerance reaches the
        # matching stage and the solver alike (the option reads null while the two differ, so 5
        # here says both have it).
        cylinder = os.path.join(DATA, "cylinder.obj")
        figures = {}
        for flags in ([], ["--no-align-to-boundary"]):
            stats = os.path.join(self.dir, "b.json")
            code, _, err = run(cylinder, "-o", os.path.join(self.dir, "b.vtp"), "--stage", "param",
                               "--target-quad-count", "500", "--boundary-tolerance", "5",
                               "--stats", stats, *flags)
            self.assertEqual(code, 0, err)
            with open(stats) as f:
                s = json.load(f)
            self.assertEqual(s["options"]["boundary_tolerance"], 5)
            self.assertIs(s["options"]["align_to_boundary"], not flags)
            figures[bool(flags)] = (s["smooth"]["constrained_frame_count"],
                                    s["param"]["aligned_boundary_edges"])
        self.assertGreater(min(figures[False]), 0)
        self.assertEqual(figures[True], (0, 0))

    def test_repair_stage_and_off_input(self):
        # Data/sphere.obj as OFF, with a comment and its points repeated per triangle (as some
        # exporters write them): the repair stage merges them back.
        reader = vtk.vtkOBJReader()
        reader.SetFileName(os.path.join(DATA, "sphere.obj"))
        reader.Update()
        pd = reader.GetOutput()
        lines = ["OFF # a sphere", "%d %d 0" % (3 * pd.GetNumberOfCells(), pd.GetNumberOfCells())]
        for c in range(pd.GetNumberOfCells()):
            cell = pd.GetCell(c)
            for k in range(3):
                lines.append("%.17g %.17g %.17g" % pd.GetPoint(cell.GetPointId(k)))
        lines += ["3 %d %d %d" % (3 * c, 3 * c + 1, 3 * c + 2) for c in range(pd.GetNumberOfCells())]
        path = self.write("sphere.off", "\n".join(lines) + "\n")
        stats = os.path.join(self.dir, "r.json")
        out = os.path.join(self.dir, "r.vtp")
        code, _, err = run(path, "-o", out, "--stage", "repair", "--stats", stats)
        self.assertEqual(code, 0, err)
        with open(stats) as f:
            s = json.load(f)
        self.assertEqual(s["stage"], "repair")
        self.assertEqual(s["input"]["points"], 3 * 5120)
        self.assertEqual(s["repair"]["merged_points"], 3 * 5120 - 2562)
        self.assertEqual(s["surface"], {"points": 2562, "triangles": 5120})
        self.assertNotIn("curvature", s)
        code, _, err = run(path, "-o", os.path.join(self.dir, "q.obj"), "--target-quad-count", "600",
                           "--stats", stats)
        self.assertEqual(code, 0, err)
        with open(stats) as f:
            q = json.load(f)["quads"]
        self.assertEqual((q["euler_characteristic"], q["irregular_vertices"]), (2, [8, 0]))

    def test_obj_statements(self):
        # Data/sphere.obj written with what OBJ files hold besides "v" and "f": texture
        # coordinates and normals in the indices, negative indices (counting back from the
        # points read so far), a face continued on the next line by a backslash, groups,
        # comments, a point and a line statement, CRLF line ends, and a face before the points it
        # uses. The repair stage gives the same surface.
        points, faces = [], []
        with open(os.path.join(DATA, "sphere.obj")) as f:
            for line in f:
                w = line.split()
                if w and w[0] == "v":
                    points.append(line.strip())
                elif w and w[0] == "f":
                    faces.append([int(i) for i in w[1:]])
        n = len(points)
        written = []
        for k, f in enumerate(faces[1:]):
            if k % 4 == 0:
                written.append("f %d/1/1 %d//1 %d/1" % tuple(f))
            elif k % 4 == 1:
                written.append("f %d \\\r\n  %d %d" % tuple(i - n - 1 for i in f))
            elif k % 4 == 2:
                written.append("f %d %d\\\r\n%d" % tuple(f))  # the backslash on the index
            else:
                written.append("f %d %d %d" % tuple(f))
        # a comment that ends in a backslash does not take the next line with it
        text = ["# sphere", "mtllib none.mtl", "o sphere", "f %d %d %d" % tuple(faces[0]), "g all",
                "s 1", "vt 0 0", "vn 0 0 1", "# points \\"] + points + written + ["p 1", "l 1 2 3"]
        path = self.write("sphere_statements.obj", "\r\n".join(text) + "\r\n")
        sizes = []
        for source in (os.path.join(DATA, "sphere.obj"), path):
            stats = os.path.join(self.dir, "s.json")
            code, _, err = run(source, "-o", os.path.join(self.dir, "s.vtp"), "--stage", "repair",
                               "--stats", stats)
            self.assertEqual(code, 0, err)
            with open(stats) as f:
                s = json.load(f)
            sizes.append((s["surface"], s["repair"]["merged_points"]))
        self.assertEqual(sizes[0], sizes[1])
        self.assertEqual(sizes[0], ({"points": 2562, "triangles": 5120}, 0))

    def test_obj_coordinates_in_double_precision(self):
        # A tetrahedron whose coordinates single precision cannot hold: read (and written) as the
        # doubles nearest to what the file says.
        # (1e-400 is below the smallest double: read as 0, not refused)
        values = (0.1, 0.7, 0.3, 1.0000000001)
        text = "v 0.1 0 1e-400\nv 0 0.7 0\nv 0 0 0.3\nv 1.0000000001 1.0000000001 1.0000000001\n" \
            "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n"
        out = os.path.join(self.dir, "d.vtp")
        code, _, err = run(self.write("double.obj", text), "-o", out, "--stage", "repair",
                           "--minimum-component-triangle-count", "0")
        self.assertEqual(code, 0, err)
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(out)
        reader.Update()
        pd = reader.GetOutput()
        found = {x for i in range(pd.GetNumberOfPoints()) for x in pd.GetPoint(i)} - {0.0}
        self.assertEqual(found, set(values))

    def test_bad_off_files(self):
        # A generated corpus of broken OFF files: each gets one line that names what is wrong.
        tri = "0 0 0\n1 0 0\n0 1 0\n"
        cases = {
            "header": ("OFX\n3 1 0\n" + tri + "3 0 1 2\n", r"not an OFF file"),
            "prefix": ("FOOOFF\n3 1 0\n" + tri + "3 0 1 2\n", r"FOOOFF is not OFF"),
            "4d": ("4OFF\n3 1 0\n" + tri + "3 0 1 2\n", r"not three-dimensional"),
            "binary": ("OFF BINARY\n", r"binary OFF"),
            "no-counts": ("OFF\n", r"ends before the vertex and face counts"),
            "bad-counts": ("OFF\nthree 1 0\n", r"counts are missing"),
            "negative": ("OFF\n-3 1 0\n" + tri, r"negative or larger"),
            "huge": ("OFF\n1000000000 1 0\n" + tri, r"negative or larger"),
            "short-vertex": ("OFF\n3 1 0\n0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                             r"line 3: a vertex needs three coordinates"),
            "nan": ("OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", r"line 4: a non-finite"),
            "truncated-vertices": ("OFF\n3 1 0\n0 0 0\n# " + 40 * "x" + "\n",
                                   r"ends after 1 of 3 vertices"),
            "truncated-faces": ("OFF\n3 2 0\n" + tri + "3 0 1 2\n", r"ends after 1 of 2 faces"),
            "index": ("OFF\n3 1 0\n" + tri + "3 0 1 3\n", r"line 6: .*vertex 3, but the file"),
            "short-face": ("OFF\n3 1 0\n" + tri + "3 0 1\n", r"fewer than its 3 points"),
            "zero-face": ("OFF\n3 1 0\n" + tri + "0\n", r"number of points"),
        }
        for name, (text, pattern) in cases.items():
            with self.subTest(name=name):
                self.assert_one_line_error([self.write(name + ".off", text), "-o",
                                            os.path.join(self.dir, "x.vtp")], 1,
                                           r"^quadcover: error: cannot read .*" + pattern)

    def test_every_input_format_and_legacy_output(self):
        # Convert Data/sphere.obj to .ply, .stl (binary and ASCII), .vtp, .vtk with VTK and read
        # each back; an STL repeats each point per facet, and the reader joins them again.
        reader = vtk.vtkOBJReader()
        reader.SetFileName(os.path.join(DATA, "sphere.obj"))
        reader.Update()
        ascii_stl = vtk.vtkSTLWriter()
        ascii_stl.SetFileTypeToASCII()
        writers = {".ply": vtk.vtkPLYWriter(), ".stl": vtk.vtkSTLWriter(),
                   "_ascii.stl": ascii_stl,
                   ".vtp": vtk.vtkXMLPolyDataWriter(), ".vtk": vtk.vtkPolyDataWriter()}
        stats = os.path.join(self.dir, "formats.json")
        for ext, w in writers.items():
            path = os.path.join(self.dir, "sphere" + ext)
            w.SetFileName(path)
            w.SetInputData(reader.GetOutput())
            w.Write()
            code, _, err = run(path, "-o", os.path.join(self.dir, "out.vtk"), "--stage",
                               "curvature", "--stats", stats)
            self.assertEqual(code, 0, ext + ": " + err)
            with open(stats) as f:
                read = json.load(f)["input"]
            self.assertEqual(read["points"], reader.GetOutput().GetNumberOfPoints(), ext)
            legacy = vtk.vtkPolyDataReader()
            legacy.SetFileName(os.path.join(self.dir, "out.vtk"))
            legacy.Update()
            self.assertEqual(legacy.GetOutput().GetNumberOfCells(), 5120, ext)
            self.assertIsNotNone(legacy.GetOutput().GetCellData().GetArray("FrameU"), ext)

    def test_repairs_are_counted(self):
        # Two quads sharing an edge through duplicated points, one triangle facing the other way.
        path = self.write("repair.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                          "v 1 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 0 2 0\n"
                          "f 1 2 3 4\nf 5 6 7 8\nf 3 4 9\n")
        stats = os.path.join(self.dir, "repair.json")
        code, _, err = run(path, "-o", os.path.join(self.dir, "r.vtp"), "--stats", stats)
        self.assertEqual(code, 0, err)
        with open(stats) as f:
            r = json.load(f)["repair"]
        self.assertEqual(r["merged_points"], 2)
        self.assertEqual(r["triangulated_polygons"], 2)
        self.assertEqual(r["reoriented_triangles"], 1)

    def test_fandisk_from_shared_data(self):
        path = os.path.join(SHARED, "fandisk.obj")
        if not SHARED or not os.path.exists(path):
            self.skipTest("shared mesh not found: " + path)
        out = os.path.join(self.dir, "f.vtp")
        code, _, err = run(path, "-o", out, "--stage", "curvature")
        self.assertEqual(code, 0, err)
        self.check_frames(out)

    def test_refined_spot_keeps_its_windings_and_topology(self):
        # spot refined 16 times (94k triangles) at 3,000 quads: each cone's fan is small against a
        # grid cell, and the map's repair once left two -1/4 cones closed up beside points wound
        # twice (the quad mesh then lost cells and its Euler characteristic)
        path = os.path.join(SHARED, "spot.obj")
        if not SHARED or not os.path.exists(path):
            self.skipTest("shared mesh not found: " + path)
        reader = vtk.vtkOBJReader()
        reader.SetFileName(path)
        clean = vtk.vtkCleanPolyData()
        clean.SetInputConnection(reader.GetOutputPort())
        triangles = vtk.vtkTriangleFilter()
        triangles.SetInputConnection(clean.GetOutputPort())
        loop = vtk.vtkLoopSubdivisionFilter()
        loop.SetInputConnection(triangles.GetOutputPort())
        loop.SetNumberOfSubdivisions(2)
        writer = vtk.vtkXMLPolyDataWriter()
        refined = os.path.join(self.dir, "spot16.vtp")
        writer.SetFileName(refined)
        writer.SetInputConnection(loop.GetOutputPort())
        writer.Write()
        stats = os.path.join(self.dir, "s.json")
        code, _, err = run(refined, "-o", os.path.join(self.dir, "q.vtp"), "--target-quad-count",
                           "3000", "--no-compute-hausdorff-distance", "--stats", stats)
        self.assertEqual(code, 0, err)
        with open(stats) as f:
            s = json.load(f)
        self.assertEqual(s["param"]["flipped_triangles"][2], 0)
        self.assertEqual(s["param"]["winding_errors"], 0)
        self.assertEqual(s["quads"]["dropped_cells"], [0, 0, 0])
        self.assertEqual(s["quads"]["euler_characteristic"], 2)
        self.assertEqual(s["quads"]["non_manifold_edges"], 0)

    def test_truck_at_1000_quads_keeps_its_topology_on_a_finer_grid(self):
        # the truck's body at 1,000 quads: 33 boundary loops that the grid's local refinements
        # could not keep apart (its quads came out with χ -19 and 141 loops instead of -29 and
        # 147); mapped again on a grid sqrt(2) times finer, its quads keep them
        path = os.path.join(SHARED, "truck.obj")
        if not SHARED or not os.path.exists(path):
            self.skipTest("shared mesh not found: " + path)
        figures = {}
        for retries in ("0", "2"):
            stats = os.path.join(self.dir, "s%s.json" % retries)
            code, _, err = run(path, "-o", os.path.join(self.dir, "q.vtp"), "--target-quad-count",
                               "1000", "--no-compute-hausdorff-distance", "--stats", stats,
                               "--maximum-finer-grid-retries", retries)
            self.assertEqual(code, 0, err)
            with open(stats) as f:
                s = json.load(f)
            # the user hears why there are more quads than asked
            self.assertEqual("made again on a finer grid" in err, retries != "0", err)
            figures[retries] = (s["param"]["finer_grid_retries"],
                                s["quads"]["euler_characteristic"], s["quads"]["boundary_loops"],
                                s["quads"]["non_manifold_edges"])
        self.assertEqual(figures["0"][0], 0)
        self.assertNotEqual(figures["0"][1:3], (-29, 147), "without a finer grid the body's "
                            "quads lose its topology (else this test tests nothing)")
        self.assertGreater(figures["2"][0], 0)
        self.assertEqual(figures["2"][1:], (-29, 147, 0))

    def test_help(self):
        code, out, _ = run("--help")
        self.assertEqual(code, 0)
        self.assertIn("usage: quadcover", out)
        # Documentation/CommandLine.md keeps a copy of it
        doc = os.path.join(os.path.dirname(__file__), "..", "..", "Documentation",
                           "CommandLine.md")
        with open(doc, encoding="utf-8") as f:
            self.assertIn("```\n" + out + "```", f.read(),
                          "Documentation/CommandLine.md's copy of --help is not the program's")

    def test_readme_states_the_defaults_the_program_has(self):
        _, out, _ = run("--help")
        defaults = dict(re.findall(r"\n  --(?:\[no-\])?([\w-]+).*\n.*\(default ([^)]+)\)", out))
        readme = os.path.join(os.path.dirname(__file__), "..", "..", "README.md")
        with open(readme, encoding="utf-8") as f:
            rows = re.findall(r"^\| `--(?:no-)?([\w-]+)[^|]*\| ([^|]+) \|", f.read(), re.M)
        self.assertGreater(len(rows), 5)
        for flag, stated in rows:
            with self.subTest(flag=flag):
                self.assertIn(flag, defaults, "README names an option the program does not have")
                if stated.strip() not in ("off", "on") or defaults[flag] in ("on", "off"):
                    self.assertEqual(stated.strip(), defaults[flag])

    # ---- refused input: exit 1, one line ----
    def test_missing_file(self):
        self.assert_one_line_error([os.path.join(self.dir, "nope.obj"), "-o", "x.vtp"], 1,
                                   r"^quadcover: error: .*no such file")

    def test_empty_file(self):
        self.assert_one_line_error([self.write("e.obj", ""), "-o", "x.vtp"], 1,
                                   r"^quadcover: error: .*empty")

    def test_nan_and_inf_coordinates(self):
        for value in ("nan", "inf", "-inf", "NaN"):
            p = self.write("n.obj", "v 0 0 0\nv 1 0 0\nv %s 1 0\nf 1 2 3\n" % value)
            self.assert_one_line_error([p, "-o", "x.vtp"], 1,
                                       r"^quadcover: error: .*line 3 .*non-finite")

    def test_no_polygons(self):
        p = self.write("p.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n")
        self.assert_one_line_error([p, "-o", "x.vtp"], 1, r"^quadcover: error: .*no polygons")

    def test_non_manifold_edge_is_cut_apart(self):
        p = self.write("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0 0 -1\n"
                       "f 1 2 3\nf 2 1 4\nf 1 2 5\n")
        stats = os.path.join(self.dir, "m.json")
        code, _, err = run(p, "-o", os.path.join(self.dir, "m.vtp"), "--stage", "repair",
                           "--stats", stats)
        self.assertEqual(code, 0, err)
        with open(stats) as f:
            self.assertEqual(json.load(f)["repair"]["cut_edges"], 1)

    def test_moebius_strip(self):
        n, text = 12, ""
        for i in range(n):
            t = 2 * math.pi * i / n
            for w in (-0.3, 0.3):
                r = 3 + w * math.cos(t / 2)
                text += "v %r %r %r\n" % (r * math.cos(t), r * math.sin(t), w * math.sin(t / 2))
        for i in range(n):
            a, b = 2 * i + 1, 2 * i + 2
            c, d = (a + 2, b + 2) if i + 1 < n else (2, 1)
            text += "f %d %d %d\nf %d %d %d\n" % (a, c, b, b, c, d)
        p = self.write("moebius.obj", text)
        self.assert_one_line_error([p, "-o", os.path.join(self.dir, "x.vtp")], 1,
                                   r"^quadcover: error: .*component 1 of 1 is not orientable")

    def test_corrupt_vtp(self):
        p = self.write("c.vtp", "this is not xml\n")
        self.assert_one_line_error([p, "-o", "x.vtp"], 1, r"^quadcover: error: cannot read")

    def test_point_ids_out_of_range(self):
        vtk_head = "# vtk DataFile Version 3.0\nbad\nASCII\nDATASET POLYDATA\n" \
                   "POINTS 3 float\n0 0 0 1 0 0 0 1 0\n"
        ply_head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n" \
                   "property float y\nproperty float z\nelement face 1\n" \
                   "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n"
        cases = {"huge.vtk": vtk_head + "POLYGONS 1 4\n3 0 1 100000000\n",
                 "negative.vtk": vtk_head + "POLYGONS 1 4\n3 0 1 -5\n",
                 "quad.vtk": vtk_head + "POLYGONS 1 5\n4 0 1 2 70000\n",
                 "huge.ply": ply_head + "3 0 1 70000000\n"}
        for name, text in cases.items():
            with self.subTest(name=name):
                self.assert_one_line_error([self.write(name, text), "-o",
                                            os.path.join(self.dir, "x.vtp")], 1,
                                           r"^quadcover: error: .*refers to point")
        # The same in binary PLY, big- and little-endian.
        import struct
        for fmt, end in (("binary_little_endian", "<"), ("binary_big_endian", ">")):
            head = ("ply\nformat %s 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                    "property float z\nelement face 2\nproperty list uchar int vertex_indices\n"
                    "end_header\n" % fmt).encode()
            body = struct.pack(end + "9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
            body += struct.pack(end + "B3i", 3, 0, 1, 2) + struct.pack(end + "B3i", 3, 0, 2, 5)
            path = os.path.join(self.dir, fmt + ".ply")
            with open(path, "wb") as f:
                f.write(head + body)
            with self.subTest(fmt=fmt):
                self.assert_one_line_error([path, "-o", "x.vtp"], 1, r"face 1 refers to point 5")
        obj = self.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n")
        self.assert_one_line_error([obj, "-o", "x.vtp"], 1,
                                   r"^quadcover: error: .*line 4 refers to vertex 9")
        obj = self.write("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n")
        self.assert_one_line_error([obj, "-o", "x.vtp"], 1, r"refers to vertex 0")

    def test_collinear_points_are_refused(self):
        p = self.write("line.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nf 1 2 3\nf 2 4 3\n")
        self.assert_one_line_error([p, "-o", os.path.join(self.dir, "x.vtp")], 1,
                                   r"^quadcover: error: .*degenerate")

    def test_strip_joins_do_not_become_triangles(self):
        p = self.write("strip.vtk", "# vtk DataFile Version 3.0\nstrip\nASCII\n"
                       "DATASET POLYDATA\nPOINTS 8 float\n"
                       "0 0 0 1 0 0 0 1 0 1 1 0 3 0 0 4 0 0 3 1 0 4 1 0\n"
                       "TRIANGLE_STRIPS 1 11\n10 0 1 2 3 3 4 4 5 6 7\n")
        out = os.path.join(self.dir, "strip.vtp")
        code, _, err = run(p, "-o", out, "--stage", "curvature",
                           "--minimum-component-triangle-count", "0")
        self.assertEqual(code, 0, err)
        self.assertEqual(self.check_frames(out).GetNumberOfCells(), 4)
        # refined by default: each of the two squares' two triangles into 4^4 (512 >= 256)
        code, _, err = run(p, "-o", out, "--stage", "curvature")
        self.assertEqual(code, 0, err)
        self.assertEqual(self.check_frames(out).GetNumberOfCells(), 4 * 256)

    def test_user_frames_reach_the_filter(self):
        # A torus with FrameU = z everywhere: kept (projected) unless --no-use-input-frames.
        reader = vtk.vtkOBJReader()
        reader.SetFileName(os.path.join(DATA, "torus.obj"))
        reader.Update()
        torus = reader.GetOutput()
        frame = vtk.vtkDoubleArray()
        frame.SetName("FrameU")
        frame.SetNumberOfComponents(3)
        for _ in range(torus.GetNumberOfCells()):
            frame.InsertNextTuple3(0.0, 0.0, 1.0)
        torus.GetCellData().AddArray(frame)
        path = os.path.join(self.dir, "user.vtp")
        w = vtk.vtkXMLPolyDataWriter()
        w.SetFileName(path)
        w.SetInputData(torus)
        w.Write()

        def mean_abs_uz(*extra):
            out = os.path.join(self.dir, "u.vtp")
            code, _, err = run(path, "-o", out, "--stage", "curvature", *extra)
            self.assertEqual(code, 0, err)
            u = self.check_frames(out).GetCellData().GetArray("FrameU")
            return sum(abs(u.GetComponent(i, 2)) for i in range(u.GetNumberOfTuples())) \
                / u.GetNumberOfTuples()

        # The projected z axis has a large z part; the curvature frame (along the parallels of
        # the torus) has none.
        self.assertGreater(mean_abs_uz(), 0.5)
        self.assertLess(mean_abs_uz("--no-use-input-frames"), 0.01)

    def test_unknown_input_extension(self):
        self.assert_one_line_error([self.write("a.txt", "x"), "-o", "x.vtp"], 1,
                                   r"unknown extension")

    # ---- bad usage: exit 2, one line ----
    def test_usage_errors(self):
        knot = os.path.join(DATA, "knot.obj")
        cases = [([], r"no input file"),
                 ([knot], r"no output file"),
                 ([knot, "-o", "x.txt"], r"cannot write .*unknown extension"),
                 ([knot, "-o", "x.vtp", "--stage", "bogus"], r"unknown stage 'bogus'"),
                 ([knot, "-o", "x.vtp", "--smoothing-weight", "1.5"], r"invalid value"),
                 ([knot, "-o", "x.vtp", "--maximum-number-of-iterations", "2.5"],
                  r"invalid value"),
                 ([knot, "-o", "x.vtp", "--number-of-threads", "1e10"], r"invalid value"),
                 ([knot, "-o", "x.vtp", "--branch-point-weight"], r"needs a value"),
                 ([knot, "-o", "x.vtp", "--neighborhood-radius", "-1"], r"invalid value"),
                 ([knot, "-o", "x.vtp", "--neighborhood-radius=nan"], r"invalid value"),
                 ([knot, "-o", "x.vtp", "--frobnicate"], r"unknown option --frobnicate"),
                 ([knot, "-o", "x.vtp", "--no-smoothing-weight"], r"unknown option"),
                 ([knot, "-o", "x.vtp", "--pure-quads=1"], r"takes no value"),
                 ([knot, "-o", "x.vtp", "--no-pure-quads=1"], r"--no-pure-quads takes no value"),
                 ([knot, "-o", "x.vtp", "--verbose=yes"], r"--verbose takes no value"),
                 ([knot, "-o", "x.vtp", "--stage"], r"--stage needs a value"),
                 ([knot, "-o", "x.vtp", "--stage=bogus"], r"unknown stage 'bogus'"),
                 ([knot, "-o", "x.vtp", "--rounding-mode", "best"],
                  r"invalid value 'best' for --rounding-mode \(none, simple, greedy\)"),
                 ([knot, "-o", "x.vtp", "--target-quad-count", "0"], r"invalid value"),
                 ([knot, "-o", "x.vtp", "--target-edge-length", "-1"], r"invalid value")]
        for args, pattern in cases:
            with self.subTest(args=args):
                self.assert_one_line_error(args, 2, pattern)


if __name__ == "__main__":
    unittest.main(verbosity=2)
