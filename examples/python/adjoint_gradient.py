"""An adjoint-style design loop: the gradient of an objective on the volume mesh with respect to
the design variables, through the transpose of the deformation's derivative.

    PYTHONPATH=build/python python3 examples/python/adjoint_gradient.py [--steps 8] [--method dg-idw]

The design: three bumps on the NACA0012's upper surface, d_y = sum_j a_j * b_j(x) with
b_j(x) = sin(pi x^e_j)^3, so the surface displacement is S a (S: boundary nodes x designs).
The volume mesh follows: X(a) = X0 + J S a (J = d volume points / d surface points, exact for
translations). The objective stands for a flow solver's: f(a) = 1/2 |X(a) - X_target|^2 over the
nodes within one chord of the airfoil, X_target the mesh of a hidden design a*. Its gradient is
df/da = S^T J^T (X(a) - X_target) restricted to those nodes: one transpose product per design
iteration (an adjoint solver hands dgwarp its df/dX the same way), checked here against a central
finite difference of f. Steepest descent with an exact line search (f is quadratic in a) moves
toward a* (slowly: the bumps overlap, so f's valleys are narrow; an optimiser would use a
quasi-Newton method on the same gradients).
"""

import argparse

import numpy as np

import dgwarp


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=8, help="steepest-descent steps")
    parser.add_argument("--method", default="dg-idw", help="dg-idw or dg-harmonic")
    args = parser.parse_args()

    mesh = dgwarp.case("naca0012")
    plan = dgwarp.prepare(mesh, moving=["airfoil"], method=args.method)
    x = plan.boundary_points
    upper = plan.moving & (x[:, 1] > 0)
    chord = np.clip(x[:, 0], 0, 1)
    S = np.zeros((len(x), 2, 3))  # surface displacement per design variable
    for j, e in enumerate((0.5, 1.0, 2.0)):  # bumps peaking near 25%, 50% and 70% of the chord
        S[upper, 1, j] = np.sin(np.pi * chord[upper] ** e) ** 3
    near = np.hypot(mesh.points[:, 0] - 0.5, mesh.points[:, 1]) < 1.0  # where the objective looks

    def volume(a):
        return plan.deform(translation=S @ a)

    target = volume(np.array([0.010, -0.004, 0.006]))  # the hidden design a*

    def objective(a):
        r = (volume(a) - target)[near]
        return 0.5 * np.vdot(r, r)

    def gradient(a):
        residual = np.where(near[:, None], volume(a) - target, 0.0)  # df/dX
        surface = plan.deform_derivative_transpose(residual)  # df/d(surface points) = J^T df/dX
        return np.einsum("bdj,bd->j", S, surface)  # df/da = S^T df/d(surface)

    a = np.zeros(3)
    g = gradient(a)
    h = 1e-6
    fd = np.array([(objective(a + h * e) - objective(a - h * e)) / (2 * h) for e in np.eye(3)])
    print(f"gradient at a = 0: {g} (central differences {fd}, largest relative difference "
          f"{np.abs(g - fd).max() / np.abs(fd).max():.1e})")
    for step in range(args.steps):
        g = gradient(a)
        # f is quadratic in a: the exact step along -g is |g|^2 / |J S g|^2 over the nodes it sees.
        jsg = plan.deform_derivative(S @ g)[near]
        a = a - np.vdot(g, g) / np.vdot(jsg, jsg) * g
        print(f"step {step + 1}: f = {objective(a):.3e}, a = {np.array2string(a, precision=5)}")
    print(f"design found with {plan.method}: a = {np.array2string(a, precision=5)} (hidden: [0.01 -0.004 0.006])")


if __name__ == "__main__":
    main()
