// End-to-end test of the demo page (web/) in headless Debian Chromium.
//
//   node --test tests/browser/
//
// Needs /usr/bin/chromium, the npm dev dependency playwright-core and the wasm
// build (npm run build → build/wasm/hullkit_core.mjs). Saves a screenshot of
// the default view to web/screenshot.png.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { startServer } from '../../scripts/serve.js';
import { ROOT, CHROMIUM, CHROMIUM_ARGS, decodePng, pixel, averageColor } from './helpers.js';

const VIEWPORT = { width: 1280, height: 800 };
const READY_TIMEOUT = 60_000;
const BALL_VOLUME = (4 / 3) * Math.PI;
const SCREENSHOT_PATH = path.join(ROOT, 'web', 'screenshot.png');

/** Pixels in the pink of the extreme points that the seed's epsilon left out. */
function countPink(img) {
  let count = 0;
  for (let y = 0; y < img.height; y++) {
    for (let x = 0; x < img.width; x++) {
      const [r, g, b] = pixel(img, x, y);
      if (r > 200 && g < 130 && b > 90 && b < 190) count++;
    }
  }
  return count;
}

/** Pixel statistics of the canvas image: background, coverage of the centre, hull colours. */
function analyseCanvas(img) {
  // Top-left corner: pure background (the view overlays sit on the right).
  const background = averageColor(img, 2, 2, 8, 8);
  const x0 = Math.floor(img.width * 0.3);
  const x1 = Math.ceil(img.width * 0.7);
  const y0 = Math.floor(img.height * 0.3);
  const y1 = Math.ceil(img.height * 0.7);
  let total = 0;
  let differing = 0;
  let faceColored = 0;
  for (let y = y0; y < y1; y++) {
    for (let x = x0; x < x1; x++) {
      const [r, g, b] = pixel(img, x, y);
      total++;
      const diff = Math.abs(r - background[0]) + Math.abs(g - background[1]) + Math.abs(b - background[2]);
      if (diff > 30) differing++;
      // translucent cyan/teal faces: green and blue well above red
      if (g - r > 25 && b - r > 25) faceColored++;
    }
  }
  let vertexColored = 0; // amber hull vertices, anywhere in the image
  for (let y = 0; y < img.height; y++) {
    for (let x = 0; x < img.width; x++) {
      const [r, g, b] = pixel(img, x, y);
      if (r > 190 && g > 120 && g < 220 && b < 130 && r - b > 100) vertexColored++;
    }
  }
  return {
    background: background.map((v) => Math.round(v)),
    centreDiffering: differing / total,
    centreFaceColored: faceColored / total,
    vertexColored,
  };
}

// ------------------------------------------------------------------ page helpers

async function waitForSettled(page, timeout = READY_TIMEOUT) {
  await page.waitForFunction(
    () => ['ready', 'error', 'cancelled'].includes(document.body.dataset.state),
    null,
    { timeout, polling: 100 },
  );
  return page.evaluate(() => document.body.dataset.state);
}

async function panelError(page) {
  return page.evaluate(() => {
    const el = document.getElementById('error');
    return el && !el.hidden ? el.textContent : '';
  });
}

/** Set the inputs, click Compute and wait for the next finished run. */
async function compute(page, { distribution, n, seed, text, algorithm, epsilon, merge }) {
  const before = await page.evaluate(() => window.hullkitStats?.run ?? 0);
  if (algorithm !== undefined) await page.selectOption('#algorithm', algorithm);
  if (epsilon !== undefined) await page.selectOption('#epsilon', epsilon);
  if (merge !== undefined) await page.setChecked('#merge', merge);
  if (distribution !== undefined) await page.selectOption('#distribution', distribution);
  if (n !== undefined) await page.fill('#n', String(n));
  if (seed !== undefined) await page.fill('#seed', String(seed));
  if (text !== undefined) await page.fill('#custom-points', text);
  await page.click('#compute');
  const state = await waitForSettled(page);
  const stats = await page.evaluate(() => window.hullkitStats);
  if (state === 'ready') assert.ok(stats.run > before, 'a successful run must publish new stats');
  return { state, stats };
}

