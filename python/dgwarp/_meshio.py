"""Conversion to and from meshio (Debian's python3-meshio), imported only when called.

dgwarp's cell types and meshio's have the same node order (VTK's); the names differ:
quadrilateral/quad, tetrahedron/tetra, prism/wedge. Markers travel as meshio's
cell_sets over blocks of boundary elements.
"""

import numpy as np

_TO_MESHIO = {
    "vertex": "vertex",
    "line": "line",
    "triangle": "triangle",
    "quadrilateral": "quad",
    "tetrahedron": "tetra",
    "hexahedron": "hexahedron",
    "prism": "wedge",
    "pyramid": "pyramid",
}
_FROM_MESHIO = {v: k for k, v in _TO_MESHIO.items()}
_DIMENSION = {"vertex": 0, "line": 1, "triangle": 2, "quad": 2, "tetra": 3, "hexahedron": 3, "wedge": 3, "pyramid": 3}


def _import_meshio():
    try:
        import meshio
    except ImportError as e:  # pragma: no cover - depends on the machine
        raise ImportError("dgwarp.to_meshio / from_meshio need meshio (Debian: apt install python3-meshio)") from e
    return meshio


def _cell_runs(mesh):
    """The mesh's cells as runs of one type, in cell order: [(dgwarp type, (n, k) array, first cell)]."""
    cells = mesh.cells
    if len(cells) <= 1:
        return [(t, a, 0) for t, a in cells.items()]
    index = mesh.cell_index
    code = np.empty(mesh.num_cells, dtype=np.int64)
    rank = np.empty(mesh.num_cells, dtype=np.int64)
    names = list(index)
    for i, name in enumerate(names):
        code[index[name]] = i
        rank[index[name]] = np.arange(len(index[name]))
    starts = np.flatnonzero(np.r_[True, code[1:] != code[:-1]])
    ends = np.r_[starts[1:], mesh.num_cells]
    return [(names[code[s]], cells[names[code[s]]][rank[s]:rank[s] + (e - s)], int(s)) for s, e in zip(starts, ends)]


