"""Hulls and route checks spread over a Dask cluster (or Dask's local schedulers).

    from distributed import Client
    import hullkit.dask

    client = Client("scheduler:8786")                       # or LocalCluster(...), or none
    h = hullkit.dask.hull(["part-0.ply", "part-1.ply"])      # or a Dask array of shape (n, 3)
    reports = hullkit.dask.check_routes("scene.json", routes)
    values = hullkit.dask.interpolate(LinearNDInterpolator(points, v), queries)   # a Dask array

hull: each partition (a chunk of the array, or a file read in batches) is hulled on a worker,
which keeps only its chunk, or one batch of its file, and the running hull; what travels is each
partition's hull vertices with their global indices, never the points. A tree reduction merges
them (hulls compose: hull(A u B) = hull(hull(A) u hull(B))) into the exact hull of the whole:
the same triangles, vertices, volume and area bits as hullkit.hull on one machine, wherever that
fits. Point files are indexed in the order given, each file's points after the previous file's;
files are merged as they are hulled, before every file's point count is known (see _FILE_BITS).

check_routes: the scene is made self-contained here (its text, and the bytes of the mesh files it
names and of their glTF buffers) and identified by a digest of those bytes. Each worker builds one
RouteChecker per scene and reuses it, by later calls with the same scene too. A worker gets the
scene once: it reads a scene file itself from the same path when it can (a shared or local file
system) and the digest matches, and is otherwise sent the bytes read here. The routes' legs are
checked in batches on the workers (a long route cut between batches, its pieces' reports joined)
and the reports come back in the order of the routes, identical to RouteChecker(scene).check(route)
here.

interpolate: an interpolator of hullkit.interpolate evaluated over a Dask array of queries, block
by block on the workers. What travels is the interpolator's recipe (its class, points, values and
options), once per worker: each worker builds the interpolator from it once (the triangulation
depends only on the points, so it is the same, bit for bit) and evaluates every block it is
given with it. The values are the same bits as the interpolator called here.

Every task runs hullkit on one thread by default (``threads=1``): the cluster's workers are the
parallelism. hullkit must be installed on the workers.
"""
import contextlib
import ctypes
import functools
import hashlib
import json
import math
import os
import re
import threading
import weakref

import numpy as np

import dask
from dask import delayed

from . import HullBuilder, HullkitError, _core, _scene_json, _threads, _translated, as_points

__all__ = ["hull", "hull_graph", "check_routes", "interpolate", "DaskHull"]


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


# ---- the workers' allocator -----------------------------------------------------------------------

# Dask's nanny starts workers with MALLOC_TRIM_THRESHOLD_=65536, so that freed memory goes back to
# the system. Setting it turns off glibc's adaptive mmap threshold: every block over 128 KiB is
# then mapped and unmapped afresh, and its pages are faulted in again each time. A file's hull
# took 2.9 s that way instead of 1.05 s (127 000 page faults instead of 4 000). While a hullkit
# task runs, blocks up to 32 MiB come from the heap and freed memory stays there; when the last
# running task ends, the worker's settings are restored and the heap is trimmed, so the worker
# gives the memory back as Dask intends. Nothing is changed where that variable is not set, or
# where the C library is not glibc.
_M_TRIM_THRESHOLD, _M_MMAP_THRESHOLD = -1, -3
_allocator_lock = threading.Lock()
_allocator_users = 0


@functools.lru_cache(maxsize=None)
def _glibc():
    """The C library when it is glibc (looked up once per process), else None."""
    try:
        libc = ctypes.CDLL(None)
        return libc if hasattr(libc, "mallopt") and hasattr(libc, "malloc_trim") and hasattr(libc, "gnu_get_libc_version") else None
    except OSError:  # pragma: no cover - no C library to load
        return None


def _environ_bytes(name):
    try:
        return int(os.environ[name])
    except (KeyError, ValueError):
        return None


