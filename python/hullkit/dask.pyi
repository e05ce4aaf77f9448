"""Type stubs of hullkit.dask (hulls and route checks over a Dask cluster); see dask.py."""

import os
from collections.abc import Iterable, Sequence
from typing import Any

import numpy as np
from dask.array.core import Array
from dask.delayed import Delayed
from distributed import Client
from numpy.typing import ArrayLike, NDArray

from . import _HullBuilderResult
from .interpolate import CloughTocher2DInterpolator, LinearNDInterpolator, NearestNDInterpolator

__all__ = ["hull", "hull_graph", "check_routes", "interpolate", "DaskHull"]

# A Dask array of shape (n, 3), or point files (a list or tuple at runtime).
_Source = Array | Sequence[str | os.PathLike[str]]

class DaskHull:
    point_count: int
    points: NDArray[np.float64]  # (k, 3): the hull vertices' coordinates
    index: NDArray[np.int64]  # (k,): their global indices, ascending
    dimension: int
    triangles: NDArray[np.int64]  # (m, 3), global indices
    vertices: NDArray[np.int64]  # global indices
    volume: float
    area: float
    normal: NDArray[np.float64]  # (3,)
    def __init__(self, merged: _HullBuilderResult) -> None: ...

def hull_graph(source: _Source, threads: int = ..., fan_in: int = ...) -> Delayed: ...
def hull(source: _Source, client: Client | None = ..., threads: int = ..., fan_in: int = ...) -> DaskHull: ...
def check_routes(
    scene: dict[str, Any] | str | os.PathLike[str],
    routes: Iterable[ArrayLike],
    client: Client | None = ...,
    clearance: bool = ...,
    samples: int = ...,
    threads: int = ...,
    batch: int | None = ...,
    send_scene: bool = ...,
    rotations: Iterable[ArrayLike | None] | None = ...,
) -> list[dict[str, Any]]: ...
def interpolate(
    interpolator: LinearNDInterpolator | NearestNDInterpolator | CloughTocher2DInterpolator,
    xi: Array,
    threads: int = ...,
    **options: Any,
) -> Array:
    """interpolator(xi) block by block on Dask's scheduler: a Dask array."""
