// The wasm RouteChecker in Node: one process per route, so that the first check after loading is
// a real first call (the headline: what a page sees when the user starts dragging), then the warm
// median of further re-checks of the same legs. A route whose waypoints are
// {"position": [x, y, z], "rotation": {"quaternion": [w, x, y, z]}} turns: RouteChecker.check takes
// those waypoints as they are (the JSON route file's first legs + 1 waypoints).
//   node bench/route_wasm_bench.mjs --scene bench/out/route-scene.json --route bench/out/route-hit.json [--legs 20] [--runs 21]
// Prints one JSON line: {impl: "wasm-recheck", route, legs, turned, hits, build_seconds, first_ms, warm_median_ms
// (both with the default options: clearance on), warm_verdict_median_ms (clearance off), runs_ms}.
import { readFileSync } from 'node:fs';
import { basename, dirname, join } from 'node:path';
import { parseArgs } from 'node:util';

import createHullkit from '../wasm/hullkit.js';

const { values } = parseArgs({
  options: { scene: { type: 'string' }, route: { type: 'string' }, legs: { type: 'string', default: '20' }, runs: { type: 'string', default: '21' } },
});
if (!values.scene || !values.route) {
  console.error('usage: node bench/route_wasm_bench.mjs --scene SCENE.json --route ROUTE.json [--legs 20] [--runs 21]');
  process.exit(2);
}
const legs = Number(values.legs);
const runs = Number(values.runs);

const scene = JSON.parse(readFileSync(values.scene, 'utf8'));
delete scene.route;
// Mesh files named by the scene, relative to it, handed over as bytes.
const files = {};
for (const shape of [...scene.traverse.parts, ...scene.obstacles]) {
  if (typeof shape.mesh === 'string') files[shape.mesh] = new Uint8Array(readFileSync(join(dirname(values.scene), shape.mesh)));
}
const route = JSON.parse(readFileSync(values.route, 'utf8')).slice(0, legs + 1);

const hullkit = await createHullkit();
let start = performance.now();
const checker = new hullkit.RouteChecker(scene, { files });
const constructMs = performance.now() - start;
try {
  start = performance.now();
  const first = checker.check(route);
  const firstMs = performance.now() - start;
  const times = [];
  for (let i = 0; i < runs; i++) {
    start = performance.now();
    checker.check(route);
    times.push(performance.now() - start);
  }
  // The verdicts and first contacts alone (clearance off), warm.
  const verdictTimes = [];
  for (let i = 0; i < runs; i++) {
    start = performance.now();
    checker.check(route, { clearance: false });
    verdictTimes.push(performance.now() - start);
  }
  const median = (values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];
  console.log(JSON.stringify({
    impl: 'wasm-recheck',
    route: basename(values.route, '.json'),
    legs: first.legs.length,
    turned: route.some((waypoint) => !Array.isArray(waypoint)),
    hits: first.legs.map((leg) => (leg.status === 'clear' ? 0 : 1)),
    build_seconds: checker.buildSeconds,
    construct_ms: constructMs,
    first_ms: firstMs,
    warm_median_ms: median(times),
    warm_verdict_median_ms: median(verdictTimes),
    runs_ms: times,
  }));
} finally {
  checker.delete();
}
