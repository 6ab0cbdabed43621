#!/usr/bin/python3
"""Tests of dgwarp's OpenFOAM motion solver, libdgwarpFoam.so (openfoam/), on
the pitching and plunging body (openfoam/cases/pitching_body.py, 6,300
hexahedra): ctest runs them when the plugin is built (label openfoam).

    motion_solver_test.py TEST --dgwarp BUILD/dgwarp --plugin-dir BUILD/openfoam --work DIR

TEST:
  serial       moveDynamicMesh, 3 steps: every time's points are `dgwarp deform`'s with the
               same motion (the plate's pitch and plunge as a rigid motion, which the
               solidBodyMotionDisplacement condition gives dgwarp), within 1e-12 of the mesh's
               size; checkMesh says Mesh OK at the last time
  options      the same with method dg-idw, two of its options, and rotations false: against
               `dgwarp deform` with the displacement read from the written pointDisplacement
  trapping     OpenFOAM's floating-point traps on, a set-up whose prepare divides by zero
  parallel     decomposePar (2 processors), mpirun -np 2 moveDynamicMesh -parallel: every
               point as in the serial run (within 1e-12 of the mesh's size)
  inverting    a plunge into the channel's wall (dg-idw): a FatalError naming the inverted cells, exit != 0
  folded-corners  cells with a folded corner but positive face pyramids: a warning (checkMesh
               accepts them), a FatalError with invertedCells corners
  bad-options  an option of another method, an unknown option, an unknown patch: FatalErrors
               saying so, before any step
"""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
CASE_SCRIPT = os.path.join(ROOT, "openfoam", "cases", "pitching_body.py")
BASHRC = "/usr/share/openfoam/etc/bashrc"
MPI_ENV = {"OMPI_ALLOW_RUN_AS_ROOT": "1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM": "1", "OMP_NUM_THREADS": "1",
           "OMPI_MCA_rmaps_base_oversubscribe": "1"}


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def foam(case, command, plugin_dir, expect_ok=True, timeout=300):
    """Runs an OpenFOAM command in CASE with Debian's environment; returns (exit code, log)."""
    env = dict(os.environ, LD_LIBRARY_PATH=plugin_dir + ":" + os.environ.get("LD_LIBRARY_PATH", ""), **MPI_ENV)
    script = f"source {BASHRC} >/dev/null 2>&1; cd '{case}' && {command}"
    p = subprocess.run(["bash", "-c", script], env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                       text=True, timeout=timeout)
    if expect_ok and p.returncode != 0:
        fail(f"{command} in {case} exited {p.returncode}:\n" + p.stdout[-4000:])
    return p.returncode, p.stdout


def make_case(work, name, plugin_dir, *args):
    case = os.path.join(work, name)
    shutil.rmtree(case, ignore_errors=True)
    subprocess.run([sys.executable, CASE_SCRIPT, case, "--resolution", "0.5", *args], check=True)
    foam(case, "blockMesh", plugin_dir)
    return case


def strip_comments(text):
    return re.sub(r"/\*.*?\*/", "", re.sub(r"//[^\n]*", "", text, flags=re.S), flags=re.S)


def list_body(text):
    """The text between the '(' after a list's size and its matching ')'."""
    m = re.search(r"\n\s*(\d+)\s*\(", text)
    if not m:
        raise ValueError("no list")
    start = m.end()
    depth, i = 1, start
    while depth:
        depth += {"(": 1, ")": -1}.get(text[i], 0)
        i += 1
    return int(m.group(1)), text[start:i - 1]


def read_vectors(path, field=False):
    """The vectors of a points file, or a point field's internal field."""
    text = strip_comments(open(path).read())
    if field:
        text = text[text.index("internalField"):]
        if re.match(r"internalField\s+uniform", text):
            raise ValueError(f"{path}: a uniform internal field")
    n, body = list_body(text)
    values = [float(v) for v in re.findall(r"[-+0-9.eE]+", body)]
    if len(values) != 3 * n:
        raise ValueError(f"{path}: {len(values)} numbers for {n} vectors")
    return [values[3 * i:3 * i + 3] for i in range(n)]


def patch_points(poly_mesh, patch):
    """The points of a patch's faces (ascii polyMesh)."""
    boundary = strip_comments(open(os.path.join(poly_mesh, "boundary")).read())
    m = re.search(r"\b" + patch + r"\s*\{([^}]*)\}", boundary)
    n_faces = int(re.search(r"nFaces\s+(\d+)", m.group(1)).group(1))
    start = int(re.search(r"startFace\s+(\d+)", m.group(1)).group(1))
    _, body = list_body(strip_comments(open(os.path.join(poly_mesh, "faces")).read()))
    faces = re.findall(r"\d+\(([^)]*)\)", body)
    points = set()
    for f in faces[start:start + n_faces]:
        points.update(int(v) for v in f.split())
    return sorted(points)


