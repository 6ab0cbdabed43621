"""A deform loop in Python against the C++ step on the same ~100k-node mesh (docs/PYTHON.md).

    PYTHONPATH=build/python /usr/bin/python3 bench/python_deform_loop.py [--cells 46] [--frames 40] [--threads 1]

The mesh: a hexahedral grid of the unit cube, cells^3 hexahedra (47^3 = 103,823 nodes for 46) with
a cubic body of (cells/5)^3 cells removed at its centre (markers "box" and "body"), written as SU2.
The body pitches 1 degree about z and plunges, periodically over `frames` steps (a motion file).

C++: `dgwarp deform --json` (the CLI's `seconds.deform` per frame: the library's deform() call
alone). Python: Plan.deform for the same frames, (a) with the motion as arrays per boundary node
(a solver's loop: arrays computed beforehand, out= one array), (b) with the dgwarp.Motion (which
also resolves the motion file's frame per step, outside the CLI's timing). Each series runs
`--repeats` times; a frame's time is its fastest run (robust to other processes' bursts), and
the figure is the median over the frames. One thread by default (the machine is shared).
"""

import argparse
import json
import math
import os
import pathlib
import subprocess
import tempfile
import time

import numpy as np

import dgwarp

SOURCE_DIR = pathlib.Path(__file__).resolve().parents[1]


