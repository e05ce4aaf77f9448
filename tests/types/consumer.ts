// A TypeScript consumer of the packed `hullkit` package, compiled by scripts/type_test.sh with
// --strict under several targets and libs (never skipLibCheck), then run with node. It uses the
// API as the README shows it; every value is checked at run time too, so the types and the
// runtime objects are compared. Needs no lib beyond ES2020: no DOM, no @types/node.
import createHullkit, { HullkitError } from 'hullkit';
import type {
  ConstrainedResult, DelaunayNdResult, HullNdResult, Delaunay3Options, Delaunay3Result, Delaunay3VerifyReport, DelaunayResult, GiftwrapTrace, HullResult, Hullkit, Locate3Result, LocateOptions, MeshRefineOptions,
  LocateResult, MeshData, PolygonOptions,
  RouteChecker, RouteLeg, RouteReport, RouteWaypoint, RouteScene, Vec3, VerifyReport, Voronoi3Result, VoronoiCells, VoronoiDiagram,
} from 'hullkit';

function check(condition: boolean, what: string): void {
  if (!condition) throw new Error(`type test consumer: ${what}`);
}

/** The bytes of an ASCII file's text (no TextEncoder: that needs the DOM or Node lib). */
function ascii(text: string) {
  const bytes = new Uint8Array(text.length);
  for (let i = 0; i < text.length; i++) bytes[i] = text.charCodeAt(i);
  return bytes;
}

const hullkit: Hullkit = await createHullkit();

// hull and verify
const xyz = new Float64Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.2, 0.2, 0.2]);
const result: HullResult = hullkit.hull(xyz);
const { dimension, triangles, vertices, volume, area } = result;
check(dimension === 3 && triangles.length === 12 && vertices.length === 4, 'hull of a tetrahedron');
check(Math.abs(volume - 1 / 6) < 1e-12 && area > 0, 'hull volume and area');
const equations: Float64Array = result.equations;
check(equations.length === 16 && Math.abs(Math.hypot(equations[0] ?? 0, equations[1] ?? 0, equations[2] ?? 0) - 1) < 1e-15, 'equations: unit normals');
check(hullkit.hull(xyz, { equations: false }).equations.length === 0, 'equations: false leaves them out');
// Arrays of points, as quickhull3d, three.js and delaunator take them.
const nested: number[][] = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]];
check(hullkit.hull(nested).volume === 1 / 6, 'hull of [x, y, z] arrays');
const vectors = [{ x: 0, y: 0, z: 0 }, { x: 1, y: 0, z: 0 }, { x: 0, y: 1, z: 0 }, { x: 0, y: 0, z: 1 }];
check(hullkit.hull(vectors, { algorithm: 'giftwrap' }).triangles.length === 12, 'hull of {x, y, z} objects');
check(hullkit.delaunay([[0, 0], [1, 0], [0, 1]]).triangles.length === 3, 'delaunay of [x, y] arrays');
check(hullkit.delaunay([{ x: 0, y: 0 }, { x: 1, y: 0 }, { x: 0, y: 1 }]).hull.length === 3, 'delaunay of {x, y} objects');
const merged = hullkit.hull([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0], { algorithm: 'giftwrap', mergeCoplanar: true });
if (merged.dimension === 2 && merged.normal !== undefined) {
  const normal: Float64Array = merged.normal;
  check(Math.abs(Math.abs(normal[2] ?? 0) - 1) < 1e-12, 'a square lies in z = 0');
}
const faceOffsets: Uint32Array | undefined = merged.faceOffsets;
check(faceOffsets !== undefined, 'mergeCoplanar gives faceOffsets');
const report: VerifyReport = hullkit.verify(xyz, result);
check(report.ok && report.problems.length === 0, 'verify accepts the hull');
const algorithms: readonly ('quickhull' | 'giftwrap')[] = hullkit.algorithms;
check(algorithms[0] === 'quickhull', 'default algorithm first');

// the recorded gift wrap
const trace: GiftwrapTrace = hullkit.giftwrapTrace(xyz, { scan: 'restart' });
const last = trace.kindNames[trace.kinds[trace.kinds.length - 1] ?? 0];
check(last === 'done' && hullkit.traceLimits['single-pass'] >= hullkit.traceLimits.restart, 'trace ends with done');

// errors
try {
  hullkit.hull([0, 0, Number.NaN]);
  check(false, 'NaN is refused');
} catch (error) {
  check(error instanceof HullkitError && error.pointIndex === 0 && error.name === 'HullkitError', 'HullkitError names the point');
}
const made = new HullkitError('made here', { pointIndex: 3 });
check(made.pointIndex === 3 && made.message === 'made here', 'HullkitError constructor');

