// The route benchmark's report, from the JSON lines bench/route_run.sh collected:
//   node bench/route_report.mjs [--elapsed SECONDS] META.json RESULTS.jsonl
// writes bench/results-route.md (a quick run's goes to bench/out/results-route.md) and prints the
// targets summary. `node bench/route_report.mjs --meta QUICK` prints the run's metadata as JSON.
//
// Misses are counted against the reference: FCL's collide at 2000 evenly spaced poses per leg.
// A method misses a leg when the reference finds a contact on it and the method reports it clear.
import { execFileSync } from 'node:child_process';
import { readFileSync, writeFileSync } from 'node:fs';
import { cpus, loadavg } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const root = join(here, '..');
const sh = (cmd, args) => {
  try {
    return execFileSync(cmd, args, { cwd: root, encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] }).trim();
  } catch {
    return null;
  }
};

const args = process.argv.slice(2);
if (args[0] === '--meta') {
  console.log(JSON.stringify({
    date: new Date().toISOString(),
    quick: args[1] === '1',
    cpu: cpus()[0]?.model ?? 'unknown',
    cores: cpus().length,
    load_at_start: loadavg().map((x) => Number(x.toFixed(2))),
    node: process.version,
    compiler: sh('c++', ['--version'])?.split('\n')[0] ?? null,
    commit: sh('git', ['rev-parse', '--short', 'HEAD']),
    core_modified: Boolean(sh('git', ['status', '--porcelain', '--', 'native', 'wasm', 'CMakeLists.txt'])),
    fcl: sh('dpkg-query', ['-W', '-f=${Version}', 'libfcl-dev']),
  }));
  process.exit(0);
}

let elapsed = null;
if (args[0] === '--elapsed') {
  elapsed = Number(args[1]);
  args.splice(0, 2);
}
const [metaPath, resultsPath] = args;
const meta = JSON.parse(readFileSync(metaPath, 'utf8'));
const lines = readFileSync(resultsPath, 'utf8').split('\n').filter((l) => l.startsWith('{')).map((l) => JSON.parse(l));
const find = (impl, route) => lines.find((r) => r.impl === impl && r.route === route) ?? null;

const fmt = (x, digits = 3) => (x === null || x === undefined || Number.isNaN(x) ? '–' : Number(x).toPrecision(digits));
const ms = (x) => (x === null || x === undefined ? '–' : `${fmt(x)} ms`);
const count = (hits) => hits.reduce((n, h) => n + h, 0);
/** Legs the reference sees a contact on and `hits` calls clear. */
const misses = (hits, reference) => hits.reduce((n, h, k) => n + (reference[k] && !h ? 1 : 0), 0);
/** Legs `hits` calls hit that the reference does not see (contacts between its poses, or touching). */
const extra = (hits, reference) => hits.reduce((n, h, k) => n + (!reference[k] && h ? 1 : 0), 0);

const routes = ['route-hit', 'route-clear'];
const rows = [];
const targets = [];
const target = (name, value, goal, met) => targets.push({ name, value, goal, status: value === null ? 'NOT MEASURED' : met ? 'MET' : 'NOT MET' });

for (const route of routes) {
  const hk = find('hullkit', route);
  const f100 = find('fcl-100', route);
  const ccd = find('fcl-ccd', route);
  const ref = find('fcl-reference', route);
  const wasm = find('wasm-recheck', route);
  if (!hk || !ref) {
    rows.push({ route, missing: true });
    continue;
  }
  const r = ref.hits;
  rows.push({
    route,
    legs: hk.legs,
    triangles: hk.obstacle_triangles,
    traverse: hk.traverse_vertices,
    referenceHits: count(r),
    referencePoses: ref.poses,
    hk,
    f100,
    ccd,
    wasm,
    hkMisses: misses(hk.hits, r),
    hkMissesClearance: misses(hk.hits_with_clearance, r),
    hkExtra: extra(hk.hits, r),
    f100Misses: f100 ? misses(f100.hits, r) : null,
    ccdMisses: ccd ? misses(ccd.hits, r) : null,
  });
}

const measured = rows.filter((row) => !row.missing);
for (const row of measured) {
  const name = row.route;
  const speedup = row.f100 ? row.f100.ms_per_leg / row.hk.ms_per_leg : null;
  target(`${name}: verdict + first contact vs FCL 100 poses`, speedup === null ? null : `${fmt(speedup)}x faster`, '>= 10x', speedup >= 10);
  const vsCcd = row.ccd ? row.hk.ms_per_leg / row.ccd.ms_per_leg : null;
  target(`${name}: verdict + first contact vs FCL continuousCollide`, vsCcd === null ? null : `${fmt(vsCcd)}x its time`, '<= 1x', vsCcd <= 1);
  target(`${name}: hullkit misses (vs the ${row.referencePoses}-pose reference)`, `${row.hkMisses + row.hkMissesClearance}`, '0', row.hkMisses + row.hkMissesClearance === 0);
  target(`${name}: ms per leg with clearance`, `${fmt(row.hk.ms_per_leg_clearance)} ms`, '<= 1 ms', row.hk.ms_per_leg_clearance <= 1);
  if (row.wasm) target(`${name}: wasm RouteChecker 20-leg re-check, first call`, `${fmt(row.wasm.first_ms)} ms`, '<= 20 ms', row.wasm.first_ms <= 20);
  else target(`${name}: wasm RouteChecker 20-leg re-check, first call`, null, '<= 20 ms', false);
}
if (measured.length) {
  const row = measured[0];
  const ratio = row.f100 ? row.hk.build_seconds / row.f100.build_seconds : null;
  target('BVH build vs FCL', ratio === null ? null : `${fmt(ratio)}x FCL's`, '<= 0.1x', ratio <= 0.1);
}

