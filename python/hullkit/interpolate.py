"""scipy.interpolate's triangulation interpolators on hullkit's exact point location: switching
is a change of import.

    from hullkit.interpolate import LinearNDInterpolator, NearestNDInterpolator, griddata
    # instead of: from scipy.interpolate import ...

Signatures, argument forms (points as an (n, ndim) array or a ``hullkit.spatial.Delaunay``;
queries as one array of shape (..., ndim) or as ndim broadcastable arrays), value shapes (any
trailing shape, real or complex), ``fill_value`` and ``rescale`` are scipy's, in 2D and 3D.

What differs, and why:

* Every query is located exactly (orient2d / orient3d): a query at an input point gets that
  point's value exactly, and only queries outside the convex hull get ``fill_value`` (scipy's
  Qhull-based location can return NaN inside the hull and at input points). A query on an edge
  or face shared by several simplices is interpolated in the lowest-indexed one; linear
  interpolation is continuous there, so the value is the same up to rounding.
* Queries are located in one call: sorted along a Hilbert curve and spread over ``threads``
  (a keyword scipy lacks; 0 means every core). The results are the same for every value.
* Points that span less than the full dimension (collinear in 2D, coplanar in 3D), where scipy
  raises QhullError, give no simplices: a query exactly at an input point gets that point's value
  and every other query ``fill_value``.
* ``NearestNDInterpolator`` walks the Delaunay graph with exact distance comparisons instead of a
  k-d tree: ties go to the lowest index. Its ``distance_upper_bound`` query option is supported
  (others of ``cKDTree.query`` are refused by name), in 2D and 3D.
* A ``scipy.spatial.Delaunay`` passed instead of points is not reused: its points are
  triangulated again, exactly (the simplices differ from Qhull's only where Qhull's are not
  Delaunay, or on cocircular ties).
* ``griddata(method="cubic")`` (Clough-Tocher) is not available yet: a clear error says so.

Objects pickle by their inputs and are rebuilt (the same triangulation: it depends only on the
points).
"""
import numpy as _np

from . import HullkitError, _threads, delaunay, delaunay3
from . import spatial as _spatial

__all__ = ["LinearNDInterpolator", "NearestNDInterpolator", "griddata"]


def _query_points(args, ndim):
    """scipy's reading of interpolator arguments: one array (..., ndim) (a 1-D array is taken as
    rows of ndim), or ndim arrays broadcast against each other; float64 (m, ndim) and the leading
    shape."""
    if len(args) == 1:
        args = args[0]
    if isinstance(args, tuple):
        if len(args) != ndim:
            raise HullkitError(f"expected {ndim} coordinate arrays, got {len(args)}")
        try:
            arrays = _np.broadcast_arrays(*[_np.asarray(a, dtype=_np.float64) for a in args])
        except ValueError as error:
            raise HullkitError(f"the coordinate arrays do not broadcast together: {error}") from None
        xi = _np.stack(arrays, axis=-1)
    else:
        try:
            xi = _np.asarray(args, dtype=_np.float64)
        except (TypeError, ValueError) as error:
            raise HullkitError(f"query points must be numbers convertible to float64: {error}") from None
        if xi.ndim == 1:
            xi = xi.reshape(-1, ndim) if xi.size % ndim == 0 else xi
    if xi.shape[-1:] != (ndim,):
        raise HullkitError(f"query points must have shape (..., {ndim}), got {xi.shape}")
    shape = xi.shape[:-1]
    return _np.ascontiguousarray(xi.reshape(-1, ndim)), shape


def _values(values, npoints, keep_dtype=False):
    """Values as (npoints, k) float64 or complex128 (or their own dtype with ``keep_dtype``, as
    scipy's NearestNDInterpolator keeps it), and their trailing shape."""
    array = _np.asarray(values)
    if array.ndim == 0 or array.shape[0] != npoints:
        raise HullkitError(f"different number of values and points: {array.shape[0] if array.ndim else 0} values "
                           f"for {npoints} points")
    dtype = array.dtype if keep_dtype else _np.complex128 if _np.iscomplexobj(array) else _np.float64
    try:
        array = _np.ascontiguousarray(array, dtype=dtype)
    except (TypeError, ValueError) as error:
        raise HullkitError(f"values must be numbers: {error}") from None
    return array.reshape(npoints, -1), array.shape[1:]


