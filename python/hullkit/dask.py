"""Hulls and route checks spread over a Dask cluster (or Dask's local schedulers).

    from distributed import Client
    import hullkit.dask

    client = Client("scheduler:8786")                       # or LocalCluster(...), or none
    h = hullkit.dask.hull(["part-0.ply", "part-1.ply"])      # or a Dask array of shape (n, 3)
    reports = hullkit.dask.check_routes("scene.json", routes)

hull: each partition (a chunk of the array, or a file read in batches) is hulled on a worker,
which keeps only its chunk, or one batch of its file, and the running hull; what travels is each
partition's hull vertices with their global indices, never the points. A tree reduction merges
them (hulls compose: hull(A u B) = hull(hull(A) u hull(B))) into the exact hull of the whole:
the same triangles, vertices, volume and area bits as hullkit.hull on one machine, wherever that
fits. Point files are indexed in the order given, each file's points after the previous file's.

check_routes: the scene is made self-contained (its text, and the bytes of the mesh files it
names, read here) and sent once to each worker, where one RouteChecker per worker is built and
reused; the routes are checked in batches on the workers and the reports come back in the order
of the routes, identical to RouteChecker(scene).check(route) here.

Every task runs hullkit on one thread by default (``threads=1``): the cluster's workers are the
parallelism. hullkit must be installed on the workers.
"""
import hashlib
import json
import math
import os

import numpy as np

import dask
from dask import delayed

from . import HullBuilder, HullkitError, _core, _scene_json, _translated

__all__ = ["hull", "hull_graph", "check_routes", "DaskHull"]


class DaskHull:
    """The hull of a cloud spread over a cluster: ``dimension``, ``triangles`` (m, 3) and
    ``vertices`` as int64 global indices (the same values as hullkit.hull of the whole),
    ``volume``, ``area``, ``point_count``, and ``points``/``index``: the hull vertices'
    coordinates and global indices (ascending)."""

    def __init__(self, merged):
        streamed = merged["hull"]
        index = merged["index"].astype(np.int64)
        self.point_count = int(merged["point_count"])
        self.points = merged["points"]
        self.index = index
        self.dimension = streamed.dimension
        self.triangles = index[streamed.triangles.astype(np.int64)] if len(streamed.triangles) else np.zeros((0, 3), np.int64)
        self.vertices = index[streamed.vertices.astype(np.int64)]
        self.volume = streamed.volume
        self.area = streamed.area
        self.normal = streamed.normal

    def __repr__(self):
        return (f"hullkit.dask.DaskHull(points={self.point_count}, dimension={self.dimension}, "
                f"vertices={len(self.vertices)}, triangles={len(self.triangles)})")


# ---- the tasks (run on the workers) ---------------------------------------------------------------

def _partial_block(block, first_index, threads):
    """A chunk's hull vertices with global indices."""
    builder = HullBuilder(threads=threads)
    builder.add(np.asarray(block, dtype=np.float64), int(first_index))
    out = builder.finish()
    return {"points": out["points"], "index": out["index"], "point_count": out["point_count"]}


def _partial_file(path, threads):
    """A file's hull vertices with indices counted within the file (shifted once the counts of
    the files before it are known)."""
    with _translated():
        return _core.hull_file(os.fspath(path), int(threads))


def _count(partial):
    return partial["point_count"]


def _shift(partial, counts, k):
    offset = int(sum(counts[:k]))
    return {"points": partial["points"], "index": partial["index"] + np.uint64(offset),
            "point_count": partial["point_count"]}


def _merge(partials, threads, final=False):
    """The hull of several partials' vertices: their vertices (and the whole hull when final)."""
    builder = HullBuilder(threads=threads)
    for partial in partials:
        if len(partial["index"]):
            builder.add_indexed(partial["points"], partial["index"])
    out = builder.finish()
    total = sum(int(p["point_count"]) for p in partials)
    if final:
        out["point_count"] = total
        return out
    return {"points": out["points"], "index": out["index"], "point_count": total}


# ---- the graph ------------------------------------------------------------------------------------

def _partials(source, threads):
    if isinstance(source, (list, tuple)):
        if not source:
            raise HullkitError("hullkit.dask.hull: no files given")
        paths = [os.fspath(p) for p in source]
        raw = [delayed(_partial_file, pure=True)(path, threads) for path in paths]
        counts = delayed(list)([delayed(_count)(p) for p in raw])
        return [delayed(_shift)(p, counts, k) for k, p in enumerate(raw)]
    try:
        import dask.array as da
    except ImportError:  # pragma: no cover - dask.array needs numpy, which hullkit has
        raise HullkitError("hullkit.dask.hull needs dask.array") from None
    if not isinstance(source, da.Array):
        raise HullkitError(f"hullkit.dask.hull: source must be a Dask array of shape (n, 3) or a list of point files, "
                           f"got {type(source).__name__}")
    if source.ndim != 2 or source.shape[1] != 3:
        raise HullkitError(f"hullkit.dask.hull: the array must have shape (n, 3), got {source.shape}")
    array = source
    if any(math.isnan(c) for c in array.chunks[0]):
        array = array.compute_chunk_sizes()
    if len(array.chunks[1]) != 1:
        array = array.rechunk({1: 3})
    starts = np.concatenate([[0], np.cumsum(array.chunks[0])[:-1]]).astype(np.int64)
    blocks = array.to_delayed().ravel()
    return [delayed(_partial_block)(block, int(start), threads) for block, start in zip(blocks, starts)]


