"""Plan.deform gives the CLI's result bit for bit on the same inputs, for every method and kind of motion."""

import json

import numpy as np
import pytest

import dgwarp

from conftest import MOTIONS

ROTATE_10 = {"markers": {"airfoil": {"rotate": {"angle_deg": 10, "axis": [0, 0, 1], "center": [0.25, 0, 0]}},
                         "farfield": "fixed"}}

# The CLI's flags for each Python keyword, in the cases below.
CASES = [
    ("dg-idw", {}),
    ("dg-idw", {"length_scale": "auto", "dg_idw_weights": "continuous"}),
    ("dg-idw", {"a_translation": 5.0, "a_rotation": 2.0, "length_scale": 0.5}),
    ("dgm", {}),
    ("idw", {}),
    ("idw", {"idw_moving_exponent": 2.5, "idw_static_exponent": 4.0}),
    ("rbf", {}),
    ("rbf", {"rbf_radius": 3.0, "rbf_greedy": 1e-3}),
    ("dg-harmonic", {}),
    ("dg-harmonic", {"harmonic_wall_spacing": 3.0, "harmonic_growth": 0.5}),
]


def flags(options):
    out = []
    for key, value in options.items():
        out += [f"--{key.replace('_', '-')}", str(value)]
    return out


def cli_points(cli, tmp_path, mesh_file, motion_file, *args, name="out.su2"):
    out = tmp_path / name
    cli("deform", mesh_file, "-m", motion_file, "-o", out, "-q", *args)
    return out


@pytest.mark.parametrize("method,options", CASES, ids=[f"{m}-{i}" for i, (m, _) in enumerate(CASES)])
def test_every_method_equals_the_cli(tmp_path, cli, naca_file, method, options):
    motion_file = tmp_path / "rotate.json"
    motion_file.write_text(json.dumps(ROTATE_10))
    out = cli_points(cli, tmp_path, naca_file, motion_file, "--method", method, *flags(options))
    mesh = dgwarp.read(naca_file)
    plan = dgwarp.prepare(mesh, moving=["airfoil"], method=method, **options)
    assert plan.method == method
    points = plan.deform(ROTATE_10)
    assert np.array_equal(points, dgwarp.read(out).points)
    assert not np.array_equal(points, mesh.points)


def test_a_motion_file_of_frames_equals_the_cli_frame_by_frame(tmp_path, cli, naca_file):
    motion = dgwarp.Motion(MOTIONS / "airfoil_pitch_plunge.json")
    assert motion.frames == 20 and len(motion) == 20 and motion.time(3) == pytest.approx(0.15)
    cli_points(cli, tmp_path, naca_file, MOTIONS / "airfoil_pitch_plunge.json", name="pitch.su2")
    mesh = dgwarp.read(naca_file)
    plan = dgwarp.prepare(mesh, moving=motion)
    out = np.empty_like(mesh.points)
    for frame in (0, 7, 19):
        plan.deform(motion, frame=frame, out=out)
        assert np.array_equal(out, dgwarp.read(tmp_path / f"pitch_{frame:04d}.su2").points), frame
    with pytest.raises(IndexError, match="frame 20 of a motion with 20 frames"):
        plan.deform(motion, frame=20)


def test_a_displacement_file_on_su2s_naca0012_equals_the_cli(tmp_path, cli, su2_meshes):
    mesh_file = su2_meshes / "deformation_naca0012_mesh_NACA0012_inv.su2"
    out = cli_points(cli, tmp_path, mesh_file, MOTIONS / "airfoil_bump.json", "--method", "dg-idw",
                     "--length-scale", "auto")
    mesh = dgwarp.read(mesh_file)
    motion = dgwarp.Motion(MOTIONS / "airfoil_bump.json")
    plan = dgwarp.prepare(mesh, moving=motion, method="dg-idw", length_scale="auto")
    assert plan.moving_markers == ["airfoil"]
    assert np.array_equal(plan.deform(motion), dgwarp.read(out).points)


