"""Type stubs of hullkit (PEP 561); the docstrings in __init__.py are the reference."""

import os
from collections.abc import Iterable
from typing import Any, TypedDict, overload

import numpy as np
from numpy.typing import ArrayLike, NDArray
from typing_extensions import NotRequired

from . import _core
from ._core import _DelaunayReport, _Delaunay3Report, _HullDict, _HullReport

__all__ = [
    "HullkitError", "Hull", "hull", "verify", "HullBuilder", "Delaunay", "delaunay", "verify_delaunay",
    "Delaunay3", "delaunay3", "verify_delaunay3", "check_route", "RouteChecker", "read_points", "read_mesh",
    "triangulate", "triangulate_polygon",
]
__version__: str

_Path = str | os.PathLike[str]
_Scene = dict[str, Any] | str | os.PathLike[str]

class HullkitError(ValueError):
    point: int | None
    def __init__(self, message: str, point: int | None = ...) -> None: ...

def as_points(points: ArrayLike, dims: int, what: str = ...) -> NDArray[np.float64]:
    """The points as a C-ordered float64 array of shape (n, dims), or HullkitError."""

class Hull:
    points: NDArray[np.float64]  # (n, 3)
    dimension: int
    triangles: NDArray[np.uint32]  # (m, 3)
    vertices: NDArray[np.uint32]
    volume: float
    area: float
    normal: NDArray[np.float64]  # (3,)
    faces: list[NDArray[np.uint32]] | None
    def __init__(self, result: _HullDict, points: NDArray[np.float64]) -> None: ...

def hull(
    points: ArrayLike, algorithm: str = ..., merge_coplanar: bool = ..., threads: int = ...
) -> Hull: ...
def verify(points: ArrayLike, hull_or_triangles: Hull | ArrayLike) -> _HullReport: ...

class _HullBuilderResult(TypedDict):
    hull: Hull  # over `points`
    points: NDArray[np.float64]  # (k, 3)
    index: NDArray[np.uint64]  # (k,)
    point_count: int

class HullBuilder:
    def __init__(self, algorithm: str = ..., threads: int = ...) -> None: ...
    def add(self, points: ArrayLike, first_index: int = ...) -> None: ...
    def add_indexed(self, points: ArrayLike, indices: ArrayLike) -> None: ...
    def finish(self) -> _HullBuilderResult: ...
    @property
    def points_added(self) -> int: ...

class _LocateResult(TypedDict):
    triangle: NDArray[np.int32]  # (q,), -1 outside
    barycentric: NotRequired[NDArray[np.float64]]  # (q, 3), with barycentric=True
    nearest: NotRequired[NDArray[np.int32]]  # (q,), with nearest=True

class _Locate3Result(TypedDict):
    tetrahedron: NDArray[np.int32]  # (q,), -1 outside
    barycentric: NotRequired[NDArray[np.float64]]  # (q, 4), with barycentric=True
    nearest: NotRequired[NDArray[np.int32]]  # (q,), with nearest=True

class _Voronoi3(TypedDict):
    vertices: NDArray[np.float64]  # (v, 3)
    tetrahedron_vertex: NDArray[np.uint32]  # (m,)
    face_points: NDArray[np.uint32]  # (f, 2)
    face_offsets: NDArray[np.uint32]
    face_vertices: NDArray[np.uint32]
    face_bounded: NDArray[np.uint8]  # (f,) 1 or 0
    cell_offsets: NDArray[np.uint32]
    cell_faces: NDArray[np.uint32]
    volume: NDArray[np.float64]  # (n,)

class Delaunay:
    points: NDArray[np.float64]  # (n, 2)
    dimension: int
    duplicate_count: int
    triangles: NDArray[np.uint32]  # flat, 3 per triangle (read-only)
    halfedges: NDArray[np.int32]
    hull: NDArray[np.uint32]
    representative: NDArray[np.uint32]
    polygons: list[NDArray[np.uint32]] | None  # with merge_cocircular
    def __init__(self, core: _core.Triangulation, points: NDArray[np.float64]) -> None: ...
    @overload
    def find(self, x: float, y: float, start: int = ...) -> int: ...
    @overload
    def find(self, x: ArrayLike, y: None = ..., start: int = ...) -> NDArray[np.int64]: ...
    def locate(
        self, queries: ArrayLike, barycentric: bool = ..., nearest: bool = ..., threads: int = ...
    ) -> _LocateResult: ...
    def voronoi(self, bounds: Iterable[float] | None = ...) -> list[NDArray[np.float64]]:
        """Per point, its cell's corners (k, 2); bounds: (xmin, ymin, xmax, ymax)."""

def delaunay(
    points: ArrayLike, algorithm: str = ..., merge_cocircular: bool = ..., threads: int = ...
) -> Delaunay: ...
def verify_delaunay(points: ArrayLike, triangles: ArrayLike) -> _DelaunayReport: ...

class Delaunay3:
    points: NDArray[np.float64]  # (n, 3)
    dimension: int
    duplicate_count: int
    tetrahedra: NDArray[np.uint32]  # (m, 4) (read-only, as every array here)
    neighbors: NDArray[np.int32]  # (m, 4), or (t, 3) for coplanar points
    hull: NDArray[np.uint32]  # (k, 3)
    triangles: NDArray[np.uint32]  # (t, 3)
    vertices: NDArray[np.uint32]
    representative: NDArray[np.uint32]  # (n,)
    normal: NDArray[np.float64]  # (3,)
    def __init__(self, core: _core.Tetrahedralization, points: NDArray[np.float64]) -> None: ...
    def locate(
        self, queries: ArrayLike, barycentric: bool = ..., nearest: bool = ..., threads: int = ...
    ) -> _Locate3Result: ...
    def voronoi(self) -> _Voronoi3: ...

def delaunay3(points: ArrayLike, threads: int = ..., furthest_site: bool = ...) -> Delaunay3: ...
def verify_delaunay3(points: ArrayLike, tetrahedra: Delaunay3 | ArrayLike, perturbed: bool = ...) -> _Delaunay3Report: ...

class RouteChecker:
    def __init__(self, scene: _Scene) -> None: ...
    def check(
        self,
        route: ArrayLike | None = ...,
        clearance: bool = ...,
        samples: int = ...,
        threads: int = ...,
        rotations: ArrayLike | None = ...,
    ) -> dict[str, Any]:
        """The report in `hullkit route`'s JSON format (clear, min_clearance, legs, ...)."""
    @property
    def build_seconds(self) -> float: ...

def check_route(scene: _Scene, clearance: bool = ..., samples: int = ..., threads: int = ...) -> dict[str, Any]: ...
def read_points(path: _Path, threads: int = ...) -> NDArray[np.float64]: ...
def read_mesh(path: _Path) -> tuple[NDArray[np.float64], NDArray[np.uint32]]: ...

from .constrained import triangulate as triangulate, triangulate_polygon as triangulate_polygon
