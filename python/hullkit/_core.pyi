"""hullkit's C++ core (pybind11; python/src/core.cpp). Private: use the hullkit package.

Arrays in are float64 (C order) unless named otherwise; arrays out own the core's memory."""

from typing import TypedDict

import numpy as np
from numpy.typing import NDArray

# The dicts the core returns (the public functions that return them as they are share the types).

class _HullDict(TypedDict):
    dimension: int
    triangles: NDArray[np.uint32]  # flat, 3 per triangle
    vertices: NDArray[np.uint32]
    face_offsets: NDArray[np.uint32]
    face_vertices: NDArray[np.uint32]
    normal: tuple[float, float, float]
    volume: float
    area: float

class _HullReport(TypedDict):
    ok: bool
    problems: list[str]
    problem_count: int
    notes: list[str]
    checked_points: int
    triangle_count: int
    vertex_count: int
    face_count: int
    dimension: int

class _DelaunayReport(TypedDict):
    ok: bool
    problems: list[str]
    problem_count: int
    distinct_points: int
    hull_points: int

class _Delaunay3Report(TypedDict):
    ok: bool
    problems: list[str]
    problem_count: int
    distinct_points: int
    hull_triangles: int

class _PartialHull(TypedDict):
    point_count: int
    points: NDArray[np.float64]  # (k, 3): the hull's vertices
    index: NDArray[np.uint64]  # (k,)

class _StreamedHullDict(_PartialHull):
    hull: _HullDict

class CoreError(ValueError):
    """args: (message, index of the point or query to blame, or -1)."""

def hull(
    points: NDArray[np.float64], algorithm: str = ..., merge_coplanar: bool = ..., threads: int = ...
) -> _HullDict: ...
def verify_triangles(points: NDArray[np.float64], triangles: NDArray[np.uint32], /) -> _HullReport: ...
def surface_extras(
    points: NDArray[np.float64], triangles: NDArray[np.uint32], /
) -> tuple[NDArray[np.int32], NDArray[np.float64]]: ...
def nested_lists(
    flat: NDArray[np.int64], offsets: NDArray[np.int64], rows: NDArray[np.int64], leading_empty: bool, /
) -> list[list[int]]: ...
def constrained(
    points: NDArray[np.float64],
    segments: NDArray[np.uint32],
    ring_starts: object,
    fill: str,
    convex: bool,
    holes: NDArray[np.float64],
    regions: NDArray[np.float64],
    min_angle: float,
    max_area: float,
    conforming: bool,
    max_steiner_points: int,
    keep_segments: int,
    unsuitable: object,
    mesh: object,
    mesh_areas: object,
    /,
) -> tuple[
    NDArray[np.float64],
    NDArray[np.uint32],
    NDArray[np.int32],
    NDArray[np.uint8],
    NDArray[np.uint32],
    int,
    int,
    int,
    NDArray[np.int32],
]: ...
def furthest_delaunay(
    points: NDArray[np.float64], hull: NDArray[np.uint32], /
) -> tuple[NDArray[np.int32], NDArray[np.int32], NDArray[np.int32], NDArray[np.float64], NDArray[np.int32]]: ...
def facet_sides(
    points: NDArray[np.float64], facets: NDArray[np.uint32], queries: NDArray[np.float64], /
) -> NDArray[np.int8]: ...
def facet_holding(
    points: NDArray[np.float64], facets: NDArray[np.uint32], queries: NDArray[np.float64], /
) -> NDArray[np.int32]: ...
def verify_hull(points: NDArray[np.float64], result: _HullDict, /) -> _HullReport: ...
def verify_delaunay(points: NDArray[np.float64], triangles: NDArray[np.uint32], /) -> _DelaunayReport: ...
def verify_delaunay3(
    points: NDArray[np.float64], tetrahedra: NDArray[np.uint32], perturbed: bool = ...
) -> _Delaunay3Report: ...
def hull_nd(
    points: NDArray[np.float64], /
) -> tuple[NDArray[np.int32], NDArray[np.int32], NDArray[np.int32], NDArray[np.int32]]: ...
def orient_nd(rows: NDArray[np.float64], /) -> int: ...
def read_points(path: str, threads: int = ...) -> NDArray[np.float64]: ...
def read_mesh(data: bytes, source: str, /) -> tuple[NDArray[np.float64], NDArray[np.uint32]]: ...
def json_rows_float64(array: NDArray[np.float64], /) -> str: ...
def json_rows_int64(array: NDArray[np.int64], /) -> str: ...
def hull_file(path: str, threads: int = ...) -> _PartialHull: ...

class HullBuilder:
    def __init__(self, algorithm: str = ..., threads: int = ...) -> None: ...
    def add(self, points: NDArray[np.float64], first_index: int, /) -> None: ...
    def add_indexed(self, points: NDArray[np.float64], indices: NDArray[np.uint64], /) -> None: ...
    def finish(self) -> _StreamedHullDict: ...
    @property
    def points_added(self) -> int: ...

