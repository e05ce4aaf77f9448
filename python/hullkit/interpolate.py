"""scipy.interpolate's triangulation interpolators on hullkit's exact point location: switching
is a change of import.

    from hullkit.interpolate import LinearNDInterpolator, CloughTocher2DInterpolator, griddata
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
* ``CloughTocher2DInterpolator`` (and ``griddata(method="cubic")``) builds the same surface as
  scipy's: cubic Clough-Tocher patches on the gradients that minimise the edges' curvature.
  In general position the values agree with scipy's to about 1e-14.
* Repeated points: the triangulation keeps the first of each set of equal points, and its value
  is used (scipy keeps one too, without saying which).

Objects pickle by their inputs and are rebuilt (the same triangulation: it depends only on the
points).
"""
import warnings as _warnings

import numpy as _np

from . import HullkitError, _threads, _translated, delaunay, delaunay3
from . import spatial as _spatial

__all__ = ["LinearNDInterpolator", "NearestNDInterpolator", "CloughTocher2DInterpolator", "griddata",
           "estimate_gradients_2d_global", "GradientEstimationWarning"]


class GradientEstimationWarning(Warning):
    """The gradient estimation reached ``maxiter`` sweeps before ``tol`` (as scipy's)."""


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
    _dimensions = (2, 3)

    def __init__(self, points, values, fill_value, rescale, threads):
        # Pickled by its inputs; a triangulation passed in by its points (the same triangulation).
        given = points.points if isinstance(points, _spatial.Delaunay) else points
        self._inputs = (given, values, fill_value, rescale, threads)
        if isinstance(points, _spatial.Delaunay):
            tri, array = points, points.points
            if rescale:  # scipy's words, which users' code may match
                raise HullkitError("Rescaling is not supported when passing a Delaunay triangulation as "
                                   "``points``. (It was made without rescaling: pass its points instead.)")
        else:
            source = points
            if hasattr(points, "simplices") and hasattr(points, "points"):  # scipy's Delaunay
                source = points.points
            elif isinstance(points, tuple):  # one array per coordinate, as scipy accepts
                try:
                    source = _np.stack(_np.broadcast_arrays(*[_np.asarray(c, dtype=_np.float64) for c in points]), axis=-1)
                except ValueError as error:
                    raise HullkitError(f"the points' coordinate arrays do not broadcast together: {error}") from None
                source = source.reshape(-1, source.shape[-1]) if source.ndim > 1 else source
            try:
                array = _np.ascontiguousarray(source, dtype=_np.float64)
            except (TypeError, ValueError) as error:
                raise HullkitError(f"points must be numbers convertible to float64: {error}") from None
            if array.ndim != 2 or array.shape[1] not in self._dimensions:
                shapes = " or ".join(f"(n, {k})" for k in self._dimensions)
                raise HullkitError(f"points must have shape {shapes}, got {array.shape}"
                                   + (f" ({type(self).__name__} works in {' and '.join(map(str, self._dimensions))} "
                                      "dimensions)" if array.ndim == 2 else ""))
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
        return (_rebuild, (type(self), self._inputs, getattr(self, "_options", {})))

    _query_options = False  # NearestNDInterpolator takes cKDTree.query's (some of them)

    def __call__(self, *args, **options):
        if options and not self._query_options:
            raise HullkitError(f"{type(self).__name__} takes no query options, got {sorted(options)}")
        xi, shape = _query_points(args, self.ndim)
        if self.scale is not None:
            xi = (xi - self.offset) / self.scale
        out = self._evaluate(xi, **options)
        return out.reshape(shape + self.values_shape)

    def _at_points(self, core, xi):
        """Without simplices (points spanning less than the full dimension): each query exactly
        at an input point gets its value, every other query the fill value."""
        near = core.locate(xi, nearest=True, threads=self.threads)["nearest"]
        out = self._filled(len(xi))
        hit = (near >= 0) & _np.all(self._scaled_points[_np.maximum(near, 0)] == xi, axis=1)
        out[hit] = self.values[near[hit]]
        return out

    def _finish(self, simplex, out, complex_values):
        """The core's (q, k) real results (or 2k: real parts, then imaginary) as the values' type,
        with the fill value outside the hull (where the core put NaN)."""
        if complex_values:
            k = self.values.shape[1]
            out = out[:, :k] + 1j * out[:, k:]
        outside = simplex < 0
        if outside.any() and not (_np.isscalar(self.fill_value) and _np.isnan(self.fill_value)):
            out[outside] = self.fill_value
        return out

    def _filled(self, count):
        out = _np.empty((count, self.values.shape[1]), dtype=self.values.dtype)
        out[...] = self.fill_value
        return out


