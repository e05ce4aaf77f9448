"""Wrong uses of hullkit that the stubs must make mypy reject: test_stubs.py runs mypy --strict on
this file and expects an error on each line marked with an error comment, and none elsewhere. Never
run (the calls sit in a function that nothing calls)."""

import numpy as np
from numpy.typing import NDArray

import hullkit
from hullkit.interpolate import griddata
from hullkit.spatial import ConvexHull


def misuse(points: NDArray[np.float64]) -> None:
    volume: int = hullkit.hull(points).volume  # error: a float, not an int
    hullkit.hull(points, threads="all")  # error: threads is an int
    tetrahedra: NDArray[np.int32] = hullkit.delaunay3(points).tetrahedra  # error: uint32
    hullkit.delaunay(points[:, :2]).locate(points[:, :2])["tetrahedron"]  # error: 2D locate has "triangle"
    hullkit.delaunay(points[:, :2]).find(0.5, 0.5).shape  # error: one query gives an int
    ConvexHull(points).volume.shape  # error: volume is a float
    griddata(points, points[:, 0])  # error: xi is missing
    hullkit.HullkitError("bad").point + 1  # error: point may be None
    hullkit.verify(points, hullkit.hull(points))["ok"].lower()  # error: ok is a bool
    hullkit.hull(points).triangles + hullkit.delaunay3(points).volume  # error: Delaunay3 has no volume