@contextlib.contextmanager
def _task_allocator():
    global _allocator_users
    trim = _environ_bytes("MALLOC_TRIM_THRESHOLD_")
    libc = _glibc() if trim is not None else None
    if libc is None:
        yield
        return
    with _allocator_lock:
        _allocator_users += 1
        if _allocator_users == 1:
            libc.mallopt(_M_MMAP_THRESHOLD, 32 << 20)
            libc.mallopt(_M_TRIM_THRESHOLD, 256 << 20)
    try:
        yield
    finally:
        with _allocator_lock:
            _allocator_users -= 1
            if _allocator_users == 0:
                libc.mallopt(_M_MMAP_THRESHOLD, _environ_bytes("MALLOC_MMAP_THRESHOLD_") or 128 << 10)
                libc.mallopt(_M_TRIM_THRESHOLD, trim)
                libc.malloc_trim(0)


def _on_worker(task):
    """``task`` run under _task_allocator (the tasks below are what the workers run)."""
    @functools.wraps(task)
    def run(*args, **kwargs):
        with _task_allocator():
            return task(*args, **kwargs)
    return run


# ---- the tasks (run on the workers) ---------------------------------------------------------------

@_on_worker
def _partial_block(block, first_index, threads):
    """A chunk's hull vertices with global indices."""
    builder = HullBuilder(threads=threads)
    builder.add(np.asarray(block, dtype=np.float64), int(first_index))
    out = builder.finish()
    return {"points": out["points"], "index": out["index"], "point_count": out["point_count"]}


# Files are hulled and merged before every file's point count is known: while they are merged,
# point i of file k carries the index k * 2**40 + i, which orders points as their global indices
# (file k's after file k-1's) do, so every tie-break (lowest index) and the canonical order come
# out the same; the final hull's indices are then made global.
_FILE_BITS = 40


@_on_worker
def _partial_file(path, k, threads):
    """A file's hull vertices, indexed k * 2**40 + (index within the file)."""
    with _translated():
        part = _core.hull_file(os.fspath(path), int(threads))
    if part["point_count"] >= 1 << _FILE_BITS:
        raise HullkitError(f"{os.fspath(path)}: {part['point_count']} points; hullkit.dask.hull takes at most "
                           f"2**{_FILE_BITS} - 1 points per file (split it)")
    part["index"] = part["index"] + np.uint64(k << _FILE_BITS)
    return part


def _count(partial):
    return partial["point_count"]


def _global(merged, counts):
    """The final hull's indices made global: file k's points follow the points of files 0..k-1."""
    offsets = np.concatenate([[0], np.cumsum(np.asarray(counts, dtype=np.uint64))[:-1]]).astype(np.uint64)
    index = merged["index"]
    merged["index"] = offsets[(index >> np.uint64(_FILE_BITS)).astype(np.int64)] + (index & np.uint64((1 << _FILE_BITS) - 1))
    return merged


@_on_worker
def _merge(partials, threads, final=False):
    """The hull of several partials' vertices: their vertices (and the whole hull when final)."""
    builder = HullBuilder(threads=threads)
    kept = [p for p in partials if len(p["index"])]
    if kept:  # one add: one hull of the union, rather than one per partial
        builder.add_indexed(np.concatenate([p["points"] for p in kept]), np.concatenate([p["index"] for p in kept]))
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
        if len(paths) >= 1 << (64 - _FILE_BITS):
            raise HullkitError(f"hullkit.dask.hull: {len(paths)} files; at most 2**{64 - _FILE_BITS} - 1")
        return [delayed(_partial_file, pure=True)(path, k, threads) for k, path in enumerate(paths)]
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
    partials = level = _partials(source, threads)
    while len(level) > fan_in:
        level = [delayed(_merge)(level[k:k + fan_in], threads) for k in range(0, len(level), fan_in)]
    merged = delayed(_merge)(level, threads, final=True)
    if isinstance(source, (list, tuple)):
        merged = delayed(_global)(merged, delayed(list)([delayed(_count)(p) for p in partials]))
    return merged


