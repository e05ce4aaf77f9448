// The route benchmark's scene and routes (deterministic, seeded), written to bench/out/:
//   route-scene.json     the scene: the traverse (a subdivided box, ~1.5e3 vertices, as a binary
//                        STL: route-traverse.stl) and ~1e5 obstacle triangles: the Stanford bunny
//                        (npm `bunny`, 3 674 triangles) scaled to ~1 m and repeated 27 times in a
//                        3x3x3 grid of 1.5 m cells, plus 6 thin walls (boxes) and 24 zero-thickness
//                        square plates at the corridors between the cells (a third across
//                        them, the rest just beside them); margin 0
//   route-hit.json       100 legs between random points of the grid: most legs hit a bunny
//   route-clear.json     100 legs along the corridors between the cells: most are clear; the
//                        walls and plates across corridors block some (thin obstacles that pose
//                        sampling can miss), the others pass 0.05 away
// Usage: node bench/make_route_scene.mjs [--quick]   (--quick: 20 legs per route, 9 bunnies)
import { mkdirSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

import bunny from 'bunny';
import { mulberry32 } from '../web/distributions.js';

const here = dirname(fileURLToPath(import.meta.url));
const out = join(here, 'out');
const quick = process.argv.includes('--quick');
const CELL = 1.5; // grid spacing (m); bunnies sit in the cell centres, corridors run along the cell borders
const GRID = 3;
const LEGS = quick ? 20 : 100;
const TRAVERSE_HALF = 0.1; // the traverse is a 0.2 m box
const SUBDIVISIONS = 16; // per box edge: 6 * 16^2 + 2 = 1538 vertices

const random = mulberry32(20261129);
const round = (x) => Number(x.toPrecision(12));

/** The bunny scaled so that its largest extent is 1 m, centred on the origin. */
function unitBunny() {
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (const p of bunny.positions) {
    for (let a = 0; a < 3; a++) {
      lo[a] = Math.min(lo[a], p[a]);
      hi[a] = Math.max(hi[a], p[a]);
    }
  }
  const scale = 1 / Math.max(...hi.map((h, a) => h - lo[a]));
  return bunny.positions.map((p) => p.map((x, a) => (x - (lo[a] + hi[a]) / 2) * scale));
}

/** A box surface with `n` segments per edge: vertices on the 6 faces' grids, shared along edges. */
function subdividedBox(half, n) {
  const index = new Map();
  const vertices = [];
  const triangles = [];
  const vertex = (p) => {
    const key = p.join(',');
    if (!index.has(key)) {
      index.set(key, vertices.length);
      vertices.push(p.map((x) => round(x)));
    }
    return index.get(key);
  };
  // Face (axis, side): u and v run over the other two axes; corners ordered counter-clockwise from outside.
  for (let axis = 0; axis < 3; axis++) {
    for (const side of [-1, 1]) {
      const u = (axis + 1) % 3;
      const v = (axis + 2) % 3;
      const at = (i, j) => {
        const p = [0, 0, 0];
        p[axis] = side * half;
        p[u] = -half + (2 * half * i) / n;
        p[v] = -half + (2 * half * j) / n;
        return vertex(p);
      };
      for (let i = 0; i < n; i++) {
        for (let j = 0; j < n; j++) {
          const a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
          if (side > 0) triangles.push([a, b, c], [a, c, d]);
          else triangles.push([a, c, b], [a, d, c]);
        }
      }
    }
  }
  return { vertices, triangles };
}

function binaryStl({ vertices, triangles }) {
  const bytes = new Uint8Array(84 + 50 * triangles.length);
  const view = new DataView(bytes.buffer);
  new TextEncoder().encodeInto('hullkit route benchmark traverse', bytes);
  view.setUint32(80, triangles.length, true);
  triangles.forEach((t, k) => {
    t.forEach((v, c) => vertices[v].forEach((x, a) => view.setFloat32(84 + 50 * k + 12 + 12 * c + 4 * a, x, true)));
  });
  return bytes;
}

/** A lattice edge between corridor points: from (i, j, k) * CELL one step along `axis`. */
function randomEdge() {
  const axis = Math.floor(random() * 3);
  const p = [0, 1, 2].map(() => Math.floor(random() * (GRID + 1)));
  p[axis] = Math.floor(random() * GRID);
  return { axis, p };
}

const obstacles = [];
const shape = unitBunny();
const cells = quick ? 1 : GRID; // quick: one layer of 9 bunnies
for (let i = 0; i < GRID; i++) {
  for (let j = 0; j < GRID; j++) {
    for (let k = 0; k < cells; k++) {
      const centre = [i, j, k].map((c) => (c + 0.5) * CELL);
      obstacles.push({
        name: `bunny ${i}${j}${k}`,
        vertices: shape.map((p) => p.map((x, a) => round(x + centre[a]))),
        triangles: bunny.cells,
      });
    }
  }
}
// Walls and plates at corridor edges, perpendicular to them: a few across the corridor (blocking
// it), the others shifted sideways so that their nearest edge is 0.15 from the corridor's line (a
// traverse passing by is clear of them by 0.05: near misses, where the clearance is worth having).
/** `mid` moved sideways (off the corridor along `axis`) by `offset`. */
function sideways(mid, axis, offset) {
  const c = [...mid];
  c[(axis + 1 + Math.floor(random() * 2)) % 3] += random() < 0.5 ? -offset : offset;
  return c;
}
for (let w = 0; w < 6; w++) {
  const { axis, p } = randomEdge();
  let mid = p.map((x, a) => (x + (a === axis ? 0.5 : 0)) * CELL);
  if (w >= 2) mid = sideways(mid, axis, 0.45);
  const min = mid.map((x, a) => round(a === axis ? x - 0.025 : x - 0.3));
  const max = mid.map((x, a) => round(a === axis ? x + 0.025 : x + 0.3));
  obstacles.push({ name: `wall ${w}`, box: { min, max } });
}
for (let q = 0; q < 24; q++) {
  const { axis, p } = randomEdge();
  let mid = p.map((x, a) => (x + (a === axis ? random() : 0)) * CELL);
  if (q >= 8) mid = sideways(mid, axis, 0.3);
  const u = (axis + 1) % 3;
  const v = (axis + 2) % 3;
  const corner = (su, sv) => {
    const c = [...mid];
    c[u] += su * 0.15;
    c[v] += sv * 0.15;
    return c.map(round);
  };
  obstacles.push({ name: `plate ${q}`, vertices: [corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1)], triangles: [[0, 1, 2], [0, 2, 3]] });
}

