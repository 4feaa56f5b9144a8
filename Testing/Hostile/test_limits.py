"""test_limits.py: the command line's limits on hostile arguments: a quad count beside a nonzero
edge length, targets that would need far too much memory, and running out of memory.

    test_limits.py CLI WORK
"""
import os
import re
import resource
import subprocess
import sys
import time
import unittest

import hostile_meshes as m

CLI, WORK = sys.argv[1], sys.argv[2]


def run(args, memory_mb=4096):
    """(exit status, stderr lines, seconds) of quadcover with its address space capped."""
    def cap():
        limit = memory_mb * 2 ** 20
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))

    # one OpenBLAS thread: its worker allocates a 128 MB buffer of its own, and under a cap it
    # retries that for ever instead of failing
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1")
    # QUADCOVER_HOSTILE_MEMORY_GB=0 (sanitizer builds: ASan reserves terabytes) lifts the cap
    capped = os.environ.get("QUADCOVER_HOSTILE_MEMORY_GB") != "0"
    start = time.monotonic()
    p = subprocess.run([CLI, *args], capture_output=True, text=True, timeout=60, env=env,
                       preexec_fn=cap if capped else None)
    return p.returncode, p.stderr.strip().splitlines(), time.monotonic() - start


class Limits(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        os.makedirs(WORK, exist_ok=True)
        cls.sphere = os.path.join(WORK, "sphere.obj")
        m.write_obj(cls.sphere, m.icosphere(3))
        cls.out = os.path.join(WORK, "out.vtp")

    def assert_refused(self, args, status, phrase, seconds=5.0, memory_mb=4096):
        code, lines, took = run([self.sphere, "-o", self.out, *args], memory_mb)
        self.assertEqual(code, status, lines)
        self.assertEqual(len(lines), 1, lines)
        if isinstance(phrase, re.Pattern):
            self.assertRegex(lines[0], phrase)
        else:
            self.assertIn(phrase, lines[0])
        self.assertLess(took, seconds)

    def test_quad_count_and_edge_length_together_are_bad_usage(self):
        for args in (["--target-quad-count", "500", "--target-edge-length", "0.1"],
                     ["--target-edge-length=0.1", "--target-quad-count=500"]):
            self.assert_refused(args, 2, "cannot both be given")
        code, lines, _ = run([self.sphere, "-o", self.out, "--stage", "repair",
                              "--target-edge-length", "0", "--target-quad-count", "500"])
        self.assertEqual(code, 0, lines)

    def test_far_too_many_quads_are_refused_at_once(self):
        # about 60 GB: refused before the curvature stage, not after a minute of allocating
        self.assert_refused(["--target-quad-count", "1e8"], 1,
                            "--target-quad-count 100000000 gives about 1e+08 quads, which is too "
                            "many for this surface")
        self.assert_refused(["--target-edge-length", "1e-5"], 1, "quads, which is too many")
        # each component's minimum counts too: 1,950,000 + 100,000 on the one sphere
        self.assert_refused(["--target-quad-count", "1950000", "--minimum-component-quad-count",
                             "100000"], 1, "gives about 2.05e+06 quads, which is too many")
        # the stages before the solver do not make quads
        code, lines, _ = run([self.sphere, "-o", self.out, "--stage", "smooth",
                              "--target-quad-count", "1e8"])
        self.assertEqual(code, 0, lines)

    @unittest.skipIf(os.environ.get("QUADCOVER_HOSTILE_MEMORY_GB") == "0",
                     "the memory cap is lifted")
    def test_running_out_of_memory_is_one_line(self):
        # 1.9 million quads (allowed) need about 1.2 GB; with 800 MB the map (which first splits
        # the triangles longer than 3 grid edges) or the quads stage runs out
        self.assert_refused(["--target-quad-count", "1.9e6"], 1,
                            re.compile(r": Cannot (parameterize|extract quads): out of memory\.$"),
                            seconds=30.0, memory_mb=800)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
