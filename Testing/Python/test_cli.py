"""The quadcover command line: exit status, one-line errors, arrays and --stats on success.

Needs QUADCOVER_CLI (the binary) and QUADCOVER_DATA (Data/); QUADCOVER_SHARED_DATA is optional.
"""
import json
import os
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
        self.assertEqual(s["repairs"]["merged_points"], 0)

    def test_every_input_format_and_legacy_output(self):
        # Convert Data/sphere.obj to .ply, .stl, .vtp, .vtk with VTK and read each back.
        reader = vtk.vtkOBJReader()
        reader.SetFileName(os.path.join(DATA, "sphere.obj"))
        reader.Update()
        writers = {".ply": vtk.vtkPLYWriter(), ".stl": vtk.vtkSTLWriter(),
                   ".vtp": vtk.vtkXMLPolyDataWriter(), ".vtk": vtk.vtkPolyDataWriter()}
        for ext, w in writers.items():
            path = os.path.join(self.dir, "sphere" + ext)
            w.SetFileName(path)
            w.SetInputData(reader.GetOutput())
            w.Write()
            code, _, err = run(path, "-o", os.path.join(self.dir, "out.vtk"))
            self.assertEqual(code, 0, ext + ": " + err)
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
            r = json.load(f)["repairs"]
        self.assertEqual(r["merged_points"], 2)
        self.assertEqual(r["triangulated_polygons"], 2)
        self.assertEqual(r["flipped_triangles"], 1)

    def test_fandisk_from_shared_data(self):
        path = os.path.join(SHARED, "fandisk.obj")
        if not SHARED or not os.path.exists(path):
            self.skipTest("shared mesh not found: " + path)
        out = os.path.join(self.dir, "f.vtp")
        code, _, err = run(path, "-o", out, "--stage", "curvature")
        self.assertEqual(code, 0, err)
        self.check_frames(out)

    def test_help(self):
        code, out, _ = run("--help")
        self.assertEqual(code, 0)
        self.assertIn("usage: quadcover", out)

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

    def test_non_manifold_edge(self):
        p = self.write("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0 0 -1\n"
                       "f 1 2 3\nf 2 1 4\nf 1 2 5\n")
        self.assert_one_line_error([p, "-o", os.path.join(self.dir, "x.vtp")], 1,
                                   r"^quadcover: error: .*non-manifold edges")

    def test_corrupt_vtp(self):
        p = self.write("c.vtp", "this is not xml\n")
        self.assert_one_line_error([p, "-o", "x.vtp"], 1, r"^quadcover: error: cannot read")

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
                 ([knot, "-o", "x.vtp", "--stage", "quads"], r"stage 'quads' .*not built yet"),
                 ([knot, "-o", "x.vtp", "--radius", "-1"], r"invalid value"),
                 ([knot, "-o", "x.vtp", "--frobnicate"], r"unknown option")]
        for args, pattern in cases:
            with self.subTest(args=args):
                self.assert_one_line_error(args, 2, pattern)


if __name__ == "__main__":
    unittest.main(verbosity=2)
