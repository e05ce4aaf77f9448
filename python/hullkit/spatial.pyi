"""Type stubs of hullkit.spatial (scipy.spatial's ConvexHull, Delaunay, Voronoi and tsearch); see
spatial.py."""

from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import HullkitError

__all__ = [
    "ConvexHull",
    "Delaunay",
    "Voronoi",
    "HalfspaceIntersection",
    "QhullError",
    "chebyshev_center",
    "tsearch",
    "delaunay_plot_2d",
    "convex_hull_plot_2d",
    "voronoi_plot_2d",
]

QhullError = HullkitError

class _Incremental:  # add_points and close (with incremental=True)
    def add_points(self, points: ArrayLike, restart: bool = ...) -> None: ...
    def close(self) -> None: ...

class _Cloud:  # not a class at runtime: the attributes that ConvexHull, Delaunay and Voronoi share
    points: NDArray[np.float64]  # (n, ndim)
    npoints: int
    ndim: int
    min_bound: NDArray[np.float64]  # (ndim,)
    max_bound: NDArray[np.float64]
    dimension: int  # what the points span (scipy has no such attribute)

class ConvexHull(_Cloud, _Incremental):
    vertices: NDArray[np.int32]
    coplanar: NDArray[np.int32]  # (c, 3): with Qc, the boundary points that are not vertices
    good: NDArray[np.bool_] | None  # with qhull_options "QGn" / "QG-n"
    simplices: NDArray[np.int32]  # (m, ndim)
    neighbors: NDArray[np.int32]  # (m, ndim)
    equations: NDArray[np.float64]  # (m, ndim + 1)
    volume: float
    area: float
    def __init__(self, points: ArrayLike, incremental: bool = ..., qhull_options: str | bytes | None = ...) -> None: ...

class Delaunay(_Cloud, _Incremental):
    simplices: NDArray[np.int32]  # (m, ndim + 1)
    neighbors: NDArray[np.int32]  # (m, ndim + 1)
    convex_hull: NDArray[np.int32]  # (k, ndim)
    nsimplex: int
    coplanar: NDArray[np.int32]  # (c, 3)
    paraboloid_scale: float
    paraboloid_shift: float
    def __init__(
        self,
        points: ArrayLike,
        furthest_site: bool = ...,
        incremental: bool = ...,
        qhull_options: str | bytes | None = ...,
    ) -> None: ...
    @property
    def vertices(self) -> NDArray[np.int32]:
        """Deprecated alias of simplices (a DeprecationWarning)."""
    @property
    def equations(self) -> NDArray[np.float64]:
        """(nsimplex, ndim + 2): the lifted simplices' planes."""
    def lift_points(self, x: ArrayLike) -> NDArray[np.float64]: ...
    def plane_distance(self, xi: ArrayLike) -> NDArray[np.float64]: ...
    def find_simplex(self, xi: ArrayLike, bruteforce: bool = ..., tol: float | None = ...) -> NDArray[np.int32]:
        """The simplex holding each point of xi (shape (..., ndim)): shape xi.shape[:-1], -1 outside."""
    @property
    def vertex_neighbor_vertices(self) -> tuple[NDArray[np.int32], NDArray[np.int32]]:
        """(indptr, indices)."""
    @property
    def vertex_to_simplex(self) -> NDArray[np.int32]: ...
    @property
    def transform(self) -> NDArray[np.float64]:
        """(nsimplex, ndim + 1, ndim)."""

def tsearch(tri: Delaunay, xi: ArrayLike) -> NDArray[np.int32]:
    """tri.find_simplex(xi)."""

class Voronoi(_Cloud, _Incremental):
    furthest_site: bool
    vertices: NDArray[np.float64]  # (nv, ndim)
    ridge_points: NDArray[np.int32]  # (nr, 2)
    @property
    def ridge_vertices(self) -> list[list[int]]:
        """-1: the vertex at infinity (made on first use)."""
    @property
    def regions(self) -> list[list[int]]: ...
    point_region: NDArray[np.intp]  # (n,)
    volumes: NDArray[np.float64]  # (n,): area in 2D, volume in 3D; inf when unbounded
    def __init__(
        self,
        points: ArrayLike,
        furthest_site: bool = ...,
        incremental: bool = ...,
        qhull_options: str | bytes | None = ...,
    ) -> None: ...
    @property
    def ridge_dict(self) -> dict[tuple[int, int], list[int]]: ...
    def clipped_cells(self, lower: ArrayLike | None = ..., upper: ArrayLike | None = ...) -> list[NDArray[np.float64]]:
        """2D: each point's cell clipped to the box, (k, 2) counter-clockwise."""
    def clipped_volumes(
        self, lower: ArrayLike | None = ..., upper: ArrayLike | None = ..., threads: int = ...
    ) -> NDArray[np.float64]: ...

class HalfspaceIntersection:
    halfspaces: NDArray[np.float64]  # (nineq, ndim + 1): [A; b] for A x + b <= 0
    interior_point: NDArray[np.float64]  # (ndim,)
    ndim: int
    nineq: int
    intersections: NDArray[np.float64]  # (ninter, ndim)
    dual_points: NDArray[np.float64]  # (nineq, ndim)
    dual_facets: list[list[int]]
    dual_vertices: NDArray[np.int32]
    dual_equations: NDArray[np.float64]  # (ninter, ndim + 1)
    dual_area: float
    dual_volume: float
    def __init__(
        self,
        halfspaces: ArrayLike,
        interior_point: ArrayLike,
        incremental: bool = ...,
        qhull_options: str | bytes | None = ...,
    ) -> None: ...
    def add_halfspaces(self, halfspaces: ArrayLike, restart: bool = ...) -> None: ...
    def close(self) -> None: ...

def chebyshev_center(halfspaces: ArrayLike) -> tuple[NDArray[np.float64], float]:
    """(centre, radius) of the largest ball inside the halfspaces."""

# matplotlib's Axes and Figure (Debian's matplotlib 3.6 has no type information: Any here).
def delaunay_plot_2d(tri: Delaunay, ax: Any = ...) -> Any: ...
def convex_hull_plot_2d(hull: ConvexHull, ax: Any = ...) -> Any: ...
def voronoi_plot_2d(vor: Voronoi, ax: Any = ..., **kw: Any) -> Any: ...
