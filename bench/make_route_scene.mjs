// The route benchmark's scenes and routes (deterministic, seeded), written to bench/out/:
//   route-scene.json     the scene: the traverse (a subdivided box, ~1.5e3 vertices, as a binary
//                        STL: route-traverse.stl; it turns about its centre, the pivot [0, 0, 0])
//                        and ~1e5 obstacle triangles: the Stanford bunny (npm `bunny`, 3 674
//                        triangles) scaled to ~1 m and repeated 27 times in a 3x3x3 grid of 1.5 m
//                        cells, plus 6 thin walls (boxes) and 24 zero-thickness square plates at the
//                        corridors between the cells (a third across them, the rest just beside
//                        them); margin 0
//   route-hit.json       100 legs between random points of the grid: most legs hit a bunny
//   route-clear.json     100 legs along the corridors between the cells: most are clear; the
//                        walls and plates across corridors block some (thin obstacles that pose
//                        sampling can miss), the others pass 0.05 away
//   route-turn.json      100 legs that translate and TURN, on route-scene.json: waypoints
//                        {"position", "rotation": {"quaternion"}}; every leg turns by an angle drawn
//                        uniformly from [0, 180) degrees about a uniformly random axis; half the legs
//                        step along a corridor (the turning box's corners reach 0.17 from the
//                        corridor's line, past the plates beside it at 0.15), the others jump to a
//                        random lattice point across the cells (through bunnies)
//   route-aligned-scene.json, route-aligned-traverse.stl, route-aligned.json
//                        the aligned scene: an axis-aligned box traverse (0.25 m, subdivided like the
//                        other, 1538 vertices, every coordinate a multiple of 1/64: exact in float
//                        and double) among the same bunnies, and axis-aligned walls and plates whose
//                        faces are parallel to the traverse's, placed on the corridor edges a route of
//                        100 straight corridor legs walks: most legs hit one face-on (a plate or wall
//                        across the corridor: the traverse's front face meets it flat, a coplanar
//                        first contact; some plates flush with the traverse's side, touching along an
//                        edge line only; a few smaller than the traverse's cross-section, which
//                        only a swept or solid test sees) or edge-on (a plate or thin wall along the
//                        corridor: the front face meets its leading edge; some plates in the plane
//                        of the traverse's side face, touching it exactly); the others pass plates
//                        parallel to their side faces 1/64 away (near misses). Coordinates there are
//                        dyadic, so the touching contacts are exact, not rounded away.
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

// ---- route-turn: legs that translate and turn, on route-scene.json (its own seeded stream, so
// that the routes above stay what they were).
const turnRandom = mulberry32(20261202);
/** A uniformly random unit vector. */
function unitVector(rand) {
  const z = 2 * rand() - 1;
  const phi = 2 * Math.PI * rand();
  const r = Math.sqrt(Math.max(0, 1 - z * z));
  return [r * Math.cos(phi), r * Math.sin(phi), z];
}
/** Quaternion product a b (w x y z). */
const qmul = ([aw, ax, ay, az], [bw, bx, by, bz]) => [
  aw * bw - ax * bx - ay * by - az * bz,
  aw * bx + ax * bw + ay * bz - az * by,
  aw * by - ax * bz + ay * bw + az * bx,
  aw * bz + ax * by - ay * bx + az * bw,
];
const qnormalize = (q) => {
  const n = Math.hypot(...q);
  return q.map((x) => x / n);
};
const qaxis = (axis, radians) => [Math.cos(radians / 2), ...axis.map((x) => x * Math.sin(radians / 2))];
// The lattice of corridor crossings the walks use: quick runs keep to the one layer of bunnies.
const LATTICE_Z = quick ? 1 : GRID;
const latticePoint = (rand) => [GRID, GRID, LATTICE_Z].map((n) => Math.floor(rand() * (n + 1)));
/** One step along a corridor from lattice point `p` (indices), inside the lattice. */
function corridorStep(p, rand) {
  for (;;) {
    const q = [...p];
    const axis = Math.floor(rand() * 3);
    q[axis] += rand() < 0.5 ? -1 : 1;
    if (q[axis] >= 0 && q[axis] <= (axis === 2 ? LATTICE_Z : GRID)) return { q, axis };
  }
}
const turnAngles = [];
let turnAt = [0, 0, 0];
let turnQ = qnormalize([turnRandom() - 0.5, turnRandom() - 0.5, turnRandom() - 0.5, turnRandom() - 0.5]);
const pose = (p, q) => ({ position: p.map((i) => round(i * CELL)), rotation: { quaternion: q.map(round) } });
const turnRoute = [pose(turnAt, turnQ)];
while (turnRoute.length < LEGS + 1) {
  let next;
  if (turnRandom() < 0.5) next = corridorStep(turnAt, turnRandom).q;
  else {
    do next = latticePoint(turnRandom);
    while (next.every((x, a) => x === turnAt[a]));
  }
  const degrees = 180 * turnRandom(); // [0, 180): the shorter arc is this turn, never ambiguous
  const turn = qaxis(unitVector(turnRandom), (degrees * Math.PI) / 180);
  turnQ = qnormalize(qmul(turn, turnQ));
  turnAngles.push(degrees);
  turnAt = next;
  turnRoute.push(pose(turnAt, turnQ));
}
writeFileSync(join(out, 'route-turn.json'), JSON.stringify(turnRoute));
{
  const sorted = [...turnAngles].sort((a, b) => a - b);
  console.error(`route-turn: ${LEGS} legs turning ${sorted[0].toFixed(1)}..${sorted[sorted.length - 1].toFixed(1)} degrees (median ${sorted[Math.floor(sorted.length / 2)].toFixed(1)})`);
}

