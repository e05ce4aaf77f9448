"""Type stubs of hullkit.spatial (scipy.spatial's ConvexHull, Delaunay, Voronoi and tsearch); see
spatial.py."""

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["ConvexHull", "Delaunay", "Voronoi", "tsearch"]

class _Cloud:  # not a class at runtime: the attributes that ConvexHull, Delaunay and Voronoi share
    points: NDArray[np.float64]  # (n, ndim)
    npoints: int
    ndim: int
    min_bound: NDArray[np.float64]  # (ndim,)
    max_bound: NDArray[np.float64]
    dimension: int  # what the points span (scipy has no such attribute)

class ConvexHull(_Cloud):
    vertices: NDArray[np.int32]
    simplices: NDArray[np.int32]  # (m, ndim)
    neighbors: NDArray[np.int32]  # (m, ndim)
    equations: NDArray[np.float64]  # (m, ndim + 1)
    volume: float
    area: float
    def __init__(self, points: ArrayLike, incremental: bool = ..., qhull_options: str | None = ...) -> None: ...

class Delaunay(_Cloud):
    simplices: NDArray[np.int32]  # (m, ndim + 1)
    neighbors: NDArray[np.int32]  # (m, ndim + 1)
    convex_hull: NDArray[np.int32]  # (k, ndim)
    nsimplex: int
    coplanar: NDArray[np.int32]  # (c, 3)
    def __init__(
        self, points: ArrayLike, furthest_site: bool = ..., incremental: bool = ..., qhull_options: str | None = ...
    ) -> None: ...
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

class Voronoi(_Cloud):
    furthest_site: bool
    vertices: NDArray[np.float64]  # (nv, ndim)
    ridge_points: NDArray[np.int32]  # (nr, 2)
    ridge_vertices: list[list[int]]  # -1: the vertex at infinity
    regions: list[list[int]]
    point_region: NDArray[np.intp]  # (n,)
    volumes: NDArray[np.float64]  # (n,): area in 2D, volume in 3D; inf when unbounded
    def __init__(
        self, points: ArrayLike, furthest_site: bool = ..., incremental: bool = ..., qhull_options: str | None = ...
    ) -> None: ...
    @property
    def ridge_dict(self) -> dict[tuple[int, int], list[int]]: ...
