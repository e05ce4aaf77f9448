"""hullkit.spatial.Delaunay and hullkit.delaunay against scipy.spatial.Delaunay (Qhull): the same
triangles in general position, the empty-circle property checked exactly by hullkit's own
verify, find_simplex agreeing off the edges, and answers where scipy raises."""
import numpy as np
import pytest
import scipy.spatial

import hullkit
from hullkit.spatial import Delaunay


def triangle_set(simplices):
    return set(map(tuple, np.sort(np.asarray(simplices), axis=1).tolist()))


def signed_areas(points, simplices):
    a, b, c = (points[simplices[:, k]] for k in range(3))
    return 0.5 * ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))


@pytest.mark.parametrize("seed", [1, 2])
def test_matches_scipy_in_general_position(seed):
    rng = np.random.default_rng(seed)
    points = rng.random((3000, 2))
    ours, theirs = Delaunay(points), scipy.spatial.Delaunay(points)
    assert ours.dimension == 2 and ours.npoints == theirs.npoints and ours.ndim == theirs.ndim
    assert triangle_set(ours.simplices) == triangle_set(theirs.simplices)
    assert ours.simplices.dtype == theirs.simplices.dtype == np.int32
    assert (signed_areas(points, ours.simplices) > 0).all()  # counter-clockwise
    assert hullkit.verify_delaunay(points, ours.simplices[:, [0, 2, 1]])["ok"]
    assert triangle_set(ours.convex_hull) == triangle_set(theirs.convex_hull)
    # neighbors: across the edge opposite corner j, sharing the other two corners
    for i in range(0, ours.nsimplex, 7):
        for j in range(3):
            k = ours.neighbors[i, j]
            others = set(ours.simplices[i].tolist()) - {ours.simplices[i, j]}
            if k < 0:
                assert tuple(sorted(others)) in triangle_set(ours.convex_hull)
            else:
                assert others <= set(ours.simplices[k].tolist()) and ours.simplices[i, j] not in ours.simplices[k]
    # vertex_neighbor_vertices: the same neighbour sets as scipy's
    ip, ix = ours.vertex_neighbor_vertices
    sp, sx = theirs.vertex_neighbor_vertices
    for k in range(0, ours.npoints, 11):
        assert set(ix[ip[k]:ip[k + 1]].tolist()) == set(sx[sp[k]:sp[k + 1]].tolist())
    # vertex_to_simplex: a simplex each point is a corner of
    v2s = ours.vertex_to_simplex
    assert v2s.dtype == np.int32 and (ours.simplices[v2s] == np.arange(ours.npoints)[:, None]).any(axis=1).all()
    # transform: barycentric coordinates of each simplex's centroid are 1/3 each
    t = ours.transform
    centroids = points[ours.simplices].mean(axis=1)
    bary = np.einsum("nij,nj->ni", t[:, :2], centroids - t[:, 2])
    np.testing.assert_allclose(bary, 1 / 3, atol=1e-9)


def test_find_simplex_agrees_with_scipy_off_the_edges():
    rng = np.random.default_rng(4)
    points = rng.random((2000, 2))
    ours, theirs = Delaunay(points), scipy.spatial.Delaunay(points)
    queries = rng.random((20000, 2)) * 1.4 - 0.2
    found = ours.find_simplex(queries)
    assert found.shape == (20000,) and found.dtype == np.int32
    # The same triangle (as a vertex set) wherever scipy's answer is inside one (or -1 for both).
    ours_sets = [frozenset(ours.simplices[k].tolist()) if k >= 0 else None for k in found]
    theirs_sets = [frozenset(theirs.simplices[k].tolist()) if k >= 0 else None for k in theirs.find_simplex(queries)]
    assert ours_sets == theirs_sets
    # A triangle's own corners and centroid are located in a triangle containing them.
    assert (ours.find_simplex(points[ours.simplices].mean(axis=1)) == np.arange(ours.nsimplex)).all()
    assert (ours.find_simplex(points) >= 0).all()
    assert ours.find_simplex(np.zeros((2, 3, 2)) + 0.5).shape == (2, 3)