def hull(source, client=None, threads=1, fan_in=4):
    """The exact hull of ``source`` (a Dask array of shape (n, 3), or a list of point files in
    any format hullkit reads), computed on ``client`` (a distributed.Client) or, without one,
    on Dask's current scheduler. Returns a DaskHull. ``fan_in``: partials merged per reduction
    task."""
    graph = hull_graph(source, threads=threads, fan_in=fan_in)
    merged = client.compute(graph).result() if client is not None else dask.compute(graph)[0]
    return DaskHull(merged)


# ---- route checks -------------------------------------------------------------------------------

# A JSON string token. Outside strings JSON has no quotes, so scanning left to right finds exactly
# the document's strings (and in a scene, nearly all of its length is numbers, skipped quickly).
_JSON_STRING = re.compile(r'"(?:[^"\\]|\\.)*"')
_COLON = re.compile(r"\s*:\s*")


def _mesh_names(text):
    """The values of every "mesh" key whose value is a string: what the scene's parser loads. A
    scan of the string tokens, because parsing a scene whose meshes are inline (megabytes of
    numbers) took 0.14 s in json.loads."""
    names = set()
    tokens = list(_JSON_STRING.finditer(text)) if '"mesh"' in text else []
    for key, value in zip(tokens, tokens[1:]):
        if key.group() == '"mesh"':
            colon = _COLON.match(text, key.end())
            if colon and colon.end() == value.start():
                names.add(json.loads(value.group()))
    return names


def _gltf_buffers(name, data):
    """The buffer files a .gltf names (not data: URIs), as the scene's parser asks for them:
    relative to the glTF's own folder unless absolute."""
    try:
        gltf = json.loads(data)
    except ValueError:
        return []  # not JSON: the core reports what is wrong with it
    folder = name[:name.rfind("/") + 1]
    uris = [b.get("uri") for b in gltf.get("buffers", []) if isinstance(b, dict)] if isinstance(gltf, dict) else []
    return [u if u.startswith("/") else folder + u for u in uris if isinstance(u, str) and u and not u.startswith("data:")]


def _self_contained(scene):
    """(scene JSON text, source name, {file name: bytes}): every mesh file the scene names (and
    every buffer file of a .gltf among them) is read here, so that the core needs no files; the
    text itself is kept unchanged. A scene that is not valid JSON is kept too, and fails on the
    workers with the core's message."""
    text, source, directory = _scene_json(scene)
    names = sorted(_mesh_names(text))
    files = {}
    while names:
        name = names.pop(0)
        if name in files:
            continue
        path = name if os.path.isabs(name) else os.path.join(directory, name)
        try:
            with open(path, "rb") as file:
                files[name] = file.read()
        except OSError as error:
            raise HullkitError(f"{source}: {name}: cannot open: {error.strerror}") from None
        if name.lower().endswith(".gltf"):
            names.extend(_gltf_buffers(name, files[name]))
    return text, source, files


def _digest(text, files):
    """What identifies a self-contained scene: its text and its files' bytes."""
    digest = hashlib.sha256(text.encode())
    for name in sorted(files):
        digest.update(b"\0" + name.encode() + b"\0" + hashlib.sha256(files[name]).digest())
    return digest.hexdigest()


class _SceneNotHere:
    """What a task returns when its worker has no checker for the scene and cannot read the same
    bytes from the scene's files (another machine, or files changed since): the client then sends
    the bytes it read. Returned, not raised, so that the workers log no failed task."""


_checkers = {}  # per worker process: scene digest -> the core's RouteChecker, built once and reused
_MAX_LOST_ROUNDS = 3  # check_routes: times batches may be cancelled (their scene lost) and run again
_scattered = {}  # here: (client id, scene digest) -> the future of the scene scattered to every worker
_read_on_workers = True  # workers may read a scene file themselves (tests turn it off on workers)


def _scene_here(where):
    """(text, files) of the scene file at ``where`` (an absolute path) and of the mesh files it
    names, read on this worker; None where they cannot be read."""
    if where is None or not _read_on_workers:
        return None
    try:
        text, _, files = _self_contained(where)
    except HullkitError:
        return None
    return text, files


