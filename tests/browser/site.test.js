// The static site build/site/ (npm run build; bash scripts/build.sh site) in headless Debian
// Chromium, served as a plain static host would (no allow-list) under the sub-path /demo/: the
// top index.html sends a visitor to web/ with the query kept, the hull view computes and draws,
// ?view=delaunay and ?view=route render, and no request fails or leaves /demo/.
//
//   node --test tests/browser/site.test.js
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { ROOT, openBrowser, decodePng, pixel, averageColor } from './helpers.js';
import { siteFiles } from '../../scripts/site-files.js';
import { SITE_EXTRAS } from '../../scripts/build-site.js';

const SITE = path.join(ROOT, 'build', 'site');
const PREFIX = '/demo/';
const TIMEOUT = 60_000;

/** Fails unless build/site holds exactly the current allow-list's files, as they are now. */
async function assertSiteCurrent() {
  const rebuild = 'build the site first: bash scripts/build.sh site (npm run build)';
  assert.ok(fs.existsSync(path.join(SITE, 'web', 'index.html')), `${SITE} is missing: ${rebuild}`);
  const files = await siteFiles(ROOT);
  const list = (rel) => fs.readdirSync(path.join(SITE, rel), { withFileTypes: true })
    .flatMap((d) => (d.isDirectory() ? list(path.join(rel, d.name)) : [path.join(rel, d.name).split(path.sep).join('/')]));
  assert.deepEqual(list('').sort(), [...files, ...SITE_EXTRAS].sort(), `build/site is out of date: ${rebuild}`);
  for (const file of files) {
    assert.ok(fs.readFileSync(path.join(SITE, file)).equals(fs.readFileSync(path.join(ROOT, file))), `build/site/${file} is out of date: ${rebuild}`);
  }
}

/** Share of canvas pixels that differ from the background (its top-left corner). */
async function drawnShare(page) {
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  const img = decodePng(await page.locator('#canvas').screenshot());
  const background = averageColor(img, 2, 2, 8, 8);
  let differing = 0;
  for (let y = 0; y < img.height; y += 2) {
    for (let x = 0; x < img.width; x += 2) {
      const p = pixel(img, x, y);
      if (p.reduce((s, v, k) => s + Math.abs(v - background[k]), 0) > 30) differing++;
    }
  }
  return differing / (Math.ceil(img.width / 2) * Math.ceil(img.height / 2));
}

async function settled(page, view) {
  await page.waitForFunction(
    (v) => document.body.dataset.view === v && ['ready', 'error', 'cancelled'].includes(document.body.dataset.state),
    view,
    { timeout: TIMEOUT, polling: 100 },
  );
  return page.evaluate(() => document.body.dataset.state);
}

test('the static site under /demo/: hull, Delaunay, Delaunay 3D and route views', { timeout: 180_000 }, async (t) => {
  await assertSiteCurrent();
  const { browser, mount, errors, watch, close } = await openBrowser({ folder: SITE, prefix: PREFIX });
  try {
    const page = await browser.newPage({ viewport: { width: 1280, height: 800 }, deviceScaleFactor: 1 });
    watch(page);
    const requested = [];
    page.on('request', (req) => requested.push(req.url()));
    page.on('response', (res) => { if (res.status() >= 400) errors.push(`HTTP ${res.status()}: ${res.url()}`); });

    await t.test('the site\'s top redirects to web/ with the query; the hull is computed and drawn', async () => {
      await page.goto(`${mount}?view=hull&n=3000&seed=2`);
      await page.waitForURL(/\/demo\/web\/\?/, { timeout: TIMEOUT });
      assert.equal(new URL(page.url()).pathname, `${PREFIX}web/`);
      assert.match(page.url(), /n=3000/, 'the query survives the redirect');
      assert.equal(await settled(page, 'hull'), 'ready', await page.textContent('#error'));
      const stats = await page.evaluate(() => window.hullkitStats);
      t.diagnostic(`hull: ${JSON.stringify(stats)}`);
      assert.equal(stats.n, 3000);
      assert.ok(stats.vertices > 4 && stats.faces === 2 * stats.vertices - 4, `a hull: ${stats.vertices} vertices`);
      const share = await drawnShare(page);
      assert.ok(share > 0.05, `the hull is drawn (${(100 * share).toFixed(1)}% of the canvas)`);
    });

    await t.test('?view=delaunay renders', async () => {
      await page.goto(`${mount}?view=delaunay&set=uniform&n=400&seed=3`);
      assert.equal(await settled(page, 'delaunay'), 'ready', await page.textContent('#dl-error'));
      const info = await page.evaluate(() => window.hullkitDelaunay);
      t.diagnostic(`delaunay: n ${info.n}, triangles ${info.triangles}, hull ${info.hull}`);
      assert.equal(info.n, 400);
      assert.equal(info.triangles, 2 * info.n - info.hull - 2);
      const share = await drawnShare(page);
      assert.ok(share > 0.05, `the triangulation is drawn (${(100 * share).toFixed(1)}% of the canvas)`);
    });

    await t.test('?view=delaunay3 renders, with its Voronoi diagram', async () => {
      await page.goto(`${mount}web/?view=delaunay3&dist=ball&n=300&seed=3`);
      assert.equal(await settled(page, 'delaunay3'), 'ready', await page.textContent('#d3-error'));
      await page.waitForFunction(() => window.hullkitDelaunay3?.voronoi, null, { timeout: TIMEOUT, polling: 100 });
      const info = await page.evaluate(() => window.hullkitDelaunay3);
      t.diagnostic(`delaunay3: n ${info.n}, tetrahedra ${info.tetrahedra}, hull triangles ${info.hullTriangles}`);
      assert.deepEqual([info.n, info.dimension], [300, 3]);
      assert.ok(info.tetrahedra > info.n, `${info.tetrahedra} tetrahedra`);
      const share = await drawnShare(page);
      assert.ok(share > 0.05, `the tetrahedra are drawn (${(100 * share).toFixed(1)}% of the canvas)`);
    });

    await t.test('?view=route renders (from the view switch)', async () => {
      await page.click('a[data-view-link="route"]');
      assert.equal(await settled(page, 'route'), 'ready', await page.textContent('#rt-error'));
      assert.match(page.url(), /view=route/);
      const info = await page.evaluate(() => window.hullkitRoute);
      t.diagnostic(`route: ${info.preset}, clear ${info.clear}, legs ${info.legs.map((l) => l.status)}`);
      assert.ok(info.legs.length > 0, 'legs checked');
      assert.ok(info.legs.every((l) => ['clear', 'hit'].includes(l.status)), 'every leg has a verdict');
      const share = await drawnShare(page);
      assert.ok(share > 0.05, `the scene is drawn (${(100 * share).toFixed(1)}% of the canvas)`);
    });

    await t.test('every request stayed in /demo/ and none failed', () => {
      const http = requested.filter((u) => u.startsWith('http'));
      assert.ok(http.some((u) => u.endsWith('/demo/build/wasm/hullkit_core.wasm')), 'the wasm module came from the site');
      assert.ok(http.some((u) => u.endsWith('/demo/node_modules/three/build/three.module.js')), 'three.js came from the site');
      // The top index.html replaces itself with web/ while Chromium may still be loading it; that
      // document's request is then reported as aborted, which is the redirect working, not a failure.
      const redirect = (e) => e.startsWith(`request failed: ${mount}?`) && e.endsWith('(net::ERR_ABORTED)');
      assert.deepEqual(errors.filter((e) => !redirect(e)), []);
    });
  } finally {
    await close();
  }
});
