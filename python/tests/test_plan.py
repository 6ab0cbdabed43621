"""prepare / Plan.deform with arrays, out=, views, plan files, and bad input."""

import math

import numpy as np
import pytest

import dgwarp

TRANSLATE = {"markers": {"airfoil": {"translate": [0.05, -0.02]}}}


@pytest.fixture(scope="module")
def mesh(naca_file):
    return dgwarp.read(naca_file)


@pytest.fixture(scope="module")
def plan(mesh):
    return dgwarp.prepare(mesh, moving=["airfoil"])


def test_plan_describes_its_boundary(mesh, plan):
    assert plan.moving_markers == ["airfoil"] and plan.static_markers == ["farfield"]
    nodes = np.union1d(mesh.markers["airfoil"].nodes, mesh.markers["farfield"].nodes)
    assert np.array_equal(plan.boundary_nodes, nodes)
    assert np.array_equal(plan.boundary_nodes[plan.moving], mesh.markers["airfoil"].nodes)
    assert np.array_equal(plan.boundary_points, mesh.points[nodes])
    assert np.shares_memory(plan.boundary_nodes, plan.boundary_nodes) and not plan.boundary_nodes.flags.writeable
    assert plan.mesh is not None and plan.memory_bytes > 0 and plan.summary["graph_simplices"] > 0
    assert plan.method == "dg-harmonic"  # the default, as the CLI's
    assert plan.options == {"harmonic_wall_spacing": 6.0, "harmonic_growth": 1.0, "harmonic_redo_below": 0.8}
    idw = dgwarp.prepare(mesh, moving=["airfoil"], method="dg-idw")
    assert idw.options == {"a_translation": 7.0, "a_rotation": 1.4, "length_scale": 1.0, "dg_idw_weights": "paper"}


def test_arrays_give_what_the_same_motion_as_a_dict_gives(plan):
    from_dict = plan.deform(TRANSLATE)
    assert np.array_equal(plan.deform(translation=[0.05, -0.02]), from_dict)
    assert np.array_equal(plan.deform(np.array([0.05, -0.02, 0.0])), from_dict)
    rows = np.zeros((len(plan.boundary_nodes), 2))
    rows[plan.moving] = [0.05, -0.02]
    assert np.array_equal(plan.deform(translation=rows), from_dict)
    # A rotation about the quarter chord: the rotation vector of 10 degrees about z.
    angle = math.radians(10)
    turned = plan.deform(rotation=[0, 0, angle], center=[0.25, 0])
    assert np.allclose(turned, plan.deform({"markers": {"airfoil": {"rotate": {"angle_deg": 10, "center": [0.25, 0]}}}}),
                       atol=1e-14, rtol=0)


def test_every_boundary_node_follows_its_motion_exactly(mesh, plan):
    rng = np.random.default_rng(1)
    d = np.zeros((len(plan.boundary_nodes), 2))
    d[plan.moving] = rng.normal(scale=1e-3, size=(plan.moving.sum(), 2))
    x = plan.deform(translation=d)
    assert np.array_equal(x[plan.boundary_nodes], mesh.points[plan.boundary_nodes] + d)


def test_out_is_written_in_place(mesh, plan):
    out = np.full_like(mesh.points, np.nan)
    result = plan.deform(TRANSLATE, out=out)
    assert result is out
    assert np.array_equal(out, plan.deform(TRANSLATE))
    # A view into a larger C-contiguous buffer is written in place too.
    buffer = np.zeros((2 * mesh.num_points, 2))
    view = buffer[mesh.num_points:]
    plan.deform(TRANSLATE, out=view)
    assert np.shares_memory(view, buffer) and np.array_equal(view, out) and not buffer[: mesh.num_points].any()


def test_zero_motion_is_the_identity(mesh, plan):
    assert np.array_equal(plan.deform(translation=np.zeros((len(plan.boundary_nodes), 2))), mesh.points)


