"""Plan.deform_derivative and deform_derivative_transpose (docs/PYTHON.md, "Derivatives"): J and
Jᵀ of a translation-only step against central finite differences of deform, and against each
other (the dot-product test), for dg-idw and dg-harmonic in 2D and 3D."""

import numpy as np
import pytest

import dgwarp


@pytest.fixture(scope="module")
def meshes(naca_file, su2_meshes):
    # 2D: the NACA0012 case (1,656 nodes); 3D: SU2's tetrahedral brick with its FFD box (moving "top"?).
    return {2: (dgwarp.read(naca_file), ["airfoil"]),
            3: (dgwarp.read(su2_meshes / "deformation_brick_tets_mesh_brick_tets_ffd.su2"), None)}


def plan_for(meshes, dim, method):
    mesh, moving = meshes[dim]
    if moving is None:  # the brick: its first marker moves
        moving = [mesh.marker_names[0]]
    return dgwarp.prepare(mesh, moving, method=method)


def random_direction(plan, seed):
    rng = np.random.default_rng(seed)
    v = rng.standard_normal((len(plan.boundary_nodes), plan.mesh.dim))
    v[~plan.moving] = 0  # deform's translation arrays must leave static nodes alone
    return v


@pytest.mark.parametrize("dim", [2, 3])
@pytest.mark.parametrize("method", ["dg-idw", "dg-harmonic"])
def test_the_derivative_is_the_finite_difference_of_deform(meshes, dim, method):
    plan = plan_for(meshes, dim, method)
    points = plan.mesh.points
    size = np.ptp(points, axis=0).max()
    v = random_direction(plan, 1)
    h = 1e-4 * size / np.abs(v).max()  # small: the guard and the repair stay out of it
    fd = (plan.deform(translation=h * v) - plan.deform(translation=-h * v)) / (2 * h)
    jv = plan.deform_derivative(v)
    assert jv.shape == points.shape
    assert np.abs(jv - fd).max() <= 1e-6 * np.abs(fd).max()
    # Not a zero map: volume nodes move, boundary rows are the direction itself.
    rows = np.setdiff1d(np.arange(len(points)), plan.boundary_nodes)
    assert np.abs(jv[rows]).max() > 0.01 * np.abs(v).max()
    assert np.array_equal(jv[plan.boundary_nodes], v)


@pytest.mark.parametrize("dim", [2, 3])
@pytest.mark.parametrize("method", ["dg-idw", "dg-harmonic"])
def test_the_transpose_is_the_adjoint_of_the_derivative(meshes, dim, method):
    plan = plan_for(meshes, dim, method)
    v = random_direction(plan, 2)
    w = np.random.default_rng(3).standard_normal(plan.mesh.points.shape)
    jv = plan.deform_derivative(v)
    jtw = plan.deform_derivative_transpose(w)
    assert jtw.shape == v.shape
    assert not jtw[~plan.moving].any()  # static nodes cannot move
    lhs, rhs = np.vdot(jv, w), np.vdot(v, jtw)
    assert abs(lhs - rhs) <= 1e-12 * (np.abs(jv).sum() * np.abs(w).max())
    # Column by column on a few boundary nodes: Jᵀ e_i against J's rows.
    for b in np.flatnonzero(plan.moving)[:3]:
        e = np.zeros_like(v)
        e[b, 0] = 1
        assert np.vdot(plan.deform_derivative(e), w) == pytest.approx(jtw[b, 0], rel=1e-12, abs=1e-12)


def test_out_arrays_and_refusals(meshes):
    plan = plan_for(meshes, 2, "dg-idw")
    v = random_direction(plan, 4)
    out = np.empty_like(plan.mesh.points)
    assert plan.deform_derivative(v, out=out) is out
    assert np.array_equal(out, plan.deform_derivative(v))
    with pytest.raises(ValueError, match="direction"):
        plan.deform_derivative(v[:-1])
    v[0, 0] = np.nan
    with pytest.raises(ValueError):
        plan.deform_derivative(v)
    with pytest.raises(dgwarp.Error, match="no derivative"):
        plan_for(meshes, 2, "idw").deform_derivative_transpose(np.zeros_like(plan.mesh.points))
