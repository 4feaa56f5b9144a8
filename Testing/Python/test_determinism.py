"""The same input gives the same output whatever the thread counts, and from run to run.

Runs the command line on a few surfaces with OPENBLAS_NUM_THREADS and OMP_NUM_THREADS 1 and 2
(the BLAS under CHOLMOD, CHOLMOD's own OpenMP) and --number-of-threads 1, 2 and 0 (the curvature
stage's workers, the untangling's, the components' maps), and the first settings once more,
writes .vtp, and requires every output file to be byte-identical to the first run's, with no
exception (no output holds a time: the solver's seconds go to --stats only). Where two files differ, the message names the arrays that differ
(the XML's attributes but the byte offsets into the appended data, and each array's bytes).

Needs QUADCOVER_CLI (the binary) and QUADCOVER_DATA (Data/); QUADCOVER_SHARED_DATA is optional
(spot.obj is skipped with a message when absent).
"""
import os
import struct
import subprocess
import tempfile
import unittest
import xml.etree.ElementTree as ET
import zlib

import vtk
from vtk.util.numpy_support import vtk_to_numpy

CLI = os.environ["QUADCOVER_CLI"]
DATA = os.environ["QUADCOVER_DATA"]
SHARED = os.environ.get("QUADCOVER_SHARED_DATA", "")

# (OPENBLAS_NUM_THREADS and OMP_NUM_THREADS, --number-of-threads); the first is the reference,
# and the last repeats it.
RUNS = [(1, 1), (1, 2), (1, 0), (2, 1), (2, 2), (2, 0), (1, 1)]


def read_vtp(path):
    """{element path: (attributes without the offset, bytes)} of a VTK XML file in appended
    raw mode, zlib-compressed, as vtkQuadCoverWriter writes .vtp."""
    with open(path, "rb") as f:
        text = f.read()
    start = text.index(b"<AppendedData")
    blob_start = text.index(b"_", start) + 1
    # raw bytes, read by the offsets and sizes: the closing tag is the file's last
    blob = text[blob_start:text.rindex(b"</AppendedData>")]
    root = ET.fromstring(text[:start] + b"</VTKFile>")
    uint = {"UInt32": ("I", 4), "UInt64": ("Q", 8)}[root.get("header_type", "UInt32")]
    if root.get("compressor") != "vtkZLibDataCompressor":  # what vtkQuadCoverWriter writes
        raise ValueError("%s: compressor %s" % (path, root.get("compressor")))

    def decode(offset):
        # The header (block count, block size, last block size, compressed sizes), then the
        # compressed blocks.
        width = uint[1]
        blocks = struct.unpack("<" + uint[0], blob[offset:offset + width])[0]
        header_bytes = (3 + blocks) * width
        sizes = struct.unpack("<%d%s" % (blocks, uint[0]),
                              blob[offset + 3 * width:offset + header_bytes])
        out, at = [], offset + header_bytes
        for size in sizes:
            out.append(zlib.decompress(blob[at:at + size]))
            at += size
        return b"".join(out)

    arrays = {}

    def walk(element, where):
        for index, child in enumerate(element):
            name = child.get("Name")
            key = "%s/%s[%d]%s" % (where, child.tag, index, ":" + name if name else "")
            attributes = {k: v for k, v in child.attrib.items() if k != "offset"}
            if child.tag == "DataArray":
                appended = child.get("format") == "appended"
                raw = decode(int(child.get("offset"))) if appended else (child.text or "").encode()
                arrays[key] = (attributes, raw)
            else:
                arrays[key] = (attributes, b"")
                walk(child, key)

    arrays["VTKFile"] = ({k: v for k, v in root.attrib.items()}, b"")
    walk(root, "")
    return arrays


def differences(reference, other):
    """The array paths whose attributes or bytes differ."""
    out = []
    for key in sorted(set(reference) | set(other)):
        if key not in reference or key not in other:
            out.append(key + " (missing in one)")
        elif reference[key] != other[key]:
            out.append(key)
    return out


def file_bytes(path):
    with open(path, "rb") as f:
        return f.read()


class Determinism(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def run_cli(self, surface, blas, threads, run=0):
        out = os.path.join(self.tmp.name, "%s-blas%d-threads%d-%d.vtp" % (
            os.path.splitext(os.path.basename(surface))[0], blas, threads, run))
        env = dict(os.environ, OPENBLAS_NUM_THREADS=str(blas), OMP_NUM_THREADS=str(blas))
        # --number-of-threads 0 means all cores unless this says otherwise.
        env.pop("QUADCOVER_NUM_THREADS", None)
        env.pop("GOTO_NUM_THREADS", None)
        p = subprocess.run([CLI, surface, "-o", out, "--number-of-threads", str(threads)],
                           capture_output=True, text=True, env=env, timeout=600)
        self.assertEqual(p.returncode, 0, p.stderr)
        return out

    def check_surface(self, surface):
        reference = None
        for run, (blas, threads) in enumerate(RUNS):
            out = self.run_cli(surface, blas, threads, run)
            if reference is None:
                reference = out
                self.assertTrue(any(k.endswith(":Points") for k in read_vtp(out)), "no points")
                continue
            with self.subTest(run=run, blas=blas, threads=threads):
                if file_bytes(out) != file_bytes(reference):
                    self.fail("%s: run %d, OPENBLAS/OMP_NUM_THREADS=%d --number-of-threads %d, "
                              "wrote other bytes than OPENBLAS/OMP_NUM_THREADS=1 "
                              "--number-of-threads 1; arrays that differ: %s"
                              % (os.path.basename(surface), run, blas, threads,
                                 differences(read_vtp(reference), read_vtp(out)) or "none"))

    def test_knot(self):
        self.check_surface(os.path.join(DATA, "knot.obj"))

    def test_torus(self):
        self.check_surface(os.path.join(DATA, "torus.obj"))

    def test_components(self):
        # components of very different sizes, mapped on several threads at once
        self.check_surface(os.path.join(DATA, "components.obj"))

    def test_spot(self):
        spot = os.path.join(SHARED, "spot.obj") if SHARED else ""
        if not spot or not os.path.exists(spot):
            self.skipTest("no shared spot.obj (QUADCOVER_SHARED_DATA=%s)" % SHARED)
        self.check_surface(spot)

    def test_reader_sees_differences(self):
        """The report of what differs: a changed coordinate is named, a changed attribute too."""
        out = self.run_cli(os.path.join(DATA, "torus.obj"), 1, 1)
        reference = read_vtp(out)
        points = next(k for k in reference if k.endswith(":Points"))
        changed = dict(reference)
        attributes, raw_points = reference[points]
        changed[points] = (attributes, bytes([raw_points[0] ^ 1]) + raw_points[1:])
        self.assertEqual(differences(reference, changed), [points])
        field = next(k for k in reference if k.endswith(":EdgeLength"))
        attributes, raw = reference[field]
        changed = dict(reference)
        changed[field] = (dict(attributes, RangeMin="12345"), raw)
        self.assertEqual(differences(reference, changed), [field])
        # The decoded points are what VTK's own reader reads.
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(out)
        reader.Update()
        read = vtk_to_numpy(reader.GetOutput().GetPoints().GetData())
        self.assertEqual(read.tobytes(), raw_points)


if __name__ == "__main__":
    unittest.main(verbosity=2)
