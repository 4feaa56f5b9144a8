"""Remesh every surface of a folder, the files spread over MPI ranks.

    mpiexec -n N pvbatch --symmetric remesh_many.py IN_DIR OUT_DIR [--quads Q] [--threads T]

Every rank runs this script (--symmetric) and takes every N-th file of IN_DIR in name order
(.obj .off .ply .stl .vtp .vtk), remeshes it with vtkQuadCoverRemesh and writes
OUT_DIR/<name>.vtp (the quad mesh with its arrays). It prints one line a surface,
"rank R: NAME -> OUT (Q quads)" or "rank R: NAME: error", and exits non-zero on a rank where a
surface failed. The quadcover package must be on PYTHONPATH (build/lib/python3.11/site-packages in
a build tree). Also runs without MPI (`pvpython remesh_many.py ...` or Debian's python3): one rank.
"""
import argparse
import os
import sys

from quadcover import (vtkQuadCoverErrorObserver, vtkQuadCoverReader, vtkQuadCoverRemesh,
                       vtkQuadCoverWriter)

SURFACES = (".obj", ".off", ".ply", ".stl", ".vtp", ".vtk")


def rank_and_size():
    """This process's rank and the number of ranks (0 and 1 without MPI)."""
    try:
        from vtkmodules.vtkParallelCore import vtkMultiProcessController
    except ImportError:
        return 0, 1
    controller = vtkMultiProcessController.GetGlobalController()
    if controller is None:
        return 0, 1
    return controller.GetLocalProcessId(), controller.GetNumberOfProcesses()


def remesh(path, out_path, quads, threads):
    """Writes the quad mesh of the surface in `path` to `out_path`: its quad count, or the error."""
    reader = vtkQuadCoverReader()
    reader.SetFileName(path)
    remesher = vtkQuadCoverRemesh()
    remesher.SetInputConnection(reader.GetOutputPort())
    remesher.SetTargetQuadCount(quads)
    remesher.SetNumberOfThreads(threads)
    writer = vtkQuadCoverWriter()
    writer.SetInputConnection(remesher.GetOutputPort())
    writer.SetFileName(out_path)
    errors = vtkQuadCoverErrorObserver()
    for algorithm in (reader, remesher, writer):
        errors.Attach(algorithm)
    writer.Write()
    if errors.GetError():
        raise RuntimeError(errors.GetError())
    return remesher.GetOutput().GetNumberOfCells()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("input_dir")
    parser.add_argument("output_dir")
    parser.add_argument("--quads", type=int, default=3000)
    parser.add_argument("--threads", type=int, default=0,
                        help="threads per rank (default: the cores shared among the ranks)")
    args = parser.parse_args()
    rank, size = rank_and_size()
    threads = args.threads or max(1, (os.cpu_count() or 1) // size)
    names = sorted(n for n in os.listdir(args.input_dir) if n.lower().endswith(SURFACES))
    os.makedirs(args.output_dir, exist_ok=True)
    failed = 0
    for name in names[rank::size]:
        out_path = os.path.join(args.output_dir, os.path.splitext(name)[0] + ".vtp")
        try:
            quads = remesh(os.path.join(args.input_dir, name), out_path, args.quads, threads)
            print("rank %d: %s -> %s (%d quads)" % (rank, name, out_path, quads), flush=True)
        except RuntimeError as error:
            failed += 1
            print("rank %d: %s: %s" % (rank, name, error), flush=True)
    if failed:
        sys.exit(1)


if __name__ == "__main__":
    main()