_WAYPOINT = re.compile(r"\bwaypoint (\d+)")  # in the core's messages about a route


@_on_worker
def _check_batch(scene, points, sizes, turns, turn_sizes, where, clearance, samples, threads):
    """The reports of a batch of routes or pieces of routes, as the text of a JSON array (one
    frame to send back, parsed by the client; a list of dicts would be serialized object by
    object). The pieces come packed the same way (_packed): ``points`` (n, 3) holds every piece's
    waypoints in turn, ``sizes`` how many each has; ``turns`` every turning piece's rotations
    (k, 4) in turn, ``turn_sizes`` how many each piece has (0: it translates); ``where`` (m, 2)
    the route each piece belongs to and the index there of its first waypoint, for messages.
    ``scene``: (digest, source name, path, content) with content (text, files) when sent, or None
    when the worker is to read the files at path (the client's absolute path) and check that they
    hold the bytes the client read (the digest)."""
    digest, source, where_scene, content = scene
    checker = _checkers.get(digest)
    if checker is None:
        if content is None:
            content = _scene_here(where_scene)
            if content is None or _digest(*content) != digest:
                return _SceneNotHere()
        if len(_checkers) >= 8:
            _checkers.clear()
        text, files = content
        with _translated():
            checker = _checkers[digest] = _core.RouteChecker(text, source, ".", files)
    ends, turn_ends = np.cumsum(sizes).tolist(), np.cumsum(turn_sizes).tolist()
    reports = []
    try:
        with _translated():
            for end, size, turn_end, turn_size in zip(ends, sizes.tolist(), turn_ends, turn_sizes.tolist()):
                reports.append(checker.check(points[end - size:end], turns[turn_end - turn_size:turn_end], clearance, samples, threads))
    except HullkitError as error:  # the core counts waypoints from the piece's first
        route, first = where[len(reports)].tolist()
        message = _WAYPOINT.sub(lambda m: f"waypoint {int(m.group(1)) + first}", str(error), count=1)
        raise HullkitError(f"routes[{route}]: {message}") from None
    return "[" + ",".join(reports) + "]"


def _batches(routes, rotations, legs):
    """The routes cut into batches of ``legs`` legs (the last may have fewer): each a list of
    pieces (route index, index of its first waypoint, waypoints, rotations or None). A route with
    more legs than its batch has room for continues in the next batch, from the waypoint where
    the piece before it ends: each leg is checked on its own, so the pieces' reports together
    are the route's."""
    batches, current, room = [], [], legs
    for k, (route, turn) in enumerate(zip(routes, rotations)):
        first, count = 0, len(route) - 1
        while first < count:
            take = min(count - first, room)
            end = first + take + 1
            current.append((k, first, route[first:end], None if turn is None else turn[first:end]))
            first, room = first + take, room - take
            if room == 0:
                batches.append(current)
                current, room = [], legs
    if current:
        batches.append(current)
    return batches


def _packed(pieces):
    """A batch's pieces as _check_batch takes them: five arrays."""
    sizes = np.array([len(points) for _, _, points, _ in pieces], dtype=np.int64)
    turn_sizes = np.array([0 if turn is None else len(turn) for _, _, _, turn in pieces], dtype=np.int64)
    turning = [turn for _, _, _, turn in pieces if turn is not None]
    where = np.array([(route, first) for route, first, _, _ in pieces], dtype=np.int64).reshape(-1, 2)
    return (np.concatenate([points for _, _, points, _ in pieces]), sizes,
            np.concatenate(turning) if turning else np.zeros((0, 4)), turn_sizes, where)