class _Base:
    """What the interpolators share: the points (rescaled on request, as scipy does), the exact
    triangulation, the values, and scipy's call conventions."""

    _keep_dtype = False

    def __init__(self, points, values, fill_value, rescale, threads):
        self._inputs = (points, values, fill_value, rescale, threads)
        if isinstance(points, _spatial.Delaunay):
            tri, array = points, points.points
            if rescale:
                raise HullkitError("rescale=True cannot be used with a Delaunay triangulation passed in "
                                   "(it was made without rescaling); pass the points instead")
        else:
            source = points
            if hasattr(points, "simplices") and hasattr(points, "points"):  # scipy's Delaunay
                source = points.points
            try:
                array = _np.ascontiguousarray(source, dtype=_np.float64)
            except (TypeError, ValueError) as error:
                raise HullkitError(f"points must be numbers convertible to float64: {error}") from None
            if array.ndim != 2 or array.shape[1] not in (2, 3):
                raise HullkitError(f"points must have shape (n, 2) or (n, 3), got {array.shape}"
                                   + (" (hullkit interpolates in 2 and 3 dimensions)" if array.ndim == 2 else ""))
            tri = None
        self.points = array
        self.ndim = array.shape[1]
        self.offset = self.scale = None
        if rescale:
            # scipy's rescaling: centred on the mean, each axis divided by its extent (1 when flat).
            self.offset = array.mean(axis=0)
            self.scale = _np.ptp(array, axis=0)
            self.scale[~(self.scale > 0)] = 1.0
            array = (array - self.offset) / self.scale
        self._scaled_points = array
        self.values, self.values_shape = _values(values, len(array), self._keep_dtype)
        self.fill_value = fill_value
        self.threads = threads
        self._tri = tri
        self._core = None  # hullkit.Delaunay / hullkit.Delaunay3 over the (scaled) points

    def _triangulation(self):
        if self._core is None:
            if self._tri is not None:
                self._core = self._tri._triangulation if self.ndim == 2 else self._tri._tetrahedralization
            elif self.ndim == 2:
                self._core = delaunay(self._scaled_points, threads=self.threads)
            else:
                self._core = delaunay3(self._scaled_points, threads=self.threads)
        return self._core

    def __reduce__(self):
        return (_rebuild, (type(self), self._inputs))

    def __call__(self, *args, **options):
        xi, shape = _query_points(args, self.ndim)
        if self.scale is not None:
            xi = (xi - self.offset) / self.scale
        out = self._evaluate(xi, **options)
        return out.reshape(shape + self.values_shape)

    def _filled(self, count):
        out = _np.empty((count, self.values.shape[1]), dtype=self.values.dtype)
        out[...] = self.fill_value
        return out


def _rebuild(cls, inputs):
    points, values, fill_value, rescale, threads = inputs
    if cls is NearestNDInterpolator:
        return cls(points, values, rescale=rescale, threads=threads)
    return cls(points, values, fill_value=fill_value, rescale=rescale, threads=threads)


class LinearNDInterpolator(_Base):
    """Piecewise linear interpolation over the exact Delaunay triangulation (2D) or
    tetrahedralization (3D), as scipy.interpolate.LinearNDInterpolator: each query's value is the
    barycentric blend of its simplex's corner values; ``fill_value`` (default NaN) outside the
    convex hull. See the module's documentation for what differs from scipy.

    Examples
    --------
    >>> import numpy as np
    >>> from hullkit.interpolate import LinearNDInterpolator
    >>> points = np.array([[0, 0], [1, 0], [0, 1], [1, 1]], dtype=float)
    >>> f = LinearNDInterpolator(points, points[:, 0] + 2 * points[:, 1])
    >>> f([[0.5, 0.25], [1, 1], [2, 2]]).tolist()
    [1.0, 3.0, nan]
    >>> f(np.array([0.0, 0.5]), np.array([0.0, 0.5])).tolist()  # coordinates as separate arrays
    [0.0, 1.5]
    """

    def __init__(self, points, values, fill_value=_np.nan, rescale=False, *, threads=0):
        super().__init__(points, values, fill_value, rescale, threads)

    def _evaluate(self, xi):
        core = self._triangulation()
        found = core.locate(xi, barycentric=True, nearest=core.dimension < self.ndim, threads=self.threads)
        out = self._filled(len(xi))
        if core.dimension < self.ndim:  # no simplices: exact at the input points, fill elsewhere
            near = found["nearest"]
            hit = (near >= 0) & _np.all(self._scaled_points[_np.maximum(near, 0)] == xi, axis=1)
            out[hit] = self.values[near[hit]]
            return out
        simplex = found["triangle" if self.ndim == 2 else "tetrahedron"]
        inside = _np.flatnonzero(simplex >= 0)
        corners = (core.triangles.reshape(-1, 3) if self.ndim == 2 else core.tetrahedra)[simplex[inside]]
        weights = found["barycentric"][inside]
        # Summed corner by corner: at an input point the weights are exactly 1, 0, 0 (, 0), so
        # the value is that point's exactly.
        total = weights[:, 0, None] * self.values[corners[:, 0]]
        for k in range(1, self.ndim + 1):
            total += weights[:, k, None] * self.values[corners[:, k]]
        out[inside] = total
        return out


