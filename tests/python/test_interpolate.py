"""hullkit.interpolate against scipy.interpolate on the same inputs (values where the
triangulations agree, NaN only outside the hull, exact values at input points), and the 2D point
location it rests on (hullkit.Delaunay.locate) against brute force. Run with pytest
(scripts/test.sh runs it in a virtual environment with hullkit installed from ./python)."""
import doctest
import os
import pickle
from fractions import Fraction

import numpy as np
import pytest
import scipy.interpolate
import scipy.spatial

import hullkit
from hullkit import HullkitError
from hullkit.interpolate import (CloughTocher2DInterpolator, GradientEstimationWarning, LinearNDInterpolator,
                                 NearestNDInterpolator, estimate_gradients_2d_global, griddata)


def test_docstring_examples_run():
    for function in (hullkit.Delaunay.locate, LinearNDInterpolator, NearestNDInterpolator, griddata,
                     CloughTocher2DInterpolator, estimate_gradients_2d_global):
        finder = doctest.DocTestFinder(recurse=False)
        runner = doctest.DocTestRunner()
        for test in finder.find(function, function.__name__, globs={}):
            runner.run(test)
        assert runner.failures == 0 and runner.tries > 0, function.__name__


def exact_orient(a, b, c):
    """The exact sign of the 2D orientation of a, b, c (rationals: the coordinates are doubles)."""
    a, b, c = ([Fraction(float(v)) for v in p] for p in (a, b, c))
    det = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (det > 0) - (det < 0)


def test_locate_2d_matches_brute_force_on_a_grid():
    # A 6 x 6 grid (cocircular everywhere) plus random points; queries on vertices, edge midpoints
    # and anywhere, some outside.
    rng = np.random.default_rng(3)
    grid = np.stack(np.meshgrid(np.arange(6.0), np.arange(6.0), indexing="ij"), axis=-1).reshape(-1, 2)
    points = np.vstack([grid, rng.random((20, 2)) * 5])
    d = hullkit.delaunay(points)
    triangles = d.triangles.reshape(-1, 3)
    queries = np.vstack([np.floor(rng.random((300, 2)) * 14 - 2) / 2, rng.random((100, 2)) * 7 - 1])
    found = d.locate(queries, barycentric=True, nearest=True)
    for i, q in enumerate(queries):
        holders = [t for t, tri in enumerate(triangles)
                   if all(exact_orient(points[tri[k]], points[tri[(k + 1) % 3]], q) <= 0 for k in range(3))]
        assert found["triangle"][i] == (holders[0] if holders else -1), (i, q)
        distances = [(Fraction(float(q[0])) - Fraction(float(x))) ** 2 + (Fraction(float(q[1])) - Fraction(float(y))) ** 2
                     for x, y in points]
        assert found["nearest"][i] == distances.index(min(distances))
        if holders:
            w = found["barycentric"][i]
            assert np.allclose(w @ points[triangles[holders[0]]], q, rtol=0, atol=1e-12)
        else:
            assert np.isnan(found["barycentric"][i]).all()
    for threads in (1, 2, 3):
        again = d.locate(queries, barycentric=True, nearest=True, threads=threads)
        assert all(np.array_equal(again[k], found[k], equal_nan=True) for k in found)
    with pytest.raises(HullkitError, match="query 1 has a non-finite x coordinate") as error:
        d.locate([[0, 0], [np.inf, 0]])
    assert error.value.point == 1


@pytest.mark.parametrize("ndim,n", [(2, 4000), (3, 2000)])
def test_linear_matches_scipy_in_general_position(ndim, n):
    rng = np.random.default_rng(ndim)
    points = rng.random((n, ndim))
    values = np.sin(3 * points[:, 0]) + points[:, 1:].sum(axis=1) ** 2
    queries = rng.random((20000, ndim)) * 1.1 - 0.05  # some outside the hull
    ours = LinearNDInterpolator(points, values)(queries)
    theirs = scipy.interpolate.LinearNDInterpolator(points, values)(queries)
    np.testing.assert_array_equal(np.isnan(ours), np.isnan(theirs))
    assert np.isnan(ours).sum() > 100
    inside = ~np.isnan(ours)
    np.testing.assert_allclose(ours[inside], theirs[inside], rtol=1e-12, atol=1e-12)
    # The same bits for any thread count.
    again = LinearNDInterpolator(points, values, threads=1)(queries)
    assert np.array_equal(ours, again, equal_nan=True)