// ---- the aligned scene: an axis-aligned box traverse, axis-aligned walls and plates, bunnies.
const alignedRandom = mulberry32(20261203);
const H = 0.125; // the aligned traverse's half size: 0.25 m, vertices at multiples of 1/64
const STEP = 1 / 64; // obstacle coordinates are multiples of it (exact in binary)
const bunnies = obstacles.filter((o) => o.name.startsWith('bunny'));
const alignedObstacles = [...bunnies];
const alignedRoute = [[0, 0, 0]];
const edgeKinds = [];
const seenEdges = new Set();
/** An axis-aligned box obstacle from per-axis [lo, hi] ranges. */
const boxObstacle = (name, ranges) => ({ name, box: { min: ranges.map((r) => r[0]), max: ranges.map((r) => r[1]) } });
/** An axis-aligned zero-thickness square or rectangle: fixed coordinate `at` on `axis`, ranges on the others. */
function plateObstacle(name, axis, at, ranges) {
  const u = (axis + 1) % 3;
  const v = (axis + 2) % 3;
  const corner = (i, j) => {
    const c = [0, 0, 0];
    c[axis] = at;
    c[u] = ranges[u][i];
    c[v] = ranges[v][j];
    return c;
  };
  return { name, vertices: [corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)], triangles: [[0, 1, 2], [0, 2, 3]] };
}
// What sits on a newly walked corridor edge: weights per kind (most legs hit face-on or edge-on).
const KINDS = [
  ['face-plate', 3], // plate across the corridor, centred: the front face meets it flat
  ['face-plate-half', 2], // across, shifted sideways so that it covers half the front face
  ['face-plate-flush', 1], // across, its edge flush with the traverse's side: touching along an edge line
  ['face-plate-inside', 1], // across, smaller than the front face (inside the traverse's cross-section)
  ['face-wall', 2], // a wall (box) across the corridor, its face parallel to the front face
  ['edge-plate', 3], // a plate along the corridor inside the traverse's width: the front face meets its edge
  ['edge-plate-flush', 1], // along, in the plane of the traverse's side face: touching it exactly
  ['edge-wall', 2], // a thin wall along the corridor: the front face meets its narrow end face
  ['near-parallel', 2], // plates along the corridor 1/64 beside the traverse's side faces: clear
];
const kindTotal = KINDS.reduce((n, [, w]) => n + w, 0);
function pickKind() {
  let x = alignedRandom() * kindTotal;
  for (const [kind, w] of KINDS) if ((x -= w) < 0) return kind;
  return KINDS[KINDS.length - 1][0];
}
const dyadic = (lo, hi) => lo + STEP * Math.floor(alignedRandom() * ((hi - lo) / STEP + 1)); // a multiple of STEP in [lo, hi]
let alignedAt = [0, 0, 0];
while (alignedRoute.length < LEGS + 1) {
  // Prefer corridor edges not walked yet (a few tries), so that most legs meet their own obstacle.
  let step = corridorStep(alignedAt, alignedRandom);
  for (let tries = 0; tries < 8; tries++) {
    const lo = step.q.map((x, a) => Math.min(x, alignedAt[a]));
    if (!seenEdges.has(`${step.axis}:${lo}`)) break;
    step = corridorStep(alignedAt, alignedRandom);
  }
  const { q: next, axis } = step;
  const lo = next.map((x, a) => Math.min(x, alignedAt[a]));
  const key = `${axis}:${lo}`;
  if (!seenEdges.has(key)) {
    seenEdges.add(key);
    const kind = pickKind();
    edgeKinds.push(kind);
    const base = lo.map((i) => i * CELL); // the edge runs from base along `axis` for CELL
    const u = (axis + 1 + Math.floor(alignedRandom() * 2)) % 3; // the sideways axis the kind uses
    const v = 3 - axis - u;
    const side = alignedRandom() < 0.5 ? -1 : 1;
    const ranges = [0, 1, 2].map((a) => [base[a], base[a]]);
    const name = `${kind} ${seenEdges.size}`;
    const span = (a, from, to) => (ranges[a] = [base[a] + from, base[a] + to]);
    if (kind.startsWith('face-')) {
      const s = dyadic(0.375, 1.125); // along the edge, away from both crossings
      span(u, -0.25, 0.25);
      span(v, -0.25, 0.25);
      if (kind === 'face-plate-half') span(u, side > 0 ? 0 : -0.5, side > 0 ? 0.5 : 0);
      if (kind === 'face-plate-flush') span(u, side > 0 ? H : -H - 0.5, side > 0 ? H + 0.5 : -H);
      if (kind === 'face-plate-inside') {
        span(u, -H / 2, H / 2);
        span(v, -H / 2, H / 2);
      }
      if (kind === 'face-wall') {
        span(axis, s, s + STEP * 4);
        alignedObstacles.push(boxObstacle(name, ranges));
      } else {
        alignedObstacles.push(plateObstacle(name, axis, base[axis] + s, ranges));
      }
    } else if (kind === 'edge-wall') {
      const s = dyadic(0.375, 0.875);
      span(axis, s, s + 0.375);
      span(u, -STEP * 2, STEP * 2);
      span(v, -0.25, 0.25);
      alignedObstacles.push(boxObstacle(name, ranges));
    } else {
      // plates along the corridor, in a plane perpendicular to u
      const s = dyadic(0.375, 0.875);
      span(axis, s, s + 0.375);
      span(v, -0.25, 0.25);
      if (kind === 'edge-plate') {
        const d = STEP * 4 * Math.floor(alignedRandom() * 3 - 1); // -1/16, 0 or 1/16: inside the traverse's width
        alignedObstacles.push(plateObstacle(name, u, base[u] + d, ranges));
      } else if (kind === 'edge-plate-flush') {
        alignedObstacles.push(plateObstacle(name, u, base[u] + side * H, ranges));
      } else {
        for (const sgn of [-1, 1]) alignedObstacles.push(plateObstacle(`${name}${sgn < 0 ? 'a' : 'b'}`, u, base[u] + sgn * (H + STEP), ranges));
      }
    }
  }
  alignedAt = next;
  alignedRoute.push(alignedAt.map((i) => round(i * CELL)));
}
const alignedTraverse = subdividedBox(H, SUBDIVISIONS);
writeFileSync(join(out, 'route-aligned-traverse.stl'), binaryStl(alignedTraverse));
writeFileSync(join(out, 'route-aligned-scene.json'), JSON.stringify({
  traverse: { parts: [{ name: 'box', mesh: 'route-aligned-traverse.stl' }] }, route: alignedRoute, obstacles: alignedObstacles, margin: 0,
}));
writeFileSync(join(out, 'route-aligned.json'), JSON.stringify(alignedRoute));
{
  const counts = {};
  for (const k of edgeKinds) counts[k] = (counts[k] ?? 0) + 1;
  const triangles = alignedObstacles.reduce((n, o) => n + (o.box ? 12 : o.triangles.length), 0);
  console.error(`route-aligned: ${triangles} obstacle triangles, traverse ${alignedTraverse.vertices.length} vertices, ${LEGS} legs over ${edgeKinds.length} distinct corridor edges: ${Object.entries(counts).map(([k, n]) => `${k} ${n}`).join(', ')}`);
}
