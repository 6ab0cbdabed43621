"""dgwarp.quality gives what `dgwarp quality --json` gives."""

import numpy as np
import pytest

import dgwarp

from conftest import cli_json


def summary(q):
    return {"cells": len(q.cells), "min": q.min, "mean": q.mean, "inverted": q.inverted, "worst_cell": q.worst_cell}


@pytest.mark.parametrize("name", ["unsteady_square_cylinder_mesh_square_turb_hybrid.su2",
                                  "deformation_brick_pyra_mesh_brick_pyra_ffd.su2"])
def test_quality_equals_the_cli(cli, su2_meshes, name):
    path = su2_meshes / name
    q = dgwarp.quality(dgwarp.read(path))
    expected = cli_json("quality", path)["quality"]
    assert summary(q) == {k: expected[k] for k in summary(q)}
    edges, counts = q.histogram
    assert counts.tolist() == expected["histogram"]["counts"] and edges[0] == -np.inf
    assert q.ratio is None and q.ratio_min is None
    assert np.min(q.cells) == q.min and q.cells[q.worst_cell] == q.min


def test_quality_of_other_points_equals_the_cli_with_a_reference(tmp_path, cli, naca_file):
    mesh = dgwarp.read(naca_file)
    plan = dgwarp.prepare(mesh, moving="airfoil")
    points = plan.deform(rotation=[0, 0, 0.5], center=[0.25, 0])
    deformed = tmp_path / "deformed.su2"
    mesh.write(deformed, points=points)
    expected = cli_json("quality", deformed, "--reference", naca_file)
    q = dgwarp.quality(mesh, points=points)
    assert summary(q) == {k: expected["quality"][k] for k in summary(q)}
    assert (q.ratio_min, q.ratio_mean, q.ratio_worst_cell) == (
        expected["ratio"]["min"], expected["ratio"]["mean"], expected["ratio"]["worst_cell"])
    # The same through a reference mesh.
    again = dgwarp.quality(dgwarp.read(deformed), reference=mesh)
    assert np.array_equal(again.cells, q.cells) and np.array_equal(again.ratio, q.ratio)
    # Unchanged points: every ratio is 1.
    assert np.all(dgwarp.quality(mesh, points=np.array(mesh.points)).ratio == 1)


def test_quality_refuses_bad_input(naca_file, su2_meshes):
    mesh = dgwarp.read(naca_file)
    with pytest.raises(ValueError, match=r"points must have shape \(1656, 2\)"):
        dgwarp.quality(mesh, points=np.zeros((10, 2)))
    with pytest.raises(ValueError, match=r"points\[0, 0\] is inf"):
        dgwarp.quality(mesh, points=np.full((1656, 2), np.inf))
    with pytest.raises(TypeError, match="float64"):
        dgwarp.quality(mesh, points=np.zeros((1656, 2), dtype=np.float16))
    with pytest.raises(dgwarp.MeshError, match="other cells"):
        dgwarp.quality(mesh, reference=dgwarp.read(su2_meshes / "deformation_naca0012_mesh_NACA0012_inv.su2"))
    with pytest.raises(TypeError):
        dgwarp.quality("mesh.su2")