// ---- markdown
const md = [];
md.push('# Route checking: hullkit vs FCL 0.7', '');
md.push(`Generated by \`bash bench/route_run.sh\` on ${meta.date.slice(0, 10)}${meta.quick ? ' — **QUICK smoke run (20 legs, 9 bunnies, 1 run): not for citing**' : ''}.`);
md.push(`Machine: ${meta.cpu}, ${meta.cores} cores (load at start ${meta.load_at_start.join(' ')}); ${meta.compiler}; Node ${meta.node}; FCL ${meta.fcl ?? '?'}; commit ${meta.commit}${meta.core_modified ? ' (with uncommitted changes)' : ''}${elapsed === null ? '' : `; ${elapsed} s in all`}.`, '');
if (measured.length) {
  const row = measured[0];
  md.push(`Scene (bench/make_route_scene.mjs): ${row.triangles} obstacle triangles (the Stanford bunny scaled to 1 m in a grid, thin walls, zero-thickness plates), a traverse of ${row.traverse} vertices (a subdivided 0.2 m box), margin 0. ` +
    `Every method checks the same legs; verdicts are compared with FCL's collide at ${row.referencePoses} evenly spaced poses per leg (the reference). ` +
    'Times are medians over the runs, per leg (total / legs); hullkit\'s verdict time includes the exact first-contact fraction.', '');
}
md.push('| route | legs (reference hits) | method | ms per leg | legs hit | misses vs reference |');
md.push('|---|---|---|---:|---:|---:|');
for (const row of rows) {
  if (row.missing) {
    md.push(`| ${row.route} | – | (no results) | | | |`);
    continue;
  }
  const head = `| ${row.route} | ${row.legs} (${row.referenceHits})`;
  md.push(`${head} | hullkit, verdict + first contact | ${fmt(row.hk.ms_per_leg)} | ${count(row.hk.hits)} | ${row.hkMisses} |`);
  md.push(`${head} | hullkit, with clearance | ${fmt(row.hk.ms_per_leg_clearance)} | ${count(row.hk.hits_with_clearance)} | ${row.hkMissesClearance} |`);
  if (row.f100) md.push(`${head} | FCL collide, 100 poses | ${fmt(row.f100.ms_per_leg)} | ${count(row.f100.hits)} | ${row.f100Misses} |`);
  if (row.ccd) md.push(`${head} | FCL continuousCollide (default request) | ${fmt(row.ccd.ms_per_leg)} | ${count(row.ccd.hits)} | ${row.ccdMisses} |`);
  md.push(`${head} | FCL collide, ${row.referencePoses} poses (reference) | ${fmt(row.f100 ? find('fcl-reference', row.route).ms_per_leg : null)} | ${row.referenceHits} | – |`);
}
md.push('');
if (measured.length) {
  const row = measured[0];
  md.push(`Scene preparation: hullkit ${fmt(row.hk.build_seconds * 1e3)} ms (hulls + BVH), FCL ${row.f100 ? fmt(row.f100.build_seconds * 1e3) : '–'} ms (BVHModel<OBBRSS> of the obstacles and the traverse).`);
  for (const r of measured) {
    if (r.hkExtra) md.push(`On ${r.route}, hullkit reports ${r.hkExtra} hit(s) the reference does not see: contacts between its poses or exact touching, which poses cannot certify.`);
  }
  md.push('');
}
const wasmRows = measured.filter((row) => row.wasm);
if (wasmRows.length) {
  md.push('| wasm RouteChecker in Node, 20 legs | first check after loading | warm median | warm median, clearance off | scene preparation |');
  md.push('|---|---:|---:|---:|---:|');
  for (const row of wasmRows) {
    md.push(`| ${row.route} | ${ms(row.wasm.first_ms)} | ${ms(row.wasm.warm_median_ms)} | ${ms(row.wasm.warm_verdict_median_ms)} | ${ms(row.wasm.build_seconds * 1e3)} (${ms(row.wasm.construct_ms)} from the scene object) |`);
  }
  md.push('');
}
md.push('## Targets', '');
md.push('| target | measured | goal | status |');
md.push('|---|---|---|---|');
for (const t of targets) md.push(`| ${t.name} | ${t.value ?? '–'} | ${t.goal} | ${t.status} |`);
md.push('');

const mdPath = meta.quick ? join(here, 'out', 'results-route.md') : join(here, 'results-route.md');
writeFileSync(mdPath, md.join('\n'));
console.log(`route bench: wrote ${mdPath}`);
for (const t of targets) console.log(`${t.status.padEnd(12)} ${t.name}: ${t.value ?? '–'} (goal ${t.goal})`);