def diagonal(points):
    lo = [min(p[k] for p in points) for k in range(3)]
    hi = [max(p[k] for p in points) for k in range(3)]
    return sum((h - l) ** 2 for h, l in zip(hi, lo)) ** 0.5


def largest_difference(a, b):
    if len(a) != len(b):
        fail(f"{len(a)} points against {len(b)}")
    return max(max(abs(x - y) for x, y in zip(p, q)) for p, q in zip(a, b))


def times(case):
    return sorted((t for t in os.listdir(case) if re.fullmatch(r"[0-9.e+-]+", t) and t != "0"), key=float)


def displacement_motion(case, t, body):
    """The motion file for `dgwarp deform` of time t: the body's displacement as written in t/pointDisplacement."""
    d = read_vectors(os.path.join(case, t, "pointDisplacement"), field=True)
    csv = os.path.join(case, f"body-{t}.csv")
    with open(csv, "w") as f:
        f.write("node,dx,dy,dz\n")
        for n in body:
            f.write(f"{n},{d[n][0]!r},{d[n][1]!r},{d[n][2]!r}\n")
    return '{"markers": {"body": {"displacement_file": "%s"}}}' % os.path.basename(csv)


def rigid_motion(amplitude_deg, plunge, frequency):
    """The motion file for `dgwarp deform` of time t from pitching_body.py's motion itself: multiMotion's
    septernion product x' = R(x + D), a pitch R by amplitude_deg sin(2 pi f t) about z through the origin
    (the plate's bounding-box centre) and D = (0, plunge sin(2 pi f t), 0), is the rotation about the
    origin followed by the translation R D."""
    def motion(case, t, body):
        s = math.sin(2 * math.pi * frequency * float(t))
        theta = math.radians(amplitude_deg * s)
        dy = plunge * s
        return json.dumps({"markers": {"body": {
            "rotate": {"angle_deg": amplitude_deg * s, "axis": [0, 0, 1], "center": [0, 0, 0]},
            "translate": [-math.sin(theta) * dy, math.cos(theta) * dy, 0]}}})
    return motion