async function nextFrames(page) {
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}

function checkHullStats(stats, { n, distribution }) {
  assert.equal(stats.n, n, 'stats.n');
  assert.equal(stats.distribution, distribution, 'stats.distribution');
  assert.equal(stats.dimension, 3, 'a full-dimensional hull');
  assert.ok(Number.isInteger(stats.vertices) && stats.vertices > 4 && stats.vertices <= n, `vertices ${stats.vertices}`);
  assert.equal(stats.faces, 2 * stats.vertices - 4, 'a triangulated convex polyhedron has F = 2V - 4');
  assert.equal(stats.edges, 3 * stats.vertices - 6, 'a triangulated convex polyhedron has E = 3V - 6');
  assert.ok(Number.isFinite(stats.ms) && stats.ms >= 0, `hull ms ${stats.ms}`);
  assert.ok(stats.roundTripMs >= stats.ms, 'round trip includes the hull call');
}

// ------------------------------------------------------------------ the test

test('demo page computes, draws and reports convex hulls', { timeout: 240_000 }, async (t) => {
  assert.ok(
    fs.existsSync(CHROMIUM),
    `Chromium not found at ${CHROMIUM}; install the Debian package "chromium" to run the browser test`,
  );
  const wasmGlue = path.join(ROOT, 'build', 'wasm', 'hullkit_core.mjs');
  assert.ok(fs.existsSync(wasmGlue), `${wasmGlue} is missing: build the WebAssembly module first (npm run build)`);
  let chromium;
  try {
    ({ chromium } = await import('playwright-core'));
  } catch (err) {
    assert.fail(`playwright-core is not installed (npm install): ${err.message}`);
  }

  const started = performance.now();
  let server;
  let browser;
  const consoleErrors = [];
  let ok = true;
  const step = async (name, fn) => {
    if (!ok) return t.test(name, { skip: 'an earlier step failed' }, () => {});
    return t.test(name, async () => {
      try {
        await fn();
      } catch (err) {
        ok = false;
        throw err;
      }
    });
  };

  try {
    server = await startServer({ port: 0, root: ROOT });
    const base = `http://127.0.0.1:${server.address().port}`;
    browser = await chromium.launch({ executablePath: CHROMIUM, args: CHROMIUM_ARGS });
    const page = await browser.newPage({ viewport: VIEWPORT, deviceScaleFactor: 1 });
    page.on('console', (msg) => {
      if (msg.type() === 'error') consoleErrors.push(`console.error: ${msg.text()}`);
    });
    page.on('pageerror', (err) => consoleErrors.push(`pageerror: ${err.message}`));
    page.on('crash', () => consoleErrors.push('page crashed'));

    let firstStats;

    await step('default hull (ball, n = 2000) is computed on load', async () => {
      const response = await page.goto(`${base}/`);
      assert.ok(response.ok(), `GET / → ${response.status()}`);
      assert.match(page.url(), /\/web\/(\?.*)?$/, '/ redirects to /web/');
      const state = await waitForSettled(page);
      assert.equal(state, 'ready', `page state ${state}; panel error: ${await panelError(page)}`);
      firstStats = await page.evaluate(() => window.hullkitStats);
      t.diagnostic(`default hull: ${JSON.stringify(firstStats)}`);
      checkHullStats(firstStats, { n: 2000, distribution: 'ball' });
      assert.ok(firstStats.volume > 0.85 * BALL_VOLUME && firstStats.volume < BALL_VOLUME, `ball hull volume ${firstStats.volume}`);
      assert.ok(firstStats.area > 0 && firstStats.area < 4 * Math.PI, `ball hull area ${firstStats.area}`);
      assert.equal(await page.textContent('#stat-vertices'), firstStats.vertices.toLocaleString('en-US'));
      assert.equal(await page.textContent('#stat-faces'), firstStats.faces.toLocaleString('en-US'));
      assert.equal(await page.isVisible('#error'), false, 'no error shown');
      // Quickhull is the default: listed first, selected, used; the epsilon is a gift wrapping option.
      const algorithms = await page.$$eval('#algorithm option', (options) => options.map((o) => o.value));
      assert.deepEqual(algorithms, ['quickhull', 'giftwrap'], 'the library\'s algorithms, its default first');
      assert.equal(await page.inputValue('#algorithm'), 'quickhull');
      assert.equal(firstStats.algorithm, 'quickhull');
      assert.equal(firstStats.epsilon, 'exact');
      assert.equal(firstStats.merged, false);
      assert.equal(await page.isDisabled('#epsilon'), true, 'no epsilon choice with quickhull');
      assert.equal(await page.evaluate(() => window.hullkitEpsilon), null);
    });

    await step('the hull is drawn on the canvas', async () => {
      await nextFrames(page);
      const canvas = page.locator('#canvas');
      const size = await canvas.evaluate((c) => ({ w: c.width, h: c.height, cw: c.clientWidth, ch: c.clientHeight }));
      assert.ok(size.w === size.cw && size.h === size.ch && size.w > 300, `canvas buffer matches its CSS size: ${JSON.stringify(size)}`);
      const img = decodePng(await canvas.screenshot());
      const a = analyseCanvas(img);
      t.diagnostic(`canvas ${img.width}x${img.height}: ${JSON.stringify(a)}`);
      assert.ok(a.background.reduce((s, v) => s + v, 0) < 150, `dark background, got ${a.background}`);
      assert.ok(a.centreDiffering > 0.6, `centre differs from the background in ${(100 * a.centreDiffering).toFixed(1)}% of pixels`);
      assert.ok(a.centreFaceColored > 0.3, `hull face colour in ${(100 * a.centreFaceColored).toFixed(1)}% of the centre`);
      assert.ok(a.vertexColored > 50, `highlighted hull vertices visible (${a.vertexColored} pixels)`);
      await page.screenshot({ path: SCREENSHOT_PATH });
    });

    await step('the canvas follows window resizes', async () => {
      await page.setViewportSize({ width: 960, height: 640 });
      await page.waitForFunction(() => {
        const c = document.getElementById('canvas');
        return c.width === c.clientWidth && c.height === c.clientHeight && c.clientHeight === 640;
      }, null, { timeout: 5000 });
      await nextFrames(page);
      const a = analyseCanvas(decodePng(await page.locator('#canvas').screenshot()));
      assert.ok(a.centreFaceColored > 0.3, `hull still drawn after resize: ${JSON.stringify(a)}`);
      await page.setViewportSize(VIEWPORT);
    });

    await step('switching to the cube distribution recomputes and updates the stats', async () => {
      const { state, stats } = await compute(page, { distribution: 'cube' });
      assert.equal(state, 'ready', `state ${state}; panel error: ${await panelError(page)}`);
      t.diagnostic(`cube hull: ${JSON.stringify(stats)}`);
      checkHullStats(stats, { n: 2000, distribution: 'cube' });
      assert.ok(stats.volume > 7 && stats.volume < 8, `cube hull volume ${stats.volume}`);
      assert.ok(stats.area > 20 && stats.area < 24, `cube hull area ${stats.area}`);
      assert.notEqual(stats.volume, firstStats.volume);
      assert.equal(await page.textContent('#stat-vertices'), stats.vertices.toLocaleString('en-US'));
    });

    await step('degenerate input gives a flat hull; invalid input an error in the panel', async () => {
      // Coplanar points: the hull is a convex polygon, drawn, with zero volume.
      let r = await compute(page, { distribution: 'plane', n: 500 });
      assert.equal(r.state, 'ready', `coplanar input: ${await panelError(page)}`);
      t.diagnostic(`coplanar hull: ${JSON.stringify(r.stats)}`);
      assert.equal(r.stats.dimension, 2);
      assert.equal(r.stats.volume, 0);
      assert.ok(r.stats.area > 3 && r.stats.area <= 4, `area of the hull of points in [-1, 1]^2: ${r.stats.area}`);
      assert.ok(r.stats.vertices >= 3 && r.stats.vertices < 500);
      assert.equal(r.stats.faces, r.stats.vertices - 2, 'a triangulated convex polygon');
      assert.equal(r.stats.edges, r.stats.vertices, 'only the polygon outline is drawn');
      assert.match(await page.textContent('#status'), /coplanar/);

      r = await compute(page, { distribution: 'ball', n: 3 });
      assert.equal(r.state, 'ready', `three points: ${await panelError(page)}`);
      assert.deepEqual([r.stats.dimension, r.stats.vertices, r.stats.faces], [2, 3, 1], 'three points span a triangle');

      // Invalid data is rejected with an explanation in the panel (no console error).
      const invalid = [
        ['a non-finite coordinate (library)', '0 0 0\n1 0 0\n0 1 0\n0 0 nan\n'],
        ['an incomplete point (library)', '0 0 0  1 0 0  0 1 0  0 0'],
        ['text that is not a number (page)', '0 0 0\n1 0 zero\n'],
      ];
      for (const [what, text] of invalid) {
        r = await compute(page, { distribution: 'custom', text });
        assert.equal(r.state, 'error', `${what} must be rejected`);
        const message = await panelError(page);
        t.diagnostic(`${what}: ${message}`);
        assert.ok(message.length > 20, `error message shown for ${what}: "${message}"`);
        assert.equal(await page.$eval('#error', (el) => getComputedStyle(el).color), 'rgb(255, 107, 107)', 'in red');
      }

      // Valid pasted points work too: a cube and its centre.
      r = await compute(page, { distribution: 'custom', text: '0 0 0, 1 0 0, 0 1 0, 1 1 0, 0 0 1, 1 0 1, 0 1 1, 1 1 1, .5 .5 .5' });
      assert.equal(r.state, 'ready', `custom cube: ${await panelError(page)}`);
      assert.deepEqual([r.stats.n, r.stats.vertices, r.stats.faces, r.stats.dimension], [9, 8, 12, 3]);
      assert.ok(Math.abs(r.stats.volume - 1) < 1e-12 && Math.abs(r.stats.area - 6) < 1e-12, 'unit cube volume and area');

      // The page survives and recovers: same seed → identical hull.
      r = await compute(page, { distribution: 'ball', n: 2000, seed: 1 });
      assert.equal(r.state, 'ready', `recovered: ${await panelError(page)}`);
      assert.equal(await page.isVisible('#error'), false, 'error cleared after a good run');
      for (const key of ['n', 'vertices', 'faces', 'volume', 'area']) {
        assert.equal(r.stats[key], firstStats[key], `deterministic ${key}`);
      }
    });

    await step('quickhull runs 100 000 points on a sphere without asking', async () => {
      const { state, stats } = await compute(page, { algorithm: 'quickhull', distribution: 'sphere', n: 100000, seed: 1 });
      assert.equal(state, 'ready', `quickhull sphere: ${await panelError(page)}`);
      assert.equal(await page.isVisible('#warning'), false, 'no confirmation for quickhull');
      t.diagnostic(`quickhull sphere 100 000: hull ${stats.ms.toFixed(0)} ms, round trip ${stats.roundTripMs.toFixed(0)} ms`);
      checkHullStats(stats, { n: 100000, distribution: 'sphere' });
      assert.equal(stats.algorithm, 'quickhull');
      assert.equal(stats.vertices, 100000, 'all points on a sphere are hull vertices');
    });

    await step('merging coplanar faces turns the cube grid into 6 squares', async () => {
      let r = await compute(page, { distribution: 'grid', n: 1000, merge: true });
      assert.equal(r.state, 'ready', `cube grid: ${await panelError(page)}`);
      t.diagnostic(`cube grid, merged: ${JSON.stringify(r.stats)}`);
      assert.equal(r.stats.n, 1000, '10 × 10 × 10 integer points');
      assert.equal(r.stats.merged, true);
      assert.deepEqual([r.stats.dimension, r.stats.vertices, r.stats.faces, r.stats.edges], [3, 8, 6, 12], '8 corners, 6 quads, 12 sides');
      assert.equal(r.stats.triangles, 12, 'drawn as 12 triangles');
      assert.equal(r.stats.volume, 729);
      assert.equal(r.stats.area, 486);
      assert.equal(await page.textContent('#stat-faces'), '6');
      assert.equal(await page.textContent('#stat-faces-label'), 'polygons');
      assert.match(await page.textContent('#status'), /6 faces: 6 quadrilaterals/);
      assert.match(page.url(), /merge=1/, 'the option is kept in the URL');

      // Without merging: the triangulation, diagonals included.
      r = await compute(page, { merge: false });
      assert.equal(r.state, 'ready');
      assert.deepEqual([r.stats.vertices, r.stats.faces, r.stats.edges, r.stats.merged], [8, 12, 18, false]);
      assert.equal(await page.textContent('#stat-faces-label'), 'triangles');
    });

    await step('the seed\'s epsilon fails or changes the hull where exact predicates do not', async () => {
      // Exact predicates with gift wrapping: a slab 2e-13 thin is a polytope.
      let r = await compute(page, { algorithm: 'giftwrap', epsilon: 'exact', distribution: 'near-coplanar', n: 2000, seed: 1 });
      assert.equal(r.state, 'ready', `near-coplanar, exact: ${await panelError(page)}`);
      assert.equal(await page.isDisabled('#epsilon'), false, 'epsilon choice with gift wrapping');
      t.diagnostic(`near-coplanar, exact: ${JSON.stringify(r.stats)}`);
      checkHullStats(r.stats, { n: 2000, distribution: 'near-coplanar' });
      assert.ok(r.stats.volume > 0 && r.stats.volume < 4 * 2e-13, `slab volume ${r.stats.volume}`);
      assert.equal(await page.evaluate(() => window.hullkitEpsilon), null);
      assert.equal(await page.isVisible('#compare'), false);
      const exact = r.stats;

      // The seed's epsilon on the same points: gift wrapping gives up, as a user-visible error.
      r = await compute(page, { epsilon: 'seed' });
      assert.equal(r.state, 'error', 'the seed\'s epsilon cannot wrap the slab');
      const message = await panelError(page);
      t.diagnostic(`near-coplanar, seed's epsilon: ${message}`);
      assert.match(message, /seed's epsilon/);
      assert.match(page.url(), /eps=seed/);
      const cmp = await page.evaluate(() => window.hullkitEpsilon);
      assert.equal(cmp.outcome, 'failed');
      assert.ok(cmp.epsilon > 1e-16 && cmp.epsilon < 1e-14, `ε ${cmp.epsilon}`);
      // (compared with quickhull: the same hull, its volume summed in another order)
      assert.deepEqual([cmp.exact.dimension, cmp.exact.vertices, cmp.exact.faces], [3, exact.vertices, exact.faces], 'compared with the exact hull');
      assert.ok(Math.abs(cmp.exact.volume - exact.volume) < 1e-9 * exact.volume, `exact volume ${cmp.exact.volume}`);
      assert.match(await page.textContent('#status'), /seed's epsilon \(ε = [\d.]+e-1\d\) could not decide/);
      assert.equal(await page.isVisible('#compare'), true, 'both outcomes side by side');
      const rows = await page.$$eval('#compare tbody tr', (trs) => trs.map((tr) => [...tr.cells].map((c) => c.textContent.trim()).join(' ')));
      assert.equal(rows[0], 'seed\'s ε error — —');
      assert.match(rows[1], new RegExp(`^exact ${exact.vertices} ${exact.faces} 7\\.\\d\\de-13$`));

      // A rotated integer grid: the epsilon snaps the rounded face points back onto the faces.
      r = await compute(page, { distribution: 'rotated-grid', n: 1000, seed: 2 });
      assert.equal(r.state, 'ready', `rotated grid, seed's epsilon: ${await panelError(page)}`);
      const diff = await page.evaluate(() => window.hullkitEpsilon);
      t.diagnostic(`rotated grid, seed's epsilon vs exact: ${JSON.stringify(diff)}`);
      assert.equal(diff.outcome, 'different');
      assert.equal(r.stats.vertices, 8, 'the seed\'s epsilon keeps the 8 corners only');
      assert.ok(diff.exact.vertices > 8 && diff.dropped === diff.exact.vertices - 8, `exact vertices ${diff.exact.vertices}`);
      assert.match(await page.textContent('#status'), /changed the hull: it left out \d+ extreme points/);
      await nextFrames(page);
      const pink = countPink(decodePng(await page.locator('#canvas').screenshot()));
      assert.ok(pink > 100, `the left-out extreme points are drawn in pink (${pink} pixels)`);

      // Quickhull has no epsilon: the choice is disabled and runs are exact.
      r = await compute(page, { algorithm: 'quickhull' });
      assert.equal(r.state, 'ready');
      assert.equal(await page.isDisabled('#epsilon'), true);
      assert.equal(r.stats.epsilon, 'exact');
      assert.equal(r.stats.vertices, diff.exact.vertices);
      assert.equal(await page.isVisible('#compare'), false);
      assert.equal(await page.isVisible('#legend-dropped'), false);
      await page.selectOption('#algorithm', 'giftwrap');
      await page.selectOption('#epsilon', 'exact');
    });

    await step('an expensive sphere run asks first and can be cancelled', async () => {
      const algorithms = await page.$$eval('#algorithm option', (options) => options.map((o) => o.value));
      assert.ok(algorithms.includes('giftwrap'), `gift wrapping offered: ${algorithms}`);
      await page.selectOption('#algorithm', 'giftwrap'); // O(n·h): 100 000 points on a sphere take minutes
      await page.selectOption('#distribution', 'sphere');
      await page.fill('#n', '100000');
      await page.click('#compute');
      assert.equal(await page.isVisible('#warning'), true, 'warning shown for 100 000 points on a sphere');
      assert.match(await page.textContent('#warning'), /Estimated time ≈ \d/);
      assert.equal(await page.evaluate(() => document.body.dataset.state), 'ready', 'nothing started yet');

      await page.click('#compute'); // the second click confirms
      assert.equal(await page.evaluate(() => document.body.dataset.state), 'computing');
      // The main thread stays responsive while the worker is busy.
      await page.waitForTimeout(1000);
      const t0 = Date.now();
      await page.evaluate(() => new Promise((r) => requestAnimationFrame(r)));
      assert.ok(Date.now() - t0 < 1000, 'animation frames keep coming during the computation');
      assert.equal(await page.evaluate(() => document.body.dataset.state), 'computing');

      await page.click('#cancel');
      assert.equal(await page.evaluate(() => document.body.dataset.state), 'cancelled');
      assert.match(await page.textContent('#status'), /Cancelled/);

      // A fresh worker serves the next request; every sphere point is a hull vertex.
      const { state, stats } = await compute(page, { distribution: 'sphere', n: 1000 });
      assert.equal(state, 'ready', `after cancel: ${await panelError(page)}`);
      t.diagnostic(`sphere hull: ${JSON.stringify(stats)}`);
      checkHullStats(stats, { n: 1000, distribution: 'sphere' });
      assert.equal(stats.vertices, 1000, 'all points on a sphere are hull vertices');
      assert.ok(stats.volume > 0.95 * BALL_VOLUME && stats.volume < BALL_VOLUME, `sphere hull volume ${stats.volume}`);
    });

    await step('no console errors or page errors', () => {
      assert.deepEqual(consoleErrors, []);
    });

    if (!ok) {
      const failShot = path.join(os.tmpdir(), 'hullkit-page-failure.png');
      await page.screenshot({ path: failShot }).catch(() => {});
      t.diagnostic(`screenshot of the failing page: ${failShot}`);
      if (consoleErrors.length) t.diagnostic(`console errors: ${consoleErrors.join(' | ')}`);
    }
  } finally {
    if (browser) await browser.close();
    if (server) await new Promise((resolve) => server.close(resolve));
    t.diagnostic(`browser test took ${((performance.now() - started) / 1000).toFixed(1)} s`);
  }
});
