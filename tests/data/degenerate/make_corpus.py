#!/usr/bin/env python3
"""Writes the degenerate-input corpus of tests/hull/degenerate.cpp into this directory.

Every file is plain text: two '#' comment lines (what the file reproduces, and the exact affine
dimension of its points as "# dimension: N", computed here with rational arithmetic), then one
point per line, "x y z" with %.17g so that the doubles read back exactly. Fixed seeds: running the
script again rewrites the same files. Python 3 standard library only.

    python3 tests/data/degenerate/make_corpus.py
"""

import math
import os
import random
from fractions import Fraction

HERE = os.path.dirname(os.path.abspath(__file__))


# ---- exact affine dimension ----

def _sub(p, q):
    return tuple(Fraction(a) - Fraction(b) for a, b in zip(p, q))


def _cross(u, v):
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def _dot(u, v):
    return sum(a * b for a, b in zip(u, v))


def affine_dimension(points):
    """-1 for no points, else the dimension of the points' affine hull, exactly."""
    if not points:
        return -1
    p0 = points[0]
    d1 = next((_sub(p, p0) for p in points if any(_sub(p, p0))), None)
    if d1 is None:
        return 0
    normal = next((c for c in (_cross(d1, _sub(p, p0)) for p in points) if any(c)), None)
    if normal is None:
        return 1
    if any(_dot(normal, _sub(p, p0)) != 0 for p in points):
        return 3
    return 2


# ---- writing ----

def fmt(value):
    text = "%.17g" % value
    assert float(text) == value
    return text


WRITTEN = []  # (name, description, dimension, point count, source address or None)


def write(name, description, points, source=None):
    points = [tuple(float(c) for c in p) for p in points]
    for p in points:
        assert all(math.isfinite(c) for c in p), name
    path = os.path.join(HERE, name)
    dimension = affine_dimension(points)
    WRITTEN.append((name, description, dimension, len(points), source))
    with open(path, "w", encoding="ascii", newline="\n") as out:
        out.write("# %s\n" % description)
        out.write("# dimension: %d\n" % dimension)
        for p in points:
            out.write("%s %s %s\n" % (fmt(p[0]), fmt(p[1]), fmt(p[2])))
    return name


def shuffled(points, seed):
    points = list(points)
    random.Random(seed).shuffle(points)
    return points


def grid(n, spacing=1):
    return [(i * spacing, j * spacing, k * spacing) for i in range(n) for j in range(n) for k in range(n)]


def apply(matrix, p):
    return tuple(sum(matrix[r][c] * p[c] for c in range(3)) for r in range(3))