def check_against_deform(case, dgwarp, deform_args, motion_of):
    """Each written time's points against `dgwarp deform` of the case with the motion motion_of(case, t, body)."""
    poly_mesh = os.path.join(case, "constant", "polyMesh")
    points0 = read_vectors(os.path.join(poly_mesh, "points"))
    body = patch_points(poly_mesh, "body")
    size = diagonal(points0)
    written = times(case)
    if not written:
        fail("moveDynamicMesh wrote no time")
    for t in written:
        motion = os.path.join(case, f"motion-{t}.json")
        with open(motion, "w") as f:
            f.write(motion_of(case, t, body) + "\n")
        reference = os.path.join(case, "reference")
        shutil.rmtree(reference, ignore_errors=True)
        os.makedirs(reference)
        os.symlink(os.path.join(case, "constant"), os.path.join(reference, "constant"))
        p = subprocess.run([dgwarp, "deform", reference, "-m", motion, "-o", reference, "--foam-time", "1", "-q",
                            *deform_args], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        if p.returncode != 0:
            fail("dgwarp deform: " + p.stdout)
        expected = read_vectors(os.path.join(reference, "1", "polyMesh", "points"))
        got = read_vectors(os.path.join(case, t, "polyMesh", "points"))
        diff = largest_difference(got, expected)
        print(f"time {t}: largest difference from dgwarp deform {diff:.3g} ({diff / size:.3g} of the mesh's size)")
        if diff > 1e-12 * size:
            fail(f"time {t}: the motion solver's points differ from dgwarp deform's by {diff} (size {size})")
    return written


def check_mesh_ok(case, plugin_dir):
    _, log = foam(case, "checkMesh -latestTime", plugin_dir)
    if "Mesh OK." not in log:
        fail("checkMesh at the last time:\n" + log[-3000:])
    print("checkMesh -latestTime: Mesh OK")


def test_serial(a):
    case = make_case(a.work, "serial", a.plugin_dir, "--steps", "3", "--dt", "0.05", "--write-interval", "1")
    _, log = foam(case, "moveDynamicMesh", a.plugin_dir)
    for expected in ("Selecting motion solver: dgwarp", "dgwarp: moving patches 1(body), fixed patches 3(inlet outlet walls)",
                     "dgwarp dg-harmonic ( harmonic-redo-below -1 ): 7566 points, 6300 cells, 322 moving and 2142 fixed boundary points"):
        if expected not in log:
            fail(f"moveDynamicMesh's log has no '{expected}':\n" + log[-3000:])
    steps = re.findall(r"dgwarp: step .* 0 of 6300 cells inverted", log)
    if len(steps) != 3:
        fail(f"{len(steps)} dgwarp steps without inverted cells in the log, expected 3")
    # (The motion solver turns dg-harmonic's guard off unless told otherwise: so does deform here.)
    if len(check_against_deform(case, a.dgwarp, ["--harmonic-redo-below", "-1"], rigid_motion(10.0, 0.25, 1.0))) != 3:
        fail("expected 3 written times")
    check_mesh_ok(case, a.plugin_dir)


def test_options(a):
    # rotations false: the plate's displacement alone, as for any other condition.
    case = make_case(a.work, "options", a.plugin_dir, "--steps", "2", "--dt", "0.05", "--write-interval", "1",
                     "--method", "dg-idw", "--option", "a-translation=5", "--option", "length-scale=auto",
                     "--option", "rotations=false")
    _, log = foam(case, "moveDynamicMesh", a.plugin_dir)
    if "dgwarp dg-idw ( a-translation 5 length-scale auto ):" not in log:
        fail("the log does not name the method and its options:\n" + log[-3000:])
    check_against_deform(case, a.dgwarp, ["--method", "dg-idw", "--a-translation", "5", "--length-scale", "auto"],
                         displacement_motion)


def test_trapping(a):
    # OpenFOAM traps floating-point exceptions (FOAM_SIGFPE); the library's prepare divides by
    # zero where harmless: with harmonic-wall-spacing 4 on this mesh it did, and the run died of
    # SIGFPE before the bridge turned the traps off around every call.
    # (Without the guard: its redo, the laplacian reference, takes 15 s here.)
    case = make_case(a.work, "trapping", a.plugin_dir, "--steps", "2", "--dt", "0.05", "--write-interval", "1",
                     "--option", "harmonic-wall-spacing=4", "--option", "harmonic-redo-below=-1")
    _, log = foam(case, "moveDynamicMesh", a.plugin_dir)
    if "trapFpe: Floating point exception trapping enabled" not in log:
        fail("OpenFOAM did not trap floating-point exceptions: the test tests nothing")
    check_against_deform(case, a.dgwarp, ["--harmonic-wall-spacing", "4", "--harmonic-redo-below", "-1"],
                         rigid_motion(10.0, 0.25, 1.0))


def test_parallel(a):
    case = make_case(a.work, "parallel", a.plugin_dir, "--steps", "3", "--dt", "0.05", "--write-interval", "1",
                     "--processors", "2")
    foam(case, "moveDynamicMesh", a.plugin_dir)
    foam(case, "decomposePar -force -copyZero", a.plugin_dir)
    _, log = foam(case, "mpirun -np 2 moveDynamicMesh -parallel", a.plugin_dir)
    if "dgwarp dg-harmonic (" not in log or "(processor 0)" not in log:
        fail("the parallel log has no dgwarp summary:\n" + log[-3000:])
    size = diagonal(read_vectors(os.path.join(case, "constant", "polyMesh", "points")))
    for t in times(case):
        serial = read_vectors(os.path.join(case, t, "polyMesh", "points"))
        merged = [None] * len(serial)
        for proc in range(2):
            pdir = os.path.join(case, f"processor{proc}")
            _, body = list_body(strip_comments(open(os.path.join(pdir, "constant", "polyMesh", "pointProcAddressing")).read()))
            ids = [int(v) for v in body.split()]
            local = read_vectors(os.path.join(pdir, t, "polyMesh", "points"))
            for i, g in enumerate(ids):
                if merged[g] is not None and merged[g] != local[i]:
                    fail(f"time {t}: point {g} differs between the processors: {merged[g]} {local[i]}")
                merged[g] = local[i]
        if any(p is None for p in merged):
            fail(f"time {t}: the processors do not hold every point")
        diff = largest_difference(merged, serial)
        print(f"time {t}: 2 processors against one: largest difference {diff:.3g}")
        if diff > 1e-12 * size:
            fail(f"time {t}: the parallel run's points differ from the serial run's by {diff}")


def test_inverting(a):
    # The plate's top (y = 0.1) plunged by 1.6 ends beyond the wall (y = 1.5). DG-IDW: no repair
    # (dg-harmonic's last resort would try, at length, to mend cells nothing can mend).
    case = make_case(a.work, "inverting", a.plugin_dir, "--steps", "1", "--dt", "0.25", "--plunge", "1.6",
                     "--amplitude-deg", "0", "--method", "dg-idw")
    code, log = foam(case, "moveDynamicMesh", a.plugin_dir, expect_ok=False)
    if code == 0:
        fail("moveDynamicMesh exited 0 on an inverting motion")
    if not re.search(r"dgwarp: the motion at time 0.25 inverts \(negative face pyramids or volumes\) \d+ of the "
                     r"6300 cells", log):
        fail("no FatalError naming the inverted cells:\n" + log[-3000:])
    if not re.search(r"dgwarp: \d+ cells with a folded corner here, the worst: \d+.*; \d+ with a negative face "
                     r"pyramid or volume: \d+", log):
        fail("the log does not list the worst inverted cells:\n" + log[-3000:])
    if os.path.exists(os.path.join(case, "0.25")):
        fail("a time folder was written for the inverting step")
    print("inverting motion: FatalError, exit", code)


def test_bad_options(a):
    cases = [
        (["--option", "a-translation=7"], "a-translation is an option of dg-idw; it does nothing with dg-harmonic"),
        (["--option", "radius=1"], "unknown method option 'radius'"),
        (["--option", "movingPatches=(wing)"], "movingPatches names wing, which is no patch of the mesh"),
        (["--method", "spline"], "unknown method 'spline'; the methods are dg-idw, dgm, idw, rbf, dg-harmonic, laplacian"),
    ]
    for args, message in cases:
        case = make_case(a.work, "bad", a.plugin_dir, "--steps", "1", "--dt", "0.05", *args)
        code, log = foam(case, "moveDynamicMesh", a.plugin_dir, expect_ok=False)
        if code == 0 or message not in log:
            fail(f"{args}: expected a FatalError saying '{message}', got exit {code}:\n" + log[-3000:])
        if "dgwarp: step" in log:
            fail(f"{args}: a step ran before the error")
        print(f"{' '.join(args)}: refused ({message})")


def test_folded_corners(a):
    # Pitch 4 degrees and plunge 0.05 at once (dg-idw): 8 cells get a folded corner
    # (Knupp's quality <= 0) whose face pyramids stay positive. OpenFOAM's checkMesh accepts
    # them: a warning and the run goes on; with invertedCells corners, a FatalError.
    args = ["--steps", "1", "--dt", "0.25", "--plunge", "0.05", "--amplitude-deg", "4", "--method", "dg-idw"]
    case = make_case(a.work, "corners", a.plugin_dir, *args)
    code, log = foam(case, "moveDynamicMesh", a.plugin_dir, expect_ok=False)
    m = re.search(r"dgwarp: step .* (\d+) of 6300 cells inverted", log)
    if not m or int(m.group(1)) == 0:
        fail("the set-up folds no corner: the test tests nothing\n" + log[-3000:])
    if "with a negative face pyramid" in log:
        fail("the set-up makes cells OpenFOAM refuses too: the test tests nothing\n" + log[-3000:])
    if code != 0 or "whose face pyramids are all positive: OpenFOAM's checkMesh accepts them; going on" not in log:
        fail(f"exit {code}: expected a warning and the run to go on\n" + log[-3000:])
    check_mesh_ok(case, a.plugin_dir)
    case = make_case(a.work, "corners-strict", a.plugin_dir, *args, "--option", "invertedCells=corners")
    code, log = foam(case, "moveDynamicMesh", a.plugin_dir, expect_ok=False)
    if code == 0 or not re.search(r"the motion at time 0.25 folds a corner of \d+ of the 6300 cells", log):
        fail(f"invertedCells corners: expected a FatalError, got exit {code}\n" + log[-3000:])
    print(f"{m.group(1)} cells with a folded corner: a warning (pyramids), a FatalError (corners)")


TESTS = {"folded-corners": test_folded_corners, "serial": test_serial, "options": test_options, "trapping": test_trapping, "parallel": test_parallel, "inverting": test_inverting,
         "bad-options": test_bad_options}


def main():
    p = argparse.ArgumentParser()
    p.add_argument("test", choices=sorted(TESTS))
    p.add_argument("--dgwarp", required=True)
    p.add_argument("--plugin-dir", required=True)
    p.add_argument("--work", required=True)
    a = p.parse_args()
    a.dgwarp = os.path.abspath(a.dgwarp)
    a.plugin_dir = os.path.abspath(a.plugin_dir)
    a.work = os.path.abspath(os.path.join(a.work, a.test))
    os.makedirs(a.work, exist_ok=True)
    TESTS[a.test](a)
    print("PASS")


if __name__ == "__main__":
    main()
