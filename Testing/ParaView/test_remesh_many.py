"""Examples/Python/remesh_many.py on two MPI ranks: each rank remeshes its share of a folder, every
output is an all-quad mesh with its input's chi, and the same bytes as one process writes.

    test_remesh_many.py MPIEXEC PVBATCH SCRIPT DATA_DIR SCRATCH_DIR
"""
import filecmp
import os
import re
import shutil
import subprocess
import sys

from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

from meshchecks import check, check_quads, finish

mpiexec, pvbatch, script, data, scratch = sys.argv[1:6]
SURFACES = {"sphere.obj": 2, "torus.obj": 0, "dumbbell.obj": 2, "bracket.obj": 0}  # name: chi
inputs = os.path.join(scratch, "in")
shutil.rmtree(scratch, ignore_errors=True)
os.makedirs(inputs)
for name in SURFACES:
    shutil.copy(os.path.join(data, name), inputs)


env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
run = subprocess.run([mpiexec, "--oversubscribe", "-n", "2", pvbatch, "--symmetric", script,
                      inputs, os.path.join(scratch, "mpi"), "--quads", "400"],
                     env=env, capture_output=True, text=True, timeout=600)
print(run.stdout)
check(run.returncode == 0, "mpiexec exited with %d: %s" % (run.returncode, run.stderr[-2000:]))
done = re.findall(r"^rank (\d): (\S+) -> ", run.stdout, re.MULTILINE)
by_rank = {r: sorted(n for q, n in done if q == r) for r in ("0", "1")}
check(sorted(n for _, n in done) == sorted(SURFACES), "remeshed %s" % sorted(done))
check(len(by_rank["0"]) == 2 and len(by_rank["1"]) == 2,
      "each rank its share (2 of 4): %s" % by_rank)

for name, chi in SURFACES.items():
    path = os.path.join(scratch, "mpi", name.replace(".obj", ".vtp"))
    if not os.path.exists(path):
        check(False, "no %s" % path)
        continue
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    check_quads(reader.GetOutput(), name, chi=chi, at_least=200)

# one process, the same files
serial = subprocess.run([sys.executable, script, inputs, os.path.join(scratch, "one"), "--quads",
                         "400"], capture_output=True, text=True, timeout=600)
check(serial.returncode == 0, "one process: %s" % serial.stderr[-2000:])
for name in SURFACES:
    vtp = name.replace(".obj", ".vtp")
    a, b = os.path.join(scratch, "mpi", vtp), os.path.join(scratch, "one", vtp)
    check(os.path.exists(a) and os.path.exists(b) and filecmp.cmp(a, b, shallow=False),
          "%s differs between two ranks and one process" % vtp)

finish("remesh_many")
