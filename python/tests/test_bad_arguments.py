"""Every public function and method of the package, fed None, wrong types and non-finite values in
each argument in turn: each call returns or raises TypeError, ValueError, IndexError or OSError
(dgwarp's errors derive from them), and the interpreter never dies (issue #27, item 7)."""

import warnings

import numpy as np
import pytest

import dgwarp

TRANSLATE = {"markers": {"airfoil": {"translate": [0.01, 0.0]}}}

# None, wrong types, non-finite and out-of-range values.
BAD = [None, "x", b"x", 1.5, float("nan"), float("inf"), -1, 2**70, [], {}, (None,), object(),
       np.array([np.nan]), np.zeros((3, 7)), np.array(["a"]), lambda *a: None]

EXPECTED = (TypeError, ValueError, IndexError, OSError)


@pytest.fixture(scope="module")
def world(naca_file, tmp_path_factory):
    mesh = dgwarp.read(naca_file)
    plan = dgwarp.prepare(mesh, ["airfoil"], method="dg-idw")
    folder = tmp_path_factory.mktemp("bad_arguments")
    plan_path = folder / "naca.plan"
    plan.save(plan_path)
    return mesh, plan, plan_path


def calls(mesh, plan, plan_path):
    """(name, function, valid keyword arguments: a function giving a fresh dict)."""
    n = mesh.num_points
    out = [
        ("read", dgwarp.read, lambda: {"path": mesh.source, "zone": None, "progress": None}),
        ("case", dgwarp.case, lambda: {"name": "rect-box", "size": 0}),
        ("set_num_threads", dgwarp.set_num_threads, lambda: {"n": 1}),
        ("Mesh.from_arrays", dgwarp.Mesh.from_arrays,
         lambda: {"points": np.array(mesh.points), "cells": {"triangle": np.array(mesh.cells["triangle"])},
                  "markers": {"airfoil": np.array(mesh.markers["airfoil"].elements["line"])}}),
        ("Mesh.write", mesh.write,
         lambda: {"path": "out.vtu", "points": np.array(mesh.points), "point_data": {"d": np.zeros(n)},
                  "cell_data": {"q": np.zeros(mesh.num_cells)}, "gmsh_version": 41}),
        ("quality", dgwarp.quality, lambda: {"mesh": mesh, "points": np.array(mesh.points), "reference": None}),
        ("untangle", dgwarp.untangle,
         lambda: {"mesh": mesh, "points": np.array(mesh.points), "fixed": None, "target": 0.0}),
        ("Motion", dgwarp.Motion, lambda: {"source": TRANSLATE}),
        ("Motion.time", dgwarp.Motion(TRANSLATE).time, lambda: {"frame": 0}),
        ("prepare", dgwarp.prepare,
         lambda: {"mesh": mesh, "moving": ["airfoil"], "static": None, "method": "dg-idw",
                  "shared_nodes": "moving_wins", "shared_tolerance": 0.0, "progress": None, "a_translation": 7.0,
                  "a_rotation": 1.4, "length_scale": 1.0, "dg_idw_weights": "paper"}),
        ("prepare(idw)", dgwarp.prepare,
         lambda: {"mesh": mesh, "moving": TRANSLATE, "method": "idw", "idw_moving_exponent": 3.0,
                  "idw_static_exponent": 2.0}),
        ("load_plan", dgwarp.load_plan,
         lambda: {"path": plan_path, "mesh": mesh, "moving": None, "static": None, "shared_nodes": "moving_wins",
                  "shared_tolerance": 0.0}),
        ("Plan.deform", plan.deform,
         lambda: {"motion": TRANSLATE, "frame": 0, "out": np.empty((n, 2)), "untangle": None,
                  "untangle_target": 0.0, "progress": None}),
        ("Plan.deform(arrays)", plan.deform,
         lambda: {"translation": [0.01, 0.0], "rotation": [0.0, 0.0, 0.01], "center": [0.25, 0.0]}),
        ("Plan.save", plan.save, lambda: {"path": "again.plan"}),
    ]
    try:
        import meshio  # noqa: F401
    except ImportError:
        return out
    m = dgwarp.to_meshio(mesh)
    out += [
        ("to_meshio", dgwarp.to_meshio,
         lambda: {"mesh": mesh, "points": np.array(mesh.points), "point_data": None, "cell_data": None}),
        ("from_meshio", dgwarp.from_meshio, lambda: {"m": m}),
    ]
    return out


def test_no_bad_argument_kills_the_interpreter(world, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # outputs named "x" (an OpenFOAM case folder) land here
    threads = dgwarp.num_threads()
    unexpected = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for name, function, valid in calls(*world):
            function(**valid())  # the valid call works
            for key in valid():
                for bad in BAD:
                    kwargs = valid()
                    kwargs[key] = bad
                    try:
                        function(**kwargs)
                    except EXPECTED:
                        pass
                    except Exception as e:  # a clear error is a TypeError, ValueError, IndexError or OSError
                        unexpected.append(f"{name}({key}={bad!r}): {type(e).__name__}: {e}")
    dgwarp.set_num_threads(threads)
    assert not unexpected, "\n".join(unexpected)


def test_none_for_a_mesh_is_a_type_error(world):
    mesh, plan, plan_path = world
    with pytest.raises(TypeError):
        dgwarp.prepare(None, ["airfoil"])
    with pytest.raises(TypeError):
        dgwarp.load_plan(plan_path, None)
    with pytest.raises(TypeError):
        dgwarp.quality(None)
    with pytest.raises(TypeError):
        dgwarp.untangle(None, np.array(mesh.points))
    with pytest.raises(TypeError, match="dgwarp.Mesh"):
        dgwarp.to_meshio(None)
    with pytest.raises(TypeError, match="meshio.Mesh"):
        dgwarp.from_meshio(None)


def test_untangle_refuses_non_finite_points(world):
    mesh = world[0]
    points = np.array(mesh.points)
    points[7, 1] = np.inf
    with pytest.raises(ValueError, match=r"points\[7, 1\] is inf"):
        dgwarp.untangle(mesh, points)
