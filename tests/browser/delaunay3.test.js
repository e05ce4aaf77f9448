// The Delaunay 3D view in headless Debian Chromium, at desktop (1400 × 900) and phone (390 × 844)
// width: it opens from ?view=delaunay3 and names itself on <body data-view>; the counts it shows
// are those of hullkit.delaunay3 for the same points (computed here in Node); moving the cutting
// plane (slider and handle) changes the pixels drawn; hovering shows a circumsphere with no point
// inside it (a grid's cospherical corners all on it); clicking a point shows the volume that
// hullkit.voronoi3 gives its cell (and says a hull point's cell is unbounded); its explanation
// opens; the furthest-site tetrahedra (Sites) are hullkit.delaunay3's too; numbers in the URL are made
// valid; nothing is fetched beyond the page's own files.
// Saves docs/delaunay3.png.
//
//   node --test tests/browser/delaunay3.test.js
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { ROOT, openBrowser, decodePng, pixel } from './helpers.js';
import createHullkit from '../../wasm/hullkit.js';
import { generatePoints } from '../../web/distributions.js';
import { siteFiles } from '../../scripts/site-files.js';
import { EXPLANATIONS } from '../../web/app/explain.js';

const DESKTOP = { width: 1400, height: 900 };
const PHONE = { width: 390, height: 844 };
const TIMEOUT = 60_000;
const DOCS = path.join(ROOT, 'docs');

async function settled(page) {
  await page.waitForFunction(() => ['ready', 'error'].includes(document.body.dataset.state), null, { timeout: TIMEOUT, polling: 100 });
  return page.evaluate(() => document.body.dataset.state);
}

/** Waits until the view has drawn run > `before` and its Voronoi diagram has come. */
async function drawn(page, before = 0) {
  await page.waitForFunction((b) => window.hullkitDelaunay3?.run > b && window.hullkitDelaunay3.voronoi && document.body.dataset.state === 'ready',
    before, { timeout: TIMEOUT, polling: 100 });
  return page.evaluate(() => window.hullkitDelaunay3);
}

async function canvasImage(page) {
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  return decodePng(await page.locator('#canvas').screenshot());
}

/** Pixels of `img` that differ from the background, and pink ones (the circumsphere). */
function census(img) {
  const [br, bg, bb] = pixel(img, 2, img.height - 3);
  let differing = 0, pink = 0, teal = 0, violet = 0;
  for (let y = 0; y < img.height; y++) {
    for (let x = 0; x < img.width; x++) {
      const [r, g, b] = pixel(img, x, y);
      if (Math.abs(r - br) + Math.abs(g - bg) + Math.abs(b - bb) > 30) differing++;
      if (r > 170 && g < 150 && b > 110 && r - g > 60) pink++;
      if (g - r > 40 && b - r > 40) teal++;
      if (r > 120 && b > 150 && g < 0.8 * Math.min(r, b)) violet++;
    }
  }
  return { total: img.width * img.height, differing, pink, teal, violet };
}

/** Pixels that differ between two images of the same size. */
function changed(a, b) {
  let count = 0;
  for (let i = 0; i < a.data.length; i += 4) {
    if (Math.abs(a.data[i] - b.data[i]) + Math.abs(a.data[i + 1] - b.data[i + 1]) + Math.abs(a.data[i + 2] - b.data[i + 2]) > 40) count++;
  }
  return count;
}

/**
 * Moves the pointer over the canvas at the first of `spots` (fractions of its width and height)
 * where a tetrahedron is shown (and `accept(hover)`): its hover hook, or null when none of them does.
 */
async function hoverAny(page, spots, accept = () => true) {
  const box = await page.locator('#canvas').boundingBox();
  for (const [fx, fy] of spots) {
    await page.mouse.move(box.x + box.width * fx, box.y + box.height * fy);
    const hover = await page.waitForFunction(() => window.hullkitDelaunay3Hover, null, { timeout: 3000, polling: 50 }).then((h) => h.jsonValue(), () => null);
    if (hover && accept(hover)) return hover;
  }
  return null;
}

const readCount = (page, id) => page.$eval(id, (el) => Number(el.textContent.replace(/,/g, '')));

