"""hullkit.spatial.Voronoi against scipy.spatial.Voronoi (Qhull) on the same inputs: the same
vertices, ridges and regions in general position and on grids, cell areas and volumes against
independent ones, and hullkit's answers where scipy raises (scipy's own TestVoronoi runs in
test_scipy_qhull.py). Run with pytest (scripts/test.sh runs it in a virtual environment with
hullkit installed from ./python)."""
import doctest
from fractions import Fraction

import numpy as np
import pytest
import scipy.spatial

import hullkit
from hullkit import HullkitError
from hullkit.spatial import Delaunay, Voronoi, tsearch


def test_docstring_examples_run():
    for function in (Voronoi, tsearch):
        finder = doctest.DocTestFinder(recurse=False)
        runner = doctest.DocTestRunner()
        for test in finder.find(function, function.__name__, globs={}):
            runner.run(test)
        assert runner.failures == 0 and runner.tries > 0, function.__name__


def vertex_matching(ours, theirs, rel=1e-9):
    """{our vertex: scipy's vertex} (and -1: -1), matching coordinates within ``rel`` of their
    magnitude; every vertex matched once."""
    assert ours.vertices.shape == theirs.vertices.shape
    tree = scipy.spatial.cKDTree(theirs.vertices)
    distance, index = tree.query(ours.vertices)
    scale = np.maximum(1.0, np.abs(theirs.vertices[index]).max(axis=1))
    assert (distance <= rel * scale).all(), f"worst: {(distance / scale).max()}"
    assert len(set(index.tolist())) == len(index), "two vertices matched one"
    mapping = dict(enumerate(index.tolist()))
    mapping[-1] = -1
    return mapping


def ridges_of(vor, mapping=None):
    """{(p, q) with p < q: the ridge's vertex set (through ``mapping``)}."""
    out = {}
    for (p, q), vertices in zip(vor.ridge_points.tolist(), vor.ridge_vertices):
        out[(min(p, q), max(p, q))] = frozenset(mapping[v] if mapping else v for v in vertices)
    return out


def region_sets(vor, mapping=None):
    return [frozenset(mapping[v] if mapping else v for v in vor.regions[r]) for r in vor.point_region]


def shoelace(corners):
    x, y = corners[:, 0], corners[:, 1]
    return 0.5 * abs(float((x * np.roll(y, -1) - np.roll(x, -1) * y).sum()))


def check_types(vor, ndim):
    assert vor.vertices.dtype == np.float64 and vor.vertices.shape[1:] == (ndim,)
    assert vor.ridge_points.dtype == np.int32 and vor.ridge_points.shape[1:] == (2,)
    assert (vor.ridge_points[:, 0] < vor.ridge_points[:, 1]).all()
    assert vor.point_region.dtype == np.intp and vor.point_region.shape == (vor.npoints,)
    assert vor.volumes.dtype == np.float64 and vor.volumes.shape == (vor.npoints,)
    assert isinstance(vor.ridge_vertices, list) and len(vor.ridge_vertices) == len(vor.ridge_points)
    assert all(type(v) is int for ridge in vor.ridge_vertices for v in ridge)
    assert all(type(v) is int for region in vor.regions for v in region)
    assert vor.regions[0] == [] and 0 not in vor.point_region.tolist()
    assert vor.furthest_site is False and vor.ndim == ndim and vor.npoints == len(vor.points)
    assert vor.ridge_dict == {tuple(p): r for p, r in zip(vor.ridge_points.tolist(), vor.ridge_vertices)}


def single_vertex_unbounded(ridges):
    """The 3D ridges that Qhull leaves out: unbounded, with one finite vertex (two rays)."""
    return {pair for pair, vertices in ridges.items() if -1 in vertices and len(vertices) == 2}