// readers
const points: Float64Array = hullkit.readPoints(ascii('0 0 0\n1 2 3\n4 5 6\n'), 'p.xyz');
check(points.length === 9 && points[5] === 3, 'readPoints');
const flat: Float64Array = hullkit.readPoints2d(ascii('0 0\n1 0\n0 1\n').buffer, 'p.txt');
check(flat.length === 6, 'readPoints2d');
const mesh: MeshData = hullkit.readMesh(ascii('v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n'), 'tri.obj');
check(mesh.vertices.length === 9 && mesh.triangles.length === 3, 'readMesh');
try {
  hullkit.readPoints(ascii('0 0 0\n1 x 2\n'), 'bad.xyz');
  check(false, 'a bad line is refused');
} catch (error) {
  check(error instanceof HullkitError && error.line === 2, `readPoints names the line (${String(error)})`);
}

// Delaunay, find, Voronoi
const xy = new Float64Array([0, 0, 1, 0, 0, 1, 1, 1, 0.5, 0.4]);
const delaunay: DelaunayResult = hullkit.delaunay(xy);
check(delaunay.dimension === 2 && delaunay.triangles.length % 3 === 0 && delaunay.halfedges instanceof Int32Array, 'delaunay');
const nearest: number = hullkit.find(xy, delaunay, 0.9, 0.9);
check(nearest === 3, 'find');
const cells: VoronoiCells = hullkit.voronoi(xy, delaunay, [-1, -1, 2, 2]);
check(cells.cellOffsets.length === xy.length / 2 + 1, 'voronoi');
const diagram: VoronoiDiagram = hullkit.voronoiDiagram(xy, delaunay);
check(diagram.cellPoint.length === 5 && diagram.pointCell instanceof Int32Array && diagram.areas.some((a) => a === Infinity), 'voronoiDiagram');
check(hullkit.delaunay(xy, { algorithm: 'giftwrap', mergeCocircular: true }).polygonOffsets !== undefined, 'polygons');

// constrained triangulation: earcut's arguments, GeoJSON, graphs
const polygon: ConstrainedResult = hullkit.triangulatePolygon([0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 3, 1, 3, 3, 1, 3], [4], { fill: 'evenodd' });
check(polygon.triangles.length === 24 && polygon.constrained instanceof Uint8Array && polygon.addedCount === 0, 'triangulatePolygon');
const polygonOptions: PolygonOptions = { dim: 3, fill: 'nonzero' };
check(hullkit.triangulatePolygon(new Float64Array([0, 0, 0, 1, 0, 0, 0, 1, 0]), null, polygonOptions).triangles.length === 3, 'dim 3');
check(hullkit.triangulatePolygon({ type: 'Polygon', coordinates: [[[0, 0], [1, 0], [0, 1]]] }).coords.length === 6, 'GeoJSON');
check(hullkit.triangulatePolygon([0, 0, 4, 0, 4, 4, 0, 4], [], { maxArea: 1, keepSegments: 'boundary' }).steinerCount > 0, 'keepSegments');
check(hullkit.triangulatePolygon([0, 0, 4, 0, 4, 4, 0, 4], [], { unsuitable: (a, b, c, area) => area > 1 + a[0] * 0 }).steinerCount > 0, 'unsuitable');
const graph: ConstrainedResult = hullkit.constrainedDelaunay([0, 0, 1, 0, 0, 1, 1, 1], [0, 3]);
check(graph.constrained.reduce((a, b) => a + b, 0) === 2 && hullkit.fillRules[0] === 'evenodd', 'constrainedDelaunay');
const meshOptions: MeshRefineOptions = { maxArea: 0.25, triangleMaxArea: [0.1, 0] };
const refined = hullkit.refineMesh(graph.coords, graph.triangles, meshOptions);
check(refined.steinerCount > 0 && refined.sourceTriangle instanceof Int32Array && refined.sourceTriangle.length === refined.triangles.length / 3, 'refineMesh');
// Point location in it: (0.5, 0.4) is the point 4 itself (a corner: weights 1, 0, 0), (0, 0.5) is on
// the hull edge from 0 to 2 (as near to 0 as to 2), (2, 2) is outside.
const locateOptions: LocateOptions = { barycentric: true, nearest: true };
const where: LocateResult = hullkit.locate(xy, delaunay, [0.5, 0.4, 0, 0.5, 2, 2], locateOptions);
const inTriangle: Int32Array = where.triangle;
const corner = inTriangle[0] ?? -1;
check(inTriangle.length === 3 && corner >= 0 && (inTriangle[1] ?? -1) >= 0 && inTriangle[2] === -1, 'locate: inside, on the hull, outside');
const w: Float64Array | undefined = where.barycentric;
check(w !== undefined && [w[0], w[1], w[2]].filter((x) => x === 1).length === 1 && delaunay.triangles[3 * corner + [w[0], w[1], w[2]].indexOf(1)] === 4, 'locate: exactly 1 at the corner');
check(where.nearest?.[0] === 4 && where.nearest[1] === 0 && where.nearest[2] === 3, 'locate: nearest (ties: the lowest index)');
check(hullkit.locate(xy, delaunay, new Float64Array([0.2, 0.2])).nearest === undefined, 'locate: nearest on request');