def _joined(batches, parts):
    """The routes' reports from the batches' pieces and their reports (``parts``, one list per
    batch): a route's later pieces are appended to its first piece's report. Its legs follow on;
    it is clear when every piece is; its min_clearance is the least of the pieces' (None where a
    piece has none), the first of equals, as the core takes it leg after leg; its seconds add up."""
    reports = []
    for pieces, part in zip(batches, parts):
        for (_, first, _, _), report in zip(pieces, part):
            if first == 0:
                reports.append(report)
                continue
            whole = reports[-1]
            whole["legs"].extend(report["legs"])
            whole["clear"] = whole["clear"] and report["clear"]
            least = report["min_clearance"]
            if least is not None and (whole["min_clearance"] is None or least < whole["min_clearance"]):
                whole["min_clearance"] = least
            whole["seconds"] += report["seconds"]
    return reports


def _scene_scattered(client, digest):
    """The future of the scene with this digest on every worker of ``client``, or None where it
    was never scattered or was lost with its workers."""
    future = _scattered.get((client.id, digest))
    return future if future is not None and future.status == "finished" else None


def _scene_on_workers(client, sent):
    """The scene ``sent`` (_check_batch's scene with its content) scattered to every worker once
    per client: later calls with the same scene (the same text and file bytes) reuse it, and the
    workers their checkers."""
    future = _scene_scattered(client, sent[0])
    if future is None:  # never sent, or lost with its workers: sent (again)
        if len(_scattered) >= 8:
            _scattered.clear()
        # One object: a tuple handed to scatter() would be scattered element by element.
        future = _scattered[(client.id, sent[0])] = client.scatter([sent], broadcast=True, hash=False)[0]
    return future