@pytest.mark.parametrize("ndim,n,seed", [(2, 3000, 1), (2, 200, 2), (3, 1500, 3), (3, 100, 4)])
def test_matches_scipy_in_general_position(ndim, n, seed):
    points = np.random.default_rng(seed).random((n, ndim))
    ours, theirs = Voronoi(points), scipy.spatial.Voronoi(points)
    check_types(ours, ndim)
    assert ours.dimension == ndim
    mapping = vertex_matching(ours, theirs)
    our_ridges, their_ridges = ridges_of(ours, mapping), ridges_of(theirs)
    if ndim == 2:
        assert our_ridges == their_ridges
    else:
        # Qhull leaves out (its option Fv documents it) the unbounded faces with one finite vertex:
        # hullkit lists them; every other ridge is the same.
        extra = set(our_ridges) - set(their_ridges)
        assert extra == single_vertex_unbounded(our_ridges) and extra
        assert {k: v for k, v in our_ridges.items() if k not in extra} == their_ridges
    assert region_sets(ours, mapping) == region_sets(theirs)
    assert len(ours.regions) == len(theirs.regions) == n + 1

    # Cell sizes: bounded 2D cells against the shoelace of scipy's regions, 3D ones against the
    # volume of the hull of scipy's region's vertices; unbounded ones inf.
    for i in range(n):
        region = theirs.regions[theirs.point_region[i]]
        if -1 in region:
            assert ours.volumes[i] == np.inf
        elif ndim == 2:
            assert ours.volumes[i] == pytest.approx(shoelace(theirs.vertices[region]), rel=1e-9)
        else:
            assert ours.volumes[i] == pytest.approx(scipy.spatial.ConvexHull(theirs.vertices[region]).volume, rel=1e-9)
    assert np.isfinite(ours.volumes).sum() > n / 3


def test_regions_are_counter_clockwise_in_2d_with_infinity_last():
    points = np.random.default_rng(5).random((500, 2))
    vor = Voronoi(points)
    for i, r in enumerate(vor.point_region):
        region = vor.regions[r]
        assert -1 not in region[:-1]
        finite = region[:-1] if region[-1] == -1 else region
        corners = vor.vertices[finite] - points[i]
        x, y = corners[:, 0], corners[:, 1]
        # Each turn around the point is counter-clockwise (also in an unbounded cell's chain).
        turns = x[:-1] * y[1:] - x[1:] * y[:-1]
        assert (turns > 0).all(), i
        if region[-1] != -1:
            assert region[0] == min(region)
            assert 0.5 * (x * np.roll(y, -1) - np.roll(x, -1) * y).sum() == pytest.approx(vor.volumes[i], rel=1e-12)
    # A 2D ridge's vertices are equidistant from its two points (rays: their finite vertex).
    for (p, q), ridge in zip(vor.ridge_points, vor.ridge_vertices):
        for v in ridge:
            if v >= 0:
                c = vor.vertices[v]
                assert np.hypot(*(c - points[p])) == pytest.approx(np.hypot(*(c - points[q])), rel=1e-9)


def exact_circumcentre(a, b, c):
    a, b, c = ([Fraction(float(x)) for x in p] for p in (a, b, c))
    bx, by, cx, cy = b[0] - a[0], b[1] - a[1], c[0] - a[0], c[1] - a[1]
    d = 2 * (bx * cy - by * cx)
    lb, lc = bx * bx + by * by, cx * cx + cy * cy
    return a[0] + (cy * lb - by * lc) / d, a[1] + (bx * lc - cx * lb) / d


@pytest.mark.parametrize("offset", [0.0, 1e6])
def test_2d_vertices_are_the_circumcentres_to_rounding(offset):
    # Far from the origin the circumcentres are computed from differences to a corner: the
    # error is relative to the circle, not to the coordinates' magnitude.
    points = np.random.default_rng(6).random((60, 2)) + offset
    d = hullkit.delaunay(points)
    vor = Voronoi(points)
    centres = {}
    for t in d.triangles.reshape(-1, 3):
        x, y = exact_circumcentre(*points[t])
        radius = float(abs(Fraction(float(points[t[0], 0])) - x) + abs(Fraction(float(points[t[0], 1])) - y))
        centres[(float(x), float(y))] = radius
    assert len(centres) == len(vor.vertices)
    for v in vor.vertices:
        (x, y), radius = min(centres.items(), key=lambda item: abs(item[0][0] - v[0]) + abs(item[0][1] - v[1]))
        assert abs(x - v[0]) + abs(y - v[1]) <= 1e-9 * radius


