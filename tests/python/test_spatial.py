"""hullkit.spatial.ConvexHull against scipy.spatial.ConvexHull (Qhull) on the same inputs, and
hullkit's answers where scipy raises; hullkit.spatial.Delaunay in 3D against scipy's attributes.
Run with pytest (scripts/test.sh runs it in a virtual environment with hullkit installed from
./python)."""
import numpy as np
import pytest
import scipy.spatial

import hullkit
from hullkit.spatial import ConvexHull, Delaunay


def random_clouds():
    rng = np.random.default_rng(7)
    ball = rng.normal(size=(3000, 3))
    ball /= np.linalg.norm(ball, axis=1)[:, None]
    ball *= rng.random(3000)[:, None] ** (1 / 3)
    # An apex with 300 neighbours over a flat base: the neighbours' path for a corner of high degree.
    angles = np.sort(rng.random(300)) * 2 * np.pi
    cone = np.vstack([np.column_stack([np.cos(angles), np.sin(angles), np.zeros(300)]), [[0.1, 0.2, 1.0]]])
    return {
        "cube": rng.random((2000, 3)),
        "ball": ball,
        "sphere": ball / np.linalg.norm(ball, axis=1)[:, None],
        "offset 1e6": rng.random((1000, 3)) + 1e6,
        "tiny": rng.random((500, 3)) * 1e-9,
        "few": rng.random((5, 3)),
        "float32 Fortran": np.asfortranarray(rng.random((800, 3)).astype(np.float32)),
        "cone": cone,
    }


def exact_volume(points, simplices):
    """The volume enclosed by outward triangles, in exact rational arithmetic (the coordinates
    are doubles, so exactly representable): the reference where two rounded results differ."""
    from fractions import Fraction

    p = [[Fraction(float(c)) for c in row] for row in points]
    o = p[simplices[0][0]]
    total = Fraction(0)
    for a, b, c in simplices:
        u, v, w = ([p[i][k] - o[k] for k in range(3)] for i in (a, b, c))
        total += (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
                  + u[2] * (v[0] * w[1] - v[1] * w[0]))
    return total / 6


def check_against_scipy(points, volume_rel=1e-12):
    ours, theirs = ConvexHull(points), scipy.spatial.ConvexHull(points)
    assert ours.npoints == theirs.npoints and ours.ndim == theirs.ndim
    assert ours.dimension == ours.ndim
    assert set(ours.vertices.tolist()) == set(theirs.vertices.tolist())
    assert ours.volume == pytest.approx(theirs.volume, rel=volume_rel)
    assert ours.area == pytest.approx(theirs.area, rel=volume_rel)
    if ours.ndim == 3:  # hullkit's volume against the exact one, closer than scipy is asked to be
        assert ours.volume == pytest.approx(float(exact_volume(ours.points, ours.simplices)), rel=1e-14)
    for name in ("vertices", "simplices", "neighbors"):
        assert getattr(ours, name).dtype == getattr(theirs, name).dtype, name
    assert ours.simplices.shape[1] == theirs.simplices.shape[1]
    assert ours.equations.shape[1] == theirs.equations.shape[1]
    np.testing.assert_array_equal(ours.min_bound, theirs.min_bound)
    np.testing.assert_array_equal(ours.max_bound, theirs.max_bound)
    return ours


def check_consistent(h):
    """neighbors share all corners but one; equations are outward unit normals with every point
    on or below each plane (to rounding) and the simplex's corners on it."""
    p = h.points.astype(np.float64)
    d = h.simplices.shape[1]
    scale = max(1.0, float(np.abs(p).max()))
    for i, simplex in enumerate(h.simplices):
        for j in range(d):
            k = h.neighbors[i, j]
            assert k >= 0
            shared = set(simplex.tolist()) - {simplex[j]}
            assert shared <= set(h.simplices[k].tolist())
            assert simplex[j] not in h.simplices[k]
    normals, offsets = h.equations[:, :-1], h.equations[:, -1]
    np.testing.assert_allclose(np.linalg.norm(normals, axis=1), 1.0, rtol=1e-12)
    heights = p @ normals.T + offsets
    assert heights.max() <= 1e-12 * scale
    corners = np.take_along_axis(heights.T, h.simplices, axis=1)
    assert np.abs(corners).max() <= 1e-12 * scale


@pytest.mark.parametrize("name", list(random_clouds()))
def test_3d_matches_scipy(name):
    # Qhull measures in rounded coordinates about its own centre: 1e6 from the origin its volume
    # is off by about 1e-11 relative (hullkit's is checked against the exact volume instead).
    h = check_against_scipy(random_clouds()[name], volume_rel=1e-9 if name == "offset 1e6" else 1e-12)
    check_consistent(h)


def test_2d_matches_scipy_and_is_counter_clockwise():
    rng = np.random.default_rng(3)
    for points in (rng.random((1000, 2)), rng.normal(size=(300, 2)) * 1e3, rng.random((4, 2))):
        h = check_against_scipy(points)
        check_consistent(h)
        ring = points[h.vertices]
        signed = 0.5 * np.sum(ring[:, 0] * np.roll(ring[:, 1], -1) - np.roll(ring[:, 0], -1) * ring[:, 1])
        assert signed > 0  # counter-clockwise, as scipy's
        assert signed == pytest.approx(h.volume, rel=1e-12)