/** Sets a range input as a user's drag would (input events while moving, change when let go). */
const slide = (page, id, value) => page.$eval(id, (el, v) => {
  el.value = String(v);
  el.dispatchEvent(new Event('input', { bubbles: true }));
  el.dispatchEvent(new Event('change', { bubbles: true }));
}, value);

/**
 * A point to click: drawn (on the kept side of the cut), on the screen inside the canvas, away
 * from the plane's handle and its neighbours on the screen, nearest `aim` (fractions of the
 * canvas) among those for which `wanted(i)` holds.
 */
async function pointToClick(page, wanted, aim = [0.5, 0.5]) {
  const box = await page.locator('#canvas').boundingBox();
  const screen = await page.evaluate(() => Array.from({ length: window.hullkitDelaunay3.n }, (_, i) => window.hullkitDelaunay3Screen(i)));
  const handle = await page.evaluate(() => window.hullkitDelaunay3Handle());
  const cx = box.x + box.width * aim[0], cy = box.y + box.height * aim[1];
  let best = -1;
  screen.forEach((s, i) => {
    if (!s || !s.kept || !wanted(i)) return;
    if (s.x < box.x + 20 || s.x > box.x + box.width - 20 || s.y < box.y + 20 || s.y > box.y + box.height - 20) return;
    if (handle && Math.hypot(s.x - handle.x, s.y - handle.y) < 45) return;
    // Alone within 12 px, or nearest the camera there: the click picks it.
    if (screen.some((o, j) => j !== i && o?.kept && Math.hypot(o.x - s.x, o.y - s.y) < 12 && o.depth < s.depth)) return;
    if (best < 0 || Math.hypot(s.x - cx, s.y - cy) < Math.hypot(screen[best].x - cx, screen[best].y - cy)) best = i;
  });
  assert.ok(best >= 0, 'a point to click');
  return { point: best, x: screen[best].x, y: screen[best].y };
}