def test_dg_harmonic_last_resort_and_untangle_equal_the_cli(tmp_path, cli, su2_meshes):
    # SU2's pyramid brick with its top face turned 10 degrees inside fixed walls: DG-harmonic's
    # one pass folds cells, and its last resort repairs them, in the CLI and here alike (its
    # guard off: the guard's laplacian, seconds here, would keep every cell valid).
    mesh_file = su2_meshes / "deformation_brick_pyra_mesh_brick_pyra_ffd.su2"
    motion_file = MOTIONS / "brick_rotate_top.json"
    mesh = dgwarp.read(mesh_file)
    motion = dgwarp.Motion(motion_file)
    with pytest.warns(dgwarp.DgwarpWarning, match="116 boundary nodes are on both a moving and a static marker"):
        harmonic = dgwarp.prepare(mesh, moving=motion, method="dg-harmonic", harmonic_redo_below=-1)  # as the CLI warns
    repaired = harmonic.deform(motion)
    raw = harmonic.deform(motion, untangle=False)
    assert dgwarp.quality(mesh, points=raw).inverted > 0  # the step alone folds cells
    assert dgwarp.quality(mesh, points=repaired).inverted == 0
    out = cli_points(cli, tmp_path, mesh_file, motion_file, "--method", "dg-harmonic", "--harmonic-redo-below", "-1")
    assert np.array_equal(repaired, dgwarp.read(out).points)
    # --untangle after DG-IDW.
    with pytest.warns(dgwarp.DgwarpWarning):
        plan = dgwarp.prepare(mesh, moving=motion, method="dg-idw", length_scale="auto")
    untangled = plan.deform(motion, untangle=True)
    out = cli_points(cli, tmp_path, mesh_file, motion_file, "--method", "dg-idw", "--length-scale", "auto",
                     "--untangle", name="u.su2")
    assert np.array_equal(untangled, dgwarp.read(out).points)


def test_plans_go_between_python_and_the_cli(tmp_path, cli, naca_file):
    motion_file = tmp_path / "rotate.json"
    motion_file.write_text(json.dumps(ROTATE_10))
    mesh = dgwarp.read(naca_file)
    for method in ("dg-idw", "dg-harmonic"):
        plan = dgwarp.prepare(mesh, moving=["airfoil"], method=method)
        saved = tmp_path / f"{method}.plan"
        plan.save(saved)
        # The CLI deforms with Python's plan ...
        out = cli_points(cli, tmp_path, naca_file, motion_file, "--plan", saved, name=f"{method}.su2")
        assert np.array_equal(plan.deform(ROTATE_10), dgwarp.read(out).points)
        # ... and Python with the CLI's.
        cli_plan = tmp_path / f"cli-{method}.plan"
        cli("prepare", naca_file, "-m", motion_file, "-o", cli_plan, "--method", method, "-q")
        loaded = dgwarp.load_plan(cli_plan, mesh)
        assert loaded.method == method and loaded.moving_markers == ["airfoil"]
        assert np.array_equal(loaded.deform(ROTATE_10), plan.deform(ROTATE_10))


def test_a_step_report_is_the_cli_json_frame(tmp_path, cli, su2_meshes):
    # Issue #32 item 4: deform(report=True) gives what a frame of `dgwarp deform --json` has,
    # the last resort's repair and the warnings as coded items included.
    mesh_file = su2_meshes / "deformation_brick_pyra_mesh_brick_pyra_ffd.su2"
    motion_file = MOTIONS / "brick_rotate_top.json"
    mesh = dgwarp.read(mesh_file)
    motion = dgwarp.Motion(motion_file)
    with pytest.warns(dgwarp.DgwarpWarning):
        plan = dgwarp.prepare(mesh, moving=motion, method="dg-harmonic", harmonic_redo_below=-1)
    points, report = plan.deform(motion, report=True)
    assert np.array_equal(points, plan.deform(motion))
    result = cli("deform", mesh_file, "-m", motion_file, "-o", tmp_path / "out.su2", "--method", "dg-harmonic",
                 "--harmonic-redo-below", "-1", "--json")
    frame = json.loads(result.stdout)["frames"][0]
    assert report["last_resort"] is True and report["untangle"]["inverted_before"] > 0
    for key in ("quality", "ratio", "inverted_by_motion", "worst_inverted_cells", "inverted_on_boundary",
                "substeps", "untangle", "last_resort", "guard", "warnings", "warning_items"):
        assert report[key] == frame[key], key
    assert set(report["seconds"]) == {"deform", "untangle", "quality"}
    # Arrays give a report too, with their warnings as items; untangle=False: the step alone, measured.
    with pytest.warns(dgwarp.DgwarpWarning, match="more than the diagonal"):
        points, report = plan.deform(translation=[0.0, 0.0, 1e3], untangle=False, report=True)
    large = [w for w in report["warning_items"] if w["code"] == "large-displacement"]
    assert large and large[0]["value"] == pytest.approx(1e3) and large[0]["marker"]
    assert report["untangle"] is None and report["last_resort"] is False
    assert report["quality"]["inverted"] == dgwarp.quality(mesh, points=points).inverted
