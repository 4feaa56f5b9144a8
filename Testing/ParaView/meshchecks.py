"""What the ParaView tests check of a quad mesh, and how they report: imported by the test
scripts beside it (their own folder is on sys.path under python3, pvpython and pvbatch)."""

failures = []


def check(condition, text):
    """Records and prints a failure when `condition` is false."""
    if not condition:
        failures.append(text)
        print("FAIL:", text)


def euler_characteristic(mesh):
    """V - E + F of a polygon mesh."""
    edges = set()
    for c in range(mesh.GetNumberOfCells()):
        ids = mesh.GetCell(c).GetPointIds()
        n = ids.GetNumberOfIds()
        for k in range(n):
            a, b = ids.GetId(k), ids.GetId((k + 1) % n)
            edges.add((min(a, b), max(a, b)))
    return mesh.GetNumberOfPoints() - len(edges) + mesh.GetNumberOfCells()


def check_quads(mesh, what, chi=2, at_least=100):
    """More than `at_least` cells, all quads, Euler characteristic `chi`."""
    cells = mesh.GetNumberOfCells()
    sizes = {mesh.GetCell(c).GetNumberOfPoints() for c in range(cells)}
    check(cells > at_least and sizes == {4},
          "%s: %d cells of %s points, not only quads" % (what, cells, sorted(sizes)))
    if cells:
        check(euler_characteristic(mesh) == chi,
              "%s: chi %d, not %d" % (what, euler_characteristic(mesh), chi))


def finish(name):
    """Exits non-zero when a check failed."""
    import sys
    if failures:
        sys.exit("%d failures" % len(failures))
    print("%s: all checks passed" % name)