def test_linear_is_exact_at_input_points_and_nan_only_outside_on_a_grid():
    # A grid: every cell's four corners are cocircular, the case where Qhull-based location
    # struggles. hullkit returns each input point's value exactly, and no NaN inside the hull.
    axes = np.meshgrid(np.linspace(0, 1, 41), np.linspace(0, 1, 41), indexing="ij")
    points = np.stack(axes, axis=-1).reshape(-1, 2)
    values = np.random.default_rng(5).random(len(points))
    f = LinearNDInterpolator(points, values)
    assert np.array_equal(f(points), values)
    inside = np.random.default_rng(6).random((50000, 2))
    out = f(inside)
    assert not np.isnan(out).any()
    assert (out >= values.min()).all() and (out <= values.max()).all()
    # Bilinear data is reproduced on every cell edge (where every triangulation agrees).
    g = LinearNDInterpolator(points, 2 * points[:, 0] - points[:, 1])
    edges = np.column_stack([np.round(inside[:, 0] * 40) / 40, inside[:, 1]])
    np.testing.assert_allclose(g(edges), 2 * edges[:, 0] - edges[:, 1], atol=1e-14)
    assert np.isnan(f([[1.5, 0.5], [-1e-9, 0.5]])).all()


def test_linear_in_3d_is_exact_at_grid_points():
    axes = np.meshgrid(*(np.arange(6.0),) * 3, indexing="ij")
    points = np.stack(axes, axis=-1).reshape(-1, 3)
    values = np.random.default_rng(7).random(len(points))
    f = LinearNDInterpolator(points, values)
    assert np.array_equal(f(points), values)
    assert not np.isnan(f(np.random.default_rng(8).random((20000, 3)) * 5)).any()
    linear = LinearNDInterpolator(points, points @ [1.0, -2.0, 0.5])
    q = np.random.default_rng(9).random((5000, 3)) * 5
    np.testing.assert_allclose(linear(q), q @ [1.0, -2.0, 0.5], atol=1e-12)


def test_value_shapes_complex_fill_value_and_call_forms():
    rng = np.random.default_rng(11)
    points = rng.random((500, 2))
    values = rng.random((500, 2, 3)) + 1j * rng.random((500, 2, 3))
    queries = rng.random((7, 5, 2)) * 1.2 - 0.1
    ours = LinearNDInterpolator(points, values, fill_value=-1 - 1j)(queries)
    theirs = scipy.interpolate.LinearNDInterpolator(points, values, fill_value=-1 - 1j)(queries)
    assert ours.shape == theirs.shape == (7, 5, 2, 3) and ours.dtype == np.complex128
    np.testing.assert_allclose(ours, theirs, rtol=1e-12, atol=1e-12)
    assert (ours == -1 - 1j).any()
    f = LinearNDInterpolator(points, points[:, 0])
    x = np.linspace(0.2, 0.8, 9)
    # Separate coordinate arrays broadcast; a flat array is read as rows of ndim.
    np.testing.assert_allclose(f(x[:, None], x[None, :]), np.broadcast_to(x[:, None], (9, 9)), atol=1e-14)
    np.testing.assert_allclose(f((x, x)), x, atol=1e-14)
    np.testing.assert_allclose(f(np.array([0.5, 0.5, 0.25, 0.75])), [0.5, 0.25], atol=1e-14)


def test_rescale_and_triangulation_inputs_match_scipy():
    rng = np.random.default_rng(12)
    points = rng.random((800, 2)) * [1.0, 1e6] + [0, -3e5]
    values = points[:, 0] ** 2 + (points[:, 1] / 1e6) ** 2
    queries = rng.random((4000, 2)) * [1.0, 1e6] + [0, -3e5]
    ours = LinearNDInterpolator(points, values, rescale=True)(queries)
    theirs = scipy.interpolate.LinearNDInterpolator(points, values, rescale=True)(queries)
    np.testing.assert_array_equal(np.isnan(ours), np.isnan(theirs))
    ok = ~np.isnan(ours)
    np.testing.assert_allclose(ours[ok], theirs[ok], rtol=1e-10)
    tri = hullkit.spatial.Delaunay(points)
    np.testing.assert_array_equal(LinearNDInterpolator(tri, values)(queries),
                                  LinearNDInterpolator(points, values)(queries))
    np.testing.assert_array_equal(LinearNDInterpolator(scipy.spatial.Delaunay(points), values)(queries),
                                  LinearNDInterpolator(points, values)(queries))
    with pytest.raises(HullkitError, match="Rescaling is not supported"):
        LinearNDInterpolator(tri, values, rescale=True)