test('the Delaunay 3D view', { timeout: 600_000 }, async (t) => {
  const hullkit = await createHullkit();
  const { browser, base, mount, errors, watch, close } = await openBrowser();
  const allowed = new Set(await siteFiles(ROOT));
  const requested = new Set();
  const record = (page) => {
    watch(page);
    page.on('request', (req) => requested.add(req.url()));
    page.on('response', (res) => { if (res.status() >= 400) errors.push(`HTTP ${res.status()}: ${res.url()}`); });
  };
  fs.mkdirSync(DOCS, { recursive: true });
  try {
    for (const [name, viewport] of [['desktop', DESKTOP], ['phone', PHONE]]) {
      await t.test(`${name}: counts as hullkit.delaunay3 gives them, the cut, a circumsphere, a Voronoi cell, the explanation`, async () => {
        const context = await browser.newContext({ viewport, deviceScaleFactor: 1 });
        const page = await context.newPage();
        record(page);
        const [dist, n, seed] = ['ball', 600, 3];
        await page.goto(`${base}?view=delaunay3&dist=${dist}&n=${n}&seed=${seed}`);
        assert.equal(await settled(page), 'ready', await page.textContent('#d3-error'));
        assert.equal(await page.evaluate(() => document.body.dataset.view), 'delaunay3');
        assert.equal(await page.getAttribute('[data-view-link="delaunay3"]', 'aria-current'), 'page');
        assert.equal(await page.isVisible('#d3-controls'), true);
        assert.equal(await page.isVisible('#controls'), false, 'the hull controls are hidden');
        let info = await drawn(page);

        // The counts shown are hullkit.delaunay3's for the same points.
        const xyz = generatePoints(dist, n, seed);
        const expected = hullkit.delaunay3(xyz);
        assert.equal(await readCount(page, '#d3-stat-n'), n);
        assert.equal(await readCount(page, '#d3-stat-tetrahedra'), expected.tetrahedra.length / 4);
        assert.equal(await readCount(page, '#d3-stat-hull'), expected.hull.length / 3);
        assert.equal(info.tetrahedra, expected.tetrahedra.length / 4);
        assert.match(await page.textContent('#d3-stat-ms'), /ms|s$/);
        assert.match(await page.textContent('#d3-stat-voronoi'), /ms|s$/);
        t.diagnostic(`${name}: ${JSON.stringify(info)}`);

        const size = await page.locator('#canvas').evaluate((c) => ({ w: c.clientWidth, h: c.clientHeight }));
        if (name === 'phone') assert.ok(size.w === PHONE.width && size.h >= 300, `the canvas spans the phone's width: ${JSON.stringify(size)}`);
        const overflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
        assert.ok(overflow <= 0, `no horizontal scrolling (${overflow} px)`);
        const before = await canvasImage(page);
        const c0 = census(before);
        t.diagnostic(`${name} canvas: ${JSON.stringify(c0)}`);
        assert.ok(c0.teal > 0.05 * c0.total, 'the tetrahedra are drawn');

        // The cutting plane: its slider moves it (the drawing changes, the URL follows) ...
        await slide(page, '#d3-offset', -0.45);
        const moved = await canvasImage(page);
        const byslider = changed(before, moved);
        t.diagnostic(`${name}: ${byslider} pixels changed by moving the plane`);
        assert.ok(byslider > 0.02 * c0.total, 'moving the plane changes what is drawn');
        assert.equal(new URL(page.url()).searchParams.get('offset'), '-0.45');
        // ... and so does dragging its handle along its normal.
        const handle = await page.evaluate(() => window.hullkitDelaunay3Handle());
        assert.ok(handle, 'the plane has a handle');
        await page.mouse.move(handle.x, handle.y);
        await page.mouse.down();
        await page.mouse.move(handle.x + 60, handle.y + 10, { steps: 5 });
        await page.mouse.up();
        const dragged = Number(await page.inputValue('#d3-offset'));
        t.diagnostic(`${name}: dragging the handle moved the plane from -0.45 to ${dragged}`);
        assert.notEqual(dragged, -0.45, 'the handle moves the plane');
        assert.equal(new URL(page.url()).searchParams.get('offset'), String(dragged));
        assert.ok(changed(moved, await canvasImage(page)) > 0.005 * c0.total, 'dragging the handle changes what is drawn');
        // Tilting it too; then back where it was.
        const untilted = await canvasImage(page);
        await slide(page, '#d3-elevation', 70);
        assert.ok(changed(untilted, await canvasImage(page)) > 0.01 * c0.total, 'tilting the plane changes what is drawn');
        await slide(page, '#d3-elevation', 15);
        await slide(page, '#d3-offset', 0.1);
        // Shrink: the slider changes the drawing too.
        const unshrunk = await canvasImage(page);
        await slide(page, '#d3-shrink', 0.4);
        assert.ok(changed(unshrunk, await canvasImage(page)) > 0.02 * c0.total, 'shrinking changes what is drawn');
        await slide(page, '#d3-shrink', 0.75);

        // Hover: the circumsphere of a tetrahedron, with no point inside it.
        const box = await page.locator('#canvas').boundingBox();
        await page.mouse.move(box.x + box.width + 5, box.y + box.height + 5); // off the canvas: no hover
        await page.waitForFunction(() => window.hullkitDelaunay3Hover === null, null, { timeout: 5000 });
        const plain = census(await canvasImage(page));
        const hover = await hoverAny(page, [[0.4, 0.45], [0.35, 0.55], [0.45, 0.6], [0.3, 0.4]]);
        assert.ok(hover, 'hovering shows a tetrahedron');
        t.diagnostic(`${name} hover: ${JSON.stringify(hover)}`);
        assert.equal(hover.exact, true, 'the points on the sphere come from the Voronoi diagram');
        assert.deepEqual([...expected.tetrahedra.subarray(4 * hover.tetrahedron, 4 * hover.tetrahedron + 4)], hover.corners, 'the tetrahedron is delaunay3\'s');
        for (const c of hover.corners) assert.ok(hover.onSphere.includes(c));
        // The page's sphere is in centred coordinates: compare distances relative to a corner's.
        const centre = await page.evaluate(() => window.hullkitDelaunay3Hover.centre);
        const at = (i) => [xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]];
        const offsetOf = hover.corners.map((c) => at(c));
        const centreAbs = centre.map((v, k) => v + (Math.min(...Array.from({ length: n }, (_, i) => xyz[3 * i + k])) + Math.max(...Array.from({ length: n }, (_, i) => xyz[3 * i + k]))) / 2);
        const r = Math.hypot(...offsetOf[0].map((v, k) => v - centreAbs[k]));
        assert.ok(Math.abs(r - hover.radius) < 1e-5 * r, `radius ${hover.radius} vs ${r}`);
        for (let i = 0; i < n; i++) {
          if (hover.onSphere.includes(i)) continue;
          assert.ok(Math.hypot(...at(i).map((v, k) => v - centreAbs[k])) > r * (1 - 1e-5), `point ${i} inside the circumsphere`);
        }
        const withSphere = census(await canvasImage(page));
        t.diagnostic(`${name}: pink pixels ${plain.pink} → ${withSphere.pink} with the circumsphere`);
        assert.ok(withSphere.pink > plain.pink + 50, 'the circumsphere is drawn');
        assert.match(await page.textContent('#d3-hover'), /circumradius/);

        // Click a point inside the hull: its Voronoi cell, with hullkit.voronoi3's volume.
        const voronoi = hullkit.voronoi3(xyz, expected);
        const onHull = new Set(expected.hull);
        const target = await pointToClick(page, (i) => !onHull.has(i), [0.62, 0.42]);
        await page.mouse.click(target.x, target.y);
        await page.waitForFunction(() => window.hullkitDelaunay3Cell, null, { timeout: TIMEOUT, polling: 50 });
        let cell = await page.evaluate(() => window.hullkitDelaunay3Cell);
        t.diagnostic(`${name}: clicked point ${target.point}: ${JSON.stringify(cell)}`);
        assert.equal(cell.point, target.point);
        assert.equal(cell.bounded, true);
        assert.equal(cell.volume, voronoi.volume[target.point], 'the volume of hullkit.voronoi3');
        assert.equal(cell.faces, voronoi.cellOffsets[target.point + 1] - voronoi.cellOffsets[target.point]);
        assert.match(await page.textContent('#d3-cell'), new RegExp(`Point ${target.point} .*volume`));
        const withCell = census(await canvasImage(page));
        assert.ok(withCell.violet > withSphere.violet + 30, `the cell is drawn: ${withCell.violet} violet pixels`);
        // For the picture: a small circumsphere (inside the hull) away from the cell.
        const spots = [];
        for (const fy of [0.55, 0.65, 0.45, 0.35, 0.7]) for (const fx of [0.38, 0.32, 0.44, 0.5]) spots.push([fx, fy]);
        await hoverAny(page, spots, (h) => h.radius < 0.3);
        if (name === 'desktop') await page.screenshot({ path: path.join(DOCS, 'delaunay3.png') });
        else await page.screenshot({ path: path.join(os.tmpdir(), 'hullkit-delaunay3-phone.png') });
        // A point on the hull: its cell is unbounded.
        const outer = await pointToClick(page, (i) => onHull.has(i));
        await page.mouse.click(outer.x, outer.y);
        await page.waitForFunction((p) => window.hullkitDelaunay3Cell?.point === p, outer.point, { timeout: TIMEOUT, polling: 50 });
        cell = await page.evaluate(() => window.hullkitDelaunay3Cell);
        assert.equal(cell.bounded, false);
        assert.equal(cell.volume, Infinity);
        assert.match(await page.textContent('#d3-cell'), /unbounded/);

        // The explanation.
        const button = page.locator('.view-panel[data-for="delaunay3"] [data-explain="delaunay3"]');
        await button.scrollIntoViewIfNeeded();
        await button.click();
        await page.waitForFunction(() => document.getElementById('explain').open, null, { timeout: 5000 });
        assert.equal(await page.getAttribute('#explain', 'data-explains'), 'delaunay3');
        assert.equal(await page.textContent('#explain-title'), EXPLANATIONS.delaunay3.title);
        const text = await page.innerText('#explain-body');
        for (const word of ['orient3d', 'insphere', 'perturbation', 'flat tetrahedron', '4D']) assert.ok(text.includes(word), `the explanation names ${word}`);
        const dialog = await page.locator('#explain').boundingBox();
        assert.ok(dialog.x >= 0 && dialog.y >= 0 && dialog.x + dialog.width <= viewport.width && dialog.y + dialog.height <= viewport.height, 'the dialog fits the screen');
        await page.screenshot({ path: path.join(os.tmpdir(), `hullkit-delaunay3-explain-${name}.png`) });
        await page.keyboard.press('Escape');
        await page.waitForFunction(() => !document.getElementById('explain').open, null, { timeout: 5000 });
        info = await page.evaluate(() => window.hullkitDelaunay3);
        assert.equal(info.run, 1, 'no recomputation for display changes');
        await context.close();
      });
    }

    await t.test('a grid: the points on a hovered circumsphere are a unit cube\'s eight corners; clipped and uncut', async () => {
      const page = await browser.newPage({ viewport: DESKTOP, deviceScaleFactor: 1 });
      record(page);
      await page.goto(`${base}?view=delaunay3&dist=grid&n=125&cut=clip`);
      assert.equal(await settled(page), 'ready');
      const info = await drawn(page);
      assert.equal(info.n, 125);
      const xyz = generatePoints('grid', 125, 1);
      assert.equal(info.tetrahedra, hullkit.delaunay3(xyz).tetrahedra.length / 4);
      assert.equal(await page.inputValue('#d3-cut'), 'clip');
      const hover = await hoverAny(page, [[0.42, 0.45], [0.5, 0.55], [0.38, 0.6], [0.55, 0.4]]);
      assert.ok(hover, 'a tetrahedron under the pointer');
      assert.equal(hover.onSphere.length, 8, `a unit cube's corners: ${hover.onSphere}`);
      const corners = hover.onSphere.map((i) => [xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]]);
      for (let k = 0; k < 3; k++) assert.equal(new Set(corners.map((c) => c[k])).size, 2, 'two values per axis');
      assert.match(await page.textContent('#d3-hover'), /4 more points lie exactly on its sphere/);
      const clipped = await canvasImage(page);
      await page.mouse.move(5, 5);
      await page.selectOption('#d3-cut', 'off');
      assert.equal(new URL(page.url()).searchParams.get('cut'), 'off');
      assert.ok(changed(clipped, await canvasImage(page)) > 1000, 'without the cut the drawing changes');
      assert.equal(await page.isDisabled('#d3-offset'), true, 'no plane to move');
      await page.close();
    });

    await t.test('furthest sites: hullkit.delaunay3\'s furthest-site tetrahedra, a circumsphere holding every point, unbounded or empty cells', async () => {
      const page = await browser.newPage({ viewport: DESKTOP, deviceScaleFactor: 1 });
      record(page);
      const [n, seed] = [400, 4];
      await page.goto(`${base}?view=delaunay3&dist=ball&n=${n}&seed=${seed}&sites=furthest`);
      assert.equal(await settled(page), 'ready', await page.textContent('#d3-error'));
      const info = await drawn(page);
      assert.equal(await page.inputValue('#d3-sites'), 'furthest');
      const xyz = generatePoints('ball', n, seed);
      const expected = hullkit.delaunay3(xyz, { furthestSite: true });
      const corners = new Set(hullkit.hull(xyz).vertices);
      assert.equal(info.sites, 'furthest');
      assert.equal(info.tetrahedra, expected.tetrahedra.length / 4);
      assert.equal(await readCount(page, '#d3-stat-tetrahedra'), expected.tetrahedra.length / 4);
      assert.equal(info.corners, corners.size);
      assert.match(await page.textContent('#d3-status'), /furthest sites: .* tetrahedra on the hull's .* corners/);
      // Hover: a circumsphere with every point inside or on it.
      const hover = await hoverAny(page, [[0.45, 0.5], [0.5, 0.45], [0.4, 0.55], [0.55, 0.55]]);
      assert.ok(hover, 'a tetrahedron under the pointer');
      assert.deepEqual([...expected.tetrahedra.subarray(4 * hover.tetrahedron, 4 * hover.tetrahedron + 4)], hover.corners);
      assert.match(await page.textContent('#d3-hover'), /every other point inside it|none outside/);
      // A corner's cell is unbounded; a point inside the hull has none.
      await page.mouse.move(5, 5);
      const corner = await pointToClick(page, (i) => corners.has(i));
      await page.mouse.click(corner.x, corner.y);
      await page.waitForFunction((p) => window.hullkitDelaunay3Cell?.point === p, corner.point, { timeout: TIMEOUT, polling: 50 });
      assert.match(await page.textContent('#d3-cell'), /furthest-site cell .* is unbounded/);
      const inner = await pointToClick(page, (i) => !corners.has(i));
      await page.mouse.click(inner.x, inner.y);
      await page.waitForFunction((p) => window.hullkitDelaunay3Cell?.point === p, inner.point, { timeout: TIMEOUT, polling: 50 });
      assert.equal((await page.evaluate(() => window.hullkitDelaunay3Cell)).faces, 0);
      assert.match(await page.textContent('#d3-cell'), /no corner of the hull: its furthest-site cell is empty/);
      // Back to the nearest sites: the Delaunay tetrahedra again, and the URL drops the option.
      await page.selectOption('#d3-sites', 'nearest');
      const back = await drawn(page, info.run);
      assert.equal(back.tetrahedra, hullkit.delaunay3(xyz).tetrahedra.length / 4);
      assert.equal(new URL(page.url()).searchParams.get('sites'), null);
      await page.close();
    });

    await t.test('a touch screen: a tap shows the circumsphere there and picks the point under the finger', async () => {
      const context = await browser.newContext({ viewport: PHONE, deviceScaleFactor: 1, hasTouch: true, isMobile: true });
      const page = await context.newPage();
      record(page);
      await page.goto(`${base}?view=delaunay3&dist=ball&n=300&seed=2`);
      assert.equal(await settled(page), 'ready');
      await drawn(page);
      const target = await pointToClick(page, () => true, [0.45, 0.55]);
      await page.touchscreen.tap(target.x, target.y);
      await page.waitForFunction((p) => window.hullkitDelaunay3Cell?.point === p, target.point, { timeout: TIMEOUT, polling: 50 });
      assert.ok(await page.evaluate(() => window.hullkitDelaunay3Hover), 'the tap shows a circumsphere (a touch screen has no hover)');
      assert.match(await page.textContent('#d3-hover'), /circumradius/);
      await context.close();
    });

    await t.test('a file opened: its points, read by the C++ readers, tetrahedralized; a bad one says why', async () => {
      const page = await browser.newPage({ viewport: DESKTOP, deviceScaleFactor: 1 });
      record(page);
      await page.goto(`${base}?view=delaunay3&n=100`);
      assert.equal(await settled(page), 'ready');
      const before = (await drawn(page)).run;
      const xyz = generatePoints('cube', 250, 9);
      let text = '# a cube of points\n';
      for (let i = 0; i < xyz.length; i += 3) text += `v ${xyz[i]} ${xyz[i + 1]} ${xyz[i + 2]}\n`;
      await page.setInputFiles('#file-input', { name: 'cloud.obj', mimeType: 'application/octet-stream', buffer: Buffer.from(text) });
      const info = await drawn(page, before);
      assert.equal(info.distribution, 'file');
      assert.equal(info.n, 250);
      assert.equal(info.tetrahedra, hullkit.delaunay3(xyz).tetrahedra.length / 4);
      assert.equal(await page.inputValue('#d3-distribution'), 'file');
      assert.match(await page.textContent('#d3-distribution option[value="file"]'), /from cloud\.obj/);
      assert.match(await page.textContent('#d3-status'), /250 points from cloud\.obj/);
      await page.setInputFiles('#file-input', { name: 'broken.xyz', mimeType: 'text/plain', buffer: Buffer.from('0 0 0\n1 nope 2\n') });
      await page.waitForFunction(() => document.body.dataset.state === 'error', null, { timeout: TIMEOUT });
      assert.match(await page.textContent('#d3-error'), /Cannot read broken\.xyz: line 2/);
      await page.close();
    });

    await t.test('coplanar points: their triangles, no tetrahedra; every cell unbounded', async () => {
      const page = await browser.newPage({ viewport: DESKTOP, deviceScaleFactor: 1 });
      record(page);
      await page.goto(`${base}?view=delaunay3&dist=plane&n=200&seed=4`);
      assert.equal(await settled(page), 'ready');
      await page.waitForFunction(() => window.hullkitDelaunay3?.run >= 1);
      const info = await page.evaluate(() => window.hullkitDelaunay3);
      const expected = hullkit.delaunay3(generatePoints('plane', 200, 4));
      assert.deepEqual([info.dimension, info.tetrahedra, info.triangles], [2, 0, expected.triangles.length / 3]);
      assert.match(await page.textContent('#d3-status'), /all on one plane/);
      const c = census(await canvasImage(page));
      assert.ok(c.teal > 1000, `the triangles are drawn: ${JSON.stringify(c)}`);
      await page.close();
    });

    await t.test('numbers in the URL become the nearest valid value, and the URL says so', async () => {
      const page = await browser.newPage({ viewport: DESKTOP, deviceScaleFactor: 1 });
      record(page);
      const param = (key) => new URL(page.url()).searchParams.get(key);
      await page.goto(`${base}?view=delaunay3&dist=cube&n=-5&seed=-3&shrink=7&offset=-9&az=999&el=-95&cut=sideways`);
      assert.equal(await settled(page), 'ready', await page.textContent('#d3-error'));
      const info = await page.evaluate(() => window.hullkitDelaunay3);
      assert.deepEqual([info.n, info.seed, info.dimension], [1, 0, 0], 'n = -5 is one point');
      assert.deepEqual(await Promise.all(['#d3-n', '#d3-seed', '#d3-shrink', '#d3-offset', '#d3-azimuth', '#d3-elevation', '#d3-cut'].map((id) => page.inputValue(id))),
        ['1', '0', '1', '-1', '180', '-90', 'whole']);
      assert.deepEqual(['n', 'seed', 'shrink', 'offset', 'az', 'el'].map(param), ['1', '0', '1', '-1', '180', '-90']);
      assert.match(await page.textContent('#d3-status'), /one distinct point/);
      // Too many points: the most the view takes, in the field and the URL (not waited for).
      await page.goto(`${base}?view=delaunay3&dist=ball&n=5000000&shrink=0.01`);
      await page.waitForFunction(() => document.body.dataset.state === 'computing', null, { timeout: TIMEOUT });
      assert.deepEqual([await page.inputValue('#d3-n'), param('n'), param('shrink')], ['200000', '200000', '0.1']);
      await page.close();
    });

    await t.test('the view switch and back/forward', async () => {
      const page = await browser.newPage({ viewport: DESKTOP, deviceScaleFactor: 1 });
      record(page);
      await page.goto(`${base}?view=hull&n=200`);
      assert.equal(await settled(page), 'ready');
      await page.click('[data-view-link="delaunay3"]');
      await page.waitForFunction(() => document.body.dataset.view === 'delaunay3');
      assert.equal(await settled(page), 'ready');
      assert.match(page.url(), /view=delaunay3/);
      assert.equal(await page.title(), 'hullkit · Delaunay tetrahedralization by lifting to 4D');
      await page.goBack();
      await page.waitForFunction(() => document.body.dataset.view === 'hull');
      await page.goForward();
      await page.waitForFunction(() => document.body.dataset.view === 'delaunay3');
      assert.equal(await page.isVisible('#d3-controls'), true);
      await page.close();
    });

    await t.test('nothing is fetched beyond the page\'s own files; no console errors', () => {
      const outside = [...requested].filter((url) => {
        if (url.startsWith('data:') || url.startsWith('blob:')) return false;
        const rel = decodeURIComponent(new URL(url).pathname).replace(/^\//, '');
        return !(url.startsWith(mount) && (allowed.has(rel) || rel === 'web/' || rel === 'web'));
      });
      assert.ok(requested.size > 10, `requests seen: ${requested.size}`);
      assert.deepEqual(outside, []);
      assert.deepEqual(errors, []);
    });
  } finally {
    await close();
  }
});