def _real_columns(array, complex_values):
    """float64, C order; complex (or, with ``complex_values``, any) arrays as their real parts
    followed by their imaginary parts along axis 1."""
    array = _np.asarray(array)
    if complex_values:
        array = _np.concatenate([array.real, array.imag], axis=1)
    return _np.ascontiguousarray(array, dtype=_np.float64)


def _rebuild(cls, inputs, options):
    points, values, fill_value, rescale, threads = inputs
    if cls is NearestNDInterpolator:
        return cls(points, values, rescale=rescale, threads=threads)
    return cls(points, values, fill_value=fill_value, rescale=rescale, threads=threads, **options)


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
        if core.dimension < self.ndim:
            return self._at_points(core, xi)
        # Located and blended in the core, corner by corner: at an input point the weights are
        # exactly 1 and 0, so the value is that point's exactly. Complex values as two real columns.
        complex_values = _np.iscomplexobj(self.values)
        with _translated():
            simplex, out = core._core.interpolate(xi, _real_columns(self.values, complex_values), _threads(self.threads))
        return self._finish(simplex, out, complex_values)


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
    _query_options = True

    # cKDTree's construction options: they shape scipy's tree, never its answers, and hullkit has
    # no tree, so they are accepted and have no effect. (boxsize, a periodic space, would change
    # the answers: refused.)
    _tree_options = frozenset({"leafsize", "compact_nodes", "copy_data", "balanced_tree"})

    def __init__(self, x, y, rescale=False, tree_options=None, *, threads=0):
        unknown = sorted(set(tree_options or {}) - self._tree_options)
        if unknown:
            raise HullkitError(f"tree_options not supported by hullkit (it has no k-d tree): {unknown}; "
                               f"{sorted(self._tree_options)} are accepted and change nothing")
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
            # NaN beyond the bound: a floating type whenever a bound is given, whatever the queries.
            out = out.astype(_np.result_type(out.dtype, _np.float64))
            out[_np.linalg.norm(self._scaled_points[near] - xi, axis=1) >= distance_upper_bound] = _np.nan
        return out


def _gradients(core, values, tol, maxiter):
    """Gradients (n, k, 2) of (n, k) real or complex values over a 2D hullkit.Delaunay (the real
    and imaginary parts separately: the estimate is linear in the values)."""
    complex_values = _np.iscomplexobj(values)
    columns = _real_columns(values, complex_values)
    if not _np.isfinite(tol) or tol < 0:
        raise HullkitError(f"tol must be a finite number >= 0, got {tol!r}")
    if int(maxiter) < 1:
        raise HullkitError(f"maxiter must be at least 1, got {maxiter!r}")
    with _translated():
        grad, sweeps, converged = core._core.gradients(columns, float(tol), int(maxiter))
    if not converged:
        _warnings.warn(f"Gradient estimation did not converge in {int(maxiter)} sweeps (tol={tol}); the "
                       "gradients may be inaccurate", GradientEstimationWarning, stacklevel=3)
    if complex_values:
        k = values.shape[1]
        grad = grad[:, :k] + 1j * grad[:, k:]
    return grad