def test_pickle_round_trip():
    rng = np.random.default_rng(13)
    points, values = rng.random((300, 3)), rng.random(300)
    queries = rng.random((1000, 3))
    for f in (LinearNDInterpolator(points, values, fill_value=7.0), NearestNDInterpolator(points, values)):
        copy = pickle.loads(pickle.dumps(f))
        assert np.array_equal(copy(queries), f(queries), equal_nan=True)


@pytest.mark.parametrize("ndim", [2, 3])
def test_nearest_matches_brute_force_with_ties_to_the_lowest_index(ndim):
    rng = np.random.default_rng(20 + ndim)
    points = np.vstack([np.floor(rng.random((300, ndim)) * 8), rng.random((100, ndim)) * 8])
    values = np.arange(len(points)) * 10
    queries = np.vstack([np.floor(rng.random((500, ndim)) * 20 - 2) / 2, rng.random((500, ndim)) * 10 - 1])
    ours = NearestNDInterpolator(points, values)(queries)
    assert ours.dtype == values.dtype
    # Exact for the half-integer queries and integer points (many ties, and repeated points); the
    # random points are at distances no rounding confuses.
    squared = ((queries[:, None, :] - points[None, :, :]) ** 2).sum(axis=2)
    np.testing.assert_array_equal(ours, values[np.argmin(squared, axis=1)])  # argmin: the first of ties
    # scipy's k-d tree on points in general position (no ties to break differently).
    spread = rng.random((2000, ndim))
    ours = NearestNDInterpolator(spread, np.arange(2000))(queries / 8)
    np.testing.assert_array_equal(ours, scipy.interpolate.NearestNDInterpolator(spread, np.arange(2000))(queries / 8))
    values = np.arange(len(points)) * 10
    bounded = NearestNDInterpolator(points, values.astype(float))(queries, distance_upper_bound=0.3)
    far = np.sqrt(squared.min(axis=1)) >= 0.3
    assert np.isnan(bounded[far]).all() and not np.isnan(bounded[~far]).any()
    with pytest.raises(HullkitError, match="eps"):
        NearestNDInterpolator(points, values)(queries, eps=0.1)
    assert NearestNDInterpolator(points, values)(points[:3], distance_upper_bound=100.0).dtype == np.float64
    with pytest.raises(HullkitError, match="takes no query options"):
        LinearNDInterpolator(points, values)(queries, distance_upper_bound=1.0)


def test_griddata_matches_scipy():
    rng = np.random.default_rng(30)
    points = rng.random((1000, 2))
    values = np.cos(4 * points[:, 0]) * points[:, 1]
    gx, gy = np.mgrid[0:1:50j, 0:1:60j]
    for method in ("linear", "nearest", "cubic"):
        ours = griddata(points, values, (gx, gy), method=method)
        theirs = scipy.interpolate.griddata(points, values, (gx, gy), method=method)
        assert ours.shape == (50, 60)
        np.testing.assert_array_equal(np.isnan(ours), np.isnan(theirs))
        ok = ~np.isnan(ours)
        np.testing.assert_allclose(ours[ok], theirs[ok], rtol=1e-12, atol=1e-12)
    with pytest.raises(HullkitError, match="unknown interpolation method"):
        griddata(points, values, (gx, gy), method="spline")


