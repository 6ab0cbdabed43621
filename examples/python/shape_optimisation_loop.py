"""A shape-optimisation-style loop: 1,000 deformations of one mesh from NumPy displacements.

    PYTHONPATH=build/python python3 examples/python/shape_optimisation_loop.py [--steps 1000]

Each design is a bump on the airfoil's upper surface, d_y = a * sin(pi x)^3, with a design
variable a chosen by a crude search; every design is one Plan.deform into the same array (no
allocation per step) and one quality check. An optimiser would call a flow solver there.
"""

import argparse
import time

import numpy as np

import dgwarp


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=1000, help="designs evaluated")
    parser.add_argument("--method", default="dg-idw", help="deformation method")
    args = parser.parse_args()

    mesh = dgwarp.case("naca0012")
    plan = dgwarp.prepare(mesh, moving=["airfoil"], method=args.method)
    # Per boundary node (Plan.boundary_nodes order): its original position, and whether it moves.
    x = plan.boundary_points
    upper = plan.moving & (x[:, 1] > 0)
    shape = np.zeros_like(x)
    shape[upper, 1] = np.sin(np.pi * np.clip(x[upper, 0], 0, 1)) ** 3  # the bump's shape, zero on static nodes

    rng = np.random.default_rng(0)
    points = np.empty_like(mesh.points)
    displacement = np.empty_like(x)
    best = (-np.inf, 0.0)
    step_seconds = []
    for step in range(args.steps):
        a = rng.uniform(-0.03, 0.03)  # the design variable
        np.multiply(shape, a, out=displacement)
        start = time.perf_counter()
        plan.deform(translation=displacement, out=points)
        step_seconds.append(time.perf_counter() - start)
        q = dgwarp.quality(mesh, points=points)
        objective = -abs(a - 0.02) if q.inverted == 0 else -np.inf  # stands for the solver's figure
        best = max(best, (objective, a))
    step_seconds = np.array(step_seconds)
    print(f"{args.steps} deformations of {mesh.num_points} nodes with {plan.method}: "
          f"median {1e3 * np.median(step_seconds):.3f} ms, min {1e3 * step_seconds.min():.3f} ms per step")
    print(f"best design a = {best[1]:.5f}")


if __name__ == "__main__":
    main()