def test_plan_file_round_trip_and_checks(tmp_path, mesh, plan, su2_meshes):
    path = tmp_path / "naca.plan"
    plan.save(path)
    loaded = dgwarp.load_plan(path, mesh)
    assert loaded.options == plan.options and loaded.moving_markers == ["airfoil"]
    assert np.array_equal(loaded.deform(TRANSLATE), plan.deform(TRANSLATE))
    with pytest.raises(dgwarp.MeshError, match="another mesh"):
        dgwarp.load_plan(path, dgwarp.read(su2_meshes / "deformation_naca0012_mesh_NACA0012_inv.su2"))
    damaged = tmp_path / "damaged.plan"
    damaged.write_bytes(path.read_bytes()[:-9])
    with pytest.raises(dgwarp.ParseError) as e:
        dgwarp.load_plan(damaged, mesh)
    assert e.value.file == str(damaged)
    with pytest.raises(dgwarp.IoError):
        dgwarp.load_plan(tmp_path / "missing.plan", mesh)
    with pytest.raises(dgwarp.InputError, match="cannot be saved|saved"):
        dgwarp.prepare(mesh, moving=["airfoil"], method="idw").save(tmp_path / "idw.plan")


def test_prepare_refuses_bad_arguments(mesh):
    with pytest.raises(dgwarp.MeshError, match="wing.*airfoil, farfield") as e:
        dgwarp.prepare(mesh, moving=["wing"])
    assert e.value.marker == "wing" and isinstance(e.value, ValueError)
    with pytest.raises(ValueError, match="unknown method 'sph'; choose one of dg-idw, dgm, idw, rbf, dg-harmonic"):
        dgwarp.prepare(mesh, moving=["airfoil"], method="sph")
    with pytest.raises(ValueError, match="rbf_radius is an option of rbf; it does nothing with dg-harmonic"):
        dgwarp.prepare(mesh, moving=["airfoil"], rbf_radius=1.0)
    with pytest.raises(TypeError, match="unexpected keyword argument 'radius'"):
        dgwarp.prepare(mesh, moving=["airfoil"], radius=1.0)
    with pytest.raises(dgwarp.InputError, match="a_translation"):
        dgwarp.prepare(mesh, moving=["airfoil"], method="dg-idw", a_translation=-1.0)
    with pytest.raises(ValueError, match="finite"):
        dgwarp.prepare(mesh, moving=["airfoil"], method="dg-idw", a_rotation=float("nan"))
    with pytest.raises(ValueError, match="'auto'"):
        dgwarp.prepare(mesh, moving=["airfoil"], method="dg-idw", length_scale="big")
    with pytest.raises(ValueError, match="both moving and static"):
        dgwarp.prepare(mesh, moving=["airfoil"], static=["airfoil", "farfield"])
    with pytest.raises(ValueError, match="'farfield' is neither moving nor static"):
        dgwarp.prepare(mesh, moving=["airfoil"], static=[])
    with pytest.raises(TypeError, match="marker names"):
        dgwarp.prepare(mesh, moving=[1])
    with pytest.raises(TypeError, match="progress must be a callable"):
        dgwarp.prepare(mesh, moving=["airfoil"], progress=3)
    with pytest.warns(dgwarp.DgwarpWarning, match="nothing moves"):
        dgwarp.prepare(mesh, moving=[])


def test_deform_refuses_bad_arrays(plan):
    n = len(plan.boundary_nodes)
    with pytest.raises(ValueError, match=rf"translation must have shape \(n, 3 or 2\)|translation must have shape \({n}, 3 or 2\), got \({n}, 4\)"):
        plan.deform(translation=np.zeros((n, 4)))
    with pytest.raises(ValueError, match=rf"got \({n - 1}, 2\)"):
        plan.deform(translation=np.zeros((n - 1, 2)))
    with pytest.raises(TypeError, match="float64.*int64"):
        plan.deform(translation=np.zeros((n, 2), dtype=np.int64))
    with pytest.raises(ValueError, match="C-contiguous"):
        plan.deform(translation=np.zeros((n, 4))[:, ::2])
    bad = np.zeros((n, 2))
    bad[np.flatnonzero(plan.moving)[3], 1] = np.nan
    with pytest.raises(ValueError, match=r"translation\[\d+, 1\] is nan"):
        plan.deform(translation=bad)
    static_row = np.zeros((n, 2))
    static_row[np.flatnonzero(~plan.moving)[0]] = 1.0
    with pytest.raises(ValueError, match="is static"):
        plan.deform(translation=static_row)
    with pytest.raises(ValueError, match="about z only"):
        plan.deform(rotation=[0.1, 0, 0])
    with pytest.raises(TypeError, match="translation must be an array of numbers"):
        plan.deform(translation="abc")
    with pytest.raises(IndexError, match="frame -1"):
        plan.deform(TRANSLATE, frame=-1)
    with pytest.raises(TypeError, match="needs a motion"):
        plan.deform()
    with pytest.raises(TypeError, match="not both"):
        plan.deform(TRANSLATE, translation=[0.1, 0])
    with pytest.raises(TypeError, match="a motion must be"):
        plan.deform(42)
    with pytest.raises(TypeError, match="ambiguous"):
        plan.deform("motion.json")


