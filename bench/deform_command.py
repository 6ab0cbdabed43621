"""The whole `dgwarp deform` command, as a user waits for it (issue #33): per format and method,
the phases the command reports (--json) and the whole wall and peak memory (/usr/bin/time).

    /usr/bin/python3 bench/deform_command.py [--size 2] [--formats su2,msh,vtu,cgns,foam]
                                             [--methods dg-harmonic,dg-idw] [--repeats 3] [--threads 2]

The mesh: `dgwarp case squeezed-sphere --size N` (0: 202k nodes, 1: 396k?, 2: 865k nodes, 5.3M
tetrahedra) with its motion "squeeze", converted once to each format (not timed). Each run reads
the mesh and writes the deformed mesh in the same format; an OpenFOAM case is written as a
case folder; a frame with inverted cells is written all the same (--allow-invalid; the last column
counts them). A row is the median run of --repeats (by wall), the first run of a series
included (it is what a user who runs once waits for). "start" is what the phases leave of the
wall: process start, the motion file, the report. With two threads or more the original quality
is measured beside the prepare, on a thread of its own: its column overlaps the prepare's. Prints the processor and the load average;
figures taken with a load above 0.5 are not results (the script says so).
"""

import argparse
import json
import os
import pathlib
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

SOURCE_DIR = pathlib.Path(__file__).resolve().parents[1]
EXTENSIONS = {"su2": ".su2", "msh": ".msh", "vtu": ".vtu", "cgns": ".cgns", "foam": "/"}


def run(args, env=None):
    r = subprocess.run(args, capture_output=True, text=True, env=env)
    if r.returncode != 0:
        sys.exit(f"{' '.join(map(str, args))} failed ({r.returncode}):\n{r.stdout}\n{r.stderr}")
    return r


def processor():
    with open("/proc/cpuinfo") as f:
        for line in f:
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    return "unknown"


def path_of(folder, stem, fmt):
    return folder / (stem + EXTENSIONS[fmt]) if fmt != "foam" else folder / stem


def one_run(cli, mesh, motion, out, method, threads):
    timed = ["/usr/bin/time", "-f", "%e %M", str(cli), "deform", str(mesh), "-m", str(motion), "-o", str(out),
             "--method", method, "--json", "-q", "--allow-invalid"]
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    r = subprocess.run(timed, capture_output=True, text=True, env=env)
    if r.returncode not in (0, 3):  # 3: inverted cells, written anyway (--allow-invalid): timed all the same
        sys.exit(f"{' '.join(timed)} failed ({r.returncode}):\n{r.stderr}")
    wall, kb = r.stderr.strip().splitlines()[-1].split()
    report = json.loads(r.stdout)
    s, frame = report["seconds"], report["frames"][0]["seconds"]
    phases = {
        "read": s["read"],
        "original quality": s["original_quality"],
        "resolve": s["resolve"],
        "prepare": report["plan"]["seconds"],
        "step": frame["deform"],
        "quality": frame["quality"],
        "write": frame["write"],
    }
    # With two threads or more the original's quality is measured beside the
    # prepare (on its own thread): it overlaps it and is not part of the sum.
    beside = threads > 1
    phases["start"] = float(wall) - sum(v for k, v in phases.items() if not (beside and k == "original quality"))
    inverted = report["frames"][0]["inverted_by_motion"]
    return {"wall": float(wall), "peak_mb": int(kb) / 1024, "phases": phases, "inverted": inverted}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--cli", default=str(SOURCE_DIR / "build" / "dgwarp"))
    p.add_argument("--size", type=int, default=2)
    p.add_argument("--formats", default="su2,msh,vtu,cgns,foam")
    p.add_argument("--methods", default="dg-harmonic,dg-idw")
    p.add_argument("--repeats", type=int, default=3)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--work", help="folder for the meshes (kept); default: a temporary folder, removed")
    a = p.parse_args()
    formats = a.formats.split(",")
    for f in formats:
        if f not in EXTENSIONS:
            sys.exit(f"unknown format {f}: one of {', '.join(EXTENSIONS)}")
    work = pathlib.Path(a.work) if a.work else pathlib.Path(tempfile.mkdtemp(prefix="dgwarp-deform-command-"))
    work.mkdir(parents=True, exist_ok=True)
    try:
        source = work / "sphere.su2"
        if not source.exists():
            run([a.cli, "case", "squeezed-sphere", "--size", str(a.size), "-o", source, "--motions", work, "-q"])
        motion = work / "squeeze.json"
        for fmt in formats:
            mesh = path_of(work, "sphere", fmt)
            if fmt != "su2" and not mesh.exists():
                run([a.cli, "convert", source, str(mesh), "-q"])
        load = os.getloadavg()[0]
        if load > 0.5:  # the meshing and conversions just now: give the load average a minute to settle
            time.sleep(60)
            load = os.getloadavg()[0]
        print(f"processor: {processor()}, {os.cpu_count()} cores; load average {load:.2f} at the start; "
              f"{a.threads} thread(s)")
        if load > 0.5:
            print("warning: the machine is not quiet (load above 0.5): these figures are not results")
        names = ["read", "original quality", "resolve", "prepare", "step", "quality", "write", "start"]
        print()
        print("| format | method | " + " | ".join(names) + " | **wall** (s) | peak (MB) | file (MB) | inverted |")
        print("|---" * (len(names) + 6) + "|")
        for fmt in formats:
            mesh = path_of(work, "sphere", fmt)
            size = (sum(f.stat().st_size for f in mesh.rglob("*") if f.is_file()) if mesh.is_dir()
                    else mesh.stat().st_size) / 1e6
            for method in a.methods.split(","):
                out = path_of(work, "out", fmt)
                runs = [one_run(a.cli, mesh, motion, out, method, a.threads) for _ in range(a.repeats)]
                runs.sort(key=lambda r: r["wall"])
                r = runs[len(runs) // 2]
                walls = ", ".join(f"{x['wall']:.2f}" for x in runs)
                cells = " | ".join(f"{r['phases'][n]:.3f}" for n in names)
                print(f"| {fmt} | {method} | {cells} | **{r['wall']:.2f}** ({walls}) | {r['peak_mb']:.0f} | "
                      f"{size:.0f} | {r['inverted']} |", flush=True)
                if out.is_dir():
                    shutil.rmtree(out)
                elif out.exists():
                    out.unlink()
        print(f"\nload average {os.getloadavg()[0]:.2f} at the end")
    finally:
        if not a.work:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
