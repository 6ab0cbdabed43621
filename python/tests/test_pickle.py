"""Meshes and plans pickle (docs/PYTHON.md, "Pickling"): what is unpickled writes and deforms to
the same bits, and carries what a process pool needs."""

import concurrent.futures
import multiprocessing
import pickle

import numpy as np
import pytest

import dgwarp

TURN = {"markers": {"airfoil": {"rotate": {"angle_deg": 7, "center": [0.25, 0]}}}}


def same_mesh(a, b):
    assert (a.dim, a.num_points, a.num_cells, a.source) == (b.dim, b.num_points, b.num_cells, b.source)
    assert np.array_equal(a.points, b.points)
    assert a.cells.keys() == b.cells.keys()
    for t in a.cells:
        assert np.array_equal(a.cells[t], b.cells[t])
    assert a.marker_names == b.marker_names
    for name in a.marker_names:
        assert np.array_equal(a.markers[name].nodes, b.markers[name].nodes)


def test_a_mesh_pickles_with_what_its_file_held_besides_it(tmp_path, su2_meshes):
    # An SU2 file with an FFD box: the unpickled mesh writes it back byte for byte, as the original does.
    mesh = dgwarp.read(su2_meshes / "deformation_brick_hex_mesh_brick_hex_ffd.su2")
    copy = pickle.loads(pickle.dumps(mesh))
    same_mesh(mesh, copy)
    mesh.write(tmp_path / "a.su2")
    copy.write(tmp_path / "b.su2")
    assert (tmp_path / "a.su2").read_bytes() == (tmp_path / "b.su2").read_bytes()
    assert b"FFD_NBOX" in (tmp_path / "b.su2").read_bytes()


def test_an_openfoam_mesh_pickles_with_its_patches(tmp_path, su2_meshes, cli):
    cli("convert", su2_meshes / "deformation_brick_tets_mesh_brick_tets_ffd.su2", tmp_path / "case")
    mesh = dgwarp.read(tmp_path / "case")
    copy = pickle.loads(pickle.dumps(mesh, protocol=pickle.HIGHEST_PROTOCOL))
    same_mesh(mesh, copy)
    mesh.write(tmp_path / "a")  # a whole polyMesh with the patches' types and entries
    copy.write(tmp_path / "b")
    for name in ("points", "faces", "owner", "neighbour", "boundary"):
        a = (tmp_path / "a" / "constant" / "polyMesh" / name).read_bytes()
        assert a == (tmp_path / "b" / "constant" / "polyMesh" / name).read_bytes(), name


def test_a_mesh_from_arrays_pickles():
    points = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=np.float64)
    mesh = dgwarp.Mesh.from_arrays(points, {"triangle": [[0, 1, 2], [0, 2, 3]]}, {"sides": [[0, 1], [1, 2], [2, 3], [3, 0]]})
    same_mesh(mesh, pickle.loads(pickle.dumps(mesh)))


@pytest.mark.parametrize("method", ["dg-harmonic", "dg-idw", "dgm", "idw", "rbf", "laplacian"])
def test_a_plan_pickles_and_deforms_to_the_same_bits(naca_file, method):
    mesh = dgwarp.read(naca_file)
    options = {"harmonic_redo_below": 0.5} if method == "dg-harmonic" else {}
    plan = dgwarp.prepare(mesh, ["airfoil"], method=method, **options)
    copy = pickle.loads(pickle.dumps(plan))
    assert (copy.method, copy.options, copy.moving_markers, copy.static_markers) == (
        plan.method, plan.options, plan.moving_markers, plan.static_markers)
    same_mesh(plan.mesh, copy.mesh)
    assert np.array_equal(plan.deform(TURN), copy.deform(TURN))


def test_a_plan_keeps_its_classification_and_shared_node_rule(naca_file):
    mesh = dgwarp.read(naca_file)
    plan = dgwarp.prepare(mesh, ["airfoil"], ["farfield"], method="dg-idw", shared_nodes="static_wins",
                          shared_tolerance=1e-6, a_translation=5.0)
    copy = pickle.loads(pickle.dumps(plan))
    assert (copy.shared_nodes, copy.options["a_translation"]) == ("static_wins", 5.0)
    motion = dict(TURN, shared_nodes="static_wins")
    assert np.array_equal(plan.deform(motion), copy.deform(motion))