def grid(*sizes):
    axes = np.meshgrid(*[np.arange(float(k)) for k in sizes], indexing="ij")
    return np.stack(axes, axis=-1).reshape(-1, len(sizes))


@pytest.mark.parametrize("sizes", [(7, 5), (4, 5, 3)])
def test_grid_has_one_vertex_per_square_or_cube_exactly_at_its_centre(sizes):
    points = grid(*sizes)
    ours, theirs = Voronoi(points), scipy.spatial.Voronoi(points)
    check_types(ours, len(sizes))
    centres = {tuple(c) for c in (grid(*[k - 1 for k in sizes]) + 0.5).tolist()}
    assert len(ours.vertices) == len(theirs.vertices) == len(centres)
    assert {tuple(v) for v in ours.vertices.tolist()} == centres  # exactly
    mapping = vertex_matching(ours, theirs, rel=0)
    assert region_sets(ours, mapping) == region_sets(theirs)
    # The cells are unit squares or cubes (boxes, unbounded on the hull): cells of grid neighbours
    # share a face, diagonal ones only an edge or a corner.
    neighbours = {(p, q) for p in range(len(points)) for q in range(p + 1, len(points))
                  if np.abs(points[p] - points[q]).sum() == 1}
    our_ridges, their_ridges = ridges_of(ours, mapping), ridges_of(theirs)
    assert set(our_ridges) == neighbours
    if len(sizes) == 2:
        assert our_ridges == their_ridges
    else:
        assert set(our_ridges) - set(their_ridges) == single_vertex_unbounded(our_ridges)
        assert {k: our_ridges[k] for k in their_ridges} == their_ridges
    inner = np.all((points > 0) & (points < np.array(sizes) - 1), axis=1)
    assert (ours.volumes[inner] == 1.0).all() and (ours.volumes[~inner] == np.inf).all()
    for i in np.flatnonzero(inner):
        assert len(ours.regions[ours.point_region[i]]) == 2 ** len(sizes)


@pytest.mark.parametrize("seed", range(12))
def test_lattice_subsets_with_ties_everywhere_match_scipy(seed):
    # Random subsets of a small integer lattice: cocircular and cospherical ties of every size,
    # exact in floating point, so Qhull merges the same cells as hullkit's exact tests.
    rng = np.random.default_rng(100 + seed)
    ndim = 2 + seed % 2
    points = np.unique(rng.integers(0, 6, (40 * (ndim - 1), ndim)).astype(float), axis=0)
    ours, theirs = Voronoi(points), scipy.spatial.Voronoi(points)
    mapping = vertex_matching(ours, theirs)
    assert region_sets(ours, mapping) == region_sets(theirs)
    our_ridges, their_ridges = ridges_of(ours, mapping), ridges_of(theirs)
    assert set(our_ridges) - set(their_ridges) == (single_vertex_unbounded(our_ridges) if ndim == 3 else set())
    assert {k: our_ridges[k] for k in their_ridges} == their_ridges
    for i in np.flatnonzero(np.isfinite(ours.volumes)):
        corners = theirs.vertices[theirs.regions[theirs.point_region[i]]]
        assert ours.volumes[i] == pytest.approx(scipy.spatial.ConvexHull(corners).volume, rel=1e-12)


