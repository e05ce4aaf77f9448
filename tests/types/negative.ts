// Lines that must NOT type-check: scripts/type_test.sh compiles this file expecting exactly one
// error on every line marked "// error" and none elsewhere, so the types are shown to catch
// mistakes (not to accept anything). Never run.
import createHullkit from 'hullkit';
import type { RouteLeg, RouteScene } from 'hullkit';

const hullkit = await createHullkit();
const xyz = new Float64Array(12);
declare const leg: RouteLeg;
declare const scene: RouteScene;

hullkit.hull('0 0 0 1 1 1'); // error
hullkit.hull(xyz, { algorithm: 'qhull' }); // error
hullkit.hull(xyz, { mergeCoplanar: 'yes' }); // error
hullkit.hull([{ x: 0, y: 0 }]); // error
hullkit.delaunay([{ x: 0 }]); // error
const wrongType: Float64Array = hullkit.hull(xyz).triangles; // error
hullkit.readMesh('cube.obj'); // error
hullkit.delaunay(xyz, { algorithm: 'quickhull' }); // error
hullkit.voronoi(xyz, { triangles: new Uint32Array(3) }, [0, 0, 1, 1]); // error
hullkit.locate(xyz, hullkit.delaunay(xyz).triangles, xyz); // error
hullkit.locate(xyz, hullkit.delaunay(xyz), [[0, 0]]); // error
hullkit.locate(xyz, hullkit.delaunay(xyz), xyz, { threads: 1 }); // error
const inside: Uint32Array = hullkit.locate(xyz, hullkit.delaunay(xyz), xyz).triangle; // error
hullkit.delaunay3([[0, 0, 0]]); // error
hullkit.hullNd(xyz); // error
hullkit.delaunayNd(xyz, 4, { furthest: true }); // error
hullkit.locateNd(xyz, hullkit.delaunayNd(xyz, 3).simplices, xyz); // error
hullkit.delaunay3(xyz, { threads: 2 }); // error
hullkit.delaunay3(xyz, { furthestSite: 1 }); // error
const flat: Uint32Array = hullkit.delaunay3(xyz).neighbors; // error
hullkit.verifyDelaunay3(xyz, hullkit.delaunay3(xyz)); // error
hullkit.locate3(xyz, hullkit.delaunay3(xyz).tetrahedra, xyz); // error
hullkit.locate3(xyz, hullkit.delaunay3(xyz), xyz, { exact: true }); // error
const located: Float64Array = hullkit.locate3(xyz, hullkit.delaunay3(xyz), xyz).tetrahedron; // error
const volumes: Uint32Array = hullkit.voronoi3(xyz, hullkit.delaunay3(xyz)).volume; // error
const position = leg.position; // error
if (leg.status === 'clear') {
  const fromClear = leg.position; // error
  const part = leg.part; // error
}
if (leg.status === 'hit') {
  const clearance = leg.clearance; // error
  const fractionOfHit: number = leg.fraction; // error
}
const unknownStatus = leg.status === 'miss'; // error
hullkit.checkRoute(scene, { sample: 4 }); // error
hullkit.checkRoute({ traverse: { parts: [] }, route: [[0, 0, 0], [1, 0, 0]] }); // error
const checker = new hullkit.RouteChecker(scene);
checker.check([[0, 0, 0], [1, 0]]); // error
checker.dispose(); // error
checker.deleted = true; // error
hullkit.RouteChecker(scene); // error
hullkit.triangulatePolygon([0, 0, 1, 0, 0, 1], [], { fill: 'winding' }); // error
hullkit.triangulatePolygon([0, 0, 1, 0, 0, 1], [], { keepSegments: 'inside' }); // error
hullkit.triangulatePolygon([0, 0, 1, 0, 0, 1], [], { unsuitable: (area: string) => area === '' }); // error
hullkit.triangulatePolygon([0, 0, 1, 0, 0, 1], [], { dim: '3' }); // error
hullkit.constrainedDelaunay([0, 0, 1, 0, 0, 1], [0, 1], { threads: 2 }); // error
hullkit.refineMesh([0, 0, 1, 0, 0, 1], [0, 1, 2], { holes: [0.5, 0.5] }); // error
hullkit.refineMesh([0, 0, 1, 0, 0, 1], [0, 1, 2], { triangleMaxArea: 0.5 }); // error
