"""dgwarp.read, Mesh (zero-copy views, from_arrays, write, write_time) and their errors."""

import json
import pathlib
import shutil

import numpy as np
import pytest

import dgwarp

from conftest import cli_json


def square_mesh():
    """Two triangles on the unit square, its four sides as two markers."""
    points = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=np.float64)
    cells = {"triangle": np.array([[0, 1, 2], [0, 2, 3]])}
    markers = {"bottom": np.array([[0, 1]]), "rest": {"line": [[1, 2], [2, 3], [3, 0]]}}
    return dgwarp.Mesh.from_arrays(points, cells, markers)


def test_read_gives_the_file_content(naca_file):
    mesh = dgwarp.read(naca_file)
    assert (mesh.dim, mesh.num_points, mesh.num_cells) == (2, 1656, 3070)
    assert mesh.marker_names == ["airfoil", "farfield"]
    assert mesh.points.shape == (1656, 2) and mesh.points.dtype == np.float64
    assert mesh.cells["triangle"].shape == (3070, 3) and mesh.cells["triangle"].dtype == np.int32
    airfoil = mesh.markers["airfoil"]
    assert airfoil.name == "airfoil" and len(airfoil.nodes) == 200
    assert np.array_equal(airfoil.nodes, np.unique(airfoil.elements["line"]))
    assert mesh.source == str(naca_file)


def test_points_and_cells_are_read_only_views_without_copy(naca_file):
    mesh = dgwarp.read(naca_file)
    a, b = mesh.points, mesh.points
    assert np.shares_memory(a, b)  # both view the mesh's own array
    assert not a.flags.writeable and not a.flags.owndata
    with pytest.raises(ValueError):
        a[0, 0] = 1.0
    assert np.shares_memory(mesh.cells["triangle"], mesh.cells["triangle"])
    del mesh  # the view keeps the mesh alive
    assert np.isfinite(a).all()


def test_mixed_cells_come_by_type_with_their_positions(su2_meshes):
    mesh = dgwarp.read(su2_meshes / "unsteady_square_cylinder_mesh_square_turb_hybrid.su2")
    assert set(mesh.cells) == {"triangle", "quadrilateral"}
    assert sum(len(v) for v in mesh.cells.values()) == mesh.num_cells
    order = np.sort(np.concatenate(list(mesh.cell_index.values())))
    assert np.array_equal(order, np.arange(mesh.num_cells))


def test_from_arrays_round_trips_through_every_format(tmp_path):
    mesh = square_mesh()
    assert mesh.marker_names == ["bottom", "rest"]
    for ext in ("su2", "msh", "vtu"):
        path = tmp_path / f"square.{ext}"
        mesh.write(path)
        back = dgwarp.read(path)
        assert np.array_equal(back.points, mesh.points), ext
        assert np.array_equal(back.cells["triangle"], mesh.cells["triangle"]), ext
        assert np.array_equal(back.markers["rest"].elements["line"], mesh.markers["rest"].elements["line"]), ext


def test_write_with_other_points_and_fields(tmp_path):
    mesh = square_mesh()
    moved = mesh.points + 0.5
    path = tmp_path / "moved.vtu"
    mesh.write(path, points=moved, point_data={"d": moved - mesh.points}, cell_data={"q": [1.0, 2.0]})
    assert np.array_equal(dgwarp.read(path).points, moved)
    assert np.array_equal(mesh.points[0], [0, 0])  # the mesh itself is unchanged


def test_su2_output_keeps_the_other_zones(tmp_path, su2_meshes):
    # SU2's multi-zone pin array: zone 2 read, written back with zone 1 around it.
    source = su2_meshes / "incomp_navierstokes_streamwise_periodic_chtPinArray_3d_3D_chtPinArray_coarse.su2"
    mesh = dgwarp.read(source, zone=2)
    out = tmp_path / "zone2.su2"
    mesh.write(out)
    again = dgwarp.read(out, zone=1)
    assert np.array_equal(again.points, dgwarp.read(source, zone=1).points)
    with pytest.warns(dgwarp.DgwarpWarning, match="holds the mesh only"):
        mesh.write(tmp_path / "zone2.vtu")


def test_cli_reads_what_python_writes(tmp_path, cli):
    path = tmp_path / "square.su2"
    square_mesh().write(path)
    info = cli_json("info", path)["mesh"]
    assert (info["dim"], info["nodes"], info["cells"]) == (2, 4, 2)
    assert [m["name"] for m in info["markers"]] == ["bottom", "rest"]


