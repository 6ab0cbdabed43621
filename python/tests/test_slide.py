"""Sliding and cyclic markers in Python plans (docs/MOTION.md "Sliding", "Cyclic pairs"):
the same first pass and step as `dgwarp deform`."""

import pickle

import numpy as np
import pytest

import dgwarp


def lattice_box(n):
    """[0, 1]^2 in (n - 1)^2 squares; markers x_m, x_p, y_m, y_p (the sides where x or y is 0 or 1).
    Node i + n j at (i, j) / (n - 1)."""
    xs = np.linspace(0.0, 1.0, n)
    points = np.stack(np.meshgrid(xs, xs, indexing="xy"), axis=-1).reshape(-1, 2)
    node = np.arange(n * n).reshape(n, n)  # node[j, i]
    i, j = np.meshgrid(np.arange(n - 1), np.arange(n - 1), indexing="xy")
    quads = np.stack([node[j, i], node[j, i + 1], node[j + 1, i + 1], node[j + 1, i]], -1).reshape(-1, 4)
    s = np.arange(n - 1)
    markers = {
        "x_m": np.stack([node[s, 0], node[s + 1, 0]], 1),
        "x_p": np.stack([node[s, n - 1], node[s + 1, n - 1]], 1),
        "y_m": np.stack([node[0, s], node[0, s + 1]], 1),
        "y_p": np.stack([node[n - 1, s], node[n - 1, s + 1]], 1),
    }
    return dgwarp.Mesh.from_arrays(points, {"quadrilateral": quads}, markers)


SQUEEZE = {"markers": {"y_p": {"translate": [0, -0.2]}, "x_m": "slide", "x_p": "slide"}}
SHEAR = {"markers": {"y_p": {"translate": [0.15, -0.1]}, "x_m": {"cyclic": "x_p"}, "x_p": {"cyclic": "x_m"}}}


@pytest.mark.parametrize("method", ["dg-harmonic", "dg-idw", "rbf"])
def test_sliding_sides_stay_on_their_lines_and_match_the_cli(tmp_path, cli, method):
    n = 9
    mesh = lattice_box(n)
    plan = dgwarp.prepare(mesh, SQUEEZE, method=method)
    moved, report = plan.deform(SQUEEZE, report=True)
    assert report["quality"]["inverted"] == 0
    x0 = mesh.points
    for i in (0, n - 1):
        side = i + n * np.arange(n)
        assert np.array_equal(moved[side, 0], x0[side, 0])  # on their lines exactly
        dy = moved[side, 1] - x0[side, 1]
        assert np.all(dy <= 1e-12) and np.all(dy >= -0.2 - 1e-12)
        assert np.all(np.diff(moved[side, 1]) > 0)
    assert np.min(moved[n * np.arange(1, n - 1), 1] - x0[n * np.arange(1, n - 1), 1]) < -0.01  # they came down
    # The CLI, on the same mesh and motion, writes the same coordinates.
    mesh.write(tmp_path / "box.su2")
    (tmp_path / "squeeze.json").write_text(__import__("json").dumps(SQUEEZE))
    cli("deform", tmp_path / "box.su2", "-m", tmp_path / "squeeze.json", "-o", tmp_path / "out.su2", "--method", method)
    assert np.array_equal(dgwarp.read(tmp_path / "out.su2").points, moved)


def test_cyclic_sides_move_as_their_images():
    n = 9
    mesh = lattice_box(n)
    plan = dgwarp.prepare(mesh, SHEAR)
    moved = plan.deform(SHEAR)
    d = moved - mesh.points
    left, right = n * np.arange(n), n * np.arange(n) + n - 1
    assert np.abs(d[left] - d[right]).max() < 1e-14
    assert np.abs(d[left, 0]).max() > 0.01  # they followed the shear
    # A step that leaves the cyclic markers out of its motion couples them still.
    again = plan.deform({"markers": {"y_p": {"translate": [0.15, -0.1]}}})
    assert np.array_equal(again, moved)


def test_a_plan_with_sliding_markers_pickles_and_refuses_what_it_cannot_do():
    mesh = lattice_box(7)
    plan = dgwarp.prepare(mesh, SQUEEZE)
    expected = plan.deform(SQUEEZE)
    back = pickle.loads(pickle.dumps(plan))
    assert np.array_equal(back.deform(SQUEEZE), expected)
    cyclic = dgwarp.prepare(mesh, SHEAR, method="dg-idw")
    assert np.array_equal(pickle.loads(pickle.dumps(cyclic)).deform(SHEAR), cyclic.deform(SHEAR))
    # A step may not make a static marker slide, nor move a sliding one.
    with pytest.raises(ValueError, match="makes marker 'y_m' slide, which the plan holds static"):
        plan.deform({"markers": {"y_p": {"translate": [0, -0.2]}, "y_m": "slide"}})
    with pytest.raises(ValueError, match="moves marker 'x_m', which the plan holds sliding"):
        plan.deform({"markers": {"y_p": {"translate": [0, -0.2]}, "x_m": {"translate": [0, 0.1]}}})
    # The derivative does not follow the first pass.
    with pytest.raises(ValueError, match="sliding or cyclic markers"):
        plan.deform_derivative(np.zeros((len(plan.boundary_nodes), 2)))