def rotation(axis, angle):
    x, y, z = axis
    norm = math.sqrt(x * x + y * y + z * z)
    x, y, z = x / norm, y / norm, z / norm
    c, s = math.cos(angle), math.sin(angle)
    t = 1 - c
    return [[t * x * x + c, t * x * y - s * z, t * x * z + s * y],
            [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
            [t * x * z - s * y, t * y * z + s * x, t * z * z + c]]


def unit_cloud(count, seed):
    rng = random.Random(seed)
    return [(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) for _ in range(count)]


# ---- the corpus ----

def synthetic():
    files = []
    add = files.append

    add(write("grid-5x5x5.txt", "integer grid 0..4 in x, y, z: 125 points, 98 of them on the cube's faces",
              grid(5)))
    add(write("grid-5x5x5-shuffled.txt", "the 5x5x5 integer grid in a shuffled order", shuffled(grid(5), 1)))

    # Rotations by Pythagorean-triple matrices (3-4-5 about z, 5-12-13 about x) of a grid with spacing
    # 65: every coordinate stays an integer, so the rotated grid is exactly a grid again.
    rz = [[Fraction(3, 5), Fraction(-4, 5), 0], [Fraction(4, 5), Fraction(3, 5), 0], [0, 0, 1]]
    rx = [[1, 0, 0], [0, Fraction(5, 13), Fraction(-12, 13)], [0, Fraction(12, 13), Fraction(5, 13)]]
    rotated = []
    for p in grid(5, 65):
        q = apply(rx, apply(rz, [Fraction(c) for c in p]))
        assert all(c.denominator == 1 for c in q)
        rotated.append(tuple(int(c) for c in q))
    add(write("grid-5x5x5-pythagorean-rotation.txt",
              "the 5x5x5 grid (spacing 65) rotated exactly by 3-4-5 and 5-12-13 rotations: integer, "
              "exactly coplanar faces in no axis plane", rotated))

    r = rotation((1.0, 2.0, 3.0), 0.7)
    add(write("grid-5x5x5-float-rotation.txt",
              "the 5x5x5 grid rotated in floating point: its faces become nearly, not exactly, coplanar",
              [apply(r, p) for p in grid(5)]))

    fcc = [(x, y, z) for x in range(7) for y in range(7) for z in range(7) if (x + y + z) % 2 == 0]
    add(write("lattice-fcc-7.txt", "face-centred cubic lattice points (x + y + z even) in 0..6", fcc))
    bcc = [(x, y, z) for x in range(5) for y in range(5) for z in range(5)]
    bcc += [(x + 0.5, y + 0.5, z + 0.5) for x in range(4) for y in range(4) for z in range(4)]
    add(write("lattice-bcc-float-rotation.txt",
              "body-centred cubic lattice rotated in floating point", [apply(rotation((2, -1, 5), 1.1), p) for p in bcc]))

    rng = random.Random(2)
    planes = [(rng.randint(-20, 20), rng.randint(-20, 20), z) for z in (0, 7) for _ in range(60)]
    add(write("two-parallel-planes.txt", "random integer points on the planes z = 0 and z = 7 only", planes))

    rng = random.Random(3)
    # Points i*u + j*v (+ w) with integer u, v spanning x + 2y + 3z = 0; w lifts them to = 15.
    u, v, w = (3, 0, -1), (0, 3, -2), (1, 1, 4)
    tilted = [tuple(i * a + j * b + s * c for a, b, c in zip(u, v, w))
              for i, j in ((rng.randint(-6, 6), rng.randint(-6, 6)) for _ in range(60)) for s in (0, 1)]
    add(write("two-parallel-tilted-planes.txt",
              "integer points on two parallel planes that are not axis planes", tilted))

    cube27 = [(x, y, z) for x in (-1, 0, 1) for y in (-1, 0, 1) for z in (-1, 0, 1)]
    add(write("cube-corners-face-edge-midpoints.txt",
              "cube corners plus the midpoints of its 12 edges and 6 faces, and its centre", shuffled(cube27, 4)))
    add(write("cube-face-and-edge-points-only.txt",
              "the cube's corners, edge midpoints and face centres and three more boundary points, none inside",
              [p for p in cube27 if p != (0, 0, 0)] + [(1, 0.5, -0.25), (0.75, 1, 1), (-1, -1, 0.125)]))

    for r2 in (25, 50, 75, 325):
        m = int(math.isqrt(r2))
        sphere = [(x, y, z) for x in range(-m, m + 1) for y in range(-m, m + 1) for z in range(-m, m + 1)
                  if x * x + y * y + z * z == r2]
        add(write("cospherical-integer-r2-%d.txt" % r2,
                  "all %d integer points with x^2 + y^2 + z^2 = %d: every point is a vertex, and faces "
                  "are polygons of up to 8 cocircular points" % (len(sphere), r2), sphere))

    line = [(1 + 2 * t, 2 - t, 3 + 5 * t) for t in (0, 5, -3, 2, 2, 9, -7, 1, 0, 4)]
    add(write("collinear-integer.txt", "integer points on one line, with repeats", line))
    add(write("collinear-dyadic.txt", "points t * (0.5, 0.25, 0.125) with exact dyadic coordinates",
              [(t * 0.5, t * 0.25, t * 0.125) for t in shuffled(range(-20, 21), 5)]))
    add(write("collinear-axis.txt", "points on the y axis", [(0, y, 0) for y in (3, -1, 8, 0, 8, 2)]))

    rng = random.Random(6)
    plane = [(x, y, 10 - x - y) for x, y in ((rng.randint(-10, 10), rng.randint(-10, 10)) for _ in range(100))]
    add(write("coplanar-integer-tilted.txt", "integer points on the plane x + y + z = 10", plane))
    circle = [(x, y, 3) for x in range(-5, 6) for y in range(-5, 6) if x * x + y * y == 25]
    add(write("coplanar-cocircular.txt", "the 12 integer points of the circle x^2 + y^2 = 25 in the plane z = 3",
              circle + [(0, 0, 3), (1, 2, 3)]))
    add(write("coplanar-grid-axis.txt", "a 6x6 grid in the plane y = -2", [(x, -2, z) for x in range(6) for z in range(6)]))
    add(write("coplanar-square-with-repeats.txt", "a square's corners, each three times, and its centre",
              [(0, 0, 5), (4, 0, 5), (4, 4, 5), (0, 4, 5)] * 3 + [(2, 2, 5)]))

    cloud = unit_cloud(30, 7)
    dup = [p for p in cloud for _ in range(10)]
    add(write("duplicated-10x.txt", "30 random points, each repeated 10 times in a row", dup))
    add(write("duplicated-10x-shuffled.txt", "30 random points, each repeated 10 times, shuffled", shuffled(dup, 8)))

    rng = random.Random(9)
    flat = [(x, y, 0.0) for x in range(6) for y in range(6)]
    bumped = [(x, y, rng.choice((-1e-12, 0.0, 0.0, 1e-12))) for x, y, _ in flat]
    add(write("coplanar-perturbed-1e-12.txt", "a 6x6 grid in z = 0 with z moved by +-1e-12 at random points", bumped))
    bumped_one = list(flat)
    bumped_one[14] = (bumped_one[14][0], bumped_one[14][1], 1e-12)
    add(write("coplanar-one-point-lifted-1e-12.txt", "a 6x6 grid in z = 0 with one inner point lifted by 1e-12",
              bumped_one))
    lifted = [(x, y, 2 ** -40 * ((x * 7 + y * 3) % 5 - 2)) for x, y, _ in flat]
    add(write("coplanar-perturbed-2pow-40.txt", "a 6x6 grid in z = 0 with z = k * 2^-40, k in -2..2", lifted))
    rng = random.Random(10)
    tilted_bumped = []
    for x, y in ((rng.randint(0, 9), rng.randint(0, 9)) for _ in range(60)):
        z = (x * 0.1 + y * 0.3)  # rounded: near, not on, the plane z = 0.1 x + 0.3 y
        tilted_bumped.append((x, y, z + rng.choice((0.0, 1e-12, -1e-12))))
    add(write("near-coplanar-tilted-rounded.txt",
              "points near the plane z = 0.1 x + 0.3 y, rounded and moved by +-1e-12", tilted_bumped))

    add(write("offset-1e9-unit-cloud.txt", "100 points in the unit cube offset by 1e9: coordinates keep ~7 digits",
              [(1e9 + x, 1e9 + y, 1e9 + z) for x, y, z in unit_cloud(100, 11)]))
    add(write("offset-1e9-unit-grid.txt", "the 5x5x5 grid scaled by 0.25 and offset by 1e9",
              [(1e9 + x * 0.25, 1e9 + y * 0.25, 1e9 + z * 0.25) for x, y, z in grid(5)]))
    for scale in ("1e-150", "1e150"):
        s = float(scale)
        add(write("scaled-%s-cloud.txt" % scale, "100 random points and a 3x3x3 grid scaled by %s" % scale,
                  [(x * s, y * s, z * s) for x, y, z in unit_cloud(100, 12) + grid(3)]))

    add(write("single-point-repeated.txt", "one point, seven times", [(1.5, -2.25, 1e-3)] * 7))
    add(write("single-point.txt", "one point", [(0, 0, 0)]))
    add(write("two-points.txt", "two distinct points", [(1, 2, 3), (-4, 5, 0.5)]))
    add(write("two-points-repeated.txt", "two distinct points, repeated", [(1, 1, 1), (2, 3, 4)] * 4))
    add(write("three-collinear-points.txt", "three collinear points, the middle one first",
              [(1, 1, 1), (0, 0, 0), (2, 2, 2)]))
    add(write("four-coplanar-points.txt", "a triangle and a point on one of its edges",
              [(0, 0, 0), (4, 0, 0), (0, 4, 0), (2, 0, 0)]))
    add(write("tetrahedron-with-face-and-edge-points.txt",
              "a tetrahedron plus points inside a face, on an edge and inside",
              [(0, 0, 0), (6, 0, 0), (0, 6, 0), (0, 0, 6), (1, 1, 0), (3, 0, 0), (1, 1, 1), (2, 2, 2)]))
    return files


def from_bug_reports():
    """Fixtures reconstructed from public bug reports of other hull libraries (see README.md)."""
    files = []
    add = files.append

    add(write("quickhull3d-issue-2-seven-points.txt",
              "mauriciopoppe/quickhull3d#2 'hangs with simple 7 point hull': the 7 integer points of the report",
              [(104, 216, 53), (104, 217, 52), (105, 216, 52), (88, 187, 43), (89, 187, 44), (89, 188, 43),
               (90, 187, 43)],
              source="https://github.com/mauriciopoppe/quickhull3d/issues/2"))

    issue5 = [(38, 89), (85, 91), (94, 89), (70, 40), (63, 90), (60, 52), (20, 16), (38, 13), (25, 82), (7, 80),
              (28, 80), (43, 64), (48, 68), (86, 64), (52, 60), (56, 75), (47, 3), (68, 13), (50, 44), (82, 54),
              (96, 45), (85, 1), (30, 24), (54, 3), (65, 95), (95, 7), (97, 42), (44, 73), (79, 55), (72, 34),
              (8, 18), (79, 46), (92, 32), (61, 29), (21, 7), (24, 25), (41, 32), (72, 91), (1, 63), (18, 8),
              (44, 99), (59, 90), (12, 15), (81, 60), (21, 10), (9, 71), (12, 86), (99, 41), (32, 48), (40, 20),
              (47, 89), (41, 9), (29, 80), (56, 63), (36, 11), (25, 14), (44, 40), (60, 41), (32, 81), (64, 56),
              (41, 90), (29, 73), (68, 97), (91, 90), (57, 0), (67, 34), (64, 8), (66, 65), (39, 90), (72, 62),
              (63, 13), (45, 94), (2, 34)]
    add(write("quickhull3d-issue-5-planar-points.txt",
              "mauriciopoppe/quickhull3d#5 'Crashes on these points': the report's 73 integer points, all with z = 0",
              [(x, y, 0) for x, y in issue5],
              source="https://github.com/mauriciopoppe/quickhull3d/issues/5"))

    pentagon = [(-8, 1, 0), (-7, 4, 0), (-6, 5, -2), (-7, 0, -4), (-8, 0, -1)]
    add(write("quickhull3d-issue-30-five-points.txt",
              "mauriciopoppe/quickhull3d#30 (via jscad/OpenJSCAD.org#1347): the five points of the report, "
              "reported as a flat pentagon losing a vertex", pentagon,
              source="https://github.com/mauriciopoppe/quickhull3d/issues/30"))
    for label, eps in (("1e-15", 1e-15), ("1e-10", 1e-10)):
        moved = list(pentagon)
        moved[1] = (-7 + eps, 4, 0)
        add(write("quickhull3d-issue-30-five-points-moved-%s.txt" % label,
                  "quickhull3d#30 / OpenJSCAD#1347 variant: the second point's x moved by %s" % label, moved,
                  source="https://github.com/jscad/OpenJSCAD.org/issues/1347"))

    add(write("threejs-issue-8416-box-with-side-points.txt",
              "mrdoob/three.js#8416 'ConvexGeometry fragility': the 16 points of the report (a box with "
              "extra points on its vertical edges)",
              [(50, 50, -40), (50, 50, -50), (-50, 50, -50), (-50, 50, -40), (50, -50, -40), (50, -50, -50),
               (-50, -50, -50), (-50, -50, -40), (50, 50, 50), (50, 50, 40), (-50, 50, 40), (-50, 50, 50),
               (50, -50, 50), (50, -50, 40), (-50, -50, 40), (-50, -50, 50)],
              source="https://github.com/mrdoob/three.js/issues/8416"))

    rng = random.Random(12327)
    planar = [(rng.randint(-50, 50), rng.randint(-50, 50), 0) for _ in range(40)]
    add(write("threejs-issue-12327-planar-input.txt",
              "mrdoob/three.js#12327 'QuickHull do not work with coplanar points' (reconstructed: the report's "
              "points are in a fiddle): 40 random integer points in the plane z = 0", planar,
              source="https://github.com/mrdoob/three.js/issues/12327"))

    box = []
    for axis in range(3):
        for sign in (-5, 5):
            for a in (-5, 5):
                for b in (-5, 5):
                    p = [0, 0, 0]
                    p[axis], p[(axis + 1) % 3], p[(axis + 2) % 3] = sign, a, b
                    box.append(tuple(p))
    add(write("threejs-issue-30407-box-geometry-vertices.txt",
              "mrdoob/three.js#30407 (ConvexHull does not merge coplanar faces): the 24 vertices of "
              "BoxGeometry(10, 10, 10), every corner three times", box,
              source="https://github.com/mrdoob/three.js/issues/30407"))

    add(write("karimnaaji-3d-quickhull-issue-2-cube-face-points.txt",
              "karimnaaji/3d-quickhull#2 'Issue with many points on one plane': the report's box with points "
              "inside and on the edges of its bottom face",
              [(0, 50, 0), (100, 100, 0), (0, 100, 0), (-100, 100, 0), (-100, 0, 0), (100, -100, 0), (0, -50, 0),
               (50, -50, 0), (-100, -100, 0), (0, -100, 0), (100, 0, 0), (100, 100, 200), (-100, 100, 200),
               (100, -100, 200), (-100, -100, 200)],
              source="https://github.com/karimnaaji/3d-quickhull/issues/2"))
    add(write("karimnaaji-3d-quickhull-issue-2-octagonal-prism.txt",
              "karimnaaji/3d-quickhull#2: the report's octagonal prism (16 points, two octagons of 8 coplanar points)",
              [(40, 100, 0), (100, 40, 0), (100, -40, 0), (40, -100, 0), (-40, -100, 0), (-100, -40, 0),
               (-100, 40, 0), (-40, 100, 0), (40, 100, 100), (100, 40, 100), (100, -40, 100), (40, -100, 100),
               (-40, -100, 100), (-100, -40, 100), (-100, 40, 100), (-40, 100, 100)],
              source="https://github.com/karimnaaji/3d-quickhull/issues/2"))

    add(write("akuukka-quickhull-issue-1-flat-quad.txt",
              "akuukka/quickhull#1 'Not getting all the triangles': the report's four points, which are "
              "coplanar (a flat quad, no tetrahedron)",
              [(-3.0, -0.25, -0.8), (-3.0, 0.25, -0.8), (-3.125, 0.25, -0.75), (-3.125, -0.25, -0.75)],
              source="https://github.com/akuukka/quickhull/issues/1"))

    add(write("unity-quickhull-issue-1-cube-face-centre.txt",
              "OskarSigvardsson/unity-quickhull#1 (fails on coplanar points), the minimal case suggested in the "
              "thread: a cube's 8 corners and the centre of one face",
              [(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)] + [(0.5, 0.5, 1)],
              source="https://github.com/OskarSigvardsson/unity-quickhull/issues/1"))
    add(write("unity-quickhull-issue-1-tetrahedron-face-point.txt",
              "OskarSigvardsson/unity-quickhull#1, the other suggested case: a tetrahedron and a point on one face",
              [(0, 0, 0), (3, 0, 0), (0, 3, 0), (0, 0, 3), (1, 1, 0)],
              source="https://github.com/OskarSigvardsson/unity-quickhull/issues/1"))
    thin = [(x, y, z) for x in (0, 6.05) for y in (0, 0.16) for z in (0, 6.59)] * 3
    add(write("unity-quickhull-issue-4-thin-box-duplicates.txt",
              "OskarSigvardsson/unity-quickhull#4 (box collider skips a vertex, reconstructed): a 6.05 x 0.16 x 6.59 "
              "box given as a 24-vertex mesh, every corner three times", shuffled(thin, 4),
              source="https://github.com/OskarSigvardsson/unity-quickhull/issues/4"))

    uv = []
    for ring in range(0, 7):
        theta = math.pi * ring / 6
        for seg in range(0, 9):  # the seam column repeats column 0; the poles repeat per segment
            phi = 2 * math.pi * (seg % 8) / 8
            uv.append((math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi), math.cos(theta)))
    add(write("convhull_3d-issue-5-uv-sphere-duplicates.txt",
              "leomccormack/convhull_3d#5 'cannot work when there exist many duplicate vertices' (reconstructed): "
              "a UV sphere's vertex buffer, whose north pole and seam repeat vertices (sin(pi) is not 0: the "
              "south pole is a tiny octagon)", uv,
              source="https://github.com/leomccormack/convhull_3d/issues/5"))

    cylinder = []
    for k in range(16):
        a = 2 * math.pi * k / 16
        for z in (-5.0, 5.0):
            cylinder.append((3.5 * math.cos(a), 3.5 * math.sin(a), z))
    sphere = [(0.0, 0.0, 2.0), (0.0, 0.0, -2.0)]
    for ring in range(1, 4):
        theta = math.pi * ring / 4
        for k in range(8):
            a = 2 * math.pi * k / 8
            sphere.append((2 * math.sin(theta) * math.cos(a), 2 * math.sin(theta) * math.sin(a), 2 * math.cos(theta)))
    minkowski = [(p[0] + q[0], p[1] + q[1], p[2] + q[2]) for p in cylinder for q in sphere]
    add(write("manifold-issue-1785-minkowski-coplanar-clusters.txt",
              "elalish/manifold#1785 (inverted faces on large coplanar clusters), reconstructed as the issue "
              "describes: the vertex sums of a 16-sided cylinder (r 3.5, h 10) and a sphere (r 2), whose "
              "rings give exactly coplanar clusters", minkowski,
              source="https://github.com/elalish/manifold/issues/1785"))

    add(write("MIConvexHull-issue-32-collinear-points.txt",
              "DesignEngrLab/MIConvexHull#32 'Convex Hull fails to create for co-linear points': the report's "
              "four points, with z = 0", [(260, 600, 0), (285, 600, 0), (310, 600, 0), (335, 600, 0)],
              source="https://github.com/DesignEngrLab/MIConvexHull/issues/32"))
    return files


