"""A typed user of hullkit: type-checked with mypy --strict against the installed stubs, and run,
by test_stubs.py. Every annotation below is also asserted at runtime, so a stub that says another
type than the code returns fails one of the two checks."""

from typing import Any

import numpy as np
from numpy.typing import NDArray

import hullkit
from hullkit.interpolate import CloughTocher2DInterpolator, LinearNDInterpolator, griddata
from hullkit.spatial import ConvexHull, Delaunay, HalfspaceIntersection, QhullError, chebyshev_center


def has_dtype(array: NDArray[Any], dtype: type[np.generic]) -> bool:
    return array.dtype == np.dtype(dtype)


def hulls(points: NDArray[np.float64]) -> None:
    h: hullkit.Hull = hullkit.hull(points, merge_coplanar=True, threads=1)
    triangles: NDArray[np.uint32] = h.triangles
    vertices: NDArray[np.uint32] = h.vertices
    normal: NDArray[np.float64] = h.normal
    assert has_dtype(triangles, np.uint32) and has_dtype(vertices, np.uint32) and has_dtype(normal, np.float64)
    assert h.faces is not None and all(has_dtype(face, np.uint32) for face in h.faces)
    size: float = h.volume + h.area  # floats, not arrays
    dimension: int = h.dimension
    assert isinstance(size, float) and dimension == 3
    report = hullkit.verify(points, h)
    ok: bool = report["ok"]
    problems: list[str] = report["problems"]
    assert ok and problems == [] and report["problem_count"] + 1 == 1

    c = ConvexHull(points)
    simplices: NDArray[np.int32] = c.simplices
    equations: NDArray[np.float64] = c.equations
    assert has_dtype(simplices, np.int32) and has_dtype(equations, np.float64)
    assert abs(c.volume - h.volume) <= 1e-12 * h.volume and c.npoints * c.ndim == points.size

    builder = hullkit.HullBuilder(threads=1)
    builder.add(points[:50])
    builder.add_indexed(points[50:], np.arange(50, len(points)))
    streamed = builder.finish()
    index: NDArray[np.uint64] = streamed["index"]
    assert has_dtype(index, np.uint64) and builder.points_added == streamed["point_count"] == len(points)
    assert (index[streamed["hull"].triangles] == triangles).all()


def triangulations(points: NDArray[np.float64], cube: NDArray[np.float64]) -> None:
    d = hullkit.delaunay(points)
    flat: NDArray[np.uint32] = d.triangles
    halfedges: NDArray[np.int32] = d.halfedges
    assert has_dtype(flat, np.uint32) and has_dtype(halfedges, np.int32)
    nearest_one: int = d.find(0.5, 0.5)  # one query: an int
    nearest_many: NDArray[np.int64] = d.find(points[:5])  # several: an array
    assert isinstance(nearest_one, int) and nearest_one + 1 > 0 and has_dtype(nearest_many, np.int64)
    queries = points[:5] * 0.9 + 0.05  # inside the unit square
    found = d.locate(queries, barycentric=True, nearest=True)
    triangle: NDArray[np.int32] = found["triangle"]
    weights: NDArray[np.float64] = found["barycentric"]
    assert has_dtype(triangle, np.int32) and has_dtype(found["nearest"], np.int32)
    t = int(triangle[0])
    corners = d.points[d.triangles[3 * t: 3 * t + 3]]
    assert np.allclose(weights[0] @ corners, queries[0])
    cells: list[NDArray[np.float64]] = d.voronoi()
    assert len(cells) == len(points) and hullkit.verify_delaunay(d.points, d.triangles)["ok"]

    d3 = hullkit.delaunay3(cube)
    tetrahedra: NDArray[np.uint32] = d3.tetrahedra
    neighbors: NDArray[np.int32] = d3.neighbors
    assert has_dtype(tetrahedra, np.uint32) and has_dtype(neighbors, np.int32)
    found3 = d3.locate(cube[:5] * 0.9 + 0.05, barycentric=True)  # inside the unit cube
    tetrahedron: NDArray[np.int32] = found3["tetrahedron"]
    weights3: NDArray[np.float64] = found3["barycentric"]
    assert has_dtype(tetrahedron, np.int32) and np.allclose(weights3.sum(axis=1), 1.0)
    assert "nearest" not in found3
    volumes: NDArray[np.float64] = d3.voronoi()["volume"]
    assert volumes.shape == (len(cube),)
    report = hullkit.verify_delaunay3(cube, d3)
    assert report["ok"] and report["hull_triangles"] == len(d3.hull)

    s = Delaunay(points)
    s_simplices: NDArray[np.int32] = s.simplices
    s_neighbors: NDArray[np.int32] = s.neighbors
    assert has_dtype(s_simplices, np.int32) and has_dtype(s_neighbors, np.int32)
    simplex: NDArray[np.int32] = s.find_simplex(queries)
    indptr, indices = s.vertex_neighbor_vertices
    transform: NDArray[np.float64] = s.transform
    assert has_dtype(simplex, np.int32) and (simplex >= 0).all() and has_dtype(indices, np.int32)
    assert len(indptr) == s.npoints + 1 and transform.shape == (s.nsimplex, 3, 2)