def test_grid_and_duplicates_and_where_scipy_raises():
    x, y = np.meshgrid(np.arange(30.0), np.arange(20.0))
    grid = np.column_stack([x.ravel(), y.ravel()])
    d = Delaunay(grid)
    assert d.nsimplex == 2 * 29 * 19
    assert hullkit.verify_delaunay(grid, d.simplices[:, [0, 2, 1]])["ok"]
    assert (signed_areas(grid, d.simplices) > 0).all()
    repeated = np.concatenate([grid, grid[:5]])
    d = Delaunay(repeated)
    assert d.nsimplex == 2 * 29 * 19
    assert d.coplanar[:, 0].tolist() == list(range(600, 605))
    assert d.coplanar[:, 2].tolist() == list(range(5))
    for point, simplex, vertex in d.coplanar:
        assert vertex in d.simplices[simplex]
    line = np.array([[0.0, 0.0], [2.0, 2.0], [1.0, 1.0], [3.0, 3.0]])
    with pytest.raises(scipy.spatial.QhullError):
        scipy.spatial.Delaunay(line)
    d = Delaunay(line)
    assert d.dimension == 1 and d.nsimplex == 0
    assert d.convex_hull.tolist() == [[0, 2], [2, 1], [1, 3]]
    ip, ix = d.vertex_neighbor_vertices
    assert sorted(ix[ip[2]:ip[3]].tolist()) == [0, 1]
    assert (d.find_simplex(line) == -1).all()
    with pytest.raises(scipy.spatial.QhullError):
        scipy.spatial.Delaunay(np.array([[0.0, 0.0], [1.0, 0.0]]))
    assert Delaunay(np.array([[0.0, 0.0], [0.0, 0.0]])).dimension == 0


def test_bad_input_and_unsupported_options():
    points = np.random.default_rng(1).random((10, 2))
    points[3, 0] = np.inf
    with pytest.raises(hullkit.HullkitError, match="point 3") as caught:
        Delaunay(points)
    assert caught.value.point == 3
    with pytest.raises(hullkit.HullkitError, match="not supported"):
        Delaunay(np.zeros((12, 10)))  # 2 to 9 dimensions (tests/python/test_spatial_nd.py), not 10
    for option, message in (({"qhull_options": "Qbb Qu"}, "Qhull option 'Qu' .* not supported"),
                            ({"qhull_options": "QG0"}, "Qhull option 'QG0' .* not supported by hullkit.spatial.Delaunay")):
        with pytest.raises(hullkit.HullkitError, match=message):
            Delaunay(np.random.default_rng(2).random((10, 2)), **option)
    with pytest.raises(hullkit.HullkitError, match="shape"):
        Delaunay(np.zeros(6))


def test_delaunator_layout_find_and_voronoi():
    rng = np.random.default_rng(9)
    points = rng.random((500, 2))
    d = hullkit.delaunay(points)
    assert d.triangles.dtype == np.uint32 and d.halfedges.dtype == np.int32 and d.hull.dtype == np.uint32
    assert len(d.triangles) == len(d.halfedges)
    with pytest.raises(ValueError):
        d.triangles[0] = 1  # read-only views of the core's arrays
    for e, f in enumerate(d.halfedges):
        if f >= 0:
            assert d.halfedges[f] == e
    queries = rng.random((300, 2))
    nearest = d.find(queries)
    brute = np.argmin(((queries[:, None, :] - points[None, :, :]) ** 2).sum(axis=2), axis=1)
    np.testing.assert_array_equal(nearest, brute)
    assert d.find(0.25, 0.75) == brute_one(points, 0.25, 0.75)
    cells = d.voronoi((0, 0, 1, 1))
    assert len(cells) == 500
    area = sum(abs(polygon_area(c)) for c in cells)
    assert area == pytest.approx(1.0, rel=1e-9)  # the cells tile the box


def brute_one(points, x, y):
    return int(np.argmin((points[:, 0] - x) ** 2 + (points[:, 1] - y) ** 2))


def polygon_area(corners):
    if len(corners) < 3:
        return 0.0
    x, y = corners[:, 0], corners[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))