README_INTRO = """# Degenerate inputs

Point sets that exercise the degenerate cases of 3D convex hulls: coplanar, collinear, cospherical
and repeated points, near-degenerate rounding, and extreme scales. `tests/hull/degenerate.cpp` computes
the hull of every `*.txt` file here with both algorithms, with and without merged coplanar faces,
checks each result with `hullkit::verify` and with the independent GMP checks, and requires both
algorithms to agree on the dimension, the vertices and the merged faces.

The files are generated by `make_corpus.py` (Python 3 standard library, fixed seeds; it also writes
this README). Each file starts with two comment lines: what it reproduces, and the exact affine
dimension of its points (`# dimension: N`, computed with rational arithmetic), which the test
checks. Then one point per line, `x y z`, printed with `%.17g`.

Regenerate with `python3 tests/data/degenerate/make_corpus.py`.
"""


def table(rows):
    lines = ["| file | points | dimension | what it reproduces |", "| --- | ---: | ---: | --- |"]
    for name, description, dimension, count, source in rows:
        text = description.replace("|", "\\|")
        if source:
            text += " ([report](%s))" % source
        lines.append("| `%s` | %d | %d | %s |" % (name, count, dimension, text))
    return "\n".join(lines) + "\n"


def write_readme(synthetic_names):
    ours = [row for row in WRITTEN if row[0] in synthetic_names]
    theirs = [row for row in WRITTEN if row[0] not in synthetic_names]
    with open(os.path.join(HERE, "README.md"), "w", encoding="utf-8", newline="\n") as out:
        out.write(README_INTRO)
        out.write("\n## Synthetic cases\n\n")
        out.write(table(ours))
        out.write("\n## Reconstructed from bug reports of other hull libraries\n\n")
        out.write("Where a report lists its points, the file holds exactly those points; where it only "
                  "describes them, the file is a reconstruction from the description (said so in the "
                  "file's first line).\n\n")
        out.write(table(theirs))


def main():
    ours = synthetic()
    names = ours + from_bug_reports()
    assert len(names) == len(set(names))
    write_readme(set(ours))
    stale = sorted(set(f for f in os.listdir(HERE) if f.endswith(".txt")) - set(names))
    for name in stale:
        print("not written by this script (remove it?):", name)
    print("wrote %d files" % len(names))


if __name__ == "__main__":
    main()