def test_cube_corners_and_cospherical_points_share_one_vertex():
    # The cube's corners: one vertex, its centre; each cell an octant; the cells of corners along
    # an edge share a quarter plane (Qhull lists no ridge at all), face diagonals only a ray.
    cube = grid(2, 2, 2)
    vor = Voronoi(cube)
    assert vor.vertices.tolist() == [[0.5, 0.5, 0.5]]
    edges = {(p, q) for p in range(8) for q in range(p + 1, 8) if np.abs(cube[p] - cube[q]).sum() == 1}
    assert set(map(tuple, vor.ridge_points.tolist())) == edges
    assert all(r == [-1, 0] for r in vor.ridge_vertices)
    assert [sorted(vor.regions[r]) for r in vor.point_region] == [[-1, 0]] * 8
    assert len(scipy.spatial.Voronoi(cube).ridge_points) == 0
    # 30 integer points on the sphere of radius 3 (exactly cospherical), with and without the
    # centre: one vertex at the origin, or a bounded cell around the centre.
    sphere = [p for p in grid(7, 7, 7) - 3 if (p ** 2).sum() == 9]
    assert len(sphere) == 30
    vor = Voronoi(sphere)
    assert vor.vertices.tolist() == [[0.0, 0.0, 0.0]] and len(scipy.spatial.Voronoi(sphere).vertices) == 1
    assert np.isinf(vor.volumes).all()
    with_centre = np.vstack([sphere, [[0, 0, 0]]])
    ours, theirs = Voronoi(with_centre), scipy.spatial.Voronoi(with_centre)
    mapping = vertex_matching(ours, theirs)
    assert region_sets(ours, mapping) == region_sets(theirs)
    hull = scipy.spatial.ConvexHull(theirs.vertices[theirs.regions[theirs.point_region[30]]])
    assert ours.volumes[30] == pytest.approx(hull.volume, rel=1e-12)
    # 2D: 12 integer points on the circle of radius 5: one vertex, twelve rays.
    circle = [p for p in grid(11, 11) - 5 if (p ** 2).sum() == 25]
    vor = Voronoi(circle)
    assert len(circle) == 12 and vor.vertices.tolist() == [[0.0, 0.0]]
    assert vor.ridge_vertices == [[-1, 0]] * 12 and all(vor.regions[r] == [0, -1] for r in vor.point_region)


@pytest.mark.parametrize("ndim", [2, 3])
def test_repeated_points_share_their_representatives_cell(ndim):
    rng = np.random.default_rng(10 + ndim)
    base = rng.random((300, ndim))
    points = np.vstack([base, base[[5, 7, 5]], grid(*[3] * ndim)[:4], grid(*[3] * ndim)[:2]])
    representative = np.arange(len(points))
    representative[300:303] = [5, 7, 5]
    representative[307:309] = [303, 304]
    ours, theirs = Voronoi(points), scipy.spatial.Voronoi(points)
    check_types(ours, ndim)
    assert (ours.point_region == ours.point_region[representative]).all()
    assert np.array_equal(ours.volumes, ours.volumes[representative])
    assert len(ours.regions) == len(points) - 5 + 1
    repeats = set(range(300, 303)) | {307, 308}
    assert not repeats & set(ours.ridge_points.ravel().tolist())
    # The same diagram as scipy's, which also gives a repeated point its twin's region (and its
    # ridges to one of the equal points, not always the first).
    mapping = vertex_matching(ours, theirs)
    assert region_sets(ours, mapping) == region_sets(theirs)
    theirs.ridge_points = representative[theirs.ridge_points]
    our_ridges, their_ridges = ridges_of(ours, mapping), ridges_of(theirs)
    extra = set(our_ridges) - set(their_ridges)
    assert extra == (single_vertex_unbounded(our_ridges) if ndim == 3 else set())
    # And the same as without the repeats.
    alone = Voronoi(np.delete(points, sorted(repeats), axis=0))
    assert len(alone.vertices) == len(ours.vertices) and len(alone.ridge_points) == len(ours.ridge_points)


def test_collinear_2d_points_have_parallel_lines_between_neighbours():
    t = np.array([3.0, -1.0, 0.5, 2.0, 0.5, 7.0])
    points = np.column_stack([1 + 2 * t, -3 + t])  # exactly on a line, unsorted, one repeat
    with pytest.raises(scipy.spatial.QhullError):
        scipy.spatial.Voronoi(points)
    vor = Voronoi(points)
    check_types(vor, 2)
    assert vor.dimension == 1 and vor.vertices.shape == (0, 2)
    along = [1, 2, 3, 0, 5]  # by t, the repeat (4) left out
    assert set(map(tuple, vor.ridge_points.tolist())) == {tuple(sorted(p)) for p in zip(along, along[1:])}
    assert vor.ridge_vertices == [[-1, -1]] * 4
    assert vor.regions == [[]] + [[-1]] * 5 and vor.point_region[4] == vor.point_region[2]
    assert np.isinf(vor.volumes).all()