class Triangulation:
    def __init__(
        self, points: NDArray[np.float64], algorithm: str, merge_cocircular: bool, threads: int, /
    ) -> None: ...
    @property
    def dimension(self) -> int: ...
    @property
    def triangles(self) -> NDArray[np.uint32]: ...
    @property
    def halfedges(self) -> NDArray[np.int32]: ...
    @property
    def hull(self) -> NDArray[np.uint32]: ...
    @property
    def representative(self) -> NDArray[np.uint32]: ...
    @property
    def polygon_offsets(self) -> NDArray[np.uint32]: ...
    @property
    def polygon_vertices(self) -> NDArray[np.uint32]: ...
    @property
    def duplicate_count(self) -> int: ...
    def find(self, queries: NDArray[np.float64], start: int, /) -> NDArray[np.int64]: ...
    def locate(
        self, queries: NDArray[np.float64], barycentric: bool = ..., nearest: bool = ..., threads: int = ...
    ) -> tuple[NDArray[np.int32], NDArray[np.float64] | None, NDArray[np.int32] | None]: ...
    def scipy_arrays(self) -> tuple[NDArray[np.int32], NDArray[np.int32]]: ...
    def interpolate(
        self, queries: NDArray[np.float64], values: NDArray[np.float64], threads: int, /
    ) -> tuple[NDArray[np.int32], NDArray[np.float64]]:
        """(triangle (q,), values (q, k), NaN outside the hull)."""
    def clough_tocher(
        self, queries: NDArray[np.float64], values: NDArray[np.float64], gradients: NDArray[np.float64], threads: int, /
    ) -> tuple[NDArray[np.int32], NDArray[np.float64]]:
        """(triangle (q,), the patches' values (q, k), NaN outside the hull); gradients (n, k, 2)."""
    def gradients(
        self, values: NDArray[np.float64], tolerance: float, max_iterations: int, /
    ) -> tuple[NDArray[np.float64], int, bool]:
        """(gradients (n, k, 2), sweeps, converged)."""
    def scipy_voronoi(self, infinity_region: bool, /) -> tuple[
        NDArray[np.float64],
        NDArray[np.int32],
        NDArray[np.int32],
        NDArray[np.int32],
        NDArray[np.int64],
        NDArray[np.intp],
        NDArray[np.float64],
    ]: ...
    def voronoi(
        self, xmin: float, ymin: float, xmax: float, ymax: float, /
    ) -> tuple[NDArray[np.uint32], NDArray[np.float64]]: ...

class Tetrahedralization:
    def __init__(self, points: NDArray[np.float64], threads: int = ..., furthest_site: bool = ...) -> None: ...
    @property
    def dimension(self) -> int: ...
    @property
    def tetrahedra(self) -> NDArray[np.uint32]: ...
    @property
    def neighbors(self) -> NDArray[np.int32]: ...
    @property
    def hull(self) -> NDArray[np.uint32]: ...
    @property
    def triangles(self) -> NDArray[np.uint32]: ...
    @property
    def vertices(self) -> NDArray[np.uint32]: ...
    @property
    def representative(self) -> NDArray[np.uint32]: ...
    @property
    def normal(self) -> tuple[float, float, float]: ...
    @property
    def duplicate_count(self) -> int: ...
    def locate(
        self, queries: NDArray[np.float64], barycentric: bool = ..., nearest: bool = ..., threads: int = ...
    ) -> tuple[NDArray[np.int32], NDArray[np.float64] | None, NDArray[np.int32] | None]: ...
    def clipped_volumes(self, low: NDArray[np.float64], high: NDArray[np.float64], threads: int, /) -> NDArray[np.float64]: ...
    def voronoi(
        self,
    ) -> tuple[
        NDArray[np.float64],  # vertices (v, 3)
        NDArray[np.uint32],  # tetrahedron_vertex
        NDArray[np.uint32],  # face_points (f, 2)
        NDArray[np.uint32],  # face_offsets
        NDArray[np.uint32],  # face_vertices
        NDArray[np.uint8],  # face_bounded
        NDArray[np.uint32],  # cell_offsets
        NDArray[np.uint32],  # cell_faces
        NDArray[np.float64],  # volume
    ]: ...
    def interpolate(
        self, queries: NDArray[np.float64], values: NDArray[np.float64], threads: int, /
    ) -> tuple[NDArray[np.int32], NDArray[np.float64]]:
        """(tetrahedron (q,), values (q, k), NaN outside the hull)."""

class TriangulationNd:
    def __init__(self, points: NDArray[np.float64], furthest_site: bool = ...) -> None: ...
    @property
    def simplices(self) -> NDArray[np.int32]: ...
    @property
    def neighbors(self) -> NDArray[np.int32]: ...
    @property
    def group(self) -> NDArray[np.int32]: ...
    @property
    def representative(self) -> NDArray[np.uint32]: ...
    @property
    def duplicate_count(self) -> int: ...
    def locate(self, xi: NDArray[np.float64], /) -> NDArray[np.int32]: ...
    def cell_volumes(self) -> NDArray[np.float64]: ...

class RouteChecker:
    def __init__(
        self, json: str, source: str, directory: str, files: dict[str, bytes] | dict[str, str] = ...
    ) -> None: ...
    def check(
        self, route: NDArray[np.float64], rotations: NDArray[np.float64], clearance: bool, samples: int, threads: int, /
    ) -> str:
        """The report as JSON text."""
    @property
    def scene_waypoints(self) -> int: ...
    @property
    def build_seconds(self) -> float: ...