@pytest.mark.parametrize("n", [5, 9, 300])
def test_griddata_on_1d_points_is_scipys_interp1d(n):
    rng = np.random.default_rng(n)
    x = rng.random(n) * 10
    x[1] = x[0]  # a repeated point: the first is kept
    y = np.stack([np.sin(x), x ** 2 + 1j * x], axis=1)  # complex, two columns
    queries = np.concatenate([rng.random(2000) * 12 - 1, x])
    keep = np.delete(np.arange(n), 1)
    for method in ("linear", "nearest", "cubic"):
        ours = griddata(x, y, queries, method=method)
        theirs = scipy.interpolate.griddata(x[keep], y[keep], queries, method=method)
        assert ours.shape == theirs.shape == (len(queries), 2)
        np.testing.assert_array_equal(np.isnan(ours), np.isnan(theirs))
        ok = ~np.isnan(ours)
        np.testing.assert_allclose(ours[ok], theirs[ok], rtol=1e-9, atol=1e-12)
        # At the points: their values exactly (the first of the repeated pair's).
        at = griddata(x, y, x[keep], method=method)
        assert np.array_equal(at, y[keep]), method
    # The forms scipy takes: (n, 1) points, one-tuple coordinates, fill_value.
    np.testing.assert_array_equal(griddata(x.reshape(-1, 1), y[:, 0], (queries,)), griddata(x, y[:, 0], queries))
    assert griddata(x, y[:, 0], [x.max() + 1], fill_value=-5.0)[0] == -5.0
    # Nearest: decided exactly, ties to the lower point. The doubles nearest 0.1, 0.2 and 0.3 put 0.2
    # nearer 0.3 (by 3e-17), where the rounded midpoint (scipy's interp1d) calls it a tie.
    assert griddata(np.array([0.1, 0.3]), np.array([1, 2]), [0.2], method="nearest").tolist() == [2]
    assert griddata(np.array([1.0, 3.0]), np.array([1, 2]), [2.0, np.nextafter(2.0, 3)], method="nearest").tolist() == [1, 2]
    with pytest.raises(HullkitError, match="needs at least 4 distinct points"):
        griddata(np.arange(3.0), np.arange(3.0), [0.5], method="cubic")
    with pytest.raises(HullkitError, match="point 2 is not finite"):
        griddata(np.array([0, 1, np.nan, 3]), np.arange(4.0), [0.5])


def test_flat_input_is_exact_at_the_points_and_fill_elsewhere():
    # scipy raises QhullError on collinear (2D) and coplanar (3D) points.
    line = np.array([[0, 0], [1, 1], [2, 2], [3, 3]], dtype=float)
    f = LinearNDInterpolator(line, [1.0, 2.0, 3.0, 4.0], fill_value=-5.0)
    np.testing.assert_array_equal(f([[2, 2], [1.5, 1.5], [0, 1]]), [3.0, -5.0, -5.0])
    plane = np.array([[x, y, 0] for x in range(3) for y in range(3)], dtype=float)
    g = LinearNDInterpolator(plane, np.arange(9.0))
    out = g([[1, 2, 0], [0.5, 0.5, 0]])
    assert out[0] == 5.0 and np.isnan(out[1])
    assert NearestNDInterpolator(plane, np.arange(9))([[1.9, 0.1, 3]]).tolist() == [6]


def test_errors_say_what_is_wrong():
    points = np.random.default_rng(40).random((50, 2))
    with pytest.raises(HullkitError, match="different number of values and points"):
        LinearNDInterpolator(points, np.zeros(49))
    with pytest.raises(HullkitError, match=r"shape \(n, 2\) or \(n, 3\)"):
        LinearNDInterpolator(np.zeros((10, 4)), np.zeros(10))
    f = LinearNDInterpolator(points, np.zeros(50))
    with pytest.raises(HullkitError, match=r"shape \(\.\.\., 2\)"):
        f(np.zeros((3, 3)))
    with pytest.raises(HullkitError, match="query 2 has a non-finite y coordinate") as error:
        f([[0.5, 0.5], [0.1, 0.2], [0.3, np.nan]])
    assert error.value.point == 2


def test_clough_tocher_matches_scipy_in_general_position():
    rng = np.random.default_rng(50)
    points = rng.random((3000, 2))
    values = np.stack([np.sin(3 * points[:, 0]) * np.cos(2 * points[:, 1]),
                       points[:, 0] ** 3 - points[:, 1]], axis=1) * (1 + 0.5j)
    queries = rng.random((30000, 2)) * 1.1 - 0.05
    ours = CloughTocher2DInterpolator(points, values)(queries)
    theirs = scipy.interpolate.CloughTocher2DInterpolator(points, values)(queries)
    assert ours.shape == theirs.shape == (30000, 2) and ours.dtype == np.complex128
    np.testing.assert_array_equal(np.isnan(ours), np.isnan(theirs))
    ok = ~np.isnan(ours)
    np.testing.assert_allclose(ours[ok], theirs[ok], rtol=1e-12, atol=1e-12)
    ours_grad = estimate_gradients_2d_global(hullkit.spatial.Delaunay(points), values[:, 0])
    theirs_grad = scipy.interpolate.interpnd.estimate_gradients_2d_global(scipy.spatial.Delaunay(points), values[:, 0])
    assert ours_grad.shape == (3000, 2)
    np.testing.assert_allclose(ours_grad, theirs_grad, rtol=1e-10, atol=1e-12)