def test_coplanar_3d_points_have_the_planar_adjacency():
    rng = np.random.default_rng(12)
    for planar in (rng.random((200, 2)), grid(5, 4), np.vstack([rng.random((40, 2)), [[0.5, 0.5]] * 2])):
        flat = Voronoi(planar)
        for lifted in (np.column_stack([planar, np.full(len(planar), 2.5)]),
                       np.column_stack([planar[:, 0], np.full(len(planar), -1.0), planar[:, 1]])):
            with pytest.raises(scipy.spatial.QhullError):
                scipy.spatial.Voronoi(lifted)
            vor = Voronoi(lifted)
            check_types(vor, 3)
            assert vor.dimension == 2 and vor.vertices.shape == (0, 3)
            # Prisms over the planar cells: the same neighbours (a grid's diagonals are not).
            assert set(map(tuple, vor.ridge_points.tolist())) == set(map(tuple, flat.ridge_points.tolist()))
            assert all(r == [-1] for r in vor.ridge_vertices)
            # The same points share a region (the repeats); each diagram numbers its regions its own way.
            pairs = set(zip(vor.point_region.tolist(), flat.point_region.tolist()))
            assert len(pairs) == len(set(vor.point_region.tolist())) == len(set(flat.point_region.tolist()))
            assert np.isinf(vor.volumes).all()
            assert all(region == [-1] for region in vor.regions[1:])


@pytest.mark.parametrize("points,dimension,pairs", [
    ([[0, 0, 0], [2, 2, 2], [1, 1, 1], [2, 2, 2]], 1, {(0, 2), (1, 2)}),
    ([[1, 2, 3]], 0, set()),
    ([[1, 2, 3], [1, 2, 3]], 0, set()),
    (np.zeros((0, 3)), -1, set()),
    ([[1, 2]], 0, set()),
    (np.zeros((0, 2)), -1, set()),
])
def test_fewer_dimensions_answer(points, dimension, pairs):
    vor = Voronoi(points)
    check_types(vor, np.shape(points)[1])
    assert vor.dimension == dimension and len(vor.vertices) == 0
    assert set(map(tuple, vor.ridge_points.tolist())) == pairs
    assert all(r == [-1] * (4 - vor.ndim) for r in vor.ridge_vertices)
    distinct = len({tuple(p) for p in np.asarray(points).tolist()})
    assert vor.regions == [[]] + [[-1]] * distinct
    assert np.isinf(vor.volumes).all()


def test_errors_say_what_is_wrong():
    with pytest.raises(HullkitError, match="point 1 has a non-finite"):
        Voronoi([[0, 0], [np.nan, 1], [1, 1]])
    with pytest.raises(HullkitError, match="point 2 has a non-finite"):
        Voronoi([[0, 0, 0], [1, 0, 0], [0, np.inf, 0], [0, 0, 1]])
    for shape in ((5,), (5, 1), (2, 2, 2)):
        with pytest.raises(HullkitError, match=r"shape \(n, k\) with 2 <= k <= 9"):
            Voronoi(np.zeros(shape))
    with pytest.raises(HullkitError, match=r"Voronoi in 10 dimensions \(at most 9\) is not supported"):
        Voronoi(np.zeros((12, 10)))
    with pytest.raises(HullkitError, match="convertible to float64"):
        Voronoi([["a", "b"]])
    with pytest.raises(ValueError):  # scipy's test_masked_array_fails
        Voronoi(np.ma.masked_all(1))
    for options in ({"qhull_options": "Qbb Qc Qz Qu"}, {"qhull_options": "QG0"}):
        with pytest.raises(HullkitError, match="not supported by hullkit.spatial.Voronoi"):
            Voronoi([[0, 0], [1, 0], [0, 1]], **options)
    with pytest.raises(HullkitError, match="furthest_site=True for coplanar or collinear 3D points is not supported by hullkit.spatial.Voronoi"):
        Voronoi([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], furthest_site=True)