def test_flat_3d_cloud_is_the_polygon_where_scipy_raises():
    rng = np.random.default_rng(5)
    uv = rng.integers(0, 1000, size=(400, 2)).astype(float)
    points = np.column_stack([uv[:, 0], uv[:, 1], 2.0 * uv[:, 0] - uv[:, 1]])  # exactly on z = 2x - y
    with pytest.raises(scipy.spatial.QhullError):
        scipy.spatial.ConvexHull(points)
    h = ConvexHull(points)
    assert h.dimension == 2 and h.volume == 0.0
    # The same corners as the 2D hull of (x, y), the plane being a graph over them.
    assert set(h.vertices.tolist()) == set(scipy.spatial.ConvexHull(uv).vertices.tolist())
    projected = scipy.spatial.ConvexHull(uv).volume
    assert h.area == pytest.approx(projected * np.sqrt(1 + 4 + 1), rel=1e-12)
    np.testing.assert_allclose(np.abs(h.equations[:, :3] @ [2.0, -1.0, -1.0]), np.sqrt(6), rtol=1e-12)


def test_collinear_repeated_and_too_few_points():
    line2 = np.array([[0, 0], [1, 1], [3, 3], [2, 2]], dtype=float)
    with pytest.raises(scipy.spatial.QhullError):
        scipy.spatial.ConvexHull(line2)
    h = ConvexHull(line2)
    assert h.dimension == 1 and sorted(h.vertices.tolist()) == [0, 2]
    assert h.volume == 0.0 and h.area == pytest.approx(2 * np.sqrt(18), rel=1e-15)
    assert h.simplices.tolist() == [[h.vertices[0], h.vertices[1]], [h.vertices[1], h.vertices[0]]]
    same = np.tile([[0.5, 0.25, 2.0]], (10, 1))
    h = ConvexHull(same)
    assert h.dimension == 0 and h.vertices.tolist() == [0] and h.simplices.shape == (0, 3)
    h = ConvexHull(np.zeros((0, 3)))
    assert h.dimension == -1 and len(h.vertices) == 0
    three = ConvexHull(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], dtype=float))
    assert three.dimension == 2 and three.area == pytest.approx(0.5)


def test_bad_input_raises_hullkit_error_naming_the_point():
    points = np.random.default_rng(1).random((50, 3))
    points[17, 1] = np.nan
    with pytest.raises(hullkit.HullkitError, match=r"point 17 .*non-finite y") as caught:
        ConvexHull(points)
    assert caught.value.point == 17
    assert isinstance(caught.value, ValueError)
    with pytest.raises(hullkit.HullkitError, match=r"shape"):
        ConvexHull(np.zeros((5, 1)))
    with pytest.raises(hullkit.HullkitError, match=r"convertible to float64"):
        ConvexHull([["a", "b", "c"]])
    with pytest.raises(hullkit.HullkitError, match="not supported"):
        ConvexHull(np.zeros((12, 11)))  # 2 to 10 dimensions
    for options in ("Qu", "Qt QR0", "QG", "QGx", "Fv"):
        with pytest.raises(hullkit.HullkitError, match="Qhull option .* not supported by hullkit.spatial.ConvexHull"):
            ConvexHull(np.random.default_rng(3).random((10, 3)), qhull_options=options)
    with pytest.raises(hullkit.HullkitError, match="qhull_options must be a string"):
        ConvexHull(np.random.default_rng(3).random((10, 3)), qhull_options=5)


def test_hull_function_threads_and_algorithms_agree():
    points = np.random.default_rng(2).random((60000, 3))
    one = hullkit.hull(points, threads=1)
    for threads in (0, 2, 3):
        other = hullkit.hull(points, threads=threads)
        np.testing.assert_array_equal(other.triangles, one.triangles)
        assert other.volume == one.volume and other.area == one.area
    small = points[:2000]
    quick, wrap = hullkit.hull(small), hullkit.hull(small, algorithm="giftwrap")
    assert set(quick.vertices.tolist()) == set(wrap.vertices.tolist())
    assert wrap.volume == pytest.approx(quick.volume, rel=1e-12)
    cube = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float)
    faces = hullkit.hull(cube, merge_coplanar=True).faces
    assert len(faces) == 6 and all(len(f) == 4 for f in faces)
    with pytest.raises(hullkit.HullkitError, match="unknown algorithm"):
        hullkit.hull(points, algorithm="qhull")
    with pytest.raises(hullkit.HullkitError, match="threads"):
        hullkit.hull(points, threads=-1)


def matched_rows(ours, theirs):
    """For each row of ``ours``, the row of ``theirs`` with the same corners (as sets)."""
    a, b = np.sort(ours, axis=1), np.sort(theirs, axis=1)
    oa, ob = np.lexsort(a.T[::-1]), np.lexsort(b.T[::-1])
    assert (a[oa] == b[ob]).all()
    match = np.empty(len(ours), dtype=np.int64)
    match[oa] = ob
    return match


