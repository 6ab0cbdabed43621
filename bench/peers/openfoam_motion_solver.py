#!/usr/bin/python3
"""dgwarp's motion solver against OpenFOAM's displacementLaplacian inside OpenFOAM runs
(issue #29; docs/RESULTS.md, "dgwarp as OpenFOAM's motion solver").

    bench/peers/openfoam_motion_solver.py [--resolution 1.6] [--steps 50] [--dt 0.01]
        [--pimple-steps 10] [--work build/peer-openfoam-motion] [--dgwarp build/dgwarp]
        [--plugin-dir build/openfoam] [--processors 2] [--threads 1]

The case: openfoam/cases/pitching_body.py (a plate pitching by 10 degrees and plunging by
0.25 in a channel, blockMesh hexahedra; --resolution 1.6: about 206k cells), the same
mesh and the same pointDisplacement condition for both solvers. Runs, each in its own
case folder:
  - moveDynamicMesh for --steps time steps with `motionSolver dgwarp` (dgwarp's default
    method) and with displacementLaplacian (inverseDistance to the plate, GAMG, 20 V-cycles
    per solve: bench/peers/openfoam.sh's converged set-up), on one process and on
    --processors processes (decomposePar -copyZero, mpirun ... -parallel);
  - pimpleFoam (laminar) for --pimple-steps steps with each, on one process.
Measured (moveDynamicMesh; the lines are time-stamped as OpenFOAM prints them), per time
step: the motion solve, from the step's "Time = " line to the motion solver's last line
(dgwarp's step line; displacementLaplacian's last GAMG solve), and the mesh update, to the
first line after mesh.update() (checkMesh's), which adds OpenFOAM's own update of the mesh's
geometry; medians and means over the steps after the first (which prepares dgwarp); the
whole run's wall time (pimpleFoam: this alone, its lines after the update being its own); at every written time, checkMesh's worst
non-orthogonality and skewness and dgwarp's Knupp quality (min) of the moved mesh; for the
parallel dgwarp run, the largest difference of its points from the serial run's.
OpenMP threads per process: --threads (1: OpenFOAM is single-threaded, one core each).
Prints markdown tables, the machine and its load; writes WORK/results.json.
"""
import argparse
import json
import os
import re
import shutil
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
CASE_SCRIPT = os.path.join(ROOT, "openfoam", "cases", "pitching_body.py")
BASHRC = "/usr/share/openfoam/etc/bashrc"
sys.path.insert(0, os.path.join(ROOT, "tests", "openfoam"))
import motion_solver_test as mst  # noqa: E402  (its OpenFOAM file readers)