def to_meshio(mesh, points=None, point_data=None, cell_data=None):
    """A meshio.Mesh of `mesh` (with `points` instead of its own, e.g. deformed ones).

    Volume cells come first, one block per run of one cell type (so cell order is kept), then one
    block per marker and element type; `cell_sets[marker]` selects a marker's elements.
    point_data: {name: (num_points, ...) array}; cell_data: {name: (num_cells, ...) array} for the
    volume cells (NaN on the markers' blocks).
    """
    from . import Mesh

    if not isinstance(mesh, Mesh):
        raise TypeError(f"to_meshio: mesh must be a dgwarp.Mesh, got {type(mesh).__name__}")
    meshio = _import_meshio()
    for name, value in (("point_data", point_data), ("cell_data", cell_data)):
        if value is not None and not isinstance(value, dict):
            raise TypeError(f"to_meshio: {name} must be a dict {{name: array}}, got {type(value).__name__}")
    try:
        xs = mesh.points if points is None else np.asarray(points, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise TypeError(f"points must be an array of numbers, got {type(points).__name__} ({e})") from None
    if xs.shape != mesh.points.shape:
        raise ValueError(f"points must have shape {mesh.points.shape}, got {xs.shape}")
    if not np.isfinite(xs).all():
        bad = tuple(int(i) for i in np.argwhere(~np.isfinite(xs))[0])
        raise ValueError(f"points[{bad[0]}, {bad[1]}] is {xs[bad]}; every value must be finite")
    runs = _cell_runs(mesh)
    blocks = [(_TO_MESHIO[t], np.array(a)) for t, a, _ in runs]
    volume_blocks = len(blocks)
    marker_blocks = {}
    for name, marker in mesh.markers.items():
        for t, a in marker.elements.items():
            marker_blocks.setdefault(name, []).append(len(blocks))
            blocks.append((_TO_MESHIO[t], np.array(a)))
    cell_sets = {}
    for name, own in marker_blocks.items():
        cell_sets[name] = [np.arange(len(b[1])) if i in own else np.empty(0, dtype=np.int64)
                           for i, b in enumerate(blocks)]
    meshio_cell_data = {}
    for name, values in (cell_data or {}).items():
        values = np.asarray(values)
        if values.ndim == 0 or values.shape[0] != mesh.num_cells:
            raise ValueError(f"cell_data['{name}'] must have {mesh.num_cells} rows, got shape {values.shape}")
        per_block = [values[s:s + len(a)] for (_, a, s) in runs]
        for i in range(volume_blocks, len(blocks)):
            per_block.append(np.full((len(blocks[i][1]),) + values.shape[1:], np.nan))
        meshio_cell_data[name] = per_block
    return meshio.Mesh(np.array(xs), blocks, point_data=dict(point_data or {}), cell_data=meshio_cell_data,
                       cell_sets=cell_sets)


def from_meshio(m):
    """A dgwarp.Mesh from a meshio.Mesh (copied).

    The mesh's dimension is that of its highest-dimensional cells (2D meshes stored with a zero z
    column are taken as 2D). Lower-dimensional blocks become markers when meshio names them:
    through cell_sets, or through Gmsh's physical groups ("gmsh:physical" cell data and field_data).
    """
    from . import Mesh

    if not (hasattr(m, "points") and hasattr(m, "cells")):
        raise TypeError(f"from_meshio: m must be a meshio.Mesh, got {type(m).__name__}")
    blocks = [(b.type, np.asarray(b.data)) for b in m.cells]
    for t, _ in blocks:
        if t not in _FROM_MESHIO:
            raise ValueError(f"meshio cell type '{t}' is not supported by dgwarp "
                             f"(it takes {', '.join(sorted(_FROM_MESHIO))}: linear cells only)")
    dim = max((_DIMENSION[t] for t, _ in blocks), default=0)
    if dim not in (2, 3):
        raise ValueError("the meshio mesh has no 2D or 3D cells")
    points = np.asarray(m.points, dtype=np.float64)
    if points.ndim != 2 or points.shape[1] not in (2, 3):
        raise ValueError(f"the meshio mesh's points must have shape (n, 2) or (n, 3), got {points.shape}")
    if dim == 2 and points.shape[1] == 3:
        if np.any(points[:, 2] != 0):
            raise ValueError("a mesh of 2D cells with non-zero z coordinates (a surface in 3D) is not a volume mesh")
        points = points[:, :2]
    # meshio's arrays may be views (its Gmsh 2.2 reader's points are columns of a wider
    # table): dgwarp takes C-contiguous float64 only, so a copy here (the mesh copies anyway).
    points = np.ascontiguousarray(points)
    cells = [(_FROM_MESHIO[t], a) for t, a in blocks if _DIMENSION[t] == dim]
    markers = {}

    def add(name, t, elements):
        if len(elements):
            markers.setdefault(name, []).append((_FROM_MESHIO[t], elements))

    for name, per_block in (m.cell_sets or {}).items():
        if name.startswith("gmsh:"):
            continue
        for (t, a), ids in zip(blocks, per_block):
            if _DIMENSION[t] == dim - 1 and ids is not None:
                add(name, t, a[np.asarray(ids, dtype=np.int64)])
    physical = (m.cell_data or {}).get("gmsh:physical")
    if physical is not None and not markers:
        names = {(int(v[1]), int(v[0])): k for k, v in (m.field_data or {}).items() if len(v) >= 2}
        for (t, a), tags in zip(blocks, physical):
            if _DIMENSION[t] != dim - 1:
                continue
            tags = np.asarray(tags)
            for tag in np.unique(tags):
                add(names.get((dim - 1, int(tag)), f"physical_{int(tag)}"), t, a[tags == tag])
    return Mesh.from_arrays(points, cells, markers)
