// The route benchmark's report, from the JSON lines bench/route_run.sh collected:
//   node bench/route_report.mjs [--elapsed SECONDS] META.json RESULTS.jsonl
// writes bench/results-route.md (a quick run's goes to bench/out/results-route.md) and prints the
// targets summary. `node bench/route_report.mjs --meta QUICK` prints the run's metadata as JSON.
//
// Misses are counted against the reference: FCL's collide at 2000 evenly spaced poses per leg (on
// the turning route, at the poses hullkit::leg_pose gives). A method misses a leg when the
// reference finds a contact on it and the method reports it clear. Targets: straight routes
// (route-hit, route-clear, route-aligned) verdict + first contact >= 10x faster than FCL's 100-pose
// sampling and no slower than FCL's continuousCollide (its default request), no misses, <= 1 ms per
// leg with clearance, the wasm 20-leg re-check's first call <= 20 ms; the turning route
// (route-turn) the same against continuousCollide with interp motion and conservative
// advancement, with clearance <= 2 ms per leg and the wasm re-check <= 40 ms.
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

const ROUTES = [
  { route: 'route-hit', scene: 'main', turned: false },
  { route: 'route-clear', scene: 'main', turned: false },
  { route: 'route-turn', scene: 'main', turned: true },
  { route: 'route-aligned', scene: 'aligned', turned: false },
];
const rows = [];
const targets = [];
const target = (name, value, goal, met) => targets.push({ name, value, goal, status: value === null ? 'NOT MEASURED' : met ? 'MET' : 'NOT MET' });
const odd = []; // anything a reader must know: a miss, a failed sanity check, a crash (a missing line)

for (const { route, scene, turned } of ROUTES) {
  const hk = find('hullkit', route);
  const f100 = find('fcl-100', route);
  const ccd = find('fcl-ccd', route);
  const ref = find('fcl-reference', route);
  const wasm = find('wasm-recheck', route);
  const checks = find('hullkit-checks', route);
  const firstClearance = lines.find((r) => r.impl === 'hullkit-first' && r.route === route && r.clearance) ?? null;
  if (!hk || !ref) {
    if (lines.some((l) => l.route === route)) odd.push(`${route}: no ${!hk ? 'hullkit' : 'reference'} results (the native run failed or timed out)`);
    rows.push({ route, missing: true });
    continue;
  }
  const r = ref.hits;
  rows.push({
    route,
    scene,
    turned,
    legs: hk.legs,
    triangles: hk.obstacle_triangles,
    traverse: hk.traverse_vertices,
    referenceHits: count(r),
    referencePoses: ref.poses,
    hk,
    f100,
    ccd,
    ref,
    wasm,
    checks,
    firstClearance,
    hkMisses: misses(hk.hits, r),
    hkMissesClearance: misses(hk.hits_with_clearance, r),
    hkExtra: extra(hk.hits, r),
    f100Misses: f100 ? misses(f100.hits, r) : null,
    ccdMisses: ccd ? misses(ccd.hits, r) : null,
    ccdExtra: ccd ? extra(ccd.hits, r) : null,
  });
}