def estimate_gradients_2d_global(tri, y, maxiter=400, tol=1e-6):
    """Gradients at the points of a 2D triangulation for a smooth (C1) interpolant of the values
    ``y`` (shape (npoints, ...), real or complex), as scipy.interpolate's: the gradients that
    minimise the curvature of the cubics along the Delaunay edges, by sweeps over the points
    until no gradient moves by more than ``tol`` times the larger of 1 and its largest component
    (a GradientEstimationWarning after ``maxiter`` sweeps). Exact for linear data up to rounding.
    ``tri``: a hullkit.spatial.Delaunay (a scipy one is triangulated again from its points).
    Returns shape ``y.shape + (2,)``.

    Examples
    --------
    >>> import numpy as np
    >>> from hullkit.spatial import Delaunay
    >>> from hullkit.interpolate import estimate_gradients_2d_global
    >>> points = np.array([[0, 0], [1, 0], [0, 1], [1, 1], [0.4, 0.6]])
    >>> g = estimate_gradients_2d_global(Delaunay(points), 3 * points[:, 0] - points[:, 1], tol=1e-12)
    >>> np.round(g, 9).tolist()[0]
    [3.0, -1.0]
    """
    if not isinstance(tri, _spatial.Delaunay):
        tri = _spatial.Delaunay(tri.points if hasattr(tri, "points") else tri)
    if tri.ndim != 2:
        raise HullkitError(f"estimate_gradients_2d_global needs a 2D triangulation, got {tri.ndim}D points")
    array = _np.asarray(y)
    if array.ndim == 0 or array.shape[0] != tri.npoints:
        raise HullkitError(f"y must have {tri.npoints} rows (one per point), got shape {array.shape}")
    flat = array.reshape(tri.npoints, -1)
    if not _np.iscomplexobj(flat):
        flat = flat.astype(_np.float64)
    grad = _gradients(tri._triangulation, flat, tol, maxiter)
    return grad.reshape(array.shape + (2,))


class CloughTocher2DInterpolator(_Base):
    """Piecewise cubic, C1-smooth interpolation in 2D, as scipy.interpolate.CloughTocher2DInterpolator:
    each triangle of the exact Delaunay triangulation is split at its centroid into three cubic
    Bezier patches (Clough-Tocher) that meet the values and the gradients ``grad``
    (estimate_gradients_2d_global, computed at construction; change them before a call to use
    others). Across an edge inside the hull, the derivative along the line joining the two
    triangles' centroids varies linearly along the edge (the same line from both sides, so
    neighbouring patches join smoothly); on a hull edge, the derivative from the edge's midpoint
    toward the centroid does. Both rules are affine invariant. Exact at the input points and for
    linear data (up to rounding); ``fill_value`` outside the hull.

    Examples
    --------
    >>> import numpy as np
    >>> from hullkit.interpolate import CloughTocher2DInterpolator
    >>> rng = np.random.default_rng(1)
    >>> points = np.vstack([[[0, 0], [1, 0], [0, 1], [1, 1]], rng.random((200, 2))])
    >>> f = CloughTocher2DInterpolator(points, points[:, 0] ** 2 + points[:, 1])
    >>> bool(abs(f(0.5, 0.5) - 0.75) < 1e-3), float(f(points[7])[0]) == points[7, 0] ** 2 + points[7, 1]
    (True, True)
    """

    _dimensions = (2,)

    def __init__(self, points, values, fill_value=_np.nan, tol=1e-6, maxiter=400, rescale=False, *, threads=0):
        super().__init__(points, values, fill_value, rescale, threads)
        self._options = {"tol": tol, "maxiter": maxiter}
        self.tol, self.maxiter = tol, maxiter
        self.grad = _gradients(self._triangulation(), self.values, tol, maxiter)

    def _evaluate(self, xi):
        core = self._triangulation()
        if core.dimension < 2:
            return self._at_points(core, xi)
        # Located and evaluated in the core, on the threads (the patches: Triangulation.clough_tocher
        # in python/src/core.cpp); complex values and their gradients as real columns.
        complex_values = _np.iscomplexobj(self.values) or _np.iscomplexobj(self.grad)
        with _translated():
            simplex, out = core._core.clough_tocher(xi, _real_columns(self.values, complex_values),
                                                    _real_columns(self.grad, complex_values), _threads(self.threads))
        return self._finish(simplex, out, complex_values)


