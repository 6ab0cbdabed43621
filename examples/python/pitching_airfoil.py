"""A pitching and plunging airfoil: prepare once, deform every time step, write VTU frames.

    PYTHONPATH=build/python python3 examples/python/pitching_airfoil.py [--frames 40] [--out pitching]

The NACA0012 case pitches 5 degrees about its quarter chord and plunges 0.1 chords, 90 degrees
apart, over one period; each frame is written as VTU with the displacement and the cell quality
(open pitching/pitch_*.vtu as a series in ParaView).
"""

import argparse
import pathlib
import time

import numpy as np

import dgwarp


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mesh", help="a mesh with markers 'airfoil' and 'farfield' (default: dgwarp's naca0012 case)")
    parser.add_argument("--frames", type=int, default=40, help="time steps over one period")
    parser.add_argument("--out", default="pitching", help="folder for the VTU frames")
    args = parser.parse_args()

    mesh = dgwarp.read(args.mesh) if args.mesh else dgwarp.case("naca0012")
    # The motion-file form of docs/MOTION.md, as a dict; frame k is at time k * time_step.
    motion = dgwarp.Motion({
        "markers": {"airfoil": {"periodic": {
            "pitch": {"amplitude_deg": 5, "frequency": 1.0, "center": [0.25, 0]},
            "plunge": {"amplitude": [0, 0.1], "frequency": 1.0, "phase_deg": 90}}}},
        "time": {"time_step": 1.0 / args.frames, "steps": args.frames},
    })
    plan = dgwarp.prepare(mesh, moving=motion)  # the Delaunay graph and the weights, once
    print(f"{mesh}\n{plan}")

    out_dir = pathlib.Path(args.out)
    out_dir.mkdir(exist_ok=True)
    points = np.empty_like(mesh.points)  # the solver's array: written in place every step
    worst = 1.0
    deform_seconds = 0.0
    for k in range(motion.frames):
        start = time.perf_counter()
        plan.deform(motion, frame=k, out=points)
        deform_seconds += time.perf_counter() - start
        q = dgwarp.quality(mesh, points=points)
        worst = min(worst, q.min)
        mesh.write(out_dir / f"pitch_{k:04d}.vtu", points=points,
                   point_data={"displacement": points - mesh.points}, cell_data={"quality": q.cells})
    print(f"{motion.frames} frames in {out_dir}/, {1e3 * deform_seconds / motion.frames:.3f} ms per step, "
          f"smallest cell quality {worst:.4f}")


if __name__ == "__main__":
    main()