def run_foam(case, command, a, stamped_log=None):
    env = dict(os.environ, LD_LIBRARY_PATH=a.plugin_dir + ":" + os.environ.get("LD_LIBRARY_PATH", ""),
               OMP_NUM_THREADS=str(a.threads), OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    script = f"source {BASHRC} >/dev/null 2>&1; cd '{case}' && exec {command}"
    start = time.monotonic()
    p = subprocess.Popen(["bash", "-c", script], env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                         text=True, bufsize=1)
    lines = []
    for line in p.stdout:
        lines.append((time.monotonic() - start, line.rstrip("\n")))
    code = p.wait()
    wall = time.monotonic() - start
    if stamped_log:
        with open(stamped_log, "w") as f:
            for t, line in lines:
                f.write(f"{t:.4f}\t{line}\n")
    if code != 0:
        sys.exit(f"{command} in {case} failed (exit {code}); log: {stamped_log}\n" +
                 "\n".join(l for _, l in lines[-30:]))
    return lines, wall


MOTION_LINE = re.compile(r"^(PIMPLE: iteration|dgwarp|GAMG:\s+Solving for cellDisplacement|Selecting|Applying|"
                         r"Constructed|\s*$|\[\d+\] dgwarp)")


def update_seconds(lines):
    """Per time step of moveDynamicMesh: (motion solve, mesh update) seconds: from its 'Time = ' line
    to the motion solver's last line (dgwarp's step line, displacementLaplacian's last GAMG solve of
    cellDisplacement), and to the first line after the update (checkMesh's), which adds OpenFOAM's
    own update of the mesh's geometry (movePoints)."""
    out, start, solved = [], None, None
    for t, line in lines:
        if line.startswith("Time = "):
            start, solved = t, None
        elif start is not None and (line.startswith("dgwarp: step") or "Solving for cellDisplacement" in line):
            solved = t
        elif start is not None and not MOTION_LINE.match(line):
            out.append((solved - start if solved is not None else None, t - start))
            start = None
    return out


def quality_of(case, t, a):
    """dgwarp's quality of time t's points (a view: the polyMesh with t's points)."""
    view = os.path.join(case, "quality-view")
    shutil.rmtree(view, ignore_errors=True)
    os.makedirs(os.path.join(view, "constant", "polyMesh"))
    for f in ("faces", "owner", "neighbour", "boundary"):
        os.symlink(os.path.join(case, "constant", "polyMesh", f), os.path.join(view, "constant", "polyMesh", f))
    os.symlink(os.path.join(case, t, "polyMesh", "points"), os.path.join(view, "constant", "polyMesh", "points"))
    out = subprocess.run([a.dgwarp, "quality", view, "--reference", case, "--json"], stdout=subprocess.PIPE,
                         text=True, check=True).stdout
    q = json.loads(out)
    return q["quality"]["min"]


def check_mesh(case, a, parallel=False):
    """checkMesh over every written time: the worst non-orthogonality, skewness, and whether each is OK."""
    cmd = "checkMesh -noZero" + (f" -parallel" if parallel else "")
    if parallel:
        cmd = f"mpirun -np {a.processors} --oversubscribe {cmd}"
    lines, _ = run_foam(case, cmd, a, os.path.join(case, "checkMesh.log"))
    text = "\n".join(l for _, l in lines)
    nonortho = [float(x) for x in re.findall(r"Mesh non-orthogonality Max: (\S+)", text)]
    skew = [float(x) for x in re.findall(r"Max skewness = (\S+)", text)]
    ok = text.count("Mesh OK.")
    failed = len(re.findall(r"Failed \d+ mesh checks", text))
    return {"non_orthogonality": max(nonortho) if nonortho else None, "skewness": max(skew) if skew else None,
            "mesh_ok": ok, "failed": failed}


def make_case(a, name, solver, application, steps, processors=None):
    case = os.path.join(a.work, name)
    shutil.rmtree(case, ignore_errors=True)
    args = [sys.executable, CASE_SCRIPT, case, "--resolution", str(a.resolution), "--solver", solver,
            "--steps", str(steps), "--dt", str(a.dt), "--application", application,
            "--processors", str(processors or a.processors)]
    subprocess.run(args, check=True)
    # The mesh once, then copied: every run starts from the same points.
    base = os.path.join(a.work, "base-mesh")
    if not os.path.isdir(base):
        subprocess.run([sys.executable, CASE_SCRIPT, base, "--resolution", str(a.resolution)], check=True)
        run_foam(base, "blockMesh", a, os.path.join(base, "blockMesh.log"))
    shutil.copytree(os.path.join(base, "constant", "polyMesh"), os.path.join(case, "constant", "polyMesh"))
    return case


def run(a, name, solver, application, steps, parallel=False):
    case = make_case(a, name, solver, application, steps)
    command = application
    if parallel:
        run_foam(case, "decomposePar -force -copyZero", a, os.path.join(case, "decomposePar.log"))
        command = f"mpirun -np {a.processors} --oversubscribe --bind-to none {application} -parallel"
    print(f"  {name}: {command} ...", flush=True)
    lines, wall = run_foam(case, command, a, os.path.join(case, "run.log"))
    r = {"name": name, "solver": solver, "application": application, "processes": a.processors if parallel else 1,
         "steps": steps, "wall_seconds": wall}
    if application == "moveDynamicMesh":  # (pimpleFoam's lines after the update are its own: whole run only)
        updates = update_seconds(lines)
        solves = [u[0] for u in updates[1:] if u[0] is not None]
        r.update({"first_update": updates[0][1], "update_median": statistics.median(u[1] for u in updates[1:]),
                  "update_mean": statistics.mean(u[1] for u in updates[1:]), "updates": len(updates),
                  "solve_median": statistics.median(solves), "solve_mean": statistics.mean(solves)})
    r.update(check_mesh(case, a, parallel))
    if not parallel:
        written = mst.times(case)
        r["quality_min"] = min(quality_of(case, t, a) for t in written)
        r["times"] = written
    r["case"] = case
    return r


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--resolution", type=float, default=1.6)
    p.add_argument("--steps", type=int, default=50)
    p.add_argument("--pimple-steps", type=int, default=10)
    p.add_argument("--dt", type=float, default=0.01)
    p.add_argument("--processors", type=int, default=2)
    p.add_argument("--threads", type=int, default=1)
    p.add_argument("--work", default=os.path.join(ROOT, "build", "peer-openfoam-motion"))
    p.add_argument("--dgwarp", default=os.path.join(ROOT, "build", "dgwarp"))
    p.add_argument("--plugin-dir", default=os.path.join(ROOT, "build", "openfoam"))
    p.add_argument("--skip-parallel", action="store_true")
    p.add_argument("--skip-pimple", action="store_true")
    a = p.parse_args()
    a.work, a.dgwarp, a.plugin_dir = map(os.path.abspath, (a.work, a.dgwarp, a.plugin_dir))
    shutil.rmtree(os.path.join(a.work, "base-mesh"), ignore_errors=True)
    os.makedirs(a.work, exist_ok=True)
    load_before = open("/proc/loadavg").read().split()[:3]
    started = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    results = []
    for solver in ("dgwarp", "displacementLaplacian"):
        results.append(run(a, f"{solver}-serial", solver, "moveDynamicMesh", a.steps))
        if not a.skip_parallel:
            results.append(run(a, f"{solver}-P{a.processors}", solver, "moveDynamicMesh", a.steps, parallel=True))
    if not a.skip_parallel:
        # dgwarp's points on P processes against one.
        serial, par = os.path.join(a.work, "dgwarp-serial"), os.path.join(a.work, f"dgwarp-P{a.processors}")
        diff = 0.0
        for t in mst.times(serial):
            ref = mst.read_vectors(os.path.join(serial, t, "polyMesh", "points"))
            for proc in range(a.processors):
                pdir = os.path.join(par, f"processor{proc}")
                _, body = mst.list_body(mst.strip_comments(open(os.path.join(pdir, "constant", "polyMesh", "pointProcAddressing")).read()))
                ids = [int(v) for v in body.split()]
                local = mst.read_vectors(os.path.join(pdir, t, "polyMesh", "points"))
                diff = max(diff, max(max(abs(x - y) for x, y in zip(local[i], ref[g])) for i, g in enumerate(ids)))
        for r in results:
            if r["name"] == f"dgwarp-P{a.processors}":
                r["difference_from_serial"] = diff
    if not a.skip_pimple:
        for solver in ("dgwarp", "displacementLaplacian"):
            results.append(run(a, f"{solver}-pimpleFoam", solver, "pimpleFoam", a.pimple_steps))
    load_after = open("/proc/loadavg").read().split()[:3]
    cells = re.search(r"cells:\s+(\d+)", open(os.path.join(a.work, "dgwarp-serial", "checkMesh.log")).read())
    with open(os.path.join(a.work, "results.json"), "w") as f:
        json.dump({"results": results, "load_before": load_before, "load_after": load_after}, f, indent=1)

    cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "?")
    print(f"\n## dgwarp as OpenFOAM's motion solver (bench/peers/openfoam_motion_solver.py)\n")
    print(f"- {started}; {cpu}, {os.cpu_count()} cores; {a.threads} OpenMP thread(s) per process")
    print(f"- pitching_body.py --resolution {a.resolution}: {cells.group(1) if cells else '?'} cells; "
          f"{a.steps} steps of {a.dt} s (moveDynamicMesh), {a.pimple_steps} (pimpleFoam)")
    print(f"- load before {' '.join(load_before)}, after {' '.join(load_after)}\n")
    def f(r, key, digits):
        return f"{r[key]:.{digits}f}" if r.get(key) is not None else "-"

    print("| run | processes | first update s | motion solve s (median, mean) | mesh update s (median, mean) | "
          "whole run s | min quality | max non-orth. | max skewness | checkMesh |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in results:
        ok = "Mesh OK" if r["failed"] == 0 and r["mesh_ok"] else f"{r['failed']} failed"
        print(f"| {r['name']} ({r['application']}) | {r['processes']} | {f(r, 'first_update', 3)} | "
              f"{f(r, 'solve_median', 4)}, {f(r, 'solve_mean', 4)} | {f(r, 'update_median', 4)}, {f(r, 'update_mean', 4)} | "
              f"{r['wall_seconds']:.1f} | {f(r, 'quality_min', 4)} | "
              f"{r['non_orthogonality']:.2f} | {r['skewness']:.3f} | {ok} |")
    by = {r["name"]: r for r in results}
    print()
    for suffix in ["serial"] + ([f"P{a.processors}"] if not a.skip_parallel else []):
        d, l = by.get(f"dgwarp-{suffix}"), by.get(f"displacementLaplacian-{suffix}")
        if d and l:
            print(f"- moveDynamicMesh, {suffix}: displacementLaplacian / dgwarp: motion solve (median) "
                  f"{l['solve_median'] / d['solve_median']:.1f}x, mesh update {l['update_median'] / d['update_median']:.1f}x, "
                  f"whole run {l['wall_seconds'] / d['wall_seconds']:.1f}x")
    d, l = by.get("dgwarp-pimpleFoam"), by.get("displacementLaplacian-pimpleFoam")
    if d and l:
        print(f"- pimpleFoam, serial: whole run {l['wall_seconds'] / d['wall_seconds']:.1f}x")
    if "difference_from_serial" in by.get(f"dgwarp-P{a.processors}", {}):
        print(f"- dgwarp on {a.processors} processes against one: largest point difference "
              f"{by[f'dgwarp-P{a.processors}']['difference_from_serial']:.3g}")


if __name__ == "__main__":
    main()