def hull_graph(source, threads=1, fan_in=4):
    """The Dask graph (a Delayed) of hull(source): to compute with your own scheduler or client
    (``client.compute(graph)``); its result is a dict that DaskHull takes."""
    if isinstance(fan_in, bool) or not isinstance(fan_in, int) or fan_in < 2:
        raise HullkitError(f"fan_in must be an integer >= 2, got {fan_in!r}")
    level = _partials(source, threads)
    while len(level) > fan_in:
        level = [delayed(_merge)(level[k:k + fan_in], threads) for k in range(0, len(level), fan_in)]
    return delayed(_merge)(level, threads, final=True)


def hull(source, client=None, threads=1, fan_in=4):
    """The exact hull of ``source`` (a Dask array of shape (n, 3), or a list of point files in
    any format hullkit reads), computed on ``client`` (a distributed.Client) or, without one,
    on Dask's current scheduler. Returns a DaskHull. ``fan_in``: partials merged per reduction
    task."""
    graph = hull_graph(source, threads=threads, fan_in=fan_in)
    merged = client.compute(graph).result() if client is not None else dask.compute(graph)[0]
    return DaskHull(merged)


# ---- route checks -------------------------------------------------------------------------------

def _self_contained(scene):
    """(scene JSON text, source name, {mesh file name: bytes}): every "mesh" file the scene names
    is read here, so that workers need no files; the text itself travels unchanged."""
    text, source, directory = _scene_json(scene)
    if '"mesh"' not in text:  # no mesh files (parsing a large inline scene here would cost time)
        return text, source, {}
    try:
        data = json.loads(text)
    except ValueError as error:
        raise HullkitError(f"{source}: {error}") from None
    names = set()
    traverse = data.get("traverse") if isinstance(data, dict) else None
    for group in ((traverse or {}).get("parts", []) if isinstance(traverse, dict) else [],
                  data.get("obstacles", []) if isinstance(data, dict) else []):
        for item in group if isinstance(group, list) else []:
            if isinstance(item, dict) and isinstance(item.get("mesh"), str):
                names.add(item["mesh"])
    files = {}
    for name in sorted(names):
        path = os.path.join(directory, name)
        try:
            with open(path, "rb") as file:
                files[name] = file.read()
        except OSError as error:
            raise HullkitError(f"{source}: {name}: cannot open: {error.strerror}") from None
    return text, source, files


_checkers = {}  # per worker process: scene digest -> the core's RouteChecker, built once and reused


def _check_batch(scene, routes, clearance, samples, threads):
    text, source, files = scene
    key = hashlib.sha256(text.encode() + b"\0" + repr(sorted((k, hashlib.sha256(v).hexdigest()) for k, v in files.items())).encode()).hexdigest()
    checker = _checkers.get(key)
    if checker is None:
        if len(_checkers) >= 8:
            _checkers.clear()
        with _translated():
            checker = _checkers[key] = _core.RouteChecker(text, source, ".", files)
    with _translated():
        no_rotations = np.zeros((0, 4))  # translations: the routes handed to check_routes are (k, 3)
        return [json.loads(checker.check(route, no_rotations, clearance, samples, threads)) for route in routes]


def check_routes(scene, routes, client=None, clearance=True, samples=0, threads=1, batch=None):
    """Checks every route of ``routes`` (a list of (k, 3) waypoint arrays) against ``scene`` (a
    dict or a scene file) on the cluster; returns their reports (as RouteChecker.check gives
    them) in order. ``batch``: routes per task (default: about 4 tasks per worker)."""
    shipped = _self_contained(scene)
    routes = [np.ascontiguousarray(r, dtype=np.float64) for r in routes]
    for k, route in enumerate(routes):
        if route.ndim != 2 or route.shape[1] != 3 or len(route) < 2:
            raise HullkitError(f"routes[{k}] must have shape (k, 3) with k >= 2, got {route.shape}")
    if not routes:
        return []
    # A bad scene fails on the workers with the core's message (HullkitError), as it would here.
    if batch is None:
        workers = len(client.scheduler_info()["workers"]) if client is not None else os.cpu_count() or 1
        batch = max(1, math.ceil(len(routes) / (4 * max(1, workers))))
    chunks = [routes[k:k + batch] for k in range(0, len(routes), batch)]
    if client is not None:
        shared = client.scatter(shipped, broadcast=True)  # sent once to each worker
        futures = client.map(_check_batch, [shared] * len(chunks), chunks, clearance=clearance, samples=samples,
                             threads=threads, pure=False)
        results = client.gather(futures)
    else:
        shared = delayed(shipped, traverse=False)
        results = dask.compute(*[delayed(_check_batch)(shared, chunk, clearance, samples, threads) for chunk in chunks])
    return [report for part in results for report in part]
