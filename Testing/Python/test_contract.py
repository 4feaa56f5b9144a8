"""The contract between the code and its documentation, checked from Debian's Python:

- every filter property's doc comment states its default, and the fresh filter, its PrintSelf
  and that statement agree (the defaults themselves are defined once, in the Core option
  structs); options two filters share start alike;
- Documentation/Arrays.md lists exactly the names of Filters/vtkQuadCoverArrayNames.h;
- the README's Python example runs as it stands, and on shared OBJ files straight from disk.

Run by CTest with PYTHONPATH at the build's quadcover package and QUADCOVER_SOURCE at the
repository (QUADCOVER_SHARED_DATA optional).
"""
import glob
import os
import re
import unittest

import quadcover

SOURCE = os.environ.get("QUADCOVER_SOURCE", os.path.join(os.path.dirname(__file__), "..", ".."))
SHARED = os.environ.get("QUADCOVER_SHARED_DATA", "")

SETTER = re.compile(r"vtkSet(?:Clamp)?Macro\((\w+),")
DEFAULT = re.compile(r"\(default ([^);:,\s]+)")


def documented_defaults(header):
    """{property: the default its doc comment states (None when it states none)}."""
    with open(header, encoding="utf-8") as f:
        text = f.read()
    found = {}
    for m in SETTER.finditer(text):
        end = text.rfind("*/", 0, m.start())
        start = text.rfind("/**", 0, end)
        comment = text[start:end] if start >= 0 and end >= 0 else ""
        lines = [line.strip().lstrip("*/").strip() for line in comment.splitlines()]
        d = DEFAULT.search(" ".join(" ".join(lines).split()))
        found[m.group(1)] = d.group(1) if d else None
    return found


def expected(cls, text):
    if text in ("on", "off"):
        return text == "on"
    if hasattr(cls, text):
        return getattr(cls, text)
    return float(text)


class Contract(unittest.TestCase):
    def test_every_default_is_stated_and_kept(self):
        headers = glob.glob(os.path.join(SOURCE, "Filters", "vtk*.h")) + \
            glob.glob(os.path.join(SOURCE, "IO", "vtk*.h"))
        checked = 0
        for header in headers:
            name = os.path.basename(header)[:-2]
            cls = getattr(quadcover, name, None)
            defaults = documented_defaults(header)
            if not defaults:
                continue
            self.assertIsNotNone(cls, name + " is not wrapped")
            filter = cls()
            printed = str(filter)
            for prop, text in defaults.items():
                with self.subTest(filter=name, property=prop):
                    self.assertIsNotNone(text, "the doc comment states no default")
                    self.assertIn("\n  %s: " % prop, "\n" + printed.replace("\n", "\n"),
                                  "PrintSelf does not print it")
                    value = getattr(filter, "Get" + prop)()
                    if text == "none":
                        self.assertIn(value, (None, ""))
                        continue
                    want = expected(cls, text)
                    if isinstance(want, bool):
                        self.assertEqual(bool(value), want)
                    else:
                        self.assertAlmostEqual(value, want, delta=1e-12 * max(1, abs(want)))
                    shown = re.search(r"\n\s*%s: (\S+)" % prop, "\n" + printed).group(1)
                    if isinstance(want, bool):
                        self.assertEqual(shown, "On" if want else "Off")
                    elif re.match(r"^-?[\d.e+-]+$", shown):
                        self.assertAlmostEqual(float(shown), value, delta=1e-5 * max(1, abs(value)))
                    checked += 1
        self.assertGreater(checked, 20)

    def test_options_of_two_filters_start_alike(self):
        for prop, classes in {"AlignToBoundary": ("vtkFrameSmoother", "vtkQuadCoverSolver"),
                              "BoundaryTolerance": ("vtkMatchingBuilder", "vtkQuadCoverSolver"),
                              "FeatureAngle": ("vtkFrameSmoother", "vtkQuadCoverSolver",
                                               "vtkQuadExtractor"),
                              "MinimumFeatureLength": ("vtkFrameSmoother", "vtkQuadCoverSolver",
                                                       "vtkQuadExtractor")
                              }.items():
            values = {getattr(getattr(quadcover, c)(), "Get" + prop)() for c in classes}
            self.assertEqual(len(values), 1, prop)

    def test_the_array_table_lists_every_name(self):
        with open(os.path.join(SOURCE, "Filters", "vtkQuadCoverArrayNames.h"), encoding="utf-8") as f:
            header = f.read()
        names = set(re.findall(r'constexpr const char\* \w+ = "(\w+)"', header))
        with open(os.path.join(SOURCE, "Documentation", "Arrays.md"), encoding="utf-8") as f:
            table = f.read()
        rows = [line.split("|")[1] for line in table.splitlines() if line.startswith("| `")]
        listed = set(n for row in rows for n in re.findall(r"`(\w+)`", row))
        self.assertEqual(names - listed, set(), "in the header, not in Documentation/Arrays.md")
        self.assertEqual(listed - names, set(), "in Documentation/Arrays.md, not in the header")

    def readme_example(self):
        with open(os.path.join(SOURCE, "README.md"), encoding="utf-8") as f:
            readme = f.read()
        return re.search(r"```python\n(.*?)```", readme, re.S).group(1)

    def run_example(self, path):
        code = self.readme_example().replace('"Data/knot.obj"', repr(path))
        scope = {}
        exec(compile(code, "README.md", "exec"), scope)
        return scope["quads"].GetOutput(), scope["frames"]

    def test_the_readme_example_runs(self):
        cwd = os.getcwd()
        os.chdir(SOURCE)
        try:
            scope = {}
            exec(compile(self.readme_example(), "README.md", "exec"), scope)
        finally:
            os.chdir(cwd)
        out = scope["quads"].GetOutput()
        self.assertGreater(out.GetNumberOfCells(), 1500)
        self.assertEqual(out.GetFieldData().GetArray("EulerCharacteristic").GetValue(0), 0)
        # the knot's field has no singularity left, and output 1 lists none
        after = scope["matching"].GetOutput().GetFieldData().GetArray("BranchPointCount")
        self.assertEqual(scope["branch_points"].GetNumberOfPoints(), after.GetValue(1))

    def test_the_readme_example_takes_shared_obj_files(self):
        # spot's OBJ repeats every point per texture coordinate; fandisk's has none to repeat
        for name in ("spot", "fandisk"):
            path = os.path.join(SHARED, name + ".obj")
            if not SHARED or not os.path.exists(path):
                self.skipTest("shared mesh not found: " + path)
            with self.subTest(mesh=name):
                out, _ = self.run_example(path)
                fd = out.GetFieldData()
                self.assertEqual(fd.GetArray("EulerCharacteristic").GetValue(0), 2)
                self.assertEqual(fd.GetArray("QuadShare").GetValue(0), 1.0)
                self.assertEqual(fd.GetArray("NonManifoldEdges").GetValue(0), 0)


if __name__ == "__main__":
    unittest.main(verbosity=2)
