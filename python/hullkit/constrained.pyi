from collections.abc import Callable
from typing import Any, Literal, TypedDict

import numpy as np
from numpy.typing import ArrayLike, NDArray
from typing_extensions import NotRequired

__all__ = ["triangulate", "triangulate_polygon"]

_Unsuitable = Callable[[tuple[float, float], tuple[float, float], tuple[float, float], float], bool]

class _PolygonResult(TypedDict):
    coords: NDArray[np.float64]
    triangles: NDArray[np.uint32]
    halfedges: NDArray[np.int32]
    constrained: NDArray[np.uint8]
    representative: NDArray[np.uint32]
    crossing_count: int
    steiner_count: int
    unrefined_count: int

class _TriangleResult(TypedDict):
    vertices: NDArray[np.float64]
    triangles: NDArray[np.uint32]
    segments: NDArray[np.int32]
    edges: NotRequired[NDArray[np.int32]]
    neighbors: NotRequired[NDArray[np.int32]]
    holes: NotRequired[NDArray[np.float64]]
    regions: NotRequired[NDArray[np.float64]]
    triangle_attributes: NotRequired[NDArray[np.float64]]

def triangulate_polygon(
    coords: ArrayLike,
    hole_indices: ArrayLike | None = None,
    fill: Literal["evenodd", "nonzero"] = "evenodd",
    *,
    min_angle: float = 0,
    max_area: float = 0,
    conforming: bool = False,
    max_steiner_points: int = 0,
    keep_segments: Literal[0, 1, 2] = 0,
    unsuitable: _Unsuitable | None = None,
) -> _PolygonResult: ...
def triangulate(
    tri: dict[str, Any],
    opts: str = "",
    *,
    convex: bool = False,
    min_angle: float | None = None,
    max_area: float | None = None,
    conforming: bool = False,
    max_steiner_points: int = 0,
    keep_segments: Literal[0, 1, 2] = 0,
    unsuitable: _Unsuitable | None = None,
) -> _TriangleResult: ...
