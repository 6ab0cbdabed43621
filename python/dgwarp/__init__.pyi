# Type hints of the dgwarp package (docs/PYTHON.md has the whole API).
# Conventions: points are (num_points, dim) float64, row-major, dim 2 or 3; node ids are
# 0-based int32; per-cell arrays are in the mesh's cell order; per-boundary-node arrays are in
# Plan.boundary_nodes order.
import os
import pathlib
from typing import Any, Callable, Literal, Mapping, Sequence, Union

import numpy as np
import numpy.typing as npt

__all__: list[str]
__version__: str  # the project's version, as `dgwarp --version` prints it

Path = Union[str, os.PathLike[str]]
FloatArray = npt.NDArray[np.float64]
IdArray = npt.NDArray[np.int32]
Progress = Callable[[float], object]
MethodName = Literal["dg-idw", "dgm", "idw", "rbf", "dg-harmonic"]
CellTypeName = Literal["vertex", "line", "triangle", "quadrilateral", "tetrahedron", "hexahedron", "prism", "pyramid"]
Elements = Union[Mapping[str, npt.ArrayLike], Sequence[tuple[str, npt.ArrayLike]], npt.ArrayLike]
MotionLike = Union["Motion", Mapping[str, Any]]

class Error(Exception):
    """Base of every error dgwarp's library raises."""

class IoError(Error, OSError):
    filename: str
    errno: int | None
    strerror: str | None

class ParseError(Error, ValueError):
    file: str
    line: int
    expected: str
    found: str

class MeshError(Error, ValueError):
    marker: str
    index: int

class FormatError(Error, ValueError): ...

class InvalidResultError(Error, ValueError):
    count: int

class InputError(Error, ValueError): ...

class DgwarpWarning(UserWarning): ...

class Marker:
    @property
    def name(self) -> str: ...
    @property
    def nodes(self) -> IdArray: ...
    @property
    def elements(self) -> dict[str, IdArray]: ...

class Mesh:
    @staticmethod
    def point_cloud(points: npt.ArrayLike, markers: Mapping[str, npt.ArrayLike]) -> Mesh: ...
    def __getstate__(self) -> tuple[Any, ...]: ...
    def __setstate__(self, state: tuple[Any, ...]) -> None: ...
    @property
    def dim(self) -> int: ...
    @property
    def num_points(self) -> int: ...
    @property
    def num_cells(self) -> int: ...
    @property
    def points(self) -> FloatArray:
        """(num_points, dim) read-only view of the mesh's coordinates (no copy)."""
    @property
    def cells(self) -> dict[str, IdArray]: ...
    @property
    def cell_index(self) -> dict[str, npt.NDArray[np.int64]]: ...
    @property
    def markers(self) -> dict[str, Marker]: ...
    @property
    def marker_names(self) -> list[str]: ...
    @property
    def source(self) -> str: ...
    @staticmethod
    def from_arrays(points: npt.ArrayLike, cells: Elements, markers: Mapping[str, Elements] | None = None) -> Mesh: ...
    def write(
        self,
        path: Path,
        points: npt.ArrayLike | None = None,
        point_data: Mapping[str, npt.ArrayLike] | None = None,
        cell_data: Mapping[str, npt.ArrayLike] | None = None,
        gmsh_version: Literal[41, 22] = 41,
    ) -> None: ...
    def write_time(self, case: Path, time: str, points: npt.ArrayLike) -> pathlib.Path: ...

class Quality:
    @property
    def cells(self) -> FloatArray: ...
    @property
    def min(self) -> float: ...
    @property
    def mean(self) -> float: ...
    @property
    def inverted(self) -> int: ...
    @property
    def worst_cell(self) -> int: ...
    @property
    def histogram(self) -> tuple[FloatArray, npt.NDArray[np.int64]]: ...
    @property
    def ratio(self) -> FloatArray | None: ...
    @property
    def ratio_min(self) -> float | None: ...
    @property
    def ratio_mean(self) -> float | None: ...
    @property
    def ratio_worst_cell(self) -> int | None: ...

class Motion:
    def __init__(self, source: Mapping[str, Any] | Path | Motion) -> None: ...
    @property
    def frames(self) -> int: ...
    def __len__(self) -> int: ...
    def time(self, frame: int) -> float: ...
    @property
    def markers(self) -> list[str]: ...
    @property
    def shared_nodes(self) -> Literal["moving_wins", "static_wins"]: ...
    @property
    def source(self) -> str: ...

