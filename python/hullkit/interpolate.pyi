"""Type stubs of hullkit.interpolate (scipy.interpolate's triangulation interpolators); see
interpolate.py."""

from typing import Any, Literal, overload

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .spatial import Delaunay

__all__ = ["LinearNDInterpolator", "NearestNDInterpolator", "CloughTocher2DInterpolator", "griddata",
           "estimate_gradients_2d_global", "GradientEstimationWarning"]

_Points = ArrayLike | Delaunay  # (n, ndim), a tuple of coordinate arrays, or a triangulation
_Fill = complex | np.number[Any]
_Interpolated = NDArray[np.float64 | np.complex128]  # complex128 when the values are complex

class GradientEstimationWarning(Warning): ...

class _Base:
    points: NDArray[np.float64]  # (n, ndim), as given (not rescaled)
    ndim: int
    offset: NDArray[np.float64] | None  # with rescale
    scale: NDArray[np.float64] | None  # with rescale
    values: NDArray[Any]  # (n, k)
    values_shape: tuple[int, ...]
    fill_value: _Fill
    threads: int
    def __init__(self, points: _Points, values: ArrayLike, fill_value: _Fill, rescale: bool, threads: int) -> None: ...
    def __call__(self, *args: ArrayLike) -> NDArray[Any]:
        """Values at xi (shape (..., ndim), or ndim broadcastable coordinate arrays): shape
        xi.shape[:-1] + values_shape."""

class LinearNDInterpolator(_Base):
    values: _Interpolated
    def __init__(
        self, points: _Points, values: ArrayLike, fill_value: _Fill = ..., rescale: bool = ..., *, threads: int = ...
    ) -> None: ...
    def __call__(self, *args: ArrayLike) -> _Interpolated: ...

class NearestNDInterpolator(_Base):
    def __init__(
        self, x: _Points, y: ArrayLike, rescale: bool = ..., tree_options: dict[str, Any] | None = ..., *, threads: int = ...
    ) -> None: ...
    def __call__(
        self, *args: ArrayLike, distance_upper_bound: float = ..., workers: int | None = ...
    ) -> NDArray[Any]:
        """The nearest point's values, in their own dtype (NaN, as float, beyond distance_upper_bound)."""

class CloughTocher2DInterpolator(_Base):
    values: _Interpolated
    tol: float
    maxiter: int
    grad: _Interpolated  # (n, k, 2)
    def __init__(
        self,
        points: _Points,
        values: ArrayLike,
        fill_value: _Fill = ...,
        tol: float = ...,
        maxiter: int = ...,
        rescale: bool = ...,
        *,
        threads: int = ...,
    ) -> None: ...
    def __call__(self, *args: ArrayLike) -> _Interpolated: ...

def estimate_gradients_2d_global(
    tri: Delaunay | ArrayLike, y: ArrayLike, maxiter: int = ..., tol: float = ...
) -> _Interpolated:
    """Shape y.shape + (2,)."""
@overload
def griddata(
    points: _Points,
    values: ArrayLike,
    xi: ArrayLike,
    method: Literal["linear", "cubic"] = ...,
    fill_value: _Fill = ...,
    rescale: bool = ...,
    *,
    threads: int = ...,
) -> _Interpolated: ...
@overload
def griddata(
    points: _Points,
    values: ArrayLike,
    xi: ArrayLike,
    method: str,
    fill_value: _Fill = ...,
    rescale: bool = ...,
    *,
    threads: int = ...,
) -> NDArray[Any]: ...