def griddata(points, values, xi, method="linear", fill_value=_np.nan, rescale=False, *, threads=0):
    """Interpolates scattered data at ``xi``, as scipy.interpolate.griddata, in 2D and 3D:
    ``method`` "linear" (LinearNDInterpolator), "nearest" (NearestNDInterpolator; ``fill_value``
    is not used, as in scipy) or, in 2D, "cubic" (CloughTocher2DInterpolator). On 1-D points,
    as scipy's interp1d: linear, nearest, or the not-a-knot cubic spline.

    Examples
    --------
    >>> import numpy as np
    >>> from hullkit.interpolate import griddata
    >>> points = np.array([[0, 0], [2, 0], [0, 2], [2, 2]], dtype=float)
    >>> gx, gy = np.mgrid[0:2:3j, 0:2:3j]
    >>> griddata(points, points.sum(axis=1), (gx, gy)).tolist()
    [[0.0, 1.0, 2.0], [1.0, 2.0, 3.0], [2.0, 3.0, 4.0]]
    """
    if _np.ndim(points) == 1 or (isinstance(points, tuple) and len(points) == 1) or _np.shape(points)[-1:] == (1,):
        return _griddata_1d(points, values, xi, method, fill_value)
    if method == "linear":
        return LinearNDInterpolator(points, values, fill_value=fill_value, rescale=rescale, threads=threads)(xi)
    if method == "nearest":
        return NearestNDInterpolator(points, values, rescale=rescale, threads=threads)(xi)
    if method == "cubic":
        return CloughTocher2DInterpolator(points, values, fill_value=fill_value, rescale=rescale, threads=threads)(xi)
    raise HullkitError(f"unknown interpolation method {method!r}: 'linear', 'nearest' or 'cubic'")


def _griddata_1d(points, values, xi, method, fill_value):
    """griddata on 1-D points, as scipy's (which hands them to interp1d): "linear" (fill_value
    outside), "nearest" (the nearest point's value everywhere; ties: the lower point) and "cubic"
    (the not-a-knot cubic spline through the points, fill_value outside). A query exactly at a
    point gets its value exactly; of equal points the first is kept."""
    if isinstance(points, tuple):
        points = points[0]
    try:
        x = _np.asarray(points, dtype=_np.float64).reshape(-1)
    except (TypeError, ValueError) as error:
        raise HullkitError(f"points must be numbers convertible to float64: {error}") from None
    if not _np.isfinite(x).all():
        bad = int(_np.flatnonzero(~_np.isfinite(x))[0])
        raise HullkitError(f"point {bad} is not finite ({x[bad]})", bad)
    y, trailing = _values(values, len(x), keep_dtype=method == "nearest")
    if isinstance(xi, tuple):
        if len(xi) != 1:
            raise HullkitError(f"expected 1 coordinate array for 1-D points, got {len(xi)}")
        xi = xi[0]
    try:
        q = _np.asarray(xi, dtype=_np.float64)
    except (TypeError, ValueError) as error:
        raise HullkitError(f"query points must be numbers convertible to float64: {error}") from None
    shape = q.shape[:-1] if q.ndim > 1 and q.shape[-1] == 1 else q.shape
    q = q.reshape(-1)
    order = _np.argsort(x, kind="stable")
    xs, keep = _np.unique(x[order], return_index=True)  # the first of equal points (stable sort)
    ys = y[order][keep]
    if method not in ("linear", "nearest", "cubic"):
        raise HullkitError(f"unknown interpolation method {method!r}: 'linear', 'nearest' or 'cubic'")
    if len(xs) == 0:
        raise HullkitError("griddata needs at least one point")
    if method == "nearest":
        out = ys[_nearest_1d(xs, q)]
    else:
        if len(xs) < (4 if method == "cubic" else 2):
            raise HullkitError(f"griddata(method={method!r}) on 1-D points needs at least {4 if method == 'cubic' else 2} "
                               f"distinct points, got {len(xs)}")
        i = _np.clip(_np.searchsorted(xs, q, side="right") - 1, 0, len(xs) - 2)
        with _np.errstate(all="ignore"):
            t = ((q - xs[i]) / (xs[i + 1] - xs[i]))[:, None]
            if method == "linear":
                out = (1 - t) * ys[i] + t * ys[i + 1]  # exactly ys[i] at t = 0, ys[i + 1] at t = 1
            else:
                out = _cubic_1d(xs, ys, q, i)
        outside = ~((q >= xs[0]) & (q <= xs[-1]))
        out = out.astype(_np.result_type(out.dtype, _np.asarray(fill_value).dtype))
        out[outside] = fill_value
        at = _np.searchsorted(xs, q)  # a query at a point: its value, exactly
        hit = (at < len(xs)) & (xs[_np.minimum(at, len(xs) - 1)] == q)
        out[hit] = ys[at[hit]]
    return out.reshape(shape + trailing)


