"""dgwarp: deform CFD volume meshes to follow their moving boundaries.

A NumPy interface to dgwarp's C++ library (docs/PYTHON.md)::

    import dgwarp
    mesh = dgwarp.read("naca0012.su2")
    plan = dgwarp.prepare(mesh, moving=["airfoil"])
    points = plan.deform({"markers": {"airfoil": {"rotate": {"angle_deg": 5, "center": [0.25, 0]}}}})
    mesh.write("turned.vtu", points=points)
"""

from ._core import __version__
from ._core import (
    DgwarpWarning,
    Error,
    FormatError,
    InputError,
    InvalidResultError,
    IoError,
    Marker,
    Mesh,
    MeshError,
    Motion,
    ParseError,
    Plan,
    Quality,
    case,
    case_names,
    load_plan,
    num_threads,
    prepare,
    quality,
    read,
    set_num_threads,
    untangle,
)
from ._meshio import from_meshio, to_meshio

__all__ = [
    "DgwarpWarning",
    "Error",
    "FormatError",
    "InputError",
    "InvalidResultError",
    "IoError",
    "Marker",
    "Mesh",
    "MeshError",
    "Motion",
    "ParseError",
    "Plan",
    "Quality",
    "case",
    "case_names",
    "from_meshio",
    "load_plan",
    "num_threads",
    "prepare",
    "quality",
    "read",
    "set_num_threads",
    "to_meshio",
    "untangle",
]