def test_tsearch_is_find_simplex():
    rng = np.random.default_rng(13)
    for ndim in (2, 3):
        tri = Delaunay(rng.random((200, ndim)))
        queries = rng.random((50, 4, ndim)) * 1.2 - 0.1
        assert np.array_equal(tsearch(tri, queries), tri.find_simplex(queries))
    with pytest.raises(HullkitError, match="needs a Delaunay triangulation"):
        tsearch(np.zeros((3, 2)), [[0, 0]])


def test_clipped_cells_tile_the_box():
    rng = np.random.default_rng(80)
    points = np.vstack([rng.random((300, 2)), [[0.5, 0.5]]])  # the last repeats no point: the box's centre
    points = np.vstack([points, points[:3]])  # and three repeats of the first points
    vor = Voronoi(points)
    cells = vor.clipped_cells([0, 0], [1, 1])
    areas = vor.clipped_volumes([0, 0], [1, 1])
    assert len(cells) == len(points) and areas.shape == (len(points),)
    distinct = np.arange(len(points)) < 301
    assert areas[distinct].sum() == pytest.approx(1.0, rel=1e-12)  # the cells tile the box
    assert np.array_equal(areas[301:], areas[:3])  # repeats: their first's cell
    # A bounded cell inside the box is the cell itself.
    inside = [i for i in range(301) if np.isfinite(vor.volumes[i])
              and all((vor.vertices[v] > 0).all() and (vor.vertices[v] < 1).all() for v in vor.regions[vor.point_region[i]])]
    assert len(inside) > 100
    for i in inside:
        assert areas[i] == pytest.approx(vor.volumes[i], rel=1e-9)
    for i, corners in enumerate(cells[:301]):  # each corner is nearest its own point (or tied)
        d = np.linalg.norm(points[None, :301] - corners[:, None], axis=2)
        assert (d[:, i] <= d.min(axis=1) + 1e-12).all()
    # The default box is the points' bounding box; 3D and a bad box are refused.
    assert vor.clipped_volumes()[distinct].sum() == pytest.approx(np.prod(np.ptp(points, axis=0)), rel=1e-12)
    with pytest.raises(HullkitError, match="lower < upper"):
        vor.clipped_cells([0, 0], [1, 0])
    with pytest.raises(HullkitError, match=r"clipped_cells in 3D \(clipped_volumes has the volumes\) is not supported"):
        Voronoi(rng.random((30, 3))).clipped_cells()


def test_clipped_volumes_in_3d_fill_the_box():
    rng = np.random.default_rng(81)
    points = rng.random((400, 3))
    points[:4] = [[0, 0.5, 0.5], [1, 1, 1], [0.25, 0, 0.75], [0.5, 0.5, 1]]  # on the box's sides and a corner
    points = np.vstack([points, points[5:7]])  # repeats
    vor = Voronoi(points)
    volumes = vor.clipped_volumes([0, 0, 0], [1, 1, 1])
    assert volumes.shape == (402,) and (volumes[:400] > 0).all()
    assert volumes[:400].sum() == pytest.approx(1.0, rel=1e-10)  # the cells tile the box
    assert np.array_equal(volumes[400:], volumes[5:7])
    # A bounded cell inside the box keeps its volume.
    inside = [i for i in range(400) if np.isfinite(vor.volumes[i])
              and all(((vor.vertices[v] > 0) & (vor.vertices[v] < 1)).all() for v in vor.regions[vor.point_region[i]])]
    assert len(inside) > 20
    np.testing.assert_allclose(volumes[inside], vor.volumes[inside], rtol=1e-9)
    # The same bits for any number of threads; the default box is the bounding box.
    assert np.array_equal(vor.clipped_volumes([0, 0, 0], [1, 1, 1], threads=1), volumes)
    assert vor.clipped_volumes()[:400].sum() == pytest.approx(np.prod(np.ptp(points, axis=0)), rel=1e-10)
    with pytest.raises(HullkitError, match="point 1 is outside the box"):
        vor.clipped_volumes([0, 0, 0], [0.99, 1, 1])
    with pytest.raises(HullkitError, match="lower < upper"):
        vor.clipped_volumes([0, 0, 0], [1, 1, 0])