def barycentric_by_vertex(d, simplex, x):
    """Barycentric coordinates of x in each simplex from d.transform, in ascending vertex order."""
    t = d.transform[simplex]
    c = np.einsum("nij,nj->ni", t[:, :3], x - t[:, 3])
    full = np.concatenate([c, 1 - c.sum(axis=1, keepdims=True)], axis=1)
    return np.take_along_axis(full, np.argsort(d.simplices[simplex], axis=1), axis=1)


def test_delaunay_3d_matches_scipy():
    rng = np.random.default_rng(13)
    points = rng.random((2000, 3))
    ours, theirs = Delaunay(points), scipy.spatial.Delaunay(points)
    assert ours.dimension == 3
    assert (ours.ndim, ours.npoints, ours.nsimplex) == (theirs.ndim, theirs.npoints, theirs.nsimplex)
    np.testing.assert_array_equal(ours.points, theirs.points)
    np.testing.assert_array_equal(ours.min_bound, theirs.min_bound)
    np.testing.assert_array_equal(ours.max_bound, theirs.max_bound)
    for name in ("simplices", "neighbors", "convex_hull", "coplanar"):
        assert getattr(ours, name).dtype == getattr(theirs, name).dtype == np.intc, name
    assert ours.coplanar.shape == theirs.coplanar.shape == (0, 3)  # every point is a vertex
    match = matched_rows(ours.simplices, theirs.simplices)  # the same tetrahedra
    assert set(map(tuple, np.sort(ours.convex_hull, axis=1).tolist())) == \
        set(map(tuple, np.sort(theirs.convex_hull, axis=1).tolist()))
    # neighbors: across the face opposite the same vertex, the same tetrahedron (or -1 for both)
    mine = theirs.simplices[match]
    position = np.argmax(mine[:, None, :] == ours.simplices[:, :, None], axis=2)  # our corner k in theirs
    expected = np.take_along_axis(theirs.neighbors[match], position, axis=1)
    across = np.where(ours.neighbors >= 0, match[ours.neighbors], -1)
    np.testing.assert_array_equal(across, expected)
    # vertex_neighbor_vertices: the same neighbours of every point
    ip, ix = ours.vertex_neighbor_vertices
    sp, sx = theirs.vertex_neighbor_vertices
    np.testing.assert_array_equal(ip, sp)
    owner = np.repeat(np.arange(ours.npoints), np.diff(sp))
    np.testing.assert_array_equal(ix, sx[np.lexsort((sx, owner))])  # ours ascending per point
    # vertex_to_simplex: a tetrahedron each point is a corner of
    v2s = ours.vertex_to_simplex
    assert v2s.dtype == np.int32 and (ours.simplices[v2s] == np.arange(ours.npoints)[:, None]).any(axis=1).all()
    # transform: the same barycentric coordinates of points in and near each tetrahedron
    x = points[ours.simplices].mean(axis=1) + rng.normal(scale=0.01, size=(ours.nsimplex, 3))
    assert ours.transform.shape == theirs.transform.shape == (ours.nsimplex, 4, 3)
    np.testing.assert_allclose(barycentric_by_vertex(ours, np.arange(ours.nsimplex), x),
                               barycentric_by_vertex(theirs, match, x), rtol=0, atol=1e-6)
    # find_simplex: each tetrahedron's centroid (strictly inside it) is found in that very
    # tetrahedron, as scipy finds it in its own; points far outside in none; shapes kept.
    centroids = points[ours.simplices].mean(axis=1)
    found = ours.find_simplex(centroids)
    assert found.dtype == np.int32
    np.testing.assert_array_equal(found, np.arange(ours.nsimplex))
    np.testing.assert_array_equal(match[found], theirs.find_simplex(centroids))
    far = np.array([[[10.0, 0, 0], [0, -10.0, 0]], [[0, 0, 1e9], [3.0, 3.0, 3.0]]])
    assert ours.find_simplex(far).tolist() == [[-1, -1], [-1, -1]]
    with pytest.raises(hullkit.HullkitError, match="shape"):
        ours.find_simplex([[0.5, 0.5]])


def test_delaunay_3d_grid_has_no_flat_simplices():
    axes = np.meshgrid(np.arange(4.0), np.arange(3.0), np.arange(3.0), indexing="ij")
    points = np.stack(axes, axis=-1).reshape(-1, 3)
    d = Delaunay(points)
    a, b, c, e = (points[d.simplices[:, k]] for k in range(4))
    volumes = np.einsum("ij,ij->i", np.cross(b - a, c - a), e - a) / 6
    assert (volumes > 0).all() and volumes.sum() == 3 * 2 * 2
    assert d.nsimplex == 6 * 3 * 2 * 2 and d.coplanar.shape == (0, 3)
    assert len(d.convex_hull) == 2 * 2 * (3 * 2 + 3 * 2 + 2 * 2)  # two triangles per unit square