def test_read_errors_carry_the_library_message(tmp_path):
    with pytest.raises(dgwarp.IoError) as e:
        dgwarp.read(tmp_path / "missing.su2")
    assert isinstance(e.value, OSError) and isinstance(e.value, dgwarp.Error)
    assert e.value.filename == str(tmp_path / "missing.su2")
    assert str(e.value) == f"{tmp_path / 'missing.su2'}: cannot open file for reading: No such file or directory"

    bad = tmp_path / "bad.su2"
    bad.write_text("NDIME= 2\nNELEM= 1\n5 0 1 2 0\nNPOIN= x\n")
    with pytest.raises(dgwarp.ParseError) as e:
        dgwarp.read(bad)
    assert isinstance(e.value, ValueError) and e.value.file == str(bad) and e.value.line > 0
    assert str(e.value).startswith(f"{bad}:")

    with pytest.raises(dgwarp.FormatError, match="obj"):
        dgwarp.read(tmp_path / "mesh.obj")
    with pytest.raises(ValueError, match="zone"):
        dgwarp.read(bad, zone=0)


def test_from_arrays_refuses_bad_input():
    points = np.zeros((3, 2))
    with pytest.raises(dgwarp.MeshError, match="7"):
        dgwarp.Mesh.from_arrays(points, {"triangle": [[0, 1, 7]]})
    with pytest.raises(TypeError, match="integer"):
        dgwarp.Mesh.from_arrays(points, {"triangle": np.array([[0.0, 1.0, 2.0]])})
    with pytest.raises(ValueError, match=r"shape \(n, 3\)"):
        dgwarp.Mesh.from_arrays(points, {"triangle": [[0, 1, 2, 0]]})
    with pytest.raises(ValueError, match="unknown cell type 'tri'"):
        dgwarp.Mesh.from_arrays(points, {"tri": [[0, 1, 2]]})
    with pytest.raises(ValueError, match="finite"):
        dgwarp.Mesh.from_arrays(np.array([[0, 0], [1, np.nan], [0, 1]], dtype=float), {"triangle": [[0, 1, 2]]})
    with pytest.raises(TypeError, match="float64"):
        dgwarp.Mesh.from_arrays(np.zeros((3, 2), dtype=np.float32), {"triangle": [[0, 1, 2]]})
    with pytest.raises(ValueError, match="C-contiguous"):
        dgwarp.Mesh.from_arrays(np.zeros((3, 4))[:, ::2], {"triangle": [[0, 1, 2]]})
    with pytest.raises(ValueError, match=r"\(n, 2\) or \(n, 3\)"):
        dgwarp.Mesh.from_arrays(np.zeros(6), {"triangle": [[0, 1, 2]]})
    with pytest.raises(ValueError, match="cannot tell the element type"):
        dgwarp.Mesh.from_arrays(points, {"triangle": [[0, 1, 2]]}, {"m": np.zeros((1, 3), dtype=int)})


def test_write_refuses_bad_points(tmp_path):
    mesh = square_mesh()
    with pytest.raises(ValueError, match=r"points must have shape \(4, 2\), got \(4, 3\)"):
        mesh.write(tmp_path / "x.vtu", points=np.zeros((4, 3)))
    with pytest.raises(ValueError, match=r"points\[1, 0\] is nan"):
        mesh.write(tmp_path / "x.vtu", points=np.array([[0, 0], [np.nan, 0], [1, 1], [0, 1]]))
    assert not (tmp_path / "x.vtu").exists()


def test_write_refuses_to_overwrite_the_file_the_mesh_was_read_from(tmp_path, naca_file):
    # Issue #27, item 8: as the CLI refuses an output that is its input.
    victim = tmp_path / "victim.su2"
    victim.write_bytes(naca_file.read_bytes())
    mesh = dgwarp.read(victim)
    before = victim.read_bytes()
    with pytest.raises(ValueError, match="the file this mesh was read from.*write to another name"):
        mesh.write(victim, points=mesh.points + 1.0)
    (tmp_path / "link.su2").symlink_to(victim)
    with pytest.raises(ValueError, match="read from"):
        mesh.write(tmp_path / "link.su2")
    assert victim.read_bytes() == before
    mesh.write(tmp_path / "other.su2", points=mesh.points + 1.0)  # another name is fine