def cube_with_body(cells):
    """Hexahedra of the unit cube without the central body; markers box and body (quads, outward from the volume)."""
    n = cells
    xs = np.linspace(0.0, 1.0, n + 1)
    node = np.arange((n + 1) ** 3).reshape(n + 1, n + 1, n + 1)  # node[k, j, i] at (xs[i], xs[j], xs[k])
    lo, hi = round(0.4 * n), round(0.4 * n) + max(1, round(0.2 * n))
    k, j, i = np.meshgrid(np.arange(n), np.arange(n), np.arange(n), indexing="ij")
    inside = (i >= lo) & (i < hi) & (j >= lo) & (j < hi) & (k >= lo) & (k < hi)
    i, j, k = i[~inside], j[~inside], k[~inside]
    hexes = np.stack([node[k, j, i], node[k, j, i + 1], node[k, j + 1, i + 1], node[k, j + 1, i],
                      node[k + 1, j, i], node[k + 1, j, i + 1], node[k + 1, j + 1, i + 1], node[k + 1, j + 1, i]], 1)

    def faces(a, b):
        """The quadrilateral faces of the box [a, b]^3 (node index ranges)."""
        out = []
        r = np.arange(a, b)
        u, v = np.meshgrid(r, r, indexing="ij")
        u, v = u.ravel(), v.ravel()
        for fixed in (a, b):
            out.append(np.stack([node[fixed, u, v], node[fixed, u, v + 1], node[fixed, u + 1, v + 1], node[fixed, u + 1, v]], 1))
            out.append(np.stack([node[u, fixed, v], node[u, fixed, v + 1], node[u + 1, fixed, v + 1], node[u + 1, fixed, v]], 1))
            out.append(np.stack([node[u, v, fixed], node[u, v + 1, fixed], node[u + 1, v + 1, fixed], node[u + 1, v, fixed]], 1))
        return np.concatenate(out)

    box, body = faces(0, n), faces(lo, hi)
    used, remap = np.unique(hexes, return_inverse=True)  # drop the nodes inside the body
    points = np.stack(np.meshgrid(xs, xs, xs, indexing="ij"), -1)[..., ::-1].reshape(-1, 3)[used]
    lookup = np.full((n + 1) ** 3, -1)
    lookup[used] = np.arange(len(used))
    return dgwarp.Mesh.from_arrays(np.ascontiguousarray(points), {"hexahedron": remap.reshape(hexes.shape)},
                                   {"box": lookup[box], "body": lookup[body]})


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cells", type=int, default=46, help="hexahedra per side of the cube")
    parser.add_argument("--frames", type=int, default=40, help="time steps")
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--repeats", type=int, default=3, help="runs of each series")
    parser.add_argument("--cli", default=str(SOURCE_DIR / "build" / "dgwarp"))
    parser.add_argument("--method", default="dg-idw", help="the method of both loops (docs/PYTHON.md's figures: dg-idw)")
    args = parser.parse_args()

    dgwarp.set_num_threads(args.threads)
    mesh = cube_with_body(args.cells)
    motion = {"markers": {"body": {"periodic": {
                  "pitch": {"amplitude_deg": 1, "frequency": 1.0, "center": [0.5, 0.5, 0.5]},
                  "plunge": {"amplitude": [0, 0.005, 0], "frequency": 1.0, "phase_deg": 90}}}},
              "time": {"time_step": 1.0 / args.frames, "steps": args.frames}}
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        mesh.write(tmp / "cube.su2")
        (tmp / "motion.json").write_text(json.dumps(motion))
        mesh = dgwarp.read(tmp / "cube.su2")
        cpp = []
        for _ in range(args.repeats):
            report = json.loads(subprocess.run(
                [args.cli, "deform", tmp / "cube.su2", "-m", tmp / "motion.json", "-o", tmp / "out.vtu", "--json",
                 "--threads", str(args.threads), "--method", args.method], capture_output=True, text=True, check=True).stdout)
            cpp.append([f["seconds"]["deform"] for f in report["frames"]])

        m = dgwarp.Motion(tmp / "motion.json")
        plan = dgwarp.prepare(mesh, moving=m, method=args.method)
        out = np.empty_like(mesh.points)
        plan.deform(m, out=out)  # the first write into `out` faults its pages in: not part of a step
        # (a) arrays per boundary node, computed beforehand as a solver would.
        moving = plan.moving
        steps = []
        for k in range(m.frames):
            phase = 2 * math.pi * m.time(k)
            t = np.zeros((len(moving), 3))
            t[moving] = [0, 0.005 * math.sin(phase + math.pi / 2), 0]
            w = np.zeros((len(moving), 3))
            w[moving] = [0, 0, math.radians(1) * math.sin(phase)]
            steps.append((t, w))
        center = [0.5, 0.5, 0.5]
        arrays, frames = [], []
        for _ in range(args.repeats):
            run = []
            for t, w in steps:
                start = time.perf_counter()
                plan.deform(translation=t, rotation=w, center=center, out=out)
                run.append(time.perf_counter() - start)
            arrays.append(run)
            # (b) the Motion, frame by frame; the last frame must be the CLI's.
            run = []
            for k in range(m.frames):
                start = time.perf_counter()
                plan.deform(m, frame=k, out=out)
                run.append(time.perf_counter() - start)
            frames.append(run)
        last = dgwarp.read(tmp / f"out_{m.frames - 1:04d}.vtu").points
        assert np.array_equal(out, last), "Python's last frame differs from the CLI's"
        cpp, arrays, frames = (np.min(np.array(x), axis=0) for x in (cpp, arrays, frames))  # per frame, the fastest run

    load = os.getloadavg()
    print(f"mesh: {mesh.num_points} nodes, {mesh.num_cells} hexahedra, {len(plan.boundary_nodes)} boundary nodes "
          f"({int(plan.moving.sum())} moving); {m.frames} frames x {args.repeats} runs, {args.threads} thread(s); "
          f"load average {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")
    cpp_ms = 1e3 * np.median(cpp)
    for name, s in (("C++ step (dgwarp deform --json)", cpp), ("Python, arrays per node", arrays),
                    ("Python, Motion frame", frames)):
        ms = 1e3 * np.median(s)
        print(f"{name:34s} median {ms:7.3f} ms  min {1e3 * s.min():7.3f} ms  max {1e3 * s.max():7.3f} ms  "
              f"({ms / cpp_ms:.3f} x C++)")


if __name__ == "__main__":
    main()