// 3D Delaunay: the tetrahedra around the cube's corners and centre, the neighbour across a face, verify
const cubeAndCentre = new Float64Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1, 0.5, 0.5, 0.5]);
let rounds = 0;
const d3options: Delaunay3Options = { progress: (done: number, total: number) => { rounds += done <= total ? 1 : 0; } };
const tetrahedralization: Delaunay3Result = hullkit.delaunay3(cubeAndCentre, d3options);
const { tetrahedra, neighbors: across, hull: outside }: { tetrahedra: Uint32Array; neighbors: Int32Array; hull: Uint32Array } =
  tetrahedralization;
check(tetrahedralization.dimension === 3 && tetrahedra.length === 4 * 12 && outside.length === 3 * 12, 'delaunay3 of a cube and its centre');
for (let t = 0; t < tetrahedra.length / 4; t++) {
  const face = across[4 * t + 3] ?? -1; // the tetrahedron across the face opposite corner 3, or -1
  check(face === -1 || (face >= 0 && face < tetrahedra.length / 4), 'delaunay3 neighbours');
}
check(rounds >= 1, 'delaunay3 progress');
const planar: Delaunay3Result = hullkit.delaunay3([0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1]);
const up: Float64Array = planar.normal;
check(planar.dimension === 2 && planar.triangles.length === 6 && up[2] === 1 && planar.tetrahedra.length === 0, 'coplanar delaunay3');
const checked: Delaunay3VerifyReport = hullkit.verifyDelaunay3(cubeAndCentre, tetrahedra, { perturbed: true });
check(checked.ok && checked.problemCount === 0 && checked.distinctPoints === 9 && checked.hullTriangles === 12, 'verifyDelaunay3');
check(tetrahedralization.duplicateCount === 0 && tetrahedralization.representative.length === 9, 'delaunay3 duplicates');
// Any dimension: the 4-simplex's hull and triangulation, a query inside and one outside
const simplex4 = [[0, 0, 0, 0], [1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]];
const hull4: HullNdResult = hullkit.hullNd(simplex4, 4);
check(hull4.facets.length === 20 && hull4.vertices.length === 5 && hull4.group.length === 5, 'hullNd');
const tri4: DelaunayNdResult = hullkit.delaunayNd(simplex4, 4, { furthestSite: false });
const where4: Int32Array = hullkit.locateNd(simplex4, tri4, [0.1, 0.1, 0.1, 0.1, 2, 2, 2, 2]);
check(tri4.simplices.length === 5 && where4[0] === 0 && where4[1] === -1, 'delaunayNd and locateNd');
// Furthest-site: only the cube's eight corners, never its centre; flagged on the result
const furthestOptions: Delaunay3Options = { furthestSite: true };
const furthestTetrahedra: Delaunay3Result = hullkit.delaunay3(cubeAndCentre, furthestOptions);
const furthestFlag: boolean = furthestTetrahedra.furthestSite;
check(furthestFlag && !tetrahedralization.furthestSite && !furthestTetrahedra.tetrahedra.includes(8), 'delaunay3 furthestSite');
// Queries on it: the tetrahedron holding a point, barycentric weights, the nearest point; Voronoi cells
const located: Locate3Result = hullkit.locate3(cubeAndCentre, tetrahedralization, [0.4, 0.5, 0.5, 2, 2, 2], { barycentric: true, nearest: true });
const holding: Int32Array = located.tetrahedron;
const weights: Float64Array | undefined = located.barycentric;
check(holding.length === 2 && (holding[0] ?? -1) >= 0 && holding[1] === -1, 'locate3: inside, then outside the hull');
check(weights !== undefined && Math.abs((weights[0] ?? 0) + (weights[1] ?? 0) + (weights[2] ?? 0) + (weights[3] ?? 0) - 1) < 1e-12, 'locate3: barycentric');
check(located.nearest?.[0] === 8 && located.nearest[1] === 7, 'locate3: nearest (the centre, then the corner 1 1 1)');
check(hullkit.locate3(cubeAndCentre, tetrahedralization, [0.5, 0.5, 0.5]).barycentric === undefined, 'locate3: barycentric on request');
const cellsOf: Voronoi3Result = hullkit.voronoi3(cubeAndCentre, tetrahedralization);
const centreVolume: number = cellsOf.volume[8] ?? 0;
check(Math.abs(centreVolume - 9 / 16) < 1e-12 && cellsOf.volume[0] === Infinity, 'voronoi3: the centre\'s cell, |x| + |y| + |z| <= 3/4, has volume 9/16');
const faceRing: Uint32Array = cellsOf.faceVertices.subarray(cellsOf.faceOffsets[0] ?? 0, cellsOf.faceOffsets[1] ?? 0);
check(faceRing.length >= 1 && cellsOf.faceBounded instanceof Uint8Array && cellsOf.tetrahedronVertex.length === 12, 'voronoi3: faces');

