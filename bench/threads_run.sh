#!/usr/bin/env bash
# The threads-and-streaming benchmark (issue 14), side by side in one run; writes
# bench/results-threads.md. Every hullkit figure comes from a fresh process; 1-thread and 2-thread
# processes alternate (1 2, 2 1, 1 2, ...) so that a noisy neighbour on this shared 2-core machine
# slows both alike; the tables give medians and every run.
#   1. library: hullkit_threads_bench (bench/threads_bench.cpp) generates a cloud in process and
#      times hullkit::hull with HullOptions::threads 1 and 2: the first call, and the median of the
#      warm calls after it. Ball 1e7, sphere 1e6, cube 1e7. The triangle hash and the volume bits
#      must be the same for every process and thread count. Target: 2 threads <= 0.6 x 1 thread.
#   2. the whole command on 1e7 points in a cube as text (rbox 10000000 D3):
#      `hullkit hull FILE -o OUT.off --threads 1|2` (wall time and peak RSS of the process, GNU
#      time) against `qconvex o < FILE > OUT.off`. Targets: 2 threads <= 0.6 x 1 thread and
#      <= 0.1 x qconvex; the OFF files of every hullkit run byte-identical (cmp).
#   3. streaming: 1e8 points in a ball as a binary little-endian float64 PLY (2.4 GB, written by
#      hullkit_threads_bench --write-ply), `hullkit hull FILE.ply --memory 256 --stats` (streamed)
#      against `--memory 20000` (in memory). Targets: streamed peak RSS <= 300 MB, streamed wall
#      time <= 1.2 x in memory, both OFF files identical. Qhull cannot take 1e8 points as text here
#      (a 6 GB file), so qconvex runs on the same generator's first 1e7 points as text, and its
#      time and peak memory are extrapolated linearly to 1e8.
# Generated files live in bench/out/threads/ (git-ignored); the large ones (inputs and qconvex's
# OFF, which lists every input point) are deleted on exit, whatever happens.
# Environment:
#   HULLKIT_BENCH_QUICK=1      smoke test: 1/10 of the sizes, fewer runs; the report goes to
#                              bench/out/threads/results-threads.md (raw figures:
#                              results-quick.jsonl), never over bench/results-threads.md
#   HULLKIT_BENCH_NO_BUILD=1   use the build as it is
#   HULLKIT_BENCH_BUILD_DIR=D  where hullkit and hullkit_threads_bench are built (default build/bench)
#   HULLKIT_BENCH_REPORT_ONLY=1  rewrite the report from bench/out/threads/results.jsonl alone
set -euo pipefail
cd "$(dirname "$0")/.."
started=$(date +%s)
quick=${HULLKIT_BENCH_QUICK:-0}
build=${HULLKIT_BENCH_BUILD_DIR:-build/bench}
work=bench/out/threads
mkdir -p "$work"
say() { printf 'threads bench: %s\n' "$*" >&2; }