class Plan:
    def deform(
        self,
        motion: MotionLike | npt.ArrayLike | None = None,
        *,
        frame: int = 0,
        translation: npt.ArrayLike | None = None,
        rotation: npt.ArrayLike | None = None,
        center: npt.ArrayLike | None = None,
        out: FloatArray | None = None,
        untangle: bool | None = None,
        untangle_target: float = 0.0,
        progress: Progress | None = None,
    ) -> FloatArray: ...
    def deform_derivative(self, direction: npt.ArrayLike, *, out: FloatArray | None = None) -> FloatArray: ...
    def deform_derivative_transpose(self, weights: npt.ArrayLike, *, out: FloatArray | None = None) -> FloatArray: ...
    def __getstate__(self) -> tuple[Any, ...]: ...
    def __setstate__(self, state: tuple[Any, ...]) -> None: ...
    def save(self, path: Path) -> None: ...
    @property
    def method(self) -> MethodName: ...
    @property
    def options(self) -> dict[str, Any]: ...
    @property
    def mesh(self) -> Mesh: ...
    @property
    def boundary_nodes(self) -> IdArray: ...
    @property
    def moving(self) -> npt.NDArray[np.bool_]: ...
    @property
    def boundary_points(self) -> FloatArray: ...
    @property
    def moving_markers(self) -> list[str]: ...
    @property
    def static_markers(self) -> list[str]: ...
    @property
    def sliding_markers(self) -> list[str]: ...
    @property
    def cyclic_markers(self) -> list[str]: ...
    @property
    def shared_nodes(self) -> Literal["moving_wins", "static_wins"]: ...
    @property
    def memory_bytes(self) -> int: ...
    @property
    def summary(self) -> dict[str, Any]: ...

def read(path: Path, zone: int | None = None, progress: Progress | None = None) -> Mesh: ...
def quality(mesh: Mesh, points: npt.ArrayLike | None = None, reference: Mesh | None = None) -> Quality: ...
def prepare(
    mesh: Mesh,
    moving: str | Sequence[str] | MotionLike,
    static: Sequence[str] | None = None,
    method: MethodName = "dg-harmonic",
    *,
    shared_nodes: Literal["moving_wins", "static_wins"] = "moving_wins",
    shared_tolerance: float = 0.0,
    progress: Progress | None = None,
    comm: Any | None = None,
    global_ids: npt.ArrayLike | None = None,
    a_translation: float = ...,
    a_rotation: float = ...,
    length_scale: float | Literal["auto"] = ...,
    dg_idw_weights: Literal["paper", "continuous"] = ...,
    dgm_substep: bool = ...,
    idw_moving_exponent: float = ...,
    idw_static_exponent: float = ...,
    rbf_radius: float = ...,
    rbf_greedy: float = ...,
    harmonic_wall_spacing: float = ...,
    harmonic_growth: float = ...,
    harmonic_redo_below: float = ...,
    laplacian_increments: int = ...,
    laplacian_exponent: float = ...,
    laplacian_model: str = ...,
) -> Plan: ...
def load_plan(
    path: Path,
    mesh: Mesh,
    moving: str | Sequence[str] | MotionLike | None = None,
    static: Sequence[str] | None = None,
    *,
    shared_nodes: Literal["moving_wins", "static_wins"] = "moving_wins",
    shared_tolerance: float = 0.0,
    comm: Any | None = None,
    global_ids: npt.ArrayLike | None = None,
) -> Plan: ...
def case(name: str, size: int = 0) -> Mesh: ...
def case_names() -> list[str]: ...
def num_threads() -> int: ...
def set_num_threads(n: int) -> None: ...
def untangle(mesh: Mesh, points: FloatArray, fixed: npt.ArrayLike | None = None, target: float = 0.0) -> dict[str, Any]: ...
def to_meshio(
    mesh: Mesh,
    points: npt.ArrayLike | None = None,
    point_data: Mapping[str, npt.ArrayLike] | None = None,
    cell_data: Mapping[str, npt.ArrayLike] | None = None,
) -> Any: ...
def from_meshio(m: Any) -> Mesh: ...
