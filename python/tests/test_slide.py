"""Sliding and cyclic markers in Python plans (docs/MOTION.md "Sliding", "Cyclic pairs"):
the same first pass and step as `dgwarp deform`."""

import pathlib
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


OPENFOAM = pathlib.Path(__file__).resolve().parents[2] / "tests" / "data" / "openfoam"


@pytest.mark.parametrize("method", ["dg-harmonic", "dg-idw"])
def test_openfoam_cyclic_patches_couple_by_their_type_as_in_the_cli(tmp_path, cli, method):
    # channel-cyclic: 3D, its inout and sides halves cyclic patches naming each other.
    mesh = dgwarp.read(OPENFOAM / "channel-cyclic")
    motion = {"markers": {"bottomWall": {"translate": [0.2, 0, 0.1]}}}
    plan = dgwarp.prepare(mesh, motion, method=method)
    assert plan.sliding_markers == []
    assert sorted(plan.cyclic_markers) == sorted(["inout1_half0", "inout1_half1", "inout2_half0", "inout2_half1",
                                                  "sides1_half0", "sides1_half1", "sides2_half0", "sides2_half1"])
    moved = plan.deform(motion)
    assert not np.array_equal(moved, mesh.points)
    # As `dgwarp deform` couples them by their type: the same coordinates.
    (tmp_path / "motion.json").write_text(__import__("json").dumps(motion))
    cli("deform", OPENFOAM / "channel-cyclic", "-m", tmp_path / "motion.json", "-o", tmp_path / "out.vtu",
        "--method", method)
    assert np.array_equal(dgwarp.read(tmp_path / "out.vtu").points, moved)
    # Named in the motion, a patch is as the motion says: held, no longer coupled.
    held = dgwarp.prepare(mesh, {"markers": dict(motion["markers"], inout1_half0="fixed", inout1_half1="fixed")},
                          method=method)
    assert "inout1_half0" not in held.cyclic_markers and "inout1_half0" in held.static_markers
    # A plan of such markers pickles with them.
    assert np.array_equal(pickle.loads(pickle.dumps(plan)).deform(motion), moved)


def test_openfoam_empty_patches_slide_by_their_type_and_the_case_stays_3d():
    # cavity: a 2D case stored in 3D, frontAndBack empty. Python deforms the 3D mesh, its empty patch sliding
    # in its planes (the CLI deforms the 2D case: docs/PYTHON.md).
    mesh = dgwarp.read(OPENFOAM / "cavity")
    plan = dgwarp.prepare(mesh, ["movingWall"])
    assert plan.sliding_markers == ["frontAndBack"]
    lid = {"markers": {"movingWall": {"translate": [0.01, -0.01, 0]}}}
    moved = plan.deform(lid)
    assert np.array_equal(pickle.loads(pickle.dumps(plan)).deform(lid), moved)
    z0 = mesh.points[:, 2]
    assert np.abs(moved[:, 2] - z0).max() < 1e-12  # every node on one of the two planes stays on it
    assert np.abs(moved[:, :2] - mesh.points[:, :2]).max() > 0.005
    # Named static, it is held instead.
    held = dgwarp.prepare(mesh, ["movingWall"], ["fixedWalls", "frontAndBack"])
    assert held.sliding_markers == [] and "frontAndBack" in held.static_markers
    back = pickle.loads(pickle.dumps(held))
    assert back.sliding_markers == [] and back.static_markers == held.static_markers


def test_a_patch_named_fixed_stays_held_after_unpickling_beside_one_that_slides():
    # frontAndBack (empty: slides by its type) named fixed, fixedWalls named to slide: the pickled
    # classification names every marker, so unpickling does not make frontAndBack slide by its type.
    mesh = dgwarp.read(OPENFOAM / "cavity")
    motion = {"markers": {"movingWall": {"translate": [0.01, 0, 0]}, "frontAndBack": "fixed", "fixedWalls": "slide"}}
    plan = dgwarp.prepare(mesh, motion)
    assert plan.sliding_markers == ["fixedWalls"] and "frontAndBack" in plan.static_markers
    back = pickle.loads(pickle.dumps(plan))
    assert back.sliding_markers == ["fixedWalls"] and back.static_markers == plan.static_markers
    assert np.array_equal(back.deform(motion), plan.deform(motion))


def test_a_cgns_meshs_symmetry_bcs_slide_and_a_pickled_mesh_keeps_them():
    # lower: a BCSymmetryPlane; mirror: its family's type is one; right: a wall; top: no BC.
    mesh = dgwarp.read(pathlib.Path(__file__).resolve().parents[2] / "tests" / "data" / "cgns" / "typed-square.cgns")
    assert dgwarp.prepare(mesh, ["right"]).sliding_markers == ["lower", "mirror"]
    back = pickle.loads(pickle.dumps(mesh))
    assert dgwarp.prepare(back, ["right"]).sliding_markers == ["lower", "mirror"]