def check_routes(scene, routes, client=None, clearance=True, samples=0, threads=1, batch=None, send_scene=False,
                 rotations=None):
    """Checks every route of ``routes`` (a list of (k, 3) waypoint arrays) against ``scene`` (a
    dict or a scene file) on the cluster; returns their reports (as RouteChecker.check gives
    them) in order. ``rotations``: None (every route translates), or one entry per route: None,
    or a (k, 4) array of unit quaternions w x y z, one per waypoint (legs between different
    orientations turn, as with RouteChecker.check). ``batch``: legs per task (default: the legs
    split evenly into two tasks per worker; more tasks cost the scheduler more than they
    balance). Tasks take whole routes where they fit; a route longer than a task's room is cut
    at a waypoint and continued in the next task (one long route is spread over the workers
    too), and its pieces' reports are joined into one: the same report, leg for leg.
    A route the core rejects (a coordinate out of range, a rotation that is not a unit
    quaternion) raises HullkitError naming the route and the waypoint.

    The scene and its mesh files are read here. A scene given as a file is read again by each
    worker from the same path when it can (a shared or local file system), and used there only
    if it holds the same bytes (the same SHA-256 digest over the text and every file); workers
    that cannot are sent the bytes read here, once. ``send_scene=True`` sends them to every
    worker without trying (a cluster whose workers do not see this machine's files). Batches of a
    worker that dies run again elsewhere; if the scene sent to the workers dies with every copy,
    the batches that needed it are cancelled, and they run again with the scene sent anew (up to
    three times, then HullkitError)."""
    if batch is not None and (isinstance(batch, bool) or not isinstance(batch, (int, np.integer)) or batch < 1):
        raise HullkitError(f"batch must be a positive integer, got {batch!r}")
    if not isinstance(send_scene, bool):
        raise HullkitError(f"send_scene must be True or False, got {send_scene!r}")
    text, source, files = _self_contained(scene)
    digest = _digest(text, files)
    routes = [as_points(r, 3, f"routes[{k}]") for k, r in enumerate(routes)]
    for k, route in enumerate(routes):
        if len(route) < 2:
            raise HullkitError(f"routes[{k}] must have shape (k, 3) with k >= 2, got {route.shape}")
    if rotations is not None:
        rotations = list(rotations)
        if len(rotations) != len(routes):
            raise HullkitError(f"rotations has {len(rotations)} entries for {len(routes)} routes (one per route, None for one that translates)")
        rotations = [None if turn is None else as_points(turn, 4, f"rotations[{k}]") for k, turn in enumerate(rotations)]
        for k, (route, turn) in enumerate(zip(routes, rotations)):
            if turn is not None and len(turn) != len(route):
                raise HullkitError(f"rotations[{k}] has {len(turn)} rows for the {len(route)} waypoints of routes[{k}]")
    if not routes:
        return []
    if rotations is None:
        rotations = [None] * len(routes)
    # A bad scene fails on the workers with the core's message (HullkitError), as it would here.
    if batch is None:
        workers = len(client.scheduler_info()["workers"]) if client is not None else os.cpu_count() or 1
        batch = math.ceil(sum(len(route) - 1 for route in routes) / (2 * max(1, workers)))
    batches = _batches(routes, rotations, int(batch))
    chunks = [_packed(pieces) for pieces in batches]
    sent = (digest, source, None, (text, files))  # the scene with its content, for workers that cannot read it
    if client is None:
        shared = delayed(sent, traverse=False)
        results = dask.compute(*[delayed(_check_batch)(shared, *chunk, clearance, samples, threads) for chunk in chunks])
        return _joined(batches, [json.loads(part) for part in results])
    if send_scene or not isinstance(scene, (str, os.PathLike)) or _scene_scattered(client, digest) is not None:
        shared = _scene_on_workers(client, sent)
    else:  # the workers read the scene file themselves where they can
        shared = (digest, source, os.path.abspath(os.fspath(scene)), None)
    results = [None] * len(chunks)
    pending = list(range(len(chunks)))
    lost_rounds = 0
    from distributed import as_completed
    while pending:
        # One map for every batch: each submission also walks the stack (for the dashboard).
        futures = client.map(_check_batch, [shared] * len(pending), *zip(*[chunks[k] for k in pending]),
                             clearance=clearance, samples=samples, threads=threads, pure=False)
        position = {future.key: k for k, future in zip(pending, futures)}
        missing, lost = [], []
        # Each batch's reports fetched as soon as it is done, so that the fetches (and, on a first
        # call, the connections to the workers) overlap the batches still running.
        for future, part in as_completed(futures, with_results=True):
            if isinstance(part, _SceneNotHere):
                missing.append(position[future.key])
            elif future.cancelled():
                # The scattered scene went with a worker that died: Dask's active memory manager
                # keeps one copy of scattered data once no task waits for it elsewhere, and data
                # that was never computed cannot be computed again. Its batches are cancelled with
                # it; they run again with the scene sent anew.
                lost.append(position[future.key])
            else:
                results[position[future.key]] = json.loads(part)
        if lost:
            lost_rounds += 1
            if lost_rounds > _MAX_LOST_ROUNDS:
                raise HullkitError(f"check_routes: {len(lost)} of {len(chunks)} batches were cancelled on the cluster "
                                   f"{lost_rounds} times (the scene sent to the workers was lost, or the tasks were "
                                   "cancelled); no reports")
        pending = sorted(missing + lost)
        if pending:  # some workers could not read the scene, or lost it: it is sent to every worker
            shared = _scene_on_workers(client, sent)
    return _joined(batches, results)


# ---- interpolation ------------------------------------------------------------------------------

class _Recipe:
    """What a worker needs to build an interpolator: its class, inputs and options, and the
    threads each block is evaluated on. Pickled once per worker; the worker keeps one built
    interpolator per recipe object (_built)."""

    __slots__ = ("cls", "inputs", "options", "threads", "__weakref__")

    def __init__(self, interpolator, threads):
        self.cls, self.inputs = type(interpolator), interpolator._inputs
        self.options, self.threads = dict(getattr(interpolator, "_options", {})), threads

    def __getstate__(self):
        return (self.cls, self.inputs, self.options, self.threads)

    def __setstate__(self, state):
        self.cls, self.inputs, self.options, self.threads = state

    def build(self):
        from . import interpolate as _interpolate
        # As unpickling does, with this recipe's threads in place of the interpolator's.
        return _interpolate._rebuild(self.cls, self.inputs[:-1] + (self.threads,), self.options)


