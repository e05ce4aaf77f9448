// The page in headless Debian Chromium, measured as a user meets it (part of `npm run bench`):
//   1. the first hull after page load (1e5 points in a cube; module loading excluded: the hull
//      call inside the worker) against later hulls of the same size in the same page;
//   2. 1e6 points in a ball: from the click on Compute to the hull drawn (generation, hull,
//      transfer, geometry and first frame), the first run in a fresh page and later ones;
//   3. the frame rate while orbiting the hull of 1e5 points on a sphere (1e5 hull vertices).
// Writes bench/results-page.md and prints it.
//   node bench/page_bench.mjs [--quick]
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { execSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { startServer } from '../scripts/serve.js';
import { CHROMIUM, CHROMIUM_ARGS } from '../tests/browser/helpers.js';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const quick = process.argv.includes('--quick') || process.env.HULLKIT_BENCH_QUICK === '1';
const LATER_RUNS = quick ? 2 : 7;
const BIG_RUNS = quick ? 1 : 3;
const say = (s) => process.stderr.write(`${s}\n`);
const median = (xs) => {
  const s = [...xs].sort((a, b) => a - b);
  return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
};

async function settled(page, timeout = 180_000) {
  await page.waitForFunction(() => ['ready', 'error'].includes(document.body.dataset.state), null, { timeout, polling: 20 });
  const state = await page.evaluate(() => document.body.dataset.state);
  if (state !== 'ready') throw new Error(`the page reports ${state}: ${await page.textContent('#error')}`);
}

/** Sets n and the seed, clicks Compute; resolves with {stats, wallMs} once drawn. */
async function compute(page, { distribution, n, seed }) {
  const before = await page.evaluate(() => window.hullkitStats?.run ?? 0);
  await page.selectOption('#distribution', distribution);
  await page.fill('#n', String(n));
  await page.fill('#seed', String(seed));
  const wallMs = await page.evaluate(async (b) => {
    const t0 = performance.now();
    document.getElementById('compute').click();
    await new Promise((resolve) => {
      const poll = () => ((window.hullkitStats?.run ?? 0) > b && document.body.dataset.state === 'ready'
        ? requestAnimationFrame(() => resolve()) : setTimeout(poll, 5));
      poll();
    });
    return performance.now() - t0;
  }, before);
  const stats = await page.evaluate(() => window.hullkitStats);
  return { stats, wallMs };
}

const { chromium } = await import('playwright-core');
const server = await startServer({ port: 0, root: ROOT });
const base = `http://127.0.0.1:${server.address().port}/web/`;
const browser = await chromium.launch({ executablePath: CHROMIUM, args: CHROMIUM_ARGS });
const started = Date.now();
const rows = {};
try {
  // 1. first hull after load vs later ones, 1e5 in a cube
  {
    const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
    await page.goto(`${base}?view=hull&dist=cube&n=100000&seed=1`);
    await settled(page);
    const first = await page.evaluate(() => window.hullkitStats.ms);
    const later = [];
    for (let i = 0; i < LATER_RUNS; i++) later.push((await compute(page, { distribution: 'cube', n: 100000, seed: 2 + i })).stats.ms);
    rows.first = { first, later: median(later), ratio: first / median(later) };
    say(`first hull after load, 1e5 cube: ${first.toFixed(1)} ms; later median ${median(later).toFixed(1)} ms`);
    await page.close();
  }
  // 2. 1e6 in a ball: click to drawn
  {
    const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
    await page.goto(`${base}?view=hull&dist=cube&n=1000&seed=1`);
    await settled(page);
    const runs = [];
    for (let i = 0; i < BIG_RUNS + 1; i++) {
      const { stats, wallMs } = await compute(page, { distribution: 'ball', n: 1_000_000, seed: 11 + i });
      runs.push({ wallMs, hullMs: stats.ms, roundTripMs: stats.roundTripMs, vertices: stats.vertices });
      say(`1e6 ball run ${i + 1}: click to drawn ${wallMs.toFixed(0)} ms (hull ${stats.ms.toFixed(0)} ms, round trip ${stats.roundTripMs.toFixed(0)} ms)`);
    }
    rows.big = {
      firstWall: runs[0].wallMs, firstHull: runs[0].hullMs,
      laterWall: median(runs.slice(1).map((r) => r.wallMs)), laterHull: median(runs.slice(1).map((r) => r.hullMs)),
      vertices: runs[0].vertices,
    };
    await page.close();
  }
  // 3. frame rate while orbiting the hull of 1e5 points on a sphere
  {
    const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
    await page.goto(`${base}?view=hull&dist=sphere&n=100000&seed=1`);
    await settled(page);
    const vertices = await page.evaluate(() => window.hullkitStats.vertices);
    const box = await page.locator('#canvas').boundingBox();
    const cx = box.x + box.width / 2, cy = box.y + box.height / 2;
    await page.evaluate(() => {
      window.__frames = [];
      const count = (t) => { window.__frames.push(t); window.__raf = requestAnimationFrame(count); };
      window.__raf = requestAnimationFrame(count);
    });
    await page.mouse.move(cx, cy);
    await page.mouse.down();
    const t0 = Date.now();
    const f0 = await page.evaluate(() => window.__frames.length);
    const seconds = quick ? 1.5 : 4;
    let k = 0;
    while (Date.now() - t0 < seconds * 1000) {
      k++;
      await page.mouse.move(cx + 200 * Math.sin(k / 15), cy + 60 * Math.cos(k / 20));
    }
    await page.mouse.up();
    // Frames between the first and the last animation frame of the drag (timestamps in the page).
    const stamps = (await page.evaluate(() => window.__frames)).slice(f0);
    const frames = stamps.length - 1;
    const fps = frames > 0 ? (1000 * frames) / (stamps.at(-1) - stamps[0]) : 0;
    rows.orbit = { vertices, fps, frames };
    say(`orbiting the hull of 1e5 sphere points (${vertices} vertices): ${fps.toFixed(1)} frames per second (${frames} frames)`);
    await page.close();
  }
} finally {
  await browser.close();
  server.close();
}

let commit = '';
try { commit = execSync('git rev-parse --short HEAD', { cwd: ROOT }).toString().trim(); } catch { /* not a clone */ }
const chromiumVersion = (() => { try { return execSync(`${CHROMIUM} --version 2>/dev/null`).toString().trim(); } catch { return 'chromium'; } })();
const fmt = (ms) => (ms >= 100 ? ms.toFixed(0) : ms.toFixed(1));
const status = (ok) => (ok ? '**met**' : '**not met**');
const md = `# The page in headless Chromium

Written by \`node bench/page_bench.mjs\` (part of \`npm run bench\`) on ${new Date().toISOString().slice(0, 10)} in ${Math.round((Date.now() - started) / 1000)} s${quick ? ' — **quick smoke run**' : ''}.
${chromiumVersion} (software WebGL: SwiftShader), ${os.cpus().length} cores, load average ${os.loadavg().map((x) => x.toFixed(2)).join(' ')} at the end; commit ${commit}.

| what | first | later (median of ${LATER_RUNS} / ${BIG_RUNS}) | target | status |
| :-- | --: | --: | :-- | :-- |
| hull call of 1e5 points in a cube after page load (in the worker) | ${fmt(rows.first.first)} ms | ${fmt(rows.first.later)} ms | first ≤ 1.5× later | ${status(rows.first.ratio <= 1.5)} (${rows.first.ratio.toFixed(2)}×) |
| 1e6 points in a ball, click on Compute to hull drawn | ${fmt(rows.big.firstWall)} ms | ${fmt(rows.big.laterWall)} ms | ≤ 1500 ms | ${status(rows.big.firstWall <= 1500)} |
| … of which the hull call (${rows.big.vertices} hull vertices) | ${fmt(rows.big.firstHull)} ms | ${fmt(rows.big.laterHull)} ms | | |
| orbiting the hull of 1e5 points on a sphere (${rows.orbit.vertices} vertices) | ${rows.orbit.frames > 0 ? `${rows.orbit.fps.toFixed(1)} frames/s` : 'no frame completed'} | | figure | |

"Click to drawn" runs from the click on Compute to the first animation frame after the result is
drawn: generating the points in the worker, the hull, computing the edges, transferring the arrays
and building the three.js geometry. The frame rate is counted with requestAnimationFrame while the
mouse drags the view for ${quick ? 1.5 : 4} s.
`;
const out = quick ? path.join(ROOT, 'bench/out/results-page.md') : path.join(ROOT, 'bench/results-page.md');
fs.mkdirSync(path.dirname(out), { recursive: true });
fs.writeFileSync(out, md);
process.stdout.write(md);
