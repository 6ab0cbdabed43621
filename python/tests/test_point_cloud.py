"""Mesh.point_cloud: points without cells, deformed as a mesh's volume nodes."""

import pickle

import numpy as np
import pytest

import dgwarp


def ring_in_box(n_cloud=600, dim=2, seed=0):
    """A ring of 40 'body' points inside the corners of a box, and random points between them."""
    t = np.linspace(0, 2 * np.pi, 40, endpoint=False)
    body = np.c_[0.2 * np.cos(t), 0.2 * np.sin(t)]
    box = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1], [0, -1], [1, 0], [0, 1], [-1, 0]], dtype=float)
    rng = np.random.default_rng(seed)
    cloud = rng.uniform(-0.95, 0.95, (n_cloud, 2))
    cloud = cloud[np.hypot(*cloud.T) > 0.3]
    if dim == 3:  # the ring at z = 0, the box's corners at z = +-0.2 (around the cloud)
        body = np.c_[body, np.zeros(len(body))]
        box = np.array([[x, y, z] for x in (-1, 1) for y in (-1, 1) for z in (-0.2, 0.2)], dtype=float)
        cloud = np.c_[cloud, rng.uniform(-0.1, 0.1, len(cloud))]
    return np.r_[body, box, cloud], {"body": np.arange(40), "box": 40 + np.arange(8)}


TURN = {"markers": {"body": {"rotate": {"angle_deg": 15, "center": [0, 0]}}}}


@pytest.mark.parametrize("method", ["dg-harmonic", "dg-idw", "idw", "rbf"])
def test_a_point_cloud_deforms_with_its_markers(method):
    points, markers = ring_in_box()
    cloud = dgwarp.Mesh.point_cloud(points, markers)
    assert (cloud.num_points, cloud.num_cells, cloud.marker_names) == (len(points), 0, ["body", "box"])
    plan = dgwarp.prepare(cloud, ["body"], method=method)
    moved = plan.deform(TURN)
    c, s = np.cos(np.radians(15)), np.sin(np.radians(15))
    assert np.allclose(moved[:40], points[:40] @ np.array([[c, s], [-s, c]]), atol=1e-12)  # the body turns
    assert np.array_equal(moved[40:48], points[40:48])  # the box stays
    assert np.hypot(*(moved[48:] - points[48:]).T).max() > 0.02  # the cloud follows
    # As the same points would in a mesh: the methods use the boundary nodes, not the cells
    # (dg-harmonic's guard aside, which measures cells: off here).
    tri = pytest.importorskip("matplotlib.tri")
    ring = np.c_[np.arange(40), (np.arange(40) + 1) % 40]
    around = 40 + np.array([0, 4, 1, 5, 2, 6, 3, 7])
    mesh = dgwarp.Mesh.from_arrays(points, {"triangle": tri.Triangulation(*points.T).triangles},
                                   {"body": ring, "box": np.c_[around, np.roll(around, -1)]})
    options = {"harmonic_redo_below": -1} if method == "dg-harmonic" else {}
    as_mesh = dgwarp.prepare(mesh, ["body"], method=method, **options).deform(TURN, untangle=False)
    assert np.array_equal(moved, as_mesh)
    assert np.array_equal(pickle.loads(pickle.dumps(plan)).deform(TURN), moved)


def test_a_3d_point_cloud_and_what_a_cloud_cannot_do(tmp_path):
    points, markers = ring_in_box(dim=3)
    cloud = dgwarp.Mesh.point_cloud(points, markers)
    moved = dgwarp.prepare(cloud, ["body"], method="dg-idw").deform(
        {"markers": {"body": {"translate": [0.05, 0, 0]}}})
    assert np.allclose(moved[:40, 0], points[:40, 0] + 0.05)
    with pytest.raises(dgwarp.Error, match="cells"):
        dgwarp.prepare(cloud, ["body"], method="laplacian")
    with pytest.raises(dgwarp.MeshError, match="cells"):
        cloud.write(tmp_path / "cloud.vtu")
    with pytest.raises(dgwarp.MeshError, match="node 5000"):
        dgwarp.Mesh.point_cloud(points, {"body": [0, 5000]})