// route checking: legs narrowed by their status
const scene: RouteScene = {
  traverse: { parts: [{ name: 'cube', box: { min: [0, 0, 0], max: [1, 1, 1] } }] },
  route: [[0, 0, 0], [5, 0, 0]],
  obstacles: [
    { name: 'wall', box: { min: [3, -10, -10], max: [4, 10, 10] } },
    { name: 'plate', vertices: new Float64Array([2.2, -5, -5, 2.2, 5, -5, 2.2, 0, 5]), triangles: new Uint32Array([0, 1, 2]) },
  ],
  margin: 0,
};

/** One line per leg; each branch reads fields only legs of that status have. */
function describe(leg: RouteLeg): string {
  if (leg.status === 'hit') {
    const [lo, hi]: [number, number] = leg.fraction;
    const at: Vec3 = leg.position;
    return `hit ${leg.obstacle} triangle ${leg.triangle} by ${leg.part} in [${lo}, ${hi}] at x ${at[0]}`;
  }
  if (leg.status === 'clear') {
    const clearance: number | null = leg.clearance;
    return `clear by ${clearance ?? 'unknown'} from ${leg.obstacle ?? 'nothing'}`;
  }
  const overlap: 'start-overlap' = leg.status;
  return `${overlap} ${leg.obstacle} ${leg.part}`;
}

const once: RouteReport = hullkit.checkRoute(scene, { samples: 4 });
check(!once.clear && once.legs.length === 1, 'the cube hits');
const [first] = once.legs;
check(first !== undefined && describe(first).startsWith('hit plate'), 'first contact is the plate');
check(typeof first?.sampled?.hit === 'boolean', 'samples give sampled');

const { route: _ownRoute, ...withoutRoute } = scene; // a checker's scene may leave the route out
const checker: RouteChecker = new hullkit.RouteChecker(withoutRoute);
try {
  const back = checker.check([[0, 0, 0], [-5, 0, 0]], { clearance: true });
  const leg = back.legs[0];
  check(back.clear && leg?.status === 'clear' && leg.clearance !== null && leg.clearance > 0, 'going back is clear');
  check(checker.check(new Float64Array([0, 0, 0, 0, 3, 0])).legs.length === 1 && checker.buildSeconds >= 0, 'flat route');
  // A leg that turns: waypoints with a rotation, the hit's orientation and graze flag.
  const turning: RouteWaypoint[] = [
    [0, 0, 0],
    { position: [5, 0, 0], rotation: { axis: [0, 0, 1], degrees: 90 } },
    { position: [5, 0, 1], rotation: { quaternion: [1, 0, 0, 0] } },
    { position: [5, 0, 2], rotation: { yaw_pitch_roll_degrees: [0, 10, 0] } },
  ];
  const turned = checker.check(turning).legs[0];
  if (turned?.status === 'hit') {
    const rotation: [number, number, number, number] | undefined = turned.rotation;
    const grazing: true | undefined = turned.grazing;
    check(rotation !== undefined && rotation.length === 4 && grazing === undefined, 'a turning hit reports its orientation');
  } else {
    check(false, 'the turning cube hits the plate');
  }
} finally {
  checker.delete();
}
check(checker.deleted, 'deleted');

// meshes as bytes and by name
const withMeshBytes = hullkit.checkRoute(
  { ...scene, obstacles: [{ name: 'tri', mesh: ascii('v 2 -5 -5\nv 2 5 -5\nv 2 0 5\nf 1 2 3\n') }] },
  { clearance: false },
);
check(withMeshBytes.legs[0]?.status === 'hit', 'mesh bytes');
const byName = hullkit.checkRoute(
  { ...scene, obstacles: [{ mesh: 'tri.obj' }] },
  { files: new Map([['tri.obj', ascii('v 2 -5 -5\nv 2 5 -5\nv 2 0 5\nf 1 2 3\n')]]) },
);
check(byName.legs[0]?.status === 'hit' && byName.legs[0].obstacle === 'obstacle 0', 'mesh by name');
check(once.seconds >= 0 && once.build_seconds >= 0 && (once.min_clearance === null || typeof once.min_clearance === 'number'), 'report fields');