def test_clough_tocher_is_exact_at_points_and_for_planes_and_smooth_across_edges():
    rng = np.random.default_rng(51)
    axes = np.meshgrid(np.linspace(0, 1, 21), np.linspace(0, 1, 21), indexing="ij")
    points = np.vstack([np.stack(axes, axis=-1).reshape(-1, 2), rng.random((100, 2))])
    values = np.cos(3 * points[:, 0]) + points[:, 1] ** 2
    f = CloughTocher2DInterpolator(points, values)
    assert np.array_equal(f(points), values)
    plane = CloughTocher2DInterpolator(points, 2 - points[:, 0] + 4 * points[:, 1])
    q = rng.random((5000, 2))
    np.testing.assert_allclose(plane(q), 2 - q[:, 0] + 4 * q[:, 1], atol=1e-12)
    # C1: across every interior edge, the value and both derivatives agree on its two sides.
    d = hullkit.delaunay(points)
    t, h = d.triangles, d.halfedges
    inner = np.flatnonzero(h > np.arange(len(h)))[:300]
    a, b = points[t[inner]], points[t[np.where(inner % 3 == 2, inner - 2, inner + 1)]]
    s = rng.random((len(inner), 1)) * 0.8 + 0.1
    on_edge = a + s * (b - a)
    normal = np.stack([-(b - a)[:, 1], (b - a)[:, 0]], axis=1)
    normal /= np.linalg.norm(normal, axis=1)[:, None]
    step = 1e-6
    left, right = f(on_edge + 1e-9 * normal), f(on_edge - 1e-9 * normal)
    np.testing.assert_allclose(left, right, atol=1e-7)
    for direction in (normal, np.stack([normal[:, 1], -normal[:, 0]], axis=1)):
        side1 = (f(on_edge + 2 * step * normal + step * direction) - f(on_edge + 2 * step * normal - step * direction)) / (2 * step)
        side2 = (f(on_edge - 2 * step * normal + step * direction) - f(on_edge - 2 * step * normal - step * direction)) / (2 * step)
        np.testing.assert_allclose(side1, side2, atol=1e-3)


def test_clough_tocher_gradient_warning_flat_input_and_errors():
    rng = np.random.default_rng(52)
    points = rng.random((400, 2))
    with pytest.warns(GradientEstimationWarning, match="did not converge"):
        CloughTocher2DInterpolator(points, np.sin(5 * points[:, 0]), maxiter=1)
    f = CloughTocher2DInterpolator(points, points[:, 0], fill_value=-1.0)
    assert f([[3.0, 3.0]]).tolist() == [-1.0]
    with pytest.raises(HullkitError, match="not finite"):
        CloughTocher2DInterpolator(points, np.where(np.arange(400) == 7, np.nan, 1.0))
    with pytest.raises(HullkitError, match=r"shape \(n, 2\)"):
        CloughTocher2DInterpolator(rng.random((40, 3)), np.zeros(40))
    line = np.array([[0, 0], [1, 1], [2, 2]], dtype=float)
    g = CloughTocher2DInterpolator(line, [1.0, 2.0, 5.0])
    out = g([[1, 1], [0.5, 0.5]])
    assert out[0] == 2.0 and np.isnan(out[1])


# scipy's own test files for these interpolators, as Debian installs them, run with hullkit
# standing in (their imports rewritten in a temporary copy; nothing of them is kept here). Each
# test scipy itself passes must pass, except these, for the reasons given:
SCIPY_SUITES = {
    "test_interpnd.py": {
        "import scipy.interpolate.interpnd as interpnd": "import hullkit.interpolate as interpnd",
        "import scipy.spatial._qhull as qhull": "import hullkit.spatial as qhull",
    },
    "test_ndgriddata.py": {"from scipy.interpolate import (": "from hullkit.interpolate import ("},
}
EXPECTED_FAILURES = {
    # Four cocircular corners of a square: the test assumes Qhull's diagonal, hullkit's exact
    # tie-break takes the other one (both are Delaunay).
    "test_interpnd.py::TestLinearNDInterpolation::test_square",
}


def test_scipy_interpolation_suites_pass_with_hullkit(tmp_path):
    from scipy_suites import assert_failures_are, run_scipy_suites

    directory = os.path.join(os.path.dirname(scipy.interpolate.__file__), "tests")
    outcomes = run_scipy_suites(tmp_path, directory, SCIPY_SUITES)
    assert len(outcomes) >= 39, f"only {len(outcomes)} tests ran"
    assert_failures_are(outcomes, EXPECTED_FAILURES)