_built = weakref.WeakKeyDictionary()
_built_lock = threading.Lock()
_builds = 0  # interpolators this process has built (the tests check: one per worker)


def _interpolator_for(recipe):
    """The worker's interpolator for ``recipe``: built by the first task that needs it (under a
    lock: the other tasks wait for it rather than build it again), with its triangulation."""
    global _builds
    with _built_lock:
        interpolator = _built.get(recipe)
        if interpolator is None:
            interpolator = recipe.build()
            _builds += 1
            interpolator._triangulation()
            _built[recipe] = interpolator
        return interpolator


@_on_worker
def _interpolate_block(recipe, block, options):
    return _interpolator_for(recipe)(np.asarray(block, dtype=np.float64), **options)


def interpolate(interpolator, xi, threads=1, **options):
    """``interpolator`` (a LinearNDInterpolator, NearestNDInterpolator or
    CloughTocher2DInterpolator of hullkit.interpolate) evaluated at the queries ``xi``, a Dask
    array of shape (..., ndim): a Dask array of shape xi.shape[:-1] + the values' trailing shape,
    computed block by block on Dask's scheduler (a distributed.Client's when one is current).
    The interpolator's points and values are sent once to each worker that evaluates a block and
    the interpolator built there once (``threads``: the threads each block is evaluated on; the
    workers are the parallelism). ``options``: query options (NearestNDInterpolator's
    ``distance_upper_bound``). The values are the same bits as ``interpolator(xi)`` here."""
    from . import interpolate as _interpolate
    try:
        import dask.array as da
    except ImportError:  # pragma: no cover - dask.array needs numpy, which hullkit has
        raise HullkitError("hullkit.dask.interpolate needs dask.array") from None
    kinds = (_interpolate.LinearNDInterpolator, _interpolate.NearestNDInterpolator,
             _interpolate.CloughTocher2DInterpolator)
    if not isinstance(interpolator, kinds):
        raise HullkitError(f"hullkit.dask.interpolate needs an interpolator of hullkit.interpolate, "
                           f"got {type(interpolator).__name__}")
    if not isinstance(xi, da.Array):
        raise HullkitError(f"hullkit.dask.interpolate: xi must be a Dask array of shape (..., {interpolator.ndim}), "
                           f"got {type(xi).__name__}")
    if xi.ndim < 1 or xi.shape[-1] != interpolator.ndim:
        raise HullkitError(f"hullkit.dask.interpolate: xi must have shape (..., {interpolator.ndim}), got {xi.shape}")
    _threads_checked = _threads(threads)
    if options and not interpolator._query_options:
        raise HullkitError(f"{type(interpolator).__name__} takes no query options, got {sorted(options)}")
    if len(xi.chunks[-1]) != 1:
        xi = xi.rechunk({xi.ndim - 1: interpolator.ndim})
    trailing = tuple(interpolator.values_shape)
    dtype = interpolator.values.dtype
    if isinstance(interpolator, _interpolate.NearestNDInterpolator):
        if np.isfinite(options.get("distance_upper_bound", np.inf)):
            dtype = np.result_type(dtype, np.float64)
    elif isinstance(interpolator, _interpolate.CloughTocher2DInterpolator) and np.iscomplexobj(interpolator.grad):
        dtype = np.complex128
    # Keys from the content (the class, points, values, options and threads): the same
    # interpolation is the same graph, and two different ones never share a key.
    recipe = _Recipe(interpolator, _threads_checked)
    token = dask.base.tokenize(recipe.cls.__qualname__, recipe.inputs, recipe.options, recipe.threads)
    shared = delayed(recipe, name=f"hullkit-interpolator-{token}", traverse=False)
    last = xi.ndim - 1
    return da.map_blocks(_interpolate_block, shared, xi, options, dtype=dtype, drop_axis=last,
                         new_axis=list(range(last, last + len(trailing))) or None,
                         chunks=xi.chunks[:-1] + tuple((size,) for size in trailing),
                         name=f"hullkit-interpolate-{dask.base.tokenize(token, xi.name, options)}")