// Routes. Hit: uniform random waypoints over the grid. Clear: a random walk on the corridor lattice.
const span = GRID * CELL;
// (quick: the bunnies fill one layer of cells, so the hit route stays in that layer)
const hitRoute = Array.from({ length: LEGS + 1 }, () => [0, 1, 2].map((a) => round(random() * (a === 2 ? cells * CELL : span))));
const clearRoute = [[0, 0, 0]];
while (clearRoute.length < LEGS + 1) {
  const p = [...clearRoute[clearRoute.length - 1]];
  const axis = Math.floor(random() * 3);
  const step = random() < 0.5 ? -CELL : CELL;
  if (p[axis] + step < 0 || p[axis] + step > span) continue;
  p[axis] = round(p[axis] + step);
  clearRoute.push(p);
}

const traverse = subdividedBox(TRAVERSE_HALF, SUBDIVISIONS);
mkdirSync(out, { recursive: true });
writeFileSync(join(out, 'route-traverse.stl'), binaryStl(traverse));
const scene = { traverse: { parts: [{ name: 'box', mesh: 'route-traverse.stl' }] }, route: hitRoute, obstacles, margin: 0 };
writeFileSync(join(out, 'route-scene.json'), JSON.stringify(scene));
writeFileSync(join(out, 'route-hit.json'), JSON.stringify(hitRoute));
writeFileSync(join(out, 'route-clear.json'), JSON.stringify(clearRoute));
const triangleCount = obstacles.reduce((n, o) => n + (o.box ? 12 : o.triangles.length), 0);
console.error(`route scene: ${triangleCount} obstacle triangles, traverse ${traverse.vertices.length} vertices / ${traverse.triangles.length} triangles, ${LEGS} legs per route${quick ? ' (quick)' : ''}`);