def test_a_damaged_pickle_is_refused(naca_file):
    plan = dgwarp.prepare(dgwarp.read(naca_file), ["airfoil"], method="dg-idw")
    state = list(plan.__getstate__())
    damaged = bytearray(state[9])  # the plan file's bytes
    damaged[len(damaged) // 2] ^= 0xFF
    state[9] = bytes(damaged)
    with pytest.raises(dgwarp.ParseError, match="checksum"):
        dgwarp.Plan.__new__(dgwarp.Plan).__setstate__(tuple(state))
    with pytest.raises(ValueError, match="not the pickled state of a dgwarp.Plan"):
        dgwarp.Plan.__new__(dgwarp.Plan).__setstate__(("something else",))
    older = list(plan.__getstate__())[:10]  # version 1 had no sliding or cyclic markers
    older[1] = 1
    with pytest.raises(ValueError, match=r"pickled by another version of dgwarp \(state version 1, this one reads 2\)"):
        dgwarp.Plan.__new__(dgwarp.Plan).__setstate__(tuple(older))
    mesh_state = list(plan.mesh.__getstate__())
    mesh_state[3] = mesh_state[3][:-8]  # a point short
    with pytest.raises(ValueError, match="points are not whole rows"):
        dgwarp.Mesh.__new__(dgwarp.Mesh).__setstate__(tuple(mesh_state))
    mesh_state = list(plan.mesh.__getstate__())
    mesh_state[3] = mesh_state[3][:-16]  # a node short: cells name a node the mesh does not have
    with pytest.raises(dgwarp.MeshError):
        dgwarp.Mesh.__new__(dgwarp.Mesh).__setstate__(tuple(mesh_state))


def _deform_in_child(plan, motion):
    return plan.deform(motion)


def test_a_process_pool_deforms_with_a_pickled_plan(naca_file):
    plan = dgwarp.prepare(dgwarp.read(naca_file), ["airfoil"])
    motions = [{"markers": {"airfoil": {"rotate": {"angle_deg": a, "center": [0.25, 0]}}}} for a in (3, 6)]
    with concurrent.futures.ProcessPoolExecutor(2, mp_context=multiprocessing.get_context("spawn")) as pool:
        results = list(pool.map(_deform_in_child, [plan, plan], motions))
    for motion, result in zip(motions, results):
        assert np.array_equal(result, plan.deform(motion))


def test_polyhedra_come_as_face_lists_pickle_and_build_back(tmp_path):
    # snappyHexMesh's sphere in a box (tests/data/openfoam): its polyhedra come as lists of
    # face arrays (pointing out of the cell), and a mesh built from them is the same mesh.
    import pathlib
    case = pathlib.Path(__file__).resolve().parents[2] / "tests" / "data" / "openfoam" / "snappy-sphere"
    mesh = dgwarp.read(case)
    assert len(mesh.cells["polyhedron"]) == 272 and mesh.cells["hexahedron"].shape == (576, 8)
    first = mesh.cells["polyhedron"][0]
    assert len(first) >= 4 and all(len(face) >= 3 for face in first)
    copy = pickle.loads(pickle.dumps(mesh))
    assert copy.cells.keys() == mesh.cells.keys()
    assert all(len(a) == len(b) and all(np.array_equal(f, g) for f, g in zip(a, b))
               for a, b in zip(copy.cells["polyhedron"], mesh.cells["polyhedron"]))
    built = dgwarp.Mesh.from_arrays(mesh.points, {"polyhedron": mesh.cells["polyhedron"]}, {})
    built.write(tmp_path / "p.vtu")
    again = dgwarp.read(tmp_path / "p.vtu")
    assert all(len(a) == len(b) and all(np.array_equal(f, g) for f, g in zip(a, b))
               for a, b in zip(again.cells["polyhedron"], mesh.cells["polyhedron"]))