def test_deform_refuses_bad_out(mesh, plan):
    n = mesh.num_points
    with pytest.raises(TypeError, match="NumPy array"):
        plan.deform(TRANSLATE, out=[[0.0, 0.0]] * n)
    with pytest.raises(TypeError, match="float64.*float32"):
        plan.deform(TRANSLATE, out=np.zeros((n, 2), dtype=np.float32))
    with pytest.raises(ValueError, match=rf"out must have shape \({n}, 2\), got \({n}, 3\)"):
        plan.deform(TRANSLATE, out=np.zeros((n, 3)))
    with pytest.raises(ValueError, match="C-contiguous"):
        plan.deform(TRANSLATE, out=np.zeros((n, 4))[:, ::2])
    with pytest.raises(ValueError, match="C-contiguous"):
        plan.deform(TRANSLATE, out=np.zeros((2, n)).T)
    with pytest.raises(ValueError, match="read-only"):
        plan.deform(TRANSLATE, out=mesh.points)


def test_deform_refuses_bad_motions(plan):
    with pytest.raises(dgwarp.MeshError, match="names marker 'wing'.*airfoil, farfield") as e:
        plan.deform({"markers": {"wing": {"translate": [1, 0]}}})
    assert e.value.marker == "wing"
    with pytest.raises(dgwarp.MeshError, match="moves marker 'farfield', which the plan holds static"):
        plan.deform({"markers": {"farfield": {"translate": [1, 0]}}})
    with pytest.raises(dgwarp.ParseError, match="translte") as e:
        plan.deform({"markers": {"airfoil": {"translte": [1, 0]}}})
    assert e.value.file == "motion"
    with pytest.raises(dgwarp.ParseError, match="angle_deg"):
        plan.deform({"markers": {"airfoil": {"rotate": {"angle_deg": "ten", "center": [0, 0]}}}})
    with pytest.raises(ValueError, match="nan|NaN|finite|JSON"):
        plan.deform({"markers": {"airfoil": {"translate": [float("nan"), 0]}}})
    with pytest.raises(ValueError, match="static_wins"):
        plan.deform({"markers": {"airfoil": {"translate": [1, 0]}}, "shared_nodes": "static_wins"})
    with pytest.raises(TypeError, match="cannot be written as JSON"):
        plan.deform({"markers": {"airfoil": {"translate": object()}}})
    # NumPy values in a dict are fine.
    assert np.array_equal(plan.deform({"markers": {"airfoil": {"translate": np.array([0.05, -0.02])}}}),
                          plan.deform(TRANSLATE))


def test_dgm_invalid_graph_is_an_invalid_result(mesh):
    plan = dgwarp.prepare(mesh, moving=["airfoil"], method="dgm")
    big = {"markers": {"airfoil": {"rotate": {"angle_deg": 90, "center": [0.25, 0]}}}}
    with pytest.raises(dgwarp.InvalidResultError) as e:
        plan.deform(big)
    assert e.value.count > 0 and isinstance(e.value, ValueError)
    substep = dgwarp.prepare(mesh, moving=["airfoil"], method="dgm", dgm_substep=True)
    assert np.isfinite(substep.deform(big)).all()


def test_refusals_instead_of_silent_changes(tmp_path, mesh, plan):
    # Issue #27, item 8: a plan saved under another name than .plan, a negative shared tolerance
    # and a thread count below 1 were accepted silently (the last became 1).
    with pytest.raises(ValueError, match=r"ends in \.plan"):
        plan.save(tmp_path / "x.txt")
    assert not (tmp_path / "x.txt").exists()
    plan.save(tmp_path / "x.PLAN")  # the CLI's rule: the extension without regard to case
    for bad in (-1.0, float("nan"), float("inf")):
        with pytest.raises(ValueError, match="shared_tolerance must be a length > 0"):
            dgwarp.prepare(mesh, ["airfoil"], shared_tolerance=bad)
    threads = dgwarp.num_threads()
    for bad in (0, -1, 10**6):
        with pytest.raises(ValueError, match="set_num_threads: n must be 1 to"):
            dgwarp.set_num_threads(bad)
    assert dgwarp.num_threads() == threads


