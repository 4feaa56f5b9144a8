"""The curvature stage from Debian's Python: import, run on Data/torus.obj, check the mathematics.

Run by CTest with PYTHONPATH pointing at the build's quadcover package.
"""
import math
import os
import sys
import unittest

import vtk
from vtk.util import numpy_support
import numpy as np

from quadcover import vtkCurvatureFrames

DATA = os.environ.get("QUADCOVER_DATA", os.path.join(os.path.dirname(__file__), "..", "..", "Data"))


class CurvaturePipeline(unittest.TestCase):
    def run_filter(self, **props):
        reader = vtk.vtkOBJReader()
        reader.SetFileName(os.path.join(DATA, "torus.obj"))
        frames = vtkCurvatureFrames()
        for key, value in props.items():
            getattr(frames, "Set" + key)(value)
        frames.SetInputConnection(reader.GetOutputPort())
        frames.Update()
        return frames.GetOutput()

    def test_torus_principal_curvatures_and_directions(self):
        out = self.run_filter(NeighborhoodRadius=2.0)
        cd = out.GetCellData()
        k = numpy_support.vtk_to_numpy(cd.GetArray("PrincipalCurvatures"))
        d1 = numpy_support.vtk_to_numpy(cd.GetArray("PrincipalDirection1"))
        u = numpy_support.vtk_to_numpy(cd.GetArray("FrameU"))
        v = numpy_support.vtk_to_numpy(cd.GetArray("FrameV"))
        w = numpy_support.vtk_to_numpy(cd.GetArray("FrameWeight"))
        self.assertEqual(k.shape, (out.GetNumberOfCells(), 2))
        # Data/torus.obj: R = 1, r = 0.4, so kappa1 = 1/r = 2.5 along the tube circle.
        self.assertLess(np.abs(k[:, 0] - 2.5).mean(), 0.05)
        pts = numpy_support.vtk_to_numpy(out.GetPoints().GetData())
        tri = numpy_support.vtk_to_numpy(out.GetPolys().GetData()).reshape(-1, 4)[:, 1:]
        c = pts[tri].mean(axis=1)
        # Tube circle direction at the centroid: perpendicular to the radial (x, y) direction.
        radial = c[:, :2] / np.linalg.norm(c[:, :2], axis=1)[:, None]
        ring = np.column_stack([radial * 1.0, np.zeros(len(c))])  # the point on the core circle
        to_centre = c - ring
        circle = np.cross(to_centre, np.column_stack([-radial[:, 1], radial[:, 0], np.zeros(len(c))]))
        circle /= np.linalg.norm(circle, axis=1)[:, None]
        angle = np.degrees(np.arccos(np.clip(np.abs((d1 * circle).sum(axis=1)), 0, 1)))
        self.assertLess(np.median(angle), 2.0)
        # FrameU is a unit vector perpendicular to FrameV, and it is the kappa2 direction.
        self.assertLess(np.abs(np.linalg.norm(u, axis=1) - 1).max(), 1e-9)
        self.assertLess(np.abs((u * v).sum(axis=1)).max(), 1e-9)
        self.assertLess(np.abs((u * d1).sum(axis=1)).max(), 1e-9)
        self.assertTrue(np.all((w >= 0) & (w <= math.sqrt(2) + 1e-12)))
        self.assertGreater(out.GetFieldData().GetArray("CurvatureRadius").GetValue(0), 0.0)

    def test_properties_follow_vtk_conventions(self):
        f = vtkCurvatureFrames()
        self.assertEqual(f.GetNeighborhoodRadius(), 2.0)
        f.SetNeighborhoodRadius(1000)
        self.assertEqual(f.GetNeighborhoodRadius(), 20.0)
        f.UseInputFramesOff()
        self.assertFalse(f.GetUseInputFrames())
        self.assertIn("NeighborhoodRadius", str(f))

    def matchings_of(self, name):
        # Data/NAME.obj through curvature, smoothing and matchings, no array selection. The
        # filters are kept on the test: the pipeline does not keep its upstream alive.
        from quadcover import vtkFrameSmoother, vtkMatchingBuilder
        reader = vtk.vtkOBJReader()
        reader.SetFileName(os.path.join(DATA, name + ".obj"))
        frames = vtkCurvatureFrames()
        frames.SetInputConnection(reader.GetOutputPort())
        smoother = vtkFrameSmoother()
        smoother.SetInputConnection(frames.GetOutputPort())
        matching = vtkMatchingBuilder()
        matching.SetInputConnection(smoother.GetOutputPort())
        self.chain = (reader, frames, smoother, matching)
        return matching

    def test_whole_chain_on_the_sphere(self):
        # 8 branch points of layer shift 1 (index +1/4), and Poincare-Hopf.
        matching = self.matchings_of("sphere")
        matching.Update()
        out = matching.GetOutput()
        index = numpy_support.vtk_to_numpy(out.GetPointData().GetArray("SingularityIndex"))
        shift = numpy_support.vtk_to_numpy(out.GetPointData().GetArray("LayerShift"))
        self.assertAlmostEqual(index.sum(), 2.0, places=9)
        self.assertEqual(int((index == 0.25).sum()), 8)
        self.assertEqual(int((shift == 1).sum()), 8)
        branches = matching.GetOutput(1)
        self.assertEqual(branches.GetNumberOfPoints(), 8)

    def test_solver_after_the_chain(self):
        # The fourth stage from Python: integer seam translations, branch points on the grid.
        from quadcover import vtkQuadCoverSolver
        solver = vtkQuadCoverSolver()
        solver.SetInputConnection(self.matchings_of("roundedcube").GetOutputPort())
        solver.SetTargetQuadCount(600)
        solver.SetRoundingModeToGreedy()
        solver.Update()
        out = solver.GetOutput()
        uv = numpy_support.vtk_to_numpy(out.GetCellData().GetArray("CornerUV"))
        shift = numpy_support.vtk_to_numpy(out.GetPointData().GetArray("LayerShift"))
        tri = numpy_support.vtk_to_numpy(out.GetPolys().GetConnectivityArray()).reshape(-1, 3)
        corners = uv.reshape(-1, 3, 2)
        at_branch = corners[shift[tri] != 0]
        self.assertEqual(len(set(tri[shift[tri] != 0])), 8)
        self.assertTrue(np.allclose(at_branch, np.round(at_branch), atol=1e-6))
        e1 = corners[:, 1] - corners[:, 0]
        e2 = corners[:, 2] - corners[:, 0]
        self.assertTrue(((e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0]) > 0).all())
        flipped = out.GetFieldData().GetArray("FlippedTriangles")
        self.assertEqual(flipped.GetValue(2), 0)

    def test_quads_after_the_chain(self):
        # The fifth stage from Python: an all-quad mesh with the sphere's Euler characteristic,
        # eight valence-3 vertices, and the properties added for the quads' quality.
        from quadcover import vtkQuadCoverSolver, vtkQuadExtractor
        matching = self.matchings_of("sphere")
        self.assertTrue(matching.GetLengthScaledCost())
        solver = vtkQuadCoverSolver()
        solver.SetInputConnection(matching.GetOutputPort())
        solver.SetTargetQuadCount(800)
        extractor = vtkQuadExtractor()
        extractor.SetInputConnection(solver.GetOutputPort())
        self.assertTrue(extractor.GetRepairInvertedQuads())
        self.assertEqual(extractor.GetRelaxationIterations(), 3)
        extractor.SetRelaxationIterations(5)
        extractor.Update()
        out = extractor.GetOutput()
        self.assertGreater(out.GetNumberOfCells(), 600)
        for c in range(out.GetNumberOfCells()):
            self.assertEqual(out.GetCell(c).GetNumberOfPoints(), 4)
        fd = out.GetFieldData()
        self.assertEqual(fd.GetArray("EulerCharacteristic").GetValue(0), 2)
        self.assertEqual(fd.GetArray("InvertedQuads").GetValue(1), 0)
        valence = numpy_support.vtk_to_numpy(out.GetPointData().GetArray("Valence"))
        self.assertEqual(int((valence == 3).sum()), 8)
        self.assertEqual(int((valence != 3).sum()), int((valence == 4).sum()))

    def test_empty_input_is_an_error_not_a_crash(self):
        f = vtkCurvatureFrames()
        f.SetInputData(vtk.vtkPolyData())
        errors = []
        f.AddObserver("ErrorEvent", lambda obj, ev: errors.append(ev))
        f.Update()
        self.assertEqual(errors, ["ErrorEvent"])
        self.assertEqual(f.GetOutput().GetNumberOfCells(), 0)


if __name__ == "__main__":
    unittest.main(verbosity=2)
