// Turns the JSON lines of bench/constrained_run.sh into bench/results-constrained.md (quick mode:
// bench/out/constrained/results-constrained.md): first-call and warm times with ratios hullkit / peer,
// the correctness table, and the targets summary (also printed).
//
//   node bench/constrained_report.mjs [--quick 0|1] [--elapsed SECONDS] [--load LOADAVG] [--inputs inputs.json] RESULTS.jsonl
//
// The headline of every figure is the first call in a fresh process (what a user meets); the median of
// the later calls in that process (warm) stands beside it in parentheses. Targets (issue 31), each a
// ratio of first calls from the same run:
//   - wasm triangulatePolygon at most 0.5x earcut's time on every large polygon (>= 1e4 vertices),
//     and over the whole set of polygons (the geometric mean of the per-polygon ratios; the ratio of
//     the summed times is shown beside it);
//   - native CDT of the graph (1e6 points, 1e5 segments) at most 1.0x CGAL's
//     Constrained_Delaunay_triangulation_2;
//   - quality meshes with CGAL's angle bound (B = 0.125, about 20.7 degrees) at most 0.5x the time of
//     CGAL's Delaunay_mesher_2, judged twice: by the geometric mean of the per-polygon ratios and by
//     the worst polygon (the polygons where both ran; the skipped ones are listed with the reason).
// A target counts as met only when hullkit's output was checked ok on every input it covers.
// In quick mode the graph has 1e4 points and there is no 1e5 polygon; the report says so.
import { readFileSync, writeFileSync, existsSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import os from 'node:os';

const here = dirname(fileURLToPath(import.meta.url));
const argv = process.argv.slice(2);
const option = (name, fallback) => {
  const i = argv.indexOf(name);
  if (i < 0) return fallback;
  const [value] = argv.splice(i, 2).slice(1);
  return value;
};
const quick = option('--quick', '0') === '1';
const elapsed = option('--elapsed', null);
const load = option('--load', null);
const inputsFile = option('--inputs', join(here, 'out', 'constrained', quick ? 'inputs-quick.json' : 'inputs.json'));
const file = argv[0] ?? join(here, 'out', 'constrained', quick ? 'results-quick.jsonl' : 'results.jsonl');
const results = readFileSync(file, 'utf8').split('\n').filter(Boolean).map((line) => JSON.parse(line));
const inputs = existsSync(inputsFile) ? JSON.parse(readFileSync(inputsFile, 'utf8')) : [];
const inputNames = inputs.length ? inputs.map((i) => i.name) : [...new Set(results.map((r) => r.input))];
const info = Object.fromEntries(inputs.map((i) => [i.name, i]));
const polygons = inputNames.filter((name) => (info[name]?.kind ?? (name.startsWith('graph-') ? 'graph' : 'polygon')) === 'polygon');
const graphs = inputNames.filter((name) => !polygons.includes(name));
const size = (name) => info[name]?.vertices ?? info[name]?.points ?? results.find((r) => r.input === name && r.n)?.n ?? null;

const find = (kind, impl, input) => results.find((r) => r.kind_of_run === kind && r.impl === impl && r.input === input);
const timed = (r) => r && r.first != null && !r.error && r.verdict !== 'exception';

const seconds = (s) => (s == null ? '–' : s < 0.1 ? `${(s * 1000).toPrecision(3)} ms` : `${s.toPrecision(3)} s`);
function cell(r) {
  if (!r) return 'not run';
  switch (r.verdict) {
    case 'not available': return 'n/a';
    case 'not applicable': return '–';
    case 'skipped': return 'not run';
    case 'timeout': return `timeout (${r.error?.replace('stopped after ', '> ') ?? ''})`;
    case 'crash': return 'crash';
    case 'exception': return 'exception';
    default: break;
  }
  if (r.error) return 'error';
  const base = `${seconds(r.first)} (${seconds(r.warm)})`;
  if (r.verdict === 'wrong') return `${base} **wrong**`;
  if (r.t_junctions) return `${base} ᵀ`;
  return base;
}
const ratio = (a, b) => (timed(a) && timed(b) && a.first > 0 && b.first > 0 ? a.first / b.first : null);
const ratioText = (value) => (value == null ? '–' : `${value.toFixed(2)}×`);
const geomean = (values) => (values.length ? Math.exp(values.reduce((s, v) => s + Math.log(v), 0) / values.length) : null);

// ---- tables
const polygonRows = polygons.map((input) => {
  const wasm = find('js', 'hullkit', input);
  const earcut = find('js', 'earcut', input);
  const cells = ['constrainautor', 'cdt2d', 'poly2tri'].map((impl) => cell(find('js', impl, input)));
  return `| ${input} | ${size(input) ?? '–'} | ${info[input]?.rings ?? '–'} | ${cell(wasm)} | ${cell(earcut)} | ${ratioText(ratio(wasm, earcut))} | ${cells.join(' | ')} |`;
});
const nativeRows = polygons.map((input) => {
  const hullkit = find('native', 'hullkit', input);
  const cgal = find('native', 'cgal-cdt', input);
  const triangles = [hullkit, cgal].filter((r) => timed(r)).map((r) => r.triangles);
  return `| ${input} | ${size(input) ?? '–'} | ${cell(hullkit)} | ${cell(cgal)} | ${ratioText(ratio(hullkit, cgal))} | ` +
    `${triangles.every((t) => t === triangles[0]) ? triangles[0] ?? '–' : triangles.join(' / ')} |`;
});
// Quality meshes: hullkit-mesh against cgal-mesh. CGAL's mesh is not checked ("unchecked" when it ran).
const meshRan = (r) => timed(r) && r.verdict !== 'skipped';
const angle = (r) => (meshRan(r) && r.min_angle_deg != null ? `${r.min_angle_deg.toFixed(1)}°` : '–');
function meshCheck(r) {
  if (!r) return 'not run';
  if (r.verdict === 'skipped' || !meshRan(r)) return cell(r);
  if (r.verdict !== 'ok') return `**${r.verdict}**`;
  // hullkit's own count of triangles left below the bound (unrefined_count), when it differs.
  const own = r.unrefined != null && r.unrefined !== r.below_bound ? `; hullkit counts ${r.unrefined}` : '';
  if (!r.below_bound) return `ok${own ? ` (${own.slice(2)})` : ''}`;
  const parts = [r.excused_input_angle ? `${r.excused_input_angle} at input angles` : '', r.excused_shells ? `${r.excused_shells} between shells` : ''].filter(Boolean);
  return `ok (${r.below_bound} below the bound: ${parts.join(', ')}${own})`;
}
/** Rows of hullkit's `hullkitImpl` against CGAL's `cgalImpl` per polygon (quality meshes, refining). */
const meshRowsOf = (hullkitImpl, cgalImpl) => polygons.map((input) => {
  const h = find('native', hullkitImpl, input);
  const c = find('native', cgalImpl, input);
  if (h?.verdict === 'skipped' || c?.verdict === 'skipped') {
    const why = (h?.verdict === 'skipped' ? h : c).error ?? '';
    return `| ${input} | ${size(input) ?? '–'} | not run: ${why} | not run | – | – | – | – | – | – | – |`;
  }
  const warm = meshRan(h) && meshRan(c) && h.warm > 0 && c.warm > 0 ? h.warm / c.warm : null;
  return `| ${input} | ${size(input) ?? '–'} | ${cell(h)} | ${cell(c)} | ${ratioText(ratio(h, c))} | ${ratioText(warm)} | ` +
    `${meshRan(h) ? h.triangles : '–'} | ${meshRan(c) ? c.triangles : '–'} | ${angle(h)} | ${angle(c)} | ${meshCheck(h)} |`;
});
const meshRows = meshRowsOf('hullkit-mesh', 'cgal-mesh');
// How many fresh processes gave the first calls of these rows (bench/constrained_run.sh, FRESH_ROUNDS):
// the mesh rows, and the JavaScript pair on the large polygons.
const freshRounds = (rows) => Math.max(1, ...rows.map((r) => r.first_each?.length ?? 1));
const meshRounds = freshRounds(results.filter((r) => r.kind_of_run === 'native' && /-(mesh|refine)$/.test(r.impl)));
const jsRounds = freshRounds(results.filter((r) => r.kind_of_run === 'js'));
const meshFirsts = meshRounds > 1
  ? `Times: hullkit and CGAL each in ${meshRounds} fresh processes, taking turns; the headline is the median of their first calls, the warm figure the median of the first process's later calls.`
  : 'Times: one fresh process each; the headline is its first call.';
const refineRows = meshRowsOf('hullkit-refine', 'cgal-refine');
const refineRan = polygons.some((input) => find('native', 'hullkit-refine', input) || find('native', 'cgal-refine', input));
const graphRows = graphs.map((input) => {
  const hullkit = find('native', 'hullkit', input);
  const single = find('native-1thread', 'hullkit', input);
  const cgal = find('native', 'cgal-cdt', input);
  const wasm = find('js', 'hullkit', input);
  const con = find('js', 'constrainautor', input);
  const cdt2d = find('js', 'cdt2d', input);
  return `| ${input} | ${size(input) ?? '–'} | ${info[input]?.segments ?? '–'} | ${cell(hullkit)} | ${cell(single)} | ${cell(cgal)} | ` +
    `${ratioText(ratio(hullkit, cgal))} | ${cell(wasm)} | ${cell(con)} | ${cell(cdt2d)} | ${ratioText(ratio(wasm, con))} |`;
});

// ---- correctness
const implementations = [
  ['hullkit wasm', 'js', 'hullkit'], ['hullkit native', 'native', 'hullkit'], ['earcut', 'js', 'earcut'],
  ['delaunator + constrainautor', 'js', 'constrainautor'], ['cdt2d', 'js', 'cdt2d'], ['poly2tri', 'js', 'poly2tri'],
  ['CGAL CDT', 'native', 'cgal-cdt'], ['hullkit quality mesh', 'native', 'hullkit-mesh'],
  ['hullkit refined mesh (-r)', 'native', 'hullkit-refine'],
];
const problems = [];
const correctnessRows = implementations.map(([label, kind, impl]) => {
  const rows = results.filter((r) => r.kind_of_run === kind && r.impl === impl && !['not applicable', 'skipped'].includes(r.verdict));
  const count = (v) => rows.filter((r) => r.verdict === v).length;
  const tj = rows.filter((r) => r.verdict === 'ok' && r.t_junctions > 0);
  for (const r of rows) {
    if (r.verdict === 'ok' && !(r.t_junctions > 0)) continue;
    if (r.verdict === 'not available') continue;
    const why = r.verdict === 'ok' ? `ok, but ${r.t_junctions} T-junction line(s): a vertex on another triangle's edge (covers the polygon once, not a conforming mesh)`
      : r.reason ?? r.error ?? '';
    problems.push(`- ${label}, ${r.input}: **${r.verdict}** — ${why.replace(/\|/g, '/').slice(0, 240)}`);
  }
  const ok = count('ok');
  const na = count('not available');
  return `| ${label} | ${ok}${tj.length ? ` (${tj.length} with T-junctions)` : ''} | ${count('wrong')} | ${count('exception')} | ` +
    `${count('timeout') + count('crash')} | ${na ? `${na}${rows.length === na ? ' (all)' : ''}` : 0} |`;
});

// ---- targets
const targets = [];
function target(label, value, limit, how, blockers = []) {
  const met = value != null && value <= limit && blockers.length === 0;
  const verdict = value == null ? 'NOT MEASURED' : met ? 'MET' : 'NOT MET';
  targets.push({ label, value, met, text: `${label}: ${value == null ? 'not measured' : ratioText(value)} (target ≤ ${limit}×) ${verdict} — ${how}` +
    (blockers.length ? `; hullkit's output not ok on ${blockers.join(', ')}` : '') });
}
const large = polygons.filter((p) => (size(p) ?? 0) >= 1e4);
function polygonTarget(label, set, aggregate) {
  const pairs = set.map((input) => ({ input, h: find('js', 'hullkit', input), e: find('js', 'earcut', input) }));
  const usable = pairs.filter(({ h, e }) => ratio(h, e) != null);
  const hullkitMissing = pairs.filter(({ h }) => !timed(h)).map(({ input, h }) => `${input} (${h?.verdict ?? 'not run'})`);
  const blockers = pairs.filter(({ h }) => h && h.verdict && h.verdict !== 'ok' && h.verdict !== 'not available').map(({ input }) => input);
  if (usable.length === 0) {
    target(label, null, 0.5, hullkitMissing.length ? `hullkit wasm: ${hullkitMissing.slice(0, 3).join(', ')}${hullkitMissing.length > 3 ? ', …' : ''}` : 'no inputs');
    return;
  }
  const ratios = usable.map(({ h, e }) => h.first / e.first);
  const sumH = usable.reduce((s, { h }) => s + h.first, 0), sumE = usable.reduce((s, { e }) => s + e.first, 0);
  const worst = usable[ratios.indexOf(Math.max(...ratios))].input;
  const value = aggregate === 'worst' ? Math.max(...ratios) : geomean(ratios);
  const how = aggregate === 'worst'
    ? `worst of ${usable.length} polygon(s) (${worst}); geometric mean ${ratioText(geomean(ratios))}`
    : `geometric mean over ${usable.length} polygon(s); summed times ${ratioText(sumH / sumE)}, worst ${ratioText(Math.max(...ratios))} (${worst})`;
  const skipped = pairs.length - usable.length;
  const firsts = jsRounds > 1 ? `first calls after loading (on the polygons of 10⁴ vertices and more the medians of ${jsRounds} fresh processes each, taking turns)` : 'first calls after loading';
  target(label, value, 0.5, `${how}, ${firsts}${skipped ? `; ${skipped} left out (no time from one side)` : ''}`, blockers);
}
polygonTarget(`wasm triangulatePolygon / earcut, every polygon ≥ 1e4 vertices`, large, 'worst');
polygonTarget('wasm triangulatePolygon / earcut, the whole set', polygons, 'geomean');
for (const graph of graphs) {
  const h = find('native', 'hullkit', graph), c = find('native', 'cgal-cdt', graph);
  const blockers = h && h.verdict && !['ok', 'not available'].includes(h.verdict) ? [graph] : [];
  target(`native CDT of ${graph}, hullkit / CGAL`, ratio(h, c), 1.0,
    timed(h) ? `first call in a fresh process each (warm: ${ratioText(h.warm && c?.warm ? h.warm / c.warm : null)})` : `hullkit native: ${h?.verdict ?? 'not run'}${h?.error ? ` (${h.error.slice(0, 100)})` : ''}`,
    blockers);
}
{
  // Quality meshes: the polygons where both meshes ran; skipped ones named with their reason, polygons
  // where one side has no time (timeout, crash, ...) named as left out.
  const pairs = polygons.map((input) => ({ input, h: find('native', 'hullkit-mesh', input), c: find('native', 'cgal-mesh', input) }));
  const skipped = pairs.filter(({ h, c }) => h?.verdict === 'skipped' || c?.verdict === 'skipped');
  const run = pairs.filter((p) => !skipped.includes(p));
  const usable = run.filter(({ h, c }) => ratio(h, c) != null);
  const leftOut = run.filter((p) => !usable.includes(p))
    .map(({ input, h, c }) => `${input} (hullkit ${h?.verdict ?? 'not run'}, CGAL ${c?.verdict ?? 'not run'})`);
  const blockers = run.filter(({ h }) => h && h.verdict && !['ok', 'not available'].includes(h.verdict)).map(({ input }) => input);
  const ratios = usable.map(({ h, c }) => h.first / c.first);
  const warm = usable.filter(({ h, c }) => h.warm > 0 && c.warm > 0).map(({ h, c }) => h.warm / c.warm);
  const worst = ratios.length ? Math.max(...ratios) : null;
  const worstInput = worst == null ? null : usable[ratios.indexOf(worst)].input;
  const notes = [
    leftOut.length ? `left out (no time from one side): ${leftOut.join(', ')}` : '',
    skipped.length ? `not run: ${skipped.map(({ input, h, c }) => `${input} (${(h?.verdict === 'skipped' ? h : c).error})`).join(', ')}` : '',
  ].filter(Boolean).join('; ');
  const label = "quality meshes with CGAL's angle bound ≤ 0.5× its time";
  target(`${label}, geometric mean`, geomean(ratios), 0.5,
    ratios.length ? `hullkit-mesh / cgal-mesh first calls${meshRounds > 1 ? ` (medians of ${meshRounds} fresh processes)` : ''} over ${ratios.length} polygon(s) (warm ${ratioText(geomean(warm))}), worst ${ratioText(worst)} (${worstInput})${notes ? `; ${notes}` : ''}` : `no polygon with both times${notes ? `; ${notes}` : ''}`,
    blockers);
  target(`${label}, worst polygon`, worst, 0.5,
    ratios.length ? `${worstInput}, first calls${meshRounds > 1 ? ` (medians of ${meshRounds} fresh processes)` : ''}, of ${ratios.length} polygon(s); geometric mean ${ratioText(geomean(ratios))}${notes ? `; ${notes}` : ''}` : `no polygon with both times${notes ? `; ${notes}` : ''}`,
    blockers);
}

const cpu = os.cpus()[0]?.model ?? 'unknown CPU';
const graphInfo = graphs.map((g) => `${g}: ${info[g]?.description ?? ''}`).join('; ');
const lines = [
  '# Constrained Delaunay benchmark',
  '',
  `Written by \`bench/constrained_report.mjs\` from \`bench/constrained_run.sh\`${quick ? ' in QUICK mode (no 1e5 polygon, the graph at 1e4 points / 1e3 segments, 3 runs each: not the real figures)' : ''}` +
    `${elapsed ? `, ${elapsed} s in all` : ''}; ${cpu}, ${os.cpus().length} cores, Node ${process.version}` +
    `${load ? `; load average ${load} at the start${Number(load) > os.cpus().length / 2 ? ' (a busy machine: times are noisy)' : ''}` : ''}.`,
  '',
  'Each cell: the first call in a fresh process (the headline) and, in parentheses, the median of the later calls in',
  'the same process (warm). Ratios compare first calls. Every triangulation is checked (the first call\'s result):',
  '**wrong** marks one that does not cover exactly the polygon (or the graph\'s hull with every segment);',
  'ᵀ marks a correct cover with T-junctions (a vertex on another triangle\'s edge: not a conforming triangulation);',
  '"n/a": hullkit\'s binding or core is not available in this build; "exception": the call threw. Details under',
  '[Correctness](#correctness).',
  '',
  '## Inputs',
  '',
  '| input | vertices / points | rings / segments | what |',
  '|---|---:|---:|---|',
  ...inputNames.map((n) => `| ${n} | ${size(n) ?? '–'} | ${info[n]?.rings ?? info[n]?.segments ?? '–'} | ${info[n]?.description ?? ''} |`),
  '',
  '## Polygons with holes, JavaScript (Node)',
  '',
  'hullkit: the wasm `triangulatePolygon(coords, holeIndices)` with copies in and out; earcut on the same',
  '`Float64Array`; constrainautor: `new Delaunator(coords)`, `Constrainautor.constrainAll(ring edges)` and the',
  'inside triangles by an even-odd flood fill (all timed); cdt2d `(points, edges, {exterior: false})`; poly2tri',
  '`SweepContext` + `addHoles` + `triangulate()`. Inputs in each library\'s own form, made before the clock starts.',
  ...(jsRounds > 1 ? [`On the polygons of 10⁴ vertices and more, hullkit and earcut each ran in ${jsRounds} fresh processes, taking turns: their headline is the median of the first calls.`] : []),
  '',
  '| polygon | vertices | rings | hullkit wasm | earcut | hullkit / earcut | constrainautor | cdt2d | poly2tri |',
  '|---|---:|---:|---:|---:|---:|---:|---:|---:|',
  ...polygonRows,
  '',
  '## Polygons with holes, native',
  '',
  'hullkit: `triangulate_polygon` (even-odd). CGAL CDT: `Constrained_Delaunay_triangulation_2<Epick, ...,',
  'Exact_predicates_tag>`, spatially sorted points then `insert_constraint` per ring edge, then the nesting levels',
  '("mark domains"); the inside faces counted.',
  '',
  '| polygon | vertices | hullkit | CGAL CDT | hullkit / CGAL | triangles |',
  '|---|---:|---:|---:|---:|---:|',
  ...nativeRows,
  '',
  '## Quality meshes, native',
  '',
  'The inside of each polygon refined until every angle is at least CGAL\'s default shape bound B = 0.125',
  '(sin² of the smallest angle: asin(√0.125) ≈ 20.7048°), no area bound; a run is the whole call from the input',
  'arrays. hullkit: `triangulate_polygon` with `PolygonOptions.quality.min_angle` = 20.7048°. CGAL: the CDT and',
  'marks above, then `Delaunay_mesher_2` with `Delaunay_mesh_size_criteria_2(0.125, 0)`. hullkit\'s first mesh is',
  'checked (`checkMesh` in `bench/constrained_common.mjs`): every triangle clockwise and not flat (exact), no',
  'overlap, every boundary edge on a ring edge (the points added on ring edges are rounded to doubles), the area',
  'and the boundary\'s length the polygon\'s within a relative 1e-9, and every angle at least the bound except',
  'where a small input angle excuses it: triangles in a wedge between ring edges narrower than the bound, or',
  'between points at equal distances on two ring edges from their common end (Shewchuk\'s rule); those are',
  'counted in the check column. CGAL\'s meshes are not checked. Smallest angles: computed in doubles over all',
  'triangles, input angles below the bound included.',
  meshFirsts,
  '',
  '| polygon | vertices | hullkit | CGAL | hullkit / CGAL | warm ratio | triangles hullkit | triangles CGAL | min angle hullkit | min angle CGAL | hullkit check |',
  '|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|',
  ...meshRows,
  '',
  ...(refineRan ? [
    '## Refining a mesh (Triangle\'s -r), native',
    '',
    'The same bound applied to a mesh that exists: the time of the refinement alone, the polygon\'s triangulation made',
    'before the clock starts. hullkit: `triangulate_polygon`, then `refine_mesh(coords, triangles, ...)` timed (it',
    'checks the triangles, takes their union as the domain and triangulates it anew before refining, as Triangle',
    'flips the edges of a mesh it refines). CGAL: the CDT and marks, then `Delaunay_mesher_2` timed. hullkit\'s',
    'refined mesh gets the check of the quality meshes.',
    '',
    '| polygon | vertices | hullkit | CGAL | hullkit / CGAL | warm ratio | triangles hullkit | triangles CGAL | min angle hullkit | min angle CGAL | hullkit check |',
    '|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|',
    ...refineRows,
    '',
  ] : []),
  '## Planar straight-line graph',
  '',
  `${graphInfo}. Native: hullkit \`constrained_delaunay\` (default threads; "1 thread": \`threads = 1\`) and CGAL's CDT`,
  '(points spatially sorted, then the segments). JS: hullkit wasm `constrainedDelaunay`, delaunator + constrainautor,',
  'cdt2d; earcut and poly2tri take polygons only.',
  '',
  '| graph | points | segments | hullkit native | 1 thread | CGAL CDT | hullkit / CGAL | hullkit wasm | constrainautor | cdt2d | wasm / constrainautor |',
  '|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|',
  ...graphRows,
  '',
  '## Correctness',
  '',
  'Per implementation, over every input it was run on: the check of `bench/constrained_common.mjs` (exact',
  'orientations; every directed edge once; the triangles\' boundary equal to the rings, or the hull with every',
  'segment an edge; total area within a relative 1e-9 of the shoelace area); hullkit\'s quality meshes by the mesh',
  'check above. CGAL\'s meshes are not checked.',
  '',
  '| implementation | ok | wrong | exception | timeout / crash | not available |',
  '|---|---:|---:|---:|---:|---:|',
  ...correctnessRows,
  '',
  ...(problems.length ? problems : ['Every output checked was ok.']),
  '',
  '## Targets',
  '',
  ...targets.map((t) => `- ${t.text}`),
  '',
];
const reportFile = quick ? join(here, 'out', 'constrained', 'results-constrained.md') : join(here, 'results-constrained.md');
writeFileSync(reportFile, lines.join('\n'));
console.log(`constrained bench targets${quick ? ' (QUICK mode)' : ''}:`);
for (const t of targets) console.log(`  ${t.text}`);
console.log(`(${targets.filter((t) => t.met).length} of ${targets.length} met; report in ${reportFile.replace(`${dirname(here)}/`, '')})`);