def test_arrays_warn_as_the_same_motion_as_a_dict_does(plan):
    # Issue #27, item 15: the warnings of large motions came for dicts only.
    turn = {"markers": {"airfoil": {"rotate": {"angle_deg": 200, "center": [0.25, 0]}}}}
    with pytest.warns(dgwarp.DgwarpWarning, match="turns by 200 degrees in one step"):
        plan.deform(turn, untangle=False)
    with pytest.warns(dgwarp.DgwarpWarning, match="deform\\(\\) arrays: marker 'airfoil' turns by 200 degrees"):
        plan.deform(rotation=[0, 0, math.radians(200)], center=[0.25, 0], untangle=False)
    with pytest.warns(dgwarp.DgwarpWarning, match="moves node .* more than the diagonal"):
        plan.deform(translation=[1000.0, 0], untangle=False)
    with pytest.warns(dgwarp.DgwarpWarning, match="more than the diagonal"):
        plan.deform(np.array([1000.0, 0, 0]), untangle=False)


def test_a_non_finite_number_in_a_motion_dict_is_named_by_its_place(plan):
    # Issue #27, item 15: json's "Out of range float values are not JSON compliant" said not where.
    with pytest.raises(dgwarp.ParseError, match=r"a finite number at markers\.airfoil\.translate\[1\].*nan") as e:
        plan.deform({"markers": {"airfoil": {"translate": [0.0, float("nan")]}}})
    assert e.value.file == "motion"
    with pytest.raises(dgwarp.ParseError, match=r"rotate\.angle_deg.*inf"):
        dgwarp.Motion({"markers": {"airfoil": {"rotate": {"angle_deg": np.float32("inf"), "center": [0, 0]}}}})
    with pytest.raises(dgwarp.ParseError, match=r"translate\[0\]"):
        dgwarp.Motion({"markers": {"airfoil": {"translate": np.array([np.inf, 0.0])}}})


def test_the_rbf_error_names_the_python_keyword(su2_meshes):
    # Issue #27, item 15: it named RbfOptions::support_radius and --rbf-radius only.
    mesh = dgwarp.read(su2_meshes / "rans_naca0012_n0012_225-65.su2")
    with pytest.raises(dgwarp.InputError, match="not positive definite") as e:
        dgwarp.prepare(mesh, ["airfoil"], method="rbf")
    assert "rbf_radius" in str(e.value) and "RbfOptions" not in str(e.value)


def test_a_plan_for_another_motion_says_what_to_do(tmp_path, mesh, plan):
    # Issue #27, item 16: "(240 boundary nodes vs 240)", and no word of preparing it again.
    path = tmp_path / "naca.plan"
    plan.save(path)
    with pytest.raises(dgwarp.MeshError) as e:
        dgwarp.load_plan(path, mesh, moving=["farfield"], static=["airfoil"])
    message = str(e.value)
    assert "the same number of boundary nodes (240) with other nodes or other moving markers" in message
    assert message.endswith("prepare the plan again for this mesh and motion (dgwarp prepare, dgwarp.prepare)")
    assert "vs 240" not in message


def test_a_plan_of_another_version_says_what_to_do(tmp_path, mesh, plan):
    # Issue #27, item 16: a newer version's plan gave no advice (an older one's did).
    import struct

    for p in (plan, dgwarp.prepare(mesh, ["airfoil"], method="dg-idw")):
        path = tmp_path / f"{p.method}.plan"
        p.save(path)
        data = bytearray(path.read_bytes())
        data[8:12] = struct.pack("<I", 99)  # the format version, after the 8-byte magic
        path.write_bytes(bytes(data))
        with pytest.raises(dgwarp.ParseError, match="99 \\(a newer dgwarp's: run dgwarp prepare again\\)"):
            dgwarp.load_plan(path, mesh)