def interpolation(xy: NDArray[np.float64]) -> None:
    values = xy[:, 0] + 2 * xy[:, 1]
    linear = LinearNDInterpolator(xy, values)
    at: NDArray[np.float64 | np.complex128] = linear(xy[:3])
    assert has_dtype(at, np.float64) and np.allclose(at, values[:3])
    cubic = CloughTocher2DInterpolator(Delaunay(xy), values)
    gradients = cubic.grad
    assert gradients.shape == (len(xy), 1, 2) and np.allclose(cubic(xy[:3]) - values[:3], 0)
    gx, gy = np.meshgrid(np.linspace(0.2, 0.8, 4), np.linspace(0.2, 0.8, 4))
    grid = griddata(xy, values, (gx, gy), method="cubic")
    assert grid.shape == (4, 4)
    nearest = griddata(xy, values.astype(np.int16), xy[:3], method="nearest")
    assert has_dtype(nearest, np.int16)


def scipy_extras(square: NDArray[np.float64]) -> None:
    seen = ConvexHull(np.vstack([square[:4], [[0.5, 2.0]]]), incremental=True, qhull_options="QG4 Qt")
    good: NDArray[np.bool_] | None = seen.good
    assert good is not None and int(good.sum()) == 1
    seen.add_points(np.array([[0.5, -2.0]]), restart=False)
    seen.close()
    tri = Delaunay(square)
    distance: NDArray[np.float64] = tri.plane_distance(np.array([0.5, 0.5]))
    assert distance.shape == (tri.nsimplex,) and tri.equations.shape == (tri.nsimplex, 4)
    box = np.array([[-1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [1.0, 0.0, -1.0], [0.0, 1.0, -1.0]])
    centre, radius = chebyshev_center(box)
    hs = HalfspaceIntersection(box, centre)
    corners: NDArray[np.float64] = hs.intersections
    facets: list[list[int]] = hs.dual_facets
    assert len(corners) == len(facets) == 4 and radius == 0.5
    try:
        HalfspaceIntersection(box, np.array([2.0, 2.0]))
    except QhullError as error:
        assert error.point == 2
    else:
        raise AssertionError("no QhullError")


def main() -> None:
    rng = np.random.default_rng(5)
    corners = [[x, y, z] for x in (0.0, 1.0) for y in (0.0, 1.0) for z in (0.0, 1.0)]
    cube: NDArray[np.float64] = np.vstack([corners, rng.random((92, 3))])
    square: NDArray[np.float64] = np.vstack([[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0]], rng.random((96, 2))])
    hulls(cube)
    triangulations(square, cube)
    interpolation(square)
    scipy_extras(square)
    try:
        hullkit.hull([[np.nan, 0.0, 0.0]])
    except hullkit.HullkitError as error:
        point: int | None = error.point
        assert point == 0
    else:
        raise AssertionError("no HullkitError")


if __name__ == "__main__":
    main()
    print("typed_consumer: ok")

# constrained triangulation: earcut's arguments and Triangle's dictionary
polygon = hullkit.triangulate_polygon([0.0, 0.0, 4.0, 0.0, 4.0, 4.0, 0.0, 4.0, 1.0, 1.0, 3.0, 1.0, 3.0, 3.0, 1.0, 3.0], [4])
polygon_triangles: NDArray[np.uint32] = polygon["triangles"]
crossings: int = polygon["crossing_count"]
assert polygon_triangles.shape == (8, 3) and crossings == 0
mesh = hullkit.triangulate({"vertices": [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]], "segments": [[0, 1]]}, "pcn")
neighbors: NDArray[np.int32] = mesh["neighbors"]
assert mesh["triangles"].shape == (1, 3) and neighbors.shape == (1, 3)