const measured = rows.filter((row) => !row.missing);
for (const row of measured) {
  const name = row.route;
  const speedup = row.f100 ? row.f100.ms_per_leg / row.hk.ms_per_leg : null;
  target(`${name}: verdict + first contact vs FCL 100 poses`, speedup === null ? null : `${fmt(speedup)}x faster (${fmt(row.hk.ms_per_leg)} vs ${fmt(row.f100.ms_per_leg)} ms per leg)`, '>= 10x', speedup >= 10);
  const vsCcd = row.ccd ? row.hk.ms_per_leg / row.ccd.ms_per_leg : null;
  const ccdName = row.turned ? 'FCL continuousCollide (interp, conservative advancement)' : 'FCL continuousCollide';
  target(`${name}: verdict + first contact vs ${ccdName}`, vsCcd === null ? null : `${fmt(vsCcd)}x its time (${fmt(row.hk.ms_per_leg)} vs ${fmt(row.ccd.ms_per_leg)} ms per leg)`, '<= 1x', vsCcd <= 1);
  target(`${name}: hullkit misses (vs the ${row.referencePoses}-pose reference)`, `${row.hkMisses + row.hkMissesClearance}`, '0', row.hkMisses + row.hkMissesClearance === 0);
  const clearanceGoal = row.turned ? 2 : 1;
  target(`${name}: ms per leg with clearance`, `${fmt(row.hk.ms_per_leg_clearance)} ms`, `<= ${clearanceGoal} ms`, row.hk.ms_per_leg_clearance <= clearanceGoal);
  const wasmGoal = row.turned ? 40 : 20;
  if (row.wasm) target(`${name}: wasm RouteChecker 20-leg re-check, first call`, `${fmt(row.wasm.first_ms)} ms (warm ${fmt(row.wasm.warm_median_ms)} ms; clearance off, warm ${fmt(row.wasm.warm_verdict_median_ms)} ms)`, `<= ${wasmGoal} ms`, row.wasm.first_ms <= wasmGoal);
  else target(`${name}: wasm RouteChecker 20-leg re-check, first call`, null, `<= ${wasmGoal} ms`, false);
  if (row.hkMisses + row.hkMissesClearance) {
    const legs = row.hk.hits.map((h, k) => (row.ref.hits[k] && !h ? k : -1)).filter((k) => k >= 0);
    odd.push(`${name}: hullkit MISSES leg(s) ${legs.join(', ')} (the reference finds contact; hullkit reports clear)`);
  }
  const c = row.checks;
  if (!c) odd.push(`${name}: no sanity-check line (the native run stopped before it)`);
  else {
    const report = (list, what) => list.length && odd.push(`${name}: ${list.length} leg(s) ${what}: ${JSON.stringify(list.slice(0, 5))}`);
    report(c.hi_not_in_contact, "whose pose at hullkit's fraction_hi is not in contact by its own static test");
    report(c.lo_after_reference, "whose first-contact lo is after the reference's first pose in contact");
    report(c.clearance_mismatch, 'whose static distance at the reported fraction differs from the reported clearance');
    report(c.closer_than_clearance, 'with a pose closer than the reported clearance');
    const unexplained = c.disagreements.filter((d) => d.hullkit && d.hullkit_static_first === null);
    report(unexplained, "hullkit reports hit, and neither the reference nor hullkit's static test at the reference's poses sees a contact (a contact between poses, or a wrong verdict)");
  }
  if (row.hk.grazing_legs?.length) odd.push(`${name}: grazing hit(s) on leg(s) ${row.hk.grazing_legs.join(', ')}`);
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
const mainRow = measured.find((row) => row.scene === 'main');
const alignedRow = measured.find((row) => row.scene === 'aligned');
const runsOf = (row) => (row?.f100?.runs ? row.f100.runs : null);
if (mainRow) {
  md.push(`Scene (bench/make_route_scene.mjs): ${mainRow.triangles} obstacle triangles (the Stanford bunny scaled to 1 m in a grid, thin walls, zero-thickness plates), a traverse of ${mainRow.traverse} vertices (a subdivided 0.2 m box turning about its centre), margin 0. ` +
    'route-hit and route-clear have 100 straight legs; route-turn 100 legs that translate and turn, each by 0 to 180 degrees about a random axis (half along corridors, where the turning box reaches past plates beside it, half across the cells).');
}
if (alignedRow) {
  md.push(`The aligned scene: ${alignedRow.triangles} obstacle triangles (the same bunnies; axis-aligned walls and plates whose faces are parallel to the traverse's), an axis-aligned box traverse of ${alignedRow.traverse} vertices (0.25 m), every coordinate a multiple of 1/64; route-aligned has 100 straight corridor legs, most meeting a plate or wall face-on (coplanar first contact; some flush, touching along an edge line; some plates smaller than the traverse's cross-section) or edge-on (some in the plane of its side face, touching exactly).`);
}
if (measured.length) {
  md.push('', `Every method checks the same legs (on route-turn FCL tests the poses hullkit::leg_pose gives, and its continuousCollide moves the traverse by fcl::InterpMotion about the same pivot: the same motion); verdicts are compared with FCL's collide at ${measured[0].referencePoses} evenly spaced poses per leg (the reference). ` +
    `hullkit runs on one thread (RouteOptions::threads = 1; FCL is single-threaded). Times are per leg (total / legs): the median over the runs (hullkit ${meta.quick ? 1 : 5}, FCL ${runsOf(measured[0]) ?? '≤ 3'}; continuousCollide with conservative advancement, seconds per leg, 1) and the first call in the process: hullkit's verdict run is the process's first check, its first check with clearance was timed in a fresh process of its own; FCL's first is its first run after building its models. hullkit's verdict time includes the exact first-contact fraction.`, '');
}
md.push('| route | legs (reference hits) | method | ms per leg, median | ms per leg, first call | legs hit | misses vs reference |');
md.push('|---|---|---|---:|---:|---:|---:|');
for (const row of rows) {
  if (row.missing) {
    md.push(`| ${row.route} | – | (no results) | | | | |`);
    continue;
  }
  const head = `| ${row.route} | ${row.legs} (${row.referenceHits})`;
  const grazing = row.hk.grazing_legs?.length ? ` (${row.hk.grazing_legs.length} grazing)` : '';
  md.push(`${head} | hullkit, verdict + first contact | ${fmt(row.hk.ms_per_leg)} | ${fmt(row.hk.first_ms_per_leg)} | ${count(row.hk.hits)}${grazing} | ${row.hkMisses} |`);
  md.push(`${head} | hullkit, with clearance | ${fmt(row.hk.ms_per_leg_clearance)} | ${fmt(row.firstClearance?.first_ms_per_leg)} | ${count(row.hk.hits_with_clearance)} | ${row.hkMissesClearance} |`);
  if (row.f100) md.push(`${head} | FCL collide, 100 poses | ${fmt(row.f100.ms_per_leg)} | ${fmt(row.f100.first_ms_per_leg)} | ${count(row.f100.hits)} | ${row.f100Misses} |`);
  if (row.ccd) md.push(`${head} | FCL continuousCollide (${row.turned ? 'interp motion, conservative advancement' : 'default request'}) | ${fmt(row.ccd.ms_per_leg)} | ${fmt(row.ccd.first_ms_per_leg)} | ${count(row.ccd.hits)} | ${row.ccdMisses} |`);
  md.push(`${head} | FCL collide, ${row.referencePoses} poses (reference) | ${fmt(row.ref.ms_per_leg)} | – | ${row.referenceHits} | – |`);
}
md.push('');
if (measured.length) {
  const build = (row) => `hullkit ${fmt(row.hk.build_seconds * 1e3)} ms (hulls + BVH), FCL ${row.f100 ? fmt(row.f100.build_seconds * 1e3) : '–'} ms (BVHModel<OBBRSS> of the obstacles and the traverse)`;
  md.push(`Scene preparation: ${build(mainRow ?? measured[0])}${alignedRow ? `; the aligned scene: ${build(alignedRow)}` : ''}.`);
  for (const r of measured) {
    if (r.hkExtra) {
      const d = r.checks?.disagreements?.filter((x) => x.hullkit && !x.reference) ?? [];
      const seen = d.filter((x) => x.hullkit_static_first !== null).length;
      md.push(`On ${r.route}, hullkit reports ${r.hkExtra} hit(s) the reference does not see${r.checks ? `; hullkit's own exact static test at the reference's ${r.referencePoses} poses finds contact on ${seen} of them (legs ${d.filter((x) => x.hullkit_static_first !== null).map((x) => x.leg).join(', ') || '–'})${seen < d.length ? `, the other ${d.length - seen} are contacts between the poses or exact touching` : ''}` : ''}. ` +
        'Where the static test sees contact FCL\'s does not, a closed traverse contains an obstacle piece or touches it exactly: FCL\'s mesh collide tests triangle pairs only.');
    }
    if (r.turned && r.ccd && (r.ccdMisses || r.ccdExtra)) {
      md.push(`On ${r.route}, FCL's conservative advancement (BVHModel<OBBRSS>, its mesh-mesh path) misses ${r.ccdMisses} of the reference's ${r.referenceHits} hits and reports ${r.ccdExtra} hit(s) the reference does not see (its known mesh-mesh motion-bound problems: flexible-collision-library/fcl issues #120, #555).`);
    }
  }
  md.push('');
  md.push('Sanity checks of hullkit\'s reports against its own exact static test (RouteChecker::static_contact, untimed): on every hit leg the pose at fraction_hi is in contact; where the reference also hits, lo is not after its first pose in contact; on every clear leg the static distance at the reported fraction is the reported clearance (1e-6 relative when turning, 1e-9 straight) and no pose of 21 is closer.');
  md.push('');
  md.push('| route | hi in contact | lo <= reference | clearance at its fraction (worst relative difference) | no pose closer | legs whose contact precedes the reference\'s last clear pose |');
  md.push('|---|---|---|---|---|---|');
  const ok = (list) => (list ? (list.length ? `**${list.length} failed**` : 'all') : '–');
  for (const r of measured) {
    const c = r.checks;
    md.push(`| ${r.route} | ${ok(c?.hi_not_in_contact)} | ${ok(c?.lo_after_reference)} | ${ok(c?.clearance_mismatch)} (${c ? fmt(c.worst_clearance_relative, 2) : '–'}) | ${ok(c?.closer_than_clearance)} | ${c ? c.earlier_than_reference.length : '–'} |`);
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
if (odd.length) {
  md.push('## To look at', '');
  for (const o of odd) md.push(`- ${o}`);
  md.push('');
}

const mdPath = meta.quick ? join(here, 'out', 'results-route.md') : join(here, 'results-route.md');
writeFileSync(mdPath, md.join('\n'));
console.log(`route bench: wrote ${mdPath}`);
for (const t of targets) console.log(`${t.status.padEnd(12)} ${t.name}: ${t.value ?? '–'} (goal ${t.goal})`);
for (const o of odd) console.log(`ODD          ${o}`);