class NearestNDInterpolator(_Base):
    """The value of the nearest input point, as scipy.interpolate.NearestNDInterpolator, in 2D
    and 3D: distances compared exactly (ties: the lowest index), by walks over the Delaunay graph.
    ``distance_upper_bound`` (a query option) gives NaN beyond that distance.

    Examples
    --------
    >>> from hullkit.interpolate import NearestNDInterpolator
    >>> f = NearestNDInterpolator([[0, 0], [1, 0], [0, 1]], [10, 20, 30])
    >>> f([[0.9, 0.2], [5, 5], [0.5, 0.5]]).tolist()
    [20, 20, 10]
    """

    _keep_dtype = True

    def __init__(self, x, y, rescale=False, tree_options=None, *, threads=0):
        if tree_options:
            raise HullkitError(f"tree_options are not used by hullkit (no k-d tree): {sorted(tree_options)}")
        super().__init__(x, y, _np.nan, rescale, threads)

    def _evaluate(self, xi, distance_upper_bound=_np.inf, workers=None, **options):
        if options:
            raise HullkitError(f"query options not supported by hullkit.interpolate.NearestNDInterpolator: "
                               f"{sorted(options)} (distance_upper_bound and workers are)")
        threads = self.threads if workers is None else (0 if workers == -1 else _threads(workers))
        core = self._triangulation()
        near = core.locate(xi, nearest=True, threads=threads)["nearest"]
        if not len(self._scaled_points):
            raise HullkitError("NearestNDInterpolator needs at least one point")
        out = self.values[near]
        if _np.isfinite(distance_upper_bound):
            far = _np.linalg.norm(self._scaled_points[near] - xi, axis=1) >= distance_upper_bound
            if far.any():
                out = out.astype(_np.result_type(out.dtype, _np.float64))
                out[far] = _np.nan
        return out


def griddata(points, values, xi, method="linear", fill_value=_np.nan, rescale=False, *, threads=0):
    """Interpolates scattered data at ``xi``, as scipy.interpolate.griddata, in 2D and 3D:
    ``method`` "linear" (LinearNDInterpolator) or "nearest" (NearestNDInterpolator; ``fill_value``
    is not used, as in scipy). "cubic" (Clough-Tocher) is not available yet.

    Examples
    --------
    >>> import numpy as np
    >>> from hullkit.interpolate import griddata
    >>> points = np.array([[0, 0], [2, 0], [0, 2], [2, 2]], dtype=float)
    >>> gx, gy = np.mgrid[0:2:3j, 0:2:3j]
    >>> griddata(points, points.sum(axis=1), (gx, gy)).tolist()
    [[0.0, 1.0, 2.0], [1.0, 2.0, 3.0], [2.0, 3.0, 4.0]]
    """
    if method == "linear":
        return LinearNDInterpolator(points, values, fill_value=fill_value, rescale=rescale, threads=threads)(xi)
    if method == "nearest":
        return NearestNDInterpolator(points, values, rescale=rescale, threads=threads)(xi)
    if method == "cubic":
        raise HullkitError("griddata(method='cubic') (Clough-Tocher) is not available in hullkit yet; "
                           "use method='linear' or 'nearest', or scipy for cubic")
    raise HullkitError(f"unknown interpolation method {method!r}: 'linear' or 'nearest' ('cubic' is not available yet)")
