"""test_hostile.py: runs quadcover on one hostile case and checks the outcome its case owes.

    test_hostile.py CLI WORK NAME      writes case NAME into WORK/NAME, runs
                                       CLI CASE -o OUT.vtp --target-quad-count 500 --stats S.json
    test_hostile.py --registered NAME ...   checks that the names are exactly the cases

A refusal must come within a few seconds as exit 1 (not a signal, not abort's 134) and one line
on stderr, "quadcover: error: ...", that names the problem; a success must write a valid quad
mesh: only quads, no edge of more than two faces, each edge between two faces used once in each
direction, and the components and Euler characteristic the case expects.

quadcover runs with its address space capped at 4 GB, so that a file that makes it allocate
without bound fails here instead of taking the machine; QUADCOVER_HOSTILE_MEMORY_GB=0 lifts the
cap (an AddressSanitizer build reserves more than that up front).
"""
import json
import os
import resource
import shutil
import subprocess
import sys
import time

import hostile_cases

REFUSAL_SECONDS = 5.0
RUN_TIMEOUT = 60.0


def _cap_memory():
    gb = float(os.environ.get("QUADCOVER_HOSTILE_MEMORY_GB", "4"))
    if gb > 0:
        limit = int(gb * 2 ** 30)
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))


def run(cli, case, out, stats):
    command = [cli, case, "-o", out, "--target-quad-count", "500", "--stats", stats]
    print(" ".join(command))
    start = time.monotonic()
    p = subprocess.run(command, capture_output=True, timeout=RUN_TIMEOUT, preexec_fn=_cap_memory)
    return p.returncode, p.stderr.decode("utf-8", "replace"), time.monotonic() - start


def check_refused(expect, code, err, seconds):
    problems = []
    if code != 1:
        problems.append("exit status %d, expected 1%s" % (
            code, " (killed by signal %d)" % -code if code < 0 else ""))
    lines = err.strip("\n").split("\n") if err.strip() else []
    if len(lines) != 1:
        problems.append("expected one line on stderr, got %d" % len(lines))
    elif not lines[0].startswith("quadcover: error: "):
        problems.append("the line does not start with 'quadcover: error: '")
    elif expect.phrase.lower() not in lines[0].lower():
        problems.append("the line does not say '%s'" % expect.phrase)
    if any(not (c.isprintable() or c == "\n") for c in err):
        problems.append("stderr holds unprintable characters")
    if seconds > REFUSAL_SECONDS:
        problems.append("took %.1f s to refuse (at most %.0f)" % (seconds, REFUSAL_SECONDS))
    return problems


def read_quads(path):
    """(faces as tuples of point ids, number of points); faces None when the file is unreadable."""
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    pd = reader.GetOutput()
    if reader.GetErrorCode() or pd is None:
        return None, 0
    other = pd.GetNumberOfVerts() + pd.GetNumberOfLines() + pd.GetNumberOfStrips()
    faces = []
    polys = pd.GetPolys()
    polys.InitTraversal()
    from vtkmodules.vtkCommonCore import vtkIdList

    ids = vtkIdList()
    while polys.GetNextCell(ids):
        faces.append(tuple(ids.GetId(k) for k in range(ids.GetNumberOfIds())))
    return (faces if other == 0 else None), pd.GetNumberOfPoints()


def components(faces):
    """The number of groups of faces joined through their edges."""
    parent = list(range(len(faces)))

    def root(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    first = {}
    for f, face in enumerate(faces):
        for k in range(len(face)):
            e = frozenset((face[k], face[(k + 1) % len(face)]))
            if e in first:
                parent[root(f)] = root(first[e])
            else:
                first[e] = f
    return len({root(f) for f in range(len(faces))})


def check_mesh(faces, expect):
    problems = []
    if not faces:
        return ["the output has no faces, or cells other than polygons"]
    if any(len(f) != 4 or len(set(f)) != 4 for f in faces):
        problems.append("not all faces are quads with four distinct points")
    directed, undirected = {}, {}
    for face in faces:
        for k in range(len(face)):
            a, b = face[k], face[(k + 1) % len(face)]
            directed[(a, b)] = directed.get((a, b), 0) + 1
            e = (min(a, b), max(a, b))
            undirected[e] = undirected.get(e, 0) + 1
    if any(n > 2 for n in undirected.values()):
        problems.append("an edge has more than two faces")
    if any(n == 2 and (directed.get(e, 0), directed.get(e[::-1], 0)) != (1, 1)
           for e, n in undirected.items()):
        problems.append("an edge between two faces is not used once in each direction")
    used = {i for f in faces for i in f}
    euler = len(used) - len(undirected) + len(faces)
    count = components(faces)
    for what, got, want in (("components", count, expect.components),
                            ("Euler characteristic", euler, expect.euler)):
        allowed = want if isinstance(want, tuple) else (want,)
        if got not in allowed:
            problems.append("%s %d, expected %s" % (what, got, " or ".join(map(str, allowed))))
    return problems


def check_case(cli, work, name):
    make, expect = hostile_cases.CASES[name]
    folder = os.path.join(work, name)
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    case = make(folder)
    out, stats = os.path.join(folder, "out.vtp"), os.path.join(folder, "stats.json")
    code, err, seconds = run(cli, case, out, stats)
    print("%s: exit %d in %.2f s\n%s" % (os.path.basename(case), code, seconds, err), end="")
    if isinstance(expect, hostile_cases.Refused):
        return check_refused(expect, code, err, seconds)
    if code != 0:
        return ["exit status %d, expected 0 and a quad mesh" % code]
    faces, _ = read_quads(out)
    problems = check_mesh(faces, expect)
    if not os.path.isfile(stats):
        return problems + ["no --stats file"]
    with open(stats) as f:
        quads = json.load(f)["quads"]
    # in the output (the second figure): nothing facing against the input, nothing inside out
    for key in ("turned_quads", "inverted_quads"):
        if quads[key][1] != 0:
            problems.append("%s %s, expected 0 in the output" % (key, quads[key]))
    # every component of the input has quads on it, by the quad stage's own count too
    if quads.get("empty_components") != 0:
        problems.append("empty_components %s, expected 0" % quads.get("empty_components"))
    if expect.irregular is not None and quads["irregular_vertices"][0] > expect.irregular:
        problems.append("%d inner irregular vertices, expected at most %d" % (
            quads["irregular_vertices"][0], expect.irregular))
    return problems


def main(argv):
    if argv[1] == "--registered":
        missing = sorted(set(hostile_cases.CASES) - set(argv[2:]))
        unknown = sorted(set(argv[2:]) - set(hostile_cases.CASES))
        problems = ["case %s is not registered in CMake" % n for n in missing] + \
            ["CMake registers %s, which is no case" % n for n in unknown]
    else:
        problems = check_case(*argv[1:4])
    for p in problems:
        print("FAIL: " + p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