def test_write_refuses_fields_a_format_cannot_hold(tmp_path):
    # Issue #27, item 8: .su2 and .msh have no point or cell data; they were dropped silently.
    mesh = square_mesh()
    for ext in ("su2", "msh"):
        with pytest.raises(ValueError, match="only .vtu files hold point and cell data"):
            mesh.write(tmp_path / f"x.{ext}", point_data={"d": np.zeros(4)})
        with pytest.raises(ValueError, match="cell_data: only .vtu"):
            mesh.write(tmp_path / f"x.{ext}", cell_data={"q": np.zeros(2)})
        assert not (tmp_path / f"x.{ext}").exists()
    mesh.write(tmp_path / "x.vtu", point_data={"d": np.zeros(4)}, cell_data={"q": np.zeros(2)})


def test_io_errors_are_the_builtin_oserror_of_their_errno(tmp_path, naca_file):
    # Issue #27, item 15: IoError was no FileNotFoundError and had no errno.
    import errno

    missing = tmp_path / "missing.su2"
    with pytest.raises(FileNotFoundError) as e:
        dgwarp.read(missing)
    assert isinstance(e.value, dgwarp.IoError) and e.value.errno == errno.ENOENT
    assert e.value.strerror == "No such file or directory" and e.value.filename == str(missing)
    assert str(e.value) == f"{missing}: cannot open file for reading: No such file or directory"
    with pytest.raises(FileNotFoundError):
        dgwarp.load_plan(tmp_path / "missing.plan", dgwarp.read(naca_file))
    with pytest.raises(FileNotFoundError) as e:
        square_mesh().write(tmp_path / "no_such_folder" / "x.su2")
    assert e.value.errno == errno.ENOENT
    (tmp_path / "file").write_text("")
    with pytest.raises(NotADirectoryError):
        square_mesh().write(tmp_path / "file" / "x.su2")


OPENFOAM_CASES = pathlib.Path(__file__).resolve().parents[2] / "tests" / "data" / "openfoam"


def test_write_time_writes_what_dgwarp_deform_writes_into_an_openfoam_case(tmp_path, cli):
    case = tmp_path / "mixed"
    shutil.copytree(OPENFOAM_CASES / "mixed", case)
    motion = {"markers": {"top": {"translate": [0, 0, 0.05]}}, "default": "fixed", "shared_nodes": "moving_wins"}
    mesh = dgwarp.read(case)
    moved = dgwarp.prepare(mesh, motion).deform(motion)
    # Into another folder: its constant/polyMesh a copy of the case's, the time's points the frame's.
    written = mesh.write_time(tmp_path / "py", "0.5", moved)
    assert pathlib.Path(written) == tmp_path / "py" / "0.5" / "polyMesh" / "points"
    (tmp_path / "motion.json").write_text(json.dumps(motion))
    cli("deform", case, "-m", tmp_path / "motion.json", "-o", str(tmp_path / "cli") + "/", "--foam-time", "0.5", "-q")
    for name in ["0.5/polyMesh/points", "constant/polyMesh/points", "constant/polyMesh/faces",
                 "constant/polyMesh/owner", "constant/polyMesh/neighbour", "constant/polyMesh/boundary"]:
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name
    # Into the case itself: only the time folder is new.
    mesh.write_time(case, "0.5", moved)
    assert (case / "0.5" / "polyMesh" / "points").read_bytes() == (tmp_path / "cli" / "0.5" / "polyMesh" / "points").read_bytes()
    assert (case / "constant" / "polyMesh" / "points").read_bytes() == (OPENFOAM_CASES / "mixed" / "constant" / "polyMesh" / "points").read_bytes()
    # What it refuses.
    with pytest.raises(ValueError, match="not a time folder's name"):
        mesh.write_time(tmp_path / "py", "later", moved)
    with pytest.raises(dgwarp.InputError, match="constant/polyMesh/points"):
        mesh.write_time(case, "constant", moved)
    flat = dgwarp.Mesh.from_arrays([[0, 0], [1, 0], [0, 1]], {"triangle": [[0, 1, 2]]}, {"wall": [[0, 1]]})
    with pytest.raises(ValueError, match="3D"):
        flat.write_time(tmp_path / "flat", "0", flat.points)
