"""to_meshio / from_meshio (Debian's python3-meshio)."""

import numpy as np
import pytest

import dgwarp

meshio = pytest.importorskip("meshio")


def test_round_trip_keeps_cells_markers_and_order(su2_meshes):
    mesh = dgwarp.read(su2_meshes / "unsteady_square_cylinder_mesh_square_turb_hybrid.su2")  # triangles and quads
    m = dgwarp.to_meshio(mesh, cell_data={"q": dgwarp.quality(mesh).cells})
    assert set(m.cell_sets) == set(mesh.marker_names)
    back = dgwarp.from_meshio(m)
    assert np.array_equal(back.points, mesh.points)
    for t in mesh.cells:
        assert np.array_equal(back.cells[t], mesh.cells[t])
        assert np.array_equal(back.cell_index[t], mesh.cell_index[t])  # the cell order is kept
    for name, marker in mesh.markers.items():
        assert np.array_equal(back.markers[name].nodes, marker.nodes)
    # cell data follows the cells: the volume blocks in cell order
    volume = [b for b in m.cells if b.type in ("triangle", "quad")]
    q = np.concatenate(m.cell_data["q"][: len(volume)])
    assert np.array_equal(q, dgwarp.quality(mesh).cells)


def test_deformed_points_through_meshio_files(tmp_path, naca_file):
    mesh = dgwarp.read(naca_file)
    points = dgwarp.prepare(mesh, moving=["airfoil"]).deform(translation=[0.01, 0.02])
    path = tmp_path / "moved.vtu"
    dgwarp.to_meshio(mesh, points=points).write(path)
    assert np.array_equal(meshio.read(path).points[:, :2], points)
    # Gmsh's physical groups become markers.
    msh = tmp_path / "naca.msh"
    mesh.write(msh)
    back = dgwarp.from_meshio(meshio.read(msh))
    assert back.marker_names == mesh.marker_names and back.dim == 2
    assert np.array_equal(back.markers["airfoil"].nodes, mesh.markers["airfoil"].nodes)


def test_unsupported_cells_are_refused():
    m = meshio.Mesh(np.zeros((6, 2)), [("triangle6", np.arange(6).reshape(1, 6))])
    with pytest.raises(ValueError, match="triangle6"):
        dgwarp.from_meshio(m)


def test_3d_points_that_are_not_contiguous(tmp_path, su2_meshes):
    # Issue #27, item 12: meshio's Gmsh 2.2 reader gives points as columns of a wider table;
    # only 2D meshes were made contiguous.
    mesh = dgwarp.read(su2_meshes / "deformation_brick_tets_mesh_brick_tets_ffd.su2")
    m = dgwarp.to_meshio(mesh)
    table = np.zeros((mesh.num_points, 4))
    table[:, :3] = mesh.points
    m.points = table[:, :3]
    assert not m.points.flags.c_contiguous
    back = dgwarp.from_meshio(m)
    assert back.dim == 3 and np.array_equal(back.points, mesh.points)
    assert back.marker_names == mesh.marker_names
    # And through meshio's own Gmsh 2.2 reader.
    path = tmp_path / "brick.msh"
    with pytest.warns(dgwarp.DgwarpWarning):  # the SU2 file's FFD box and periodic data stay behind
        mesh.write(path, gmsh_version=22)
    back = dgwarp.from_meshio(meshio.read(path))
    assert np.array_equal(back.points, mesh.points) and set(back.marker_names) == set(mesh.marker_names)