def _nearest_1d(xs, q):
    """The index of the nearest of the sorted distinct ``xs`` to each query; the lower on a tie.
    Distances compared in floating point where they differ clearly, exactly (rationals) where not."""
    from fractions import Fraction

    above = _np.clip(_np.searchsorted(xs, q), 1, max(len(xs) - 1, 1))
    below = above - 1
    if len(xs) == 1:
        return _np.zeros(len(q), dtype=_np.int64)
    low, high = xs[below], xs[above]
    with _np.errstate(all="ignore"):
        to_low, to_high = _np.abs(q - low), _np.abs(high - q)
        unsure = ~(_np.abs(to_low - to_high) > 4 * _np.finfo(float).eps * _np.maximum.reduce([_np.abs(q), _np.abs(low), _np.abs(high)]))
    pick = _np.where(to_high < to_low, above, below)
    for k in _np.flatnonzero(unsure).tolist():
        a, b, c = Fraction(float(low[k])), Fraction(float(high[k])), Fraction(float(q[k]))
        pick[k] = above[k] if abs(b - c) < abs(c - a) else below[k]
    return pick


def _cubic_1d(xs, ys, q, i):
    """The not-a-knot cubic spline through (xs, ys) (scipy's interp1d(kind="cubic")) at q, which lies
    in [xs[i], xs[i + 1]] (or beyond the ends: filled by the caller). Second derivatives M from
    the spline's equations, the not-a-knot rows folded into the first and last, a tridiagonal
    solve (one pass down, one up)."""
    n = len(xs)
    h = _np.diff(xs)
    slope = (ys[1:] - ys[:-1]) / h[:, None]
    rhs = 6 * (slope[1:] - slope[:-1])  # rows 1 .. n-2
    m = n - 2
    lower = h[:-1].copy()            # coefficient of M[i-1] in row i
    diagonal = 2 * (h[:-1] + h[1:])  # of M[i]
    upper = h[1:].copy()             # of M[i+1]
    # Not-a-knot: M0 = ((h0 + h1) M1 - h0 M2) / h1, and the same at the far end.
    h0, h1 = h[0], h[1]
    diagonal[0] += h0 * (h0 + h1) / h1
    upper[0] -= h0 * h0 / h1
    g0, g1 = h[-1], h[-2]
    diagonal[-1] += g0 * (g0 + g1) / g1
    lower[-1] -= g0 * g0 / g1
    c, d = _np.empty(m), _np.empty_like(rhs)
    c[0] = upper[0] / diagonal[0]
    d[0] = rhs[0] / diagonal[0]
    for k in range(1, m):
        w = diagonal[k] - lower[k] * c[k - 1]
        c[k] = upper[k] / w if k < m - 1 else 0.0
        d[k] = (rhs[k] - lower[k] * d[k - 1]) / w
    inner = _np.empty_like(rhs)
    inner[-1] = d[-1]
    for k in range(m - 2, -1, -1):
        inner[k] = d[k] - c[k] * inner[k + 1]
    moments = _np.empty_like(ys, dtype=inner.dtype)
    moments[1:-1] = inner
    moments[0] = ((h0 + h1) * inner[0] - h0 * inner[1]) / h1
    moments[-1] = ((g0 + g1) * inner[-1] - g0 * inner[-2]) / g1
    a, b = xs[i + 1] - q, q - xs[i]
    w = h[i]
    a, b, w = a[:, None], b[:, None], w[:, None]
    return (moments[i] * a ** 3 + moments[i + 1] * b ** 3) / (6 * w) + (ys[i] / w - moments[i] * w / 6) * a \
        + (ys[i + 1] / w - moments[i + 1] * w / 6) * b