# The large files: removed on any exit so a failed run leaves no gigabytes behind.
cleanup() {
  rm -f "$work"/cube.txt "$work"/ball.ply "$work"/ball.txt "$work"/*.qconvex.off "$work"/ball-text.off \
    "$work"/time.txt "$work"/*.err "$work"/err.log
}
trap cleanup EXIT

if [ "$quick" = 1 ]; then
  # Sizes a tenth (the sphere: 1e5), enough to exercise every step in about two minutes.
  part1_clouds=(ball:1000000 sphere:100000 cube:1000000)
  cube_n=1000000 ply_n=10000000 text_n=1000000
  procs1=2 runs1=2 runs2=2 runs2_qconvex=1 runs3=1 runs3_qconvex=1
  report=$work/results-threads.md
else
  # Run counts chosen for ~15-20 min in all on a 2-core machine (measured with 5 processes where
  # there are now 9: 13.6 min at load average ~5, part 1 ~6 min, part 2 ~3 min, part 3 ~5 min; a
  # 1e8 run takes 20-90 s; 3.2 min on a quiet machine), well inside 25 min. 9 processes, not 5:
  # on this shared machine 2-thread runs slow down by 15-25% in bursts lasting several processes,
  # and a median of 5 moved with them by up to 0.1 in the ratio from one run to the next.
  part1_clouds=(ball:10000000 sphere:1000000 cube:10000000)
  cube_n=10000000 ply_n=100000000 text_n=10000000
  procs1=9 runs1=3 runs2=9 runs2_qconvex=2 runs3=3 runs3_qconvex=2
  report=bench/results-threads.md
fi
# A quick run keeps its raw figures apart, so that it never overwrites the full run's.
results=$work/results$([ "$quick" = 1 ] && echo -quick || true).jsonl

# write_report: writes $report from $results (and prints it).
write_report() {
  local report_js
  report_js=$(
  cat <<'EOF'
const fs = require('fs');
const [resultsPath, reportPath] = process.argv.slice(1);
const rows = fs.readFileSync(resultsPath, 'utf8').split('\n').filter((l) => l.startsWith('{')).map((l) => JSON.parse(l));
const runs1 = rows.find((r) => r.part === 1 && r.runs)?.runs ?? '?';
const meta = rows.find((r) => r.part === 0);
const end = rows.find((r) => r.part === 9);
const median = (xs) => {
  const v = xs.filter((x) => typeof x === 'number').sort((a, b) => a - b);
  if (!v.length) return null;
  const m = v.length >> 1;
  return v.length % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
};
const f = (x, d = 3) => (x === null || x === undefined || Number.isNaN(x) ? '–' : Number(x).toPrecision(d));
const s = (x) => (x === null ? '–' : `${f(x)} s`);
const mb = (kb) => (kb === null ? '–' : `${(kb / 1024).toFixed(0)} MB`);
const pct = (x) => (x === null ? '–' : `${(100 * x).toFixed(0)}%`);
const ratio = (a, b) => (a === null || b === null ? null : a / b);
const met = (ok) => (ok === null ? 'not measured' : ok ? 'met' : 'not met');
const list = (xs, unit = '') => xs.map((x) => (typeof x === 'number' ? f(x) : '–') + unit).join(', ');
const sci = (n) => { const e = Math.round(Math.log10(n)); return 10 ** e === n ? `1e${e}` : String(n); };
const out = [];

out.push('# Threads and streaming benchmark (issue 14)', '');
out.push(`Written by \`bash bench/threads_run.sh\` on ${meta.date}${meta.quick ? ' (**quick run**: smaller sizes, fewer runs)' : ''}. ` +
  `Machine: ${meta.nproc} hardware threads (\`nproc\`), ${meta.cpu}, ${meta.memory_gb} GB RAM; load average ` +
  `${meta.load_start} at the start and ${end.load_end} at the end (a shared machine). hullkit at commit ${meta.commit} ` +
  `plus the working tree, Release build (-O3, -ffp-contract=off) in \`${meta.build}\`; Qhull ${meta.qhull} (Debian qhull-bin). ` +
  `The whole run took ${(end.elapsed_seconds / 60).toFixed(1)} min.`, '');
out.push('Every hullkit figure comes from a fresh process. 1-thread and 2-thread processes alternate (1 2, 2 1, ...) ' +
  'so that load from elsewhere hits both; figures are medians over processes, every run is listed. ' +
  'Files the script writes (the inputs, qconvex\'s OFF) are flushed to disk (sync) before the next process is timed. ' +
  'Ratio = 2-thread / 1-thread time; efficiency = speed-up / 2 = 1-thread / (2 × 2-thread).' +
  (Math.max(...`${meta.load_start} ${end.load_end}`.split(' ').map(Number)) > meta.nproc
    ? ' The load average was above the hardware thread count: other processes competed for the cores, which weighs most on the 2-thread figures.'
    : ''), '');

// ---- part 1
out.push('## 1. Library: `hullkit::hull`, threads 1 vs 2', '');
out.push(`\`hullkit_threads_bench --cloud C --n N --threads T --runs ${runs1}\`: the cloud is generated in the process (seeded; not timed), ` +
  `then hullkit::hull is called ${runs1} times. "first" = the first call in the process (median over processes), ` +
  '"warm" = the median over processes of each process\'s median of its later calls. "identical" = the triangle array\'s ' +
  'FNV-1a hash and the volume\'s bits are the same in every process and every call, both thread counts. Target: ratio of first calls <= 0.6.', '');
out.push('| cloud | n | hull vertices / triangles | processes (1t, 2t) | 1 thread first (warm) | 2 threads first (warm) | ratio 2t/1t first (warm) | efficiency first (warm) | identical | target 2t <= 0.6 × 1t | first calls, 1 thread | first calls, 2 threads |');
out.push('|---|---:|---:|---:|---:|---:|---:|---:|---|---|---|---|');
const part1 = rows.filter((r) => r.part === 1);
for (const cloud of [...new Set(part1.map((r) => r.cloud))]) {
  const all = part1.filter((r) => r.cloud === cloud);
  const good = all.filter((r) => !r.error);
  const by = (t) => good.filter((r) => r.threads === t);
  const one = by(1), two = by(2);
  const first1 = median(one.map((r) => r.first_seconds)), first2 = median(two.map((r) => r.first_seconds));
  const warm1 = median(one.map((r) => r.warm_median_seconds)), warm2 = median(two.map((r) => r.warm_median_seconds));
  const keys = new Set(good.map((r) => `${r.triangles_fnv1a}/${r.volume_bits}`));
  const identical = good.length && keys.size === 1 && good.every((r) => r.runs_identical) && one.length && two.length;
  const errors = all.length - good.length;
  const r = ratio(first2, first1), rw = ratio(warm2, warm1);
  const g = good[0] ?? {};
  out.push(`| ${cloud} | ${sci(all[0].n)} | ${g.vertices ?? '–'} / ${g.triangles ?? '–'} | ${one.length}, ${two.length}${errors ? ` (${errors} failed)` : ''} | ` +
    `${s(first1)} (${s(warm1)}) | ${s(first2)} (${s(warm2)}) | ${f(r)} (${f(rw)}) | ${pct(r && 1 / (2 * r))} (${pct(rw && 1 / (2 * rw))}) | ` +
    `${identical ? 'yes' : 'no'} | ${met(r === null ? null : r <= 0.6)} | ${list(one.map((x) => x.first_seconds))} | ${list(two.map((x) => x.first_seconds))} |`);
}
const errs1 = part1.filter((r) => r.error);
for (const e of errs1) out.push('', `Failed: ${e.cloud} ${e.n} threads=${e.threads} process ${e.process}: ${e.error}`);
out.push('');

// ---- part 2
const part2 = rows.filter((r) => r.part === 2);
const input2 = part2.find((r) => r.impl === 'input');
const hk = (t) => part2.filter((r) => r.impl === 'hullkit' && r.threads === t);
const ok = (rs) => rs.filter((r) => r.status === 0);
const qc2 = part2.filter((r) => r.impl === 'qconvex');
const wall = (rs) => median(ok(rs).map((r) => r.wall_seconds));
const rss = (rs) => median(ok(rs).map((r) => r.peak_rss_kb));
const hullSec = (rs) => median(ok(rs).map((r) => r.stats && r.stats.seconds));
const w1 = wall(hk(1)), w2 = wall(hk(2)), wq = wall(qc2);
const h1 = hullSec(hk(1)), h2 = hullSec(hk(2));
const r2 = ratio(w2, w1), rh = ratio(h2, h1), rq = ratio(w2, wq);
const hkAll = part2.filter((r) => r.impl === 'hullkit');
const identical2 = hkAll.length > 0 && hkAll.every((r) => r.identical === true);
const v2 = ok(hkAll)[0]?.stats;
out.push(`## 2. Whole command: ${input2 ? sci(input2.n) : '?'} points as text, hullkit vs qconvex`, '');
out.push(`Input: \`rbox ${input2 ? input2.n : '?'} D3\` (uniform in a cube), ${input2 ? (input2.bytes / 1e6).toFixed(0) : '?'} MB of text. ` +
  '`hullkit hull FILE -o OUT.off --threads T --stats` and `qconvex o < FILE > OUT.off`, each run a fresh process timed whole ' +
  '(GNU time: wall clock, 10 ms resolution, and peak RSS). "hull only" is the `seconds` of hullkit\'s --stats (the hull computation without reading and writing). ' +
  `qconvex\'s \`o\` output lists every input point, so it writes about as much as it reads. Hull: ${v2 ? `${v2.vertices} vertices, ${v2.faces} triangles` : '–'}.`, '');
out.push('| measure | hullkit 1 thread | hullkit 2 threads | ratio 2t/1t | efficiency | qconvex | hullkit 2t / qconvex |');
out.push('|---|---:|---:|---:|---:|---:|---:|');
out.push(`| wall time, median | ${s(w1)} | ${s(w2)} | ${f(r2)} | ${pct(r2 && 1 / (2 * r2))} | ${s(wq)} | ${f(rq)} |`);
out.push(`| hull only (--stats), median | ${s(h1)} | ${s(h2)} | ${f(rh)} | ${pct(rh && 1 / (2 * rh))} | – | – |`);
out.push(`| peak RSS, median | ${mb(rss(hk(1)))} | ${mb(rss(hk(2)))} | – | – | ${mb(rss(qc2))} | – |`);
out.push(`| runs (wall s) | ${list(hk(1).map((r) => r.status === 0 ? r.wall_seconds : null))} | ${list(hk(2).map((r) => r.status === 0 ? r.wall_seconds : null))} | | | ${list(qc2.map((r) => r.status === 0 ? r.wall_seconds : null))} | |`);
out.push('');
out.push('| target | figure | status |', '|---|---:|---|');
out.push(`| hullkit 2 threads <= 0.6 × 1 thread (wall) | ${f(r2)} | ${met(r2 === null ? null : r2 <= 0.6)} |`);
out.push(`| hullkit 2 threads <= 0.1 × qconvex (wall) | ${f(rq)} | ${met(rq === null ? null : rq <= 0.1)} |`);
out.push(`| OFF outputs byte-identical (cmp), all ${hkAll.length} hullkit runs, both thread counts | ${identical2 ? 'identical' : 'differ'} | ${met(identical2)} |`);
for (const e of part2.filter((r) => r.status && r.status !== 0)) out.push('', `Failed: ${e.label} run ${e.run}: exit ${e.status}: ${e.error}`);
out.push('');

// ---- part 3
const part3 = rows.filter((r) => r.part === 3);
const ply = part3.find((r) => r.impl === 'input');
const text = part3.find((r) => r.impl === 'text-input');
const mode = (m) => part3.filter((r) => r.impl === 'hullkit' && r.label === m);
const st = mode('streamed'), mem = mode('memory');
const ws = wall(st), wm = wall(mem), rs = rss(st), rm = rss(mem);
const r3 = ratio(ws, wm);
const hk3 = [...st, ...mem];
const identical3 = hk3.length > 0 && hk3.every((r) => r.identical === true);
const flags = (rs) => [...new Set(ok(rs).map((r) => `${r.stats?.streamed}/${r.stats?.threads}`))].join(' ');
const v3 = ok(hk3)[0]?.stats;
out.push(`## 3. Streaming: ${ply ? sci(ply.n) : '?'} points in a ball, binary PLY`, '');
out.push(`Input: ${ply ? (ply.bytes / 1e9).toFixed(2) : '?'} GB binary little-endian PLY, float64 x y z ` +
  `(\`hullkit_threads_bench --write-ply FILE --cloud ball --n ${ply ? sci(ply.n) : '?'}\`, written in ${ply ? ply.write_seconds : '?'} s; ` +
  'just written, so normally read from the page cache). `hullkit hull FILE.ply -o OUT.off --memory MB --stats` with the default threads, ' +
  `each run a fresh process timed whole (GNU time), streamed and in-memory runs alternating. Hull: ${v3 ? `${v3.vertices} vertices, ${v3.faces} triangles` : '–'}.`, '');
out.push('| run | wall time, median | hull only (--stats), median | peak RSS, median | --stats streamed/threads | runs (wall s) |');
out.push('|---|---:|---:|---:|---|---|');
out.push(`| --memory 256 (streamed) | ${s(ws)} | ${s(hullSec(st))} | ${mb(rs)} | ${flags(st)} | ${list(st.map((r) => r.status === 0 ? r.wall_seconds : null))} |`);
out.push(`| --memory 20000 (in memory) | ${s(wm)} | ${s(hullSec(mem))} | ${mb(rm)} | ${flags(mem)} | ${list(mem.map((r) => r.status === 0 ? r.wall_seconds : null))} |`);
out.push('');
out.push('| target | figure | status |', '|---|---:|---|');
out.push(`| streamed peak RSS <= 300 MB | ${mb(rs)} | ${met(rs === null ? null : rs / 1024 <= 300)} |`);
out.push(`| streamed wall time <= 1.2 × in memory | ${f(r3)} | ${met(r3 === null ? null : r3 <= 1.2)} |`);
out.push(`| OFF outputs identical (cmp), all ${hk3.length} runs | ${identical3 ? 'identical' : 'differ'} | ${met(identical3)} |`);
for (const e of hk3.filter((r) => r.status !== 0)) out.push('', `Failed: ${e.label} run ${e.run}: exit ${e.status}: ${e.error}`);
out.push('');
const qc3 = part3.filter((r) => r.impl === 'qconvex');
const hkText = part3.filter((r) => r.impl === 'hullkit' && r.label === 'hullkit (text)');
const wq3 = wall(qc3), rq3 = rss(qc3);
const scale = ply && text ? ply.n / text.n : null;
out.push(`Qhull: a ${ply ? sci(ply.n) : '?'}-point text file would be about ${text && scale ? ((text.bytes * scale) / 1e9).toFixed(1) : '?'} GB, and qconvex holds every point in memory, ` +
  `so it ran on the same generator's first ${text ? sci(text.n) : '?'} points as text (${text ? (text.bytes / 1e6).toFixed(0) : '?'} MB, ` +
  '`hullkit_threads_bench --write-text`, shortest round-trip decimals), `qconvex o < FILE > OUT.off`; hullkit on the same text file beside it. ' +
  `The last column scales qconvex linearly (× ${scale ?? '?'}) to what it would need for ${ply ? sci(ply.n) : '?'} points; a linear extrapolation, not a measurement.`, '');
out.push(`| command | points | wall time, median | peak RSS, median | runs (wall s) | qconvex linear extrapolation to ${ply ? sci(ply.n) : '?'} |`);
out.push('|---|---:|---:|---:|---|---|');
out.push(`| qconvex o | ${text ? sci(text.n) : '?'} | ${s(wq3)} | ${mb(rq3)} | ${list(qc3.map((r) => r.status === 0 ? r.wall_seconds : null))} | ` +
  `${scale && wq3 !== null ? `~${f(wq3 * scale)} s, ~${((rq3 * scale) / 1048576).toFixed(1)} GB` : '–'} |`);
out.push(`| hullkit hull (default threads) | ${text ? sci(text.n) : '?'} | ${s(wall(hkText))} | ${mb(rss(hkText))} | ${list(hkText.map((r) => r.status === 0 ? r.wall_seconds : null))} | – |`);
for (const e of [...qc3, ...hkText].filter((r) => r.status !== 0)) out.push('', `Failed: ${e.label} run ${e.run}: exit ${e.status}: ${e.error}`);
out.push('');
out.push(`Raw figures: \`${resultsPath}\` (one JSON line per process).`, '');
fs.writeFileSync(reportPath, out.join('\n'));
process.stdout.write(out.join('\n'));
EOF
)
  node -e "$report_js" "$results" "$report"
}

# HULLKIT_BENCH_REPORT_ONLY=1: rewrite the report from the last run's results.jsonl, measure nothing.
if [ "${HULLKIT_BENCH_REPORT_ONLY:-0}" = 1 ]; then
  write_report
  exit
fi

# The reference OFF files are the first run's of this invocation, never an earlier one's.
rm -f "$work"/*-reference.off

# ---- build
if [ "${HULLKIT_BENCH_NO_BUILD:-0}" != 1 ]; then
  say "building $build (hullkit, hullkit_threads_bench)"
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DHULLKIT_TESTS=OFF -DHULLKIT_BENCH=ON >/dev/null
  cmake --build "$build" -j 2 --target hullkit hullkit_threads_bench >/dev/null
fi
tbench=$build/hullkit_threads_bench
cli=$build/hullkit
for exe in "$tbench" "$cli"; do
  [ -x "$exe" ] || { say "$exe is missing (unset HULLKIT_BENCH_NO_BUILD?)"; exit 1; }
done
if ! "$cli" hull --help | grep -q -- '--memory'; then
  say "$cli hull has no --memory option: this build predates threads and streaming"
  exit 1
fi
for tool in rbox qconvex /usr/bin/time; do
  command -v "$tool" >/dev/null || { say "$tool is missing (apt-get install qhull-bin time)"; exit 1; }
done

: >"$results"
# Facts about the machine for the report's intro; the load average shows how busy the shared
# machine was while the figures were taken.
cpu_model=$(grep -m 1 'model name' /proc/cpuinfo | sed 's/.*: //; s/["\\]//g' || echo unknown)
mem_gb=$(awk '/MemTotal/ { printf "%.0f", $2 / 1048576 }' /proc/meminfo)
printf '{"part":0,"date":"%s","nproc":%d,"cpu":"%s","memory_gb":%s,"load_start":"%s","quick":%s,"commit":"%s","build":"%s","qhull":"%s"}\n' \
  "$(date -u '+%Y-%m-%d %H:%M UTC')" "$(nproc)" "$cpu_model" "$mem_gb" "$(cut -d' ' -f1-3 /proc/loadavg)" \
  "$([ "$quick" = 1 ] && echo true || echo false)" "$(git rev-parse --short HEAD 2>/dev/null || echo unknown)" "$build" \
  "$(dpkg-query -W -f='${Version}' qhull-bin 2>/dev/null || echo unknown)" >>"$results"

# order K: the two thread counts in the order of round K, alternating which goes first.
order() { if (($1 % 2)); then echo "1 2"; else echo "2 1"; fi; }
# json_text FILE: the last 300 bytes of FILE as a JSON-safe string body (for error messages).
json_text() { tail -c 300 "$1" 2>/dev/null | tr -d '"\\' | tr '\n\t\r' '   '; }
# field NAME LINE: a number or string field of a flat JSON line, without its quotes.
field() { sed -n "s/.*\"$1\":\"\{0,1\}\([^,\"}]*\).*/\1/p" <<<"$2"; }

# measure CAP IN OUT ERR CMD...: runs CMD as a fresh process capped at CAP seconds, stdin from IN,
# stdout to OUT, stderr to ERR; GNU time measures it whole (fork to exit, its peak RSS). Sets
# m_wall (seconds, 10 ms resolution), m_rss_kb and m_status (124: stopped by the cap).
measure() {
  local cap=$1 in=$2 out=$3 err=$4
  shift 4
  m_status=0 m_wall=null m_rss_kb=null
  /usr/bin/time -f '%e %M' -o "$work/time.txt" timeout "$cap" "$@" <"$in" >"$out" 2>"$err" || m_status=$?
  read -r m_wall m_rss_kb < <(tail -n 1 "$work/time.txt") || true
}
# stats_of ERR: hullkit's --stats line (the last JSON line on its stderr), or null.
stats_of() { grep '^{' "$1" | tail -n 1 || echo null; }
# record PART IMPL LABEL THREADS RUN IDENTICAL ERRFILE: appends the last measure() as a JSON line.
record() {
  local stats=null error=""
  [ -n "$7" ] && stats=$(stats_of "$7")
  [ -z "$stats" ] && stats=null
  [ "$m_status" != 0 ] && error=$(json_text "$7")
  printf '{"part":%d,"impl":"%s","label":"%s","threads":%s,"run":%d,"wall_seconds":%s,"peak_rss_kb":%s,"status":%d,"identical":%s,"stats":%s,"error":"%s"}\n' \
    "$1" "$2" "$3" "$4" "$5" "$m_wall" "$m_rss_kb" "$m_status" "$6" "$stats" "$error" >>"$results"
  say "[part $1] $3 run $5: ${m_wall} s, peak $((m_rss_kb / 1024)) MB$([ "$m_status" != 0 ] && echo ", FAILED (exit $m_status)")"
}
# same A B: "true" when the files are byte-identical, else "false" (cmp's message on stderr).
same() { if cmp "$1" "$2" >&2; then echo true; else echo false; fi; }

# ---- 1. the library, 1 vs 2 threads, one process per run
say "part 1: hullkit::hull, threads 1 vs 2 ($procs1 processes each, $runs1 calls per process)"
for spec in "${part1_clouds[@]}"; do
  cloud=${spec%%:*} n=${spec#*:}
  for ((k = 1; k <= procs1; k++)); do
    for t in $(order "$k"); do
      status=0
      line=$(timeout 300 "$tbench" --cloud "$cloud" --n "$n" --threads "$t" --runs "$runs1" 2>"$work/err.log") || status=$?
      line=$(grep '^{' <<<"$line" | tail -n 1 || true)
      if [ "$status" != 0 ] || [ -z "$line" ]; then
        printf '{"part":1,"cloud":"%s","n":%s,"threads":%d,"process":%d,"error":"exit %d: %s"}\n' \
          "$cloud" "$n" "$t" "$k" "$status" "$(json_text "$work/err.log")" >>"$results"
        say "[part 1] $cloud $n threads=$t process $k FAILED (exit $status)"
        continue
      fi
      printf '{"part":1,"process":%d,%s\n' "$k" "${line#\{}" >>"$results"
      say "[part 1] $cloud $n threads=$t process $k: first $(field first_seconds "$line") s, warm $(field warm_median_seconds "$line") s, hash $(field triangles_fnv1a "$line")"
    done
  done
done

# Files just written are flushed to disk before anything is timed: the kernel's writeback of
# hundreds of MB (an input just generated, qconvex's OFF, which lists every point) would
# otherwise run beside the next processes, on the same 2 cores.
settle() { sync; }

# ---- 2. the whole command on text, hullkit 1 vs 2 threads vs qconvex
say "part 2: rbox $cube_n D3 > $work/cube.txt"
timeout 300 rbox "$cube_n" D3 >"$work/cube.txt"
settle
printf '{"part":2,"impl":"input","bytes":%d,"n":%d}\n' "$(stat -c %s "$work/cube.txt")" "$cube_n" >>"$results"
run_qconvex_cube() {
  measure 900 "$work/cube.txt" "$work/cube.qconvex.off" "$work/qconvex.err" qconvex o
  record 2 qconvex "qconvex o" null "$1" null "$work/qconvex.err"
  rm -f "$work/cube.qconvex.off"  # unwritten pages of a removed file are dropped, not flushed
  settle
}
for ((k = 1; k <= runs2; k++)); do
  for t in $(order "$k"); do
    off=$work/cube-t$t-run$k.off
    measure 300 /dev/null /dev/null "$work/hullkit.err" "$cli" hull "$work/cube.txt" -o "$off" --threads "$t" --stats
    # Every run's OFF against the first 1-thread run's: equal bytes across runs and thread counts.
    [ -f "$work/cube-reference.off" ] || cp "$off" "$work/cube-reference.off"
    identical=$([ "$m_status" = 0 ] && same "$work/cube-reference.off" "$off" || echo false)
    record 2 hullkit "hullkit --threads $t" "$t" "$k" "$identical" "$work/hullkit.err"
    rm -f "$off"
  done
  # qconvex between the hullkit rounds (after the first and after the last), not all at the end.
  if [ "$k" = 1 ] || { [ "$k" = "$runs2" ] && [ "$runs2_qconvex" -ge 2 ]; }; then
    run_qconvex_cube "$([ "$k" = 1 ] && echo 1 || echo 2)"
  fi
done
rm -f "$work/cube.txt" "$work/cube.qconvex.off"

# ---- 3. streaming a 1e8-point PLY with bounded memory against hulling it in memory
say "part 3: hullkit_threads_bench --write-ply $work/ball.ply --cloud ball --n $ply_n"
write_started=$(date +%s%N)
timeout 900 "$tbench" --write-ply "$work/ball.ply" --cloud ball --n "$ply_n"
write_ms=$((($(date +%s%N) - write_started) / 1000000))
settle
printf '{"part":3,"impl":"input","bytes":%d,"n":%d,"write_seconds":%d.%03d}\n' "$(stat -c %s "$work/ball.ply")" "$ply_n" \
  $((write_ms / 1000)) $((write_ms % 1000)) >>"$results"
for ((k = 1; k <= runs3; k++)); do
  for mode in $(if ((k % 2)); then echo "streamed memory"; else echo "memory streamed"; fi); do
    mb=$([ "$mode" = streamed ] && echo 256 || echo 20000)
    off=$work/ball-$mode-run$k.off
    measure 1200 /dev/null /dev/null "$work/hullkit.err" "$cli" hull "$work/ball.ply" -o "$off" --memory "$mb" --stats
    [ -f "$work/ball-reference.off" ] || cp "$off" "$work/ball-reference.off"
    identical=$([ "$m_status" = 0 ] && same "$work/ball-reference.off" "$off" || echo false)
    record 3 hullkit "$mode" null "$k" "$identical" "$work/hullkit.err"
    rm -f "$off"
  done
done
rm -f "$work/ball.ply"

say "part 3: qconvex on the first $text_n points of the same cloud, as text"
timeout 300 "$tbench" --write-text "$work/ball.txt" --cloud ball --n "$text_n"
settle
printf '{"part":3,"impl":"text-input","bytes":%d,"n":%d}\n' "$(stat -c %s "$work/ball.txt")" "$text_n" >>"$results"
for ((k = 1; k <= runs3_qconvex; k++)); do
  measure 900 "$work/ball.txt" "$work/ball.qconvex.off" "$work/qconvex.err" qconvex o
  record 3 qconvex "qconvex o (text)" null "$k" null "$work/qconvex.err"
  rm -f "$work/ball.qconvex.off"
  settle
  # hullkit on the very same text file, for scale (default threads, in memory).
  measure 300 /dev/null /dev/null "$work/hullkit.err" "$cli" hull "$work/ball.txt" -o "$work/ball-text.off" --stats
  record 3 hullkit "hullkit (text)" null "$k" null "$work/hullkit.err"
done
rm -f "$work/ball.txt" "$work/ball.qconvex.off" "$work/ball-text.off"

# ---- the report
elapsed=$(($(date +%s) - started))
printf '{"part":9,"elapsed_seconds":%d,"load_end":"%s"}\n' "$elapsed" "$(cut -d' ' -f1-3 /proc/loadavg)" >>"$results"
write_report
say "wrote $report; all done in $elapsed s ($((elapsed / 60)) min $((elapsed % 60)) s)"
