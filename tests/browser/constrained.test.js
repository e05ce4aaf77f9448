// The Delaunay view's constrained modes in headless Debian Chromium, at desktop and at phone
// width: switching to "constrained" draws the sample polygon's constrained triangulation (its
// triangles, and its constrained edges thick and orange); a square with a square hole drawn by
// clicks gives 8 triangles with the hole empty, a dragged vertex re-triangulates while it moves,
// and the link keeps the drawing; a GeoJSON file and Triangle .poly files open (the .poly as
// Triangle reads it: exterior and hole regions removed, or the whole hull when its segments
// enclose nothing); bad files and a polygon hullkit rejects show their message with the rings
// still drawn; the quality mesh meets a 20° minimum angle and a maximum area, and with "Keep
// segments whole: the boundary" (Triangle's -Y) splits no ring edge; nothing overflows the
// phone's width.
//
//   node --test tests/browser/constrained.test.js
//
// The quality-mesh subtest needs the minAngle/maxArea options of hullkit.triangulatePolygon in
// the wasm build (wasm/constrained.js); without them the page shows hullkit's "unknown option"
// and that subtest fails.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { openBrowser, decodePng, pixel, averageColor } from './helpers.js';
import createHullkit from '../../wasm/hullkit.js';
import { SAMPLE_RINGS, parseGeoJSON } from '../../web/polygons.js';

const VIEWPORTS = [['desktop', { width: 1280, height: 800 }], ['phone', { width: 390, height: 844 }]];
const TIMEOUT = 30_000;

/** Pixel counts of the plane pane: differing from the background, the constraints' orange, teal, amber, violet. */
async function planeCensus(page) {
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  const canvas = await page.locator('#canvas').boundingBox();
  const pane = await page.locator('.pane-2d').boundingBox();
  const img = decodePng(await page.locator('#canvas').screenshot());
  const background = averageColor(img, 2, img.height - 10, 8, 8);
  const counts = { total: 0, differing: 0, orange: 0, teal: 0, amber: 0, violet: 0 };
  const x0 = Math.max(0, Math.round(pane.x - canvas.x)), y0 = Math.max(0, Math.round(pane.y - canvas.y));
  for (let y = y0; y < Math.min(img.height, y0 + Math.round(pane.height)); y++) {
    for (let x = x0; x < Math.min(img.width, x0 + Math.round(pane.width)); x++) {
      const [r, g, b] = pixel(img, x, y);
      counts.total++;
      if (Math.abs(r - background[0]) + Math.abs(g - background[1]) + Math.abs(b - background[2]) > 30) counts.differing++;
      if (r > 200 && g > 70 && g < 150 && b < 110 && r - g > 90) counts.orange++;
      if (g - r > 25 && b - r > 25) counts.teal++;
      if (r > 190 && g > 160 && g < 220 && b < 130) counts.amber++;
      if (r > 150 && b > 200 && g < 150) counts.violet++;
    }
  }
  return counts;
}

async function settled(page) {
  await page.waitForFunction(() => ['ready', 'error'].includes(document.body.dataset.state), null, { timeout: TIMEOUT, polling: 50 });
  return page.evaluate(() => document.body.dataset.state);
}

const hook = (page) => page.evaluate(() => window.hullkitConstrained ?? null);
const runOf = async (page) => (await hook(page))?.run ?? 0;

/**
 * Waits for a constrained result (or error) after run `before` for which `check` holds (an
 * expression of the hook `h`, evaluated in the page).
 */
async function nextResult(page, before, check = 'true') {
  const expression = `(() => { const h = window.hullkitConstrained; return Boolean(h && h.run > ${before} && document.body.dataset.state !== 'computing' && (${check})); })()`;
  await page.waitForFunction(expression, null, { timeout: TIMEOUT, polling: 50 });
  return hook(page);
}

/** The triangles of the hook as [[x, y] × 3] and their total area. */
async function trianglesShown(page) {
  const { coords, list } = await page.evaluate(() => ({ coords: window.hullkitConstrained.coords, list: window.hullkitConstrained.triangleList }));
  const triangles = [];
  let area = 0;
  for (let t = 0; t < list.length; t += 3) {
    const p = [0, 1, 2].map((k) => [coords[2 * list[t + k]], coords[2 * list[t + k] + 1]]);
    const signed = ((p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0])) / 2;
    assert.ok(signed < 0, `triangle ${t / 3} is clockwise (y up) and not flat: ${signed}`);
    area -= signed;
    triangles.push(p);
  }
  return { triangles, area };
}

const ringArea = (ring) => Math.abs(ring.reduce((s, [x, y], i) => {
  const [u, v] = ring[(i + 1) % ring.length];
  return s + x * v - u * y;
}, 0)) / 2;

/** Clicks the plane point (x, y) of the plane pane. */
async function clickPlane(page, x, y) {
  const at = await page.evaluate(([px, py]) => window.hullkitPlaneToScreen(px, py), [x, y]);
  await page.mouse.click(at.x, at.y);
}

/** The canvas at the top of the page (a phone scrolls the panel under it). */
async function canvasInView(page) {
  await page.evaluate(() => { document.body.scrollTop = 0; document.documentElement.scrollTop = 0; });
}

const GEOJSON = {
  type: 'FeatureCollection',
  features: [
    { type: 'Feature', properties: { name: 'yard' }, geometry: { type: 'Polygon', coordinates: [
      [[0, 0], [10, 0], [10, 6], [4, 6], [4, 10], [0, 10], [0, 0]],
      [[1, 1], [3, 1], [3, 4], [1, 4], [1, 1]],
    ] } },
    { type: 'Feature', properties: {}, geometry: { type: 'MultiPolygon', coordinates: [
      [[[12, 0], [16, 0], [14, 3], [12, 0]]],
      [[[12, 5], [16, 5], [16, 9], [12, 9], [12, 5]], [[13, 6], [15, 6], [14, 8], [13, 6]]],
    ] } },
    { type: 'Feature', properties: {}, geometry: { type: 'Point', coordinates: [5, 5] } },
  ],
};
// Triangle's example of a box with a square hole (1-based), and a free vertex inside.
const BOX_POLY = `# a 3 x 3 box with a 1 x 1 hole
9 2 0 1
1 0 0 1
2 3 0 1
3 3 3 1
4 0 3 1
5 1 1 0
6 2 1 0
7 2 2 0
8 1 2 0
9 0.5 2.5 0
8 1
1 1 2 1
2 2 3 1
3 3 4 1
4 4 1 1
5 5 6 0
6 6 7 0
7 7 8 0
8 8 5 0
1
1 1.5 1.5
`;
const OPEN_POLY = `4 2 0 0
0 0 0
1 4 0
2 4 3
3 0 3
1 0
0 0 2
0
`;

const openFile = (page, name, text) => page.setInputFiles('#file-input', { name, mimeType: 'application/octet-stream', buffer: Buffer.from(text) });

test('the Delaunay view\'s constrained modes', { timeout: 300_000 }, async (t) => {
  const hullkit = await createHullkit();
  const { browser, base, errors, watch, close } = await openBrowser();
  try {
    for (const [name, viewport] of VIEWPORTS) {
      const page = await browser.newPage({ viewport, deviceScaleFactor: 1 });
      watch(page);
      const open = async (url) => {
        const other = await browser.newPage({ viewport, deviceScaleFactor: 1 });
        watch(other);
        await other.goto(url);
        return other;
      };

      await t.test(`${name}: switching to constrained draws the sample's triangles and constrained edges`, async () => {
        await page.goto(`${base}?view=delaunay&set=uniform&n=200&seed=2`);
        assert.equal(await settled(page), 'ready', await page.textContent('#dl-error'));
        const plain = await planeCensus(page);
        await page.selectOption('#dl-mode', 'constrained');
        const info = await nextResult(page, 0, 'h.triangles > 0');
        t.diagnostic(`${name}: ${JSON.stringify(info)}`);
        assert.equal(info.mode, 'constrained');
        assert.equal(info.source, 'sample');
        assert.equal(info.rings, SAMPLE_RINGS.length);
        const vertices = SAMPLE_RINGS.reduce((s, r) => s + r.length, 0);
        assert.equal(info.constrainedEdges, vertices, 'every ring edge is a constrained edge');
        assert.equal(info.addedCount, 0);
        assert.equal(info.polygonEdges, vertices);
        assert.ok(info.notDelaunay >= 1, 'the unconstrained Delaunay triangulation lacks some polygon edges');
        assert.equal(info.triangles, vertices + 2 * (SAMPLE_RINGS.length - 1) - 2, 'a polygon with h holes and n vertices has n + 2h − 2 triangles');
        const { area } = await trianglesShown(page);
        const expected = ringArea(SAMPLE_RINGS[0]) - SAMPLE_RINGS.slice(1).reduce((s, r) => s + ringArea(r), 0);
        assert.ok(Math.abs(area - expected) < 1e-12, `the triangles cover the polygon less its holes: ${area} vs ${expected}`);
        const note = await page.textContent('#dl-cdt-note');
        assert.match(note, new RegExp(`${info.notDelaunay} of its ${vertices} edges are not Delaunay edges`));
        assert.match(note, /22 constrained edges/);
        assert.equal(await page.isVisible('#dl-polygon-fields'), true);
        assert.equal(await page.isVisible('#dl-points-fields'), false);
        assert.equal(await page.textContent('#dl-stat-triangles'), String(info.triangles));
        assert.match(page.url(), /mode=constrained/);
        await canvasInView(page);
        const c = await planeCensus(page);
        t.diagnostic(`${name} plane pane: ${JSON.stringify(c)} (points mode: ${JSON.stringify(plain)})`);
        assert.ok(c.orange > 500 && plain.orange < 50, 'the constrained edges are drawn thick and orange');
        assert.ok(c.teal > 1000 && c.differing > 0.1 * c.total, 'the triangles are drawn');
      });

      await t.test(`${name}: a square with a square hole drawn by clicks gives 8 triangles, the hole empty`, async () => {
        let before = await runOf(page);
        await page.click('#dl-clear-rings');
        let info = await nextResult(page, before, 'h.rings === 0');
        assert.deepEqual([info.triangles, info.points], [0, 0]);
        await canvasInView(page);
        const outer = [[-0.8, -0.7], [0.8, -0.7], [0.8, 0.7], [-0.8, 0.7]];
        const hole = [[-0.3, -0.25], [0.3, -0.25], [0.3, 0.25], [-0.3, 0.25]];
        for (const [x, y] of outer) await clickPlane(page, x, y);
        await page.waitForFunction(() => window.hullkitConstrained.open === 4);
        assert.equal(await page.isDisabled('#dl-close-ring'), false);
        before = await runOf(page);
        await clickPlane(page, ...outer[0]); // the first vertex again closes the ring
        info = await nextResult(page, before, 'h.rings === 1');
        assert.deepEqual([info.triangles, info.open], [2, 0]);
        for (const [x, y] of hole) await clickPlane(page, x, y);
        await page.waitForFunction(() => window.hullkitConstrained.open === 4);
        before = await runOf(page);
        await page.keyboard.press('Enter'); // Enter closes it too
        info = await nextResult(page, before, 'h.rings === 2');
        t.diagnostic(`${name} square with a hole: ${JSON.stringify(info)}`);
        assert.equal(info.triangles, 8);
        assert.equal(info.constrainedEdges, 8);
        assert.equal(info.addedCount, 0);
        const { triangles, area } = await trianglesShown(page);
        const shown = await page.evaluate(() => window.hullkitConstrained.coords);
        const drawnOuter = [0, 1, 2, 3].map((i) => [shown[2 * i], shown[2 * i + 1]]);
        const drawnHole = [4, 5, 6, 7].map((i) => [shown[2 * i], shown[2 * i + 1]]);
        for (const [k, [x, y]] of [...outer, ...hole].entries()) {
          assert.ok(Math.hypot(shown[2 * k] - x, shown[2 * k + 1] - y) < 0.02, `vertex ${k} is where it was clicked`);
        }
        assert.ok(Math.abs(area - (ringArea(drawnOuter) - ringArea(drawnHole))) < 1e-9, `the square less its hole: ${area}`);
        for (const p of triangles) {
          const cx = (p[0][0] + p[1][0] + p[2][0]) / 3, cy = (p[0][1] + p[1][1] + p[2][1]) / 3;
          assert.ok(!(Math.abs(cx) < 0.29 && Math.abs(cy) < 0.24), `no triangle in the hole (centroid ${cx}, ${cy})`);
        }
        assert.match(page.url(), /rings=/, 'the drawn rings are kept in the URL');
      });

      await t.test(`${name}: a dragged vertex re-triangulates while it moves; the link keeps the drawing`, async () => {
        await canvasInView(page);
        const before = await runOf(page);
        const from = await page.evaluate(() => window.hullkitRingVertex(2));
        const to = await page.evaluate(() => window.hullkitPlaneToScreen(0.95, 0.85));
        await page.mouse.move(from.x, from.y);
        await page.mouse.down();
        await page.mouse.move((from.x + to.x) / 2, (from.y + to.y) / 2, { steps: 4 });
        // Re-triangulated before the button is released.
        const during = await nextResult(page, before, 'h.coords[5] > 0.72');
        assert.equal(during.triangles, 8);
        await page.mouse.move(to.x, to.y, { steps: 4 });
        await page.mouse.up();
        const info = await nextResult(page, during.run - 1, 'Math.abs(h.coords[4] - 0.95) < 0.02 && Math.abs(h.coords[5] - 0.85) < 0.02');
        assert.equal(info.triangles, 8);
        const link = page.url();
        assert.match(link, /mode=constrained/);
        const rings = new URL(link).searchParams.get('rings');
        assert.equal(rings.split('|').length, 2);
        assert.match(rings.split('|')[0].split(';')[2], /^0\.9[4-6]\d*,0\.8[4-6]/);
        // The link opened again: the same drawing.
        const other = await open(link);
        assert.equal(await settled(other), 'ready');
        const reopened = await nextResult(other, 0, 'h.triangles > 0');
        assert.deepEqual([reopened.mode, reopened.source, reopened.rings, reopened.triangles], ['constrained', 'drawn', 2, 8]);
        assert.equal(await other.inputValue('#dl-mode'), 'constrained');
        await other.close();
      });

      await t.test(`${name}: a GeoJSON file opens; its triangles are hullkit's`, async () => {
        const before = await runOf(page);
        await openFile(page, 'yard.geojson', JSON.stringify(GEOJSON));
        const info = await nextResult(page, before, 'h.source === "file"');
        t.diagnostic(`${name} GeoJSON: ${JSON.stringify(info)}`);
        const { xy, starts } = parseGeoJSON(JSON.stringify(GEOJSON), 'yard.geojson');
        const expected = hullkit.triangulatePolygon(xy, starts.slice(1, -1), { fill: 'evenodd' });
        assert.equal(info.rings, 5);
        assert.equal(info.triangles, expected.triangles.length / 3);
        assert.deepEqual(await page.evaluate(() => window.hullkitConstrained.triangleList), Array.from(expected.triangles));
        const { area } = await trianglesShown(page);
        assert.ok(Math.abs(area - (10 * 6 + 4 * 4 - 6 + 6 + 16 - 2)) < 1e-9, `area ${area}`);
        assert.match(await page.textContent('#file-note'), /skipped 1 geometry that is not polygons/);
        assert.match(await page.textContent('#dl-status'), /yard\.geojson/);
      });

      await t.test(`${name}: Triangle .poly files: holes and exterior removed, or the whole hull`, async () => {
        let before = await runOf(page);
        await openFile(page, 'box.poly', BOX_POLY);
        let info = await nextResult(page, before, 'h.graph === true');
        t.diagnostic(`${name} box.poly: ${JSON.stringify(info)}`);
        assert.equal(info.wholeHull, false);
        assert.equal(info.triangles, 10, 'the box less its hole, with a free vertex: 8 + 2 triangles');
        assert.ok(Math.abs((await trianglesShown(page)).area - 8) < 1e-12);
        assert.match(await page.textContent('#dl-cdt-note'), /outside the segments and the regions around the 1 hole point removed/);
        before = info.run;
        await openFile(page, 'open.poly', OPEN_POLY);
        info = await nextResult(page, before, 'h.wholeHull === true');
        assert.equal(info.triangles, 2);
        assert.match(await page.textContent('#dl-cdt-note'), /enclose no region, so the whole convex hull is triangulated/);
      });

      await t.test(`${name}: bad files and rejected polygons show their message; the rings stay drawn`, async () => {
        const shown = await hook(page);
        await openFile(page, 'broken.geojson', JSON.stringify({ type: 'LineString', coordinates: [[0, 0], [1, 1]] }));
        await page.waitForSelector('#dl-error', { state: 'visible', timeout: TIMEOUT });
        assert.equal(await page.textContent('#dl-error'), 'Cannot read broken.geojson: GeoJSON "LineString" is not a Polygon or MultiPolygon');
        assert.equal(await page.evaluate(() => document.body.dataset.state), 'error');
        assert.equal((await hook(page)).run, shown.run, 'the drawing stays as it was');
        await openFile(page, 'bad.poly', '4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n2 0\n1 1 2\n2 2 9\n0\n');
        await page.waitForFunction(() => /bad\.poly/.test(document.getElementById('dl-error').textContent));
        assert.equal(await page.textContent('#dl-error'), 'Cannot read bad.poly: line 8: segment 2 names vertex 9, not one of the 4 vertices (numbered from 1)');
        await openFile(page, 'notjson.geojson', '{"type": "Polygon", ');
        await page.waitForFunction(() => /notjson/.test(document.getElementById('dl-error').textContent));
        assert.match(await page.textContent('#dl-error'), /^Cannot read notjson\.geojson: not GeoJSON \(not valid JSON/);
        // A polygon hullkit rejects (coordinates too far apart in scale): its message, the vertex named ringed.
        const before = await runOf(page);
        await openFile(page, 'tiny.geojson', JSON.stringify({ type: 'Polygon', coordinates: [[[0, 0], [2, 0], [2, 2], [1e-200, 2]]] }));
        const info = await nextResult(page, before, 'h.error !== null');
        assert.match(info.error, /orders of magnitude/);
        assert.equal(await page.evaluate(() => document.body.dataset.state), 'error');
        assert.match(await page.textContent('#dl-error'), /^Cannot triangulate: triangulatePolygon: coordinates span too many orders of magnitude/);
        assert.match(await page.textContent('#dl-cdt-note'), /red ring marks the vertex/);
        await canvasInView(page);
        const c = await planeCensus(page);
        t.diagnostic(`${name} rejected polygon: ${JSON.stringify(c)}`);
        assert.ok(c.amber > 20 && c.orange > 50, 'not a blank view: the ring and its vertices are drawn');
      });

      await t.test(`${name}: quality mesh with a 20° minimum angle and a maximum area`, async () => {
        let before = await runOf(page);
        await page.click('#dl-sample');
        await nextResult(page, before, 'h.source === "sample" && h.error === null');
        before = await runOf(page);
        await page.selectOption('#dl-mode', 'quality');
        let info = await nextResult(page, before, 'h.mode === "quality"');
        t.diagnostic(`${name} quality 20°: ${JSON.stringify(info)}`);
        assert.equal(info.error, null, info.error);
        assert.equal(info.angleBound, 20);
        assert.equal(info.unrefinedCount, 0, 'the sample has no input angle too small to refine');
        assert.ok(info.smallestAngle >= 20 - 1e-9, `smallest angle ${info.smallestAngle}`);
        assert.equal(info.belowBound, 0);
        assert.ok(info.steinerCount > 0 && info.addedCount >= info.steinerCount, 'Steiner points added');
        assert.ok(info.triangles > 24);
        assert.match(await page.textContent('#dl-cdt-note'), /^Smallest angle 2\d\.\d° \(bound 20°\)/);
        await canvasInView(page);
        assert.ok((await planeCensus(page)).violet > 30, 'the Steiner points are drawn violet');
        // A maximum area, and the slider: both kept in the link.
        before = info.run;
        await page.fill('#dl-max-area', '0.01');
        await page.press('#dl-max-area', 'Enter');
        info = await nextResult(page, before, 'h.maxArea === 0.01');
        assert.ok(info.largestArea <= 0.01 * (1 + 1e-9), `largest area ${info.largestArea}`);
        assert.ok(info.smallestAngle >= 20 - 1e-9);
        before = info.run;
        await page.$eval('#dl-min-angle', (el) => {
          el.value = '28';
          el.dispatchEvent(new Event('input', { bubbles: true }));
          el.dispatchEvent(new Event('change', { bubbles: true }));
        });
        info = await nextResult(page, before, 'h.angleBound === 28');
        t.diagnostic(`${name} quality 28°: ${JSON.stringify(info)}`);
        assert.ok(info.smallestAngle >= 28 - 1e-9 || info.unrefinedCount > 0, `smallest angle ${info.smallestAngle}`);
        const q = new URL(page.url()).searchParams;
        assert.deepEqual([q.get('mode'), q.get('angle'), q.get('area')], ['quality', '28', '0.01']);
        assert.equal(await page.textContent('#dl-min-angle-value'), '28°');
        // Keeping the boundary whole (Triangle's -Y): refinement splits no ring edge, so the
        // constrained edges are the polygon's own; without it the area bound split some.
        assert.ok(info.constrainedEdges > info.polygonEdges, `split ring edges: ${info.constrainedEdges} constrained, ${info.polygonEdges} polygon edges`);
        before = info.run;
        await page.selectOption('#dl-keep', 'boundary');
        info = await nextResult(page, before, 'h.keepSegments === "boundary"');
        t.diagnostic(`${name} quality, boundary kept: ${JSON.stringify(info)}`);
        assert.equal(info.error, null, info.error);
        assert.equal(info.constrainedEdges, info.polygonEdges, 'no point added on a ring edge');
        assert.ok(info.steinerCount > 0 && info.largestArea <= 0.01 * (1 + 1e-9), 'still refined inside');
        assert.match(await page.textContent('#dl-cdt-note'), /boundary's segments are kept whole/);
        assert.equal(new URL(page.url()).searchParams.get('keep'), 'boundary');
        before = info.run;
        await page.selectOption('#dl-keep', 'none');
        info = await nextResult(page, before, 'h.keepSegments === "none"');
        assert.equal(new URL(page.url()).searchParams.get('keep'), null);
        // A .poly graph meshed within its segments, its hole left out.
        before = info.run;
        await page.fill('#dl-max-area', '');
        await openFile(page, 'box.poly', BOX_POLY);
        info = await nextResult(page, before, 'h.graph === true && h.maxArea === null');
        t.diagnostic(`${name} box.poly meshed: ${JSON.stringify(info)}`);
        assert.equal(info.error, null, info.error);
        assert.ok(info.smallestAngle >= 28 - 1e-9, `smallest angle ${info.smallestAngle}`);
        assert.ok(Math.abs((await trianglesShown(page)).area - 8) < 1e-9, 'the box less its hole');
      });

      await t.test(`${name}: the quality options come back from a link (made valid)`, async () => {
        await page.goto(`${base}?view=delaunay&mode=quality&angle=50&area=-1&keep=sideways`);
        await settled(page);
        assert.equal(await page.inputValue('#dl-mode'), 'quality');
        assert.equal(await page.inputValue('#dl-keep'), 'none', 'an unknown keep value is none');
        assert.equal(await page.inputValue('#dl-min-angle'), '34');
        assert.equal(await page.inputValue('#dl-max-area'), '');
        assert.equal(new URL(page.url()).searchParams.get('angle'), '34');
        assert.equal(await page.isVisible('#dl-quality-fields'), true);
        const info = await nextResult(page, 0, 'true');
        assert.ok(info.triangles > 0 || (info.error && await page.isVisible('#dl-error')), 'a mesh, or a message saying why not');
        // Back to the points: today's view.
        const run = await page.evaluate(() => window.hullkitDelaunay?.run ?? 0);
        await page.selectOption('#dl-mode', 'unconstrained');
        await page.waitForFunction((r) => (window.hullkitDelaunay?.run ?? 0) > r && document.body.dataset.state === 'ready', run, { timeout: TIMEOUT });
        assert.equal(await page.isVisible('#dl-points-fields'), true);
        assert.equal(await page.isVisible('#dl-polygon-fields'), false);
        assert.doesNotMatch(page.url(), /mode=/);
        const points = await page.evaluate(() => window.hullkitDelaunay);
        assert.equal(points.triangles, 2 * points.n - points.hull - 2);
      });

      await t.test(`${name}: the panel fits (no horizontal overflow) in each mode`, async () => {
        for (const mode of ['constrained', 'quality']) {
          await page.selectOption('#dl-mode', mode);
          await settled(page);
          const overflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
          assert.ok(overflow <= 0, `${mode}: no horizontal scrolling (${overflow} px)`);
          const panel = await page.evaluate(() => {
            const el = document.querySelector('.panel');
            return el.scrollWidth - el.clientWidth;
          });
          assert.ok(panel <= 0, `${mode}: nothing in the panel is wider than it (${panel} px)`);
        }
        const size = await page.locator('#canvas').evaluate((c) => ({ w: c.clientWidth, h: c.clientHeight }));
        const width = viewport.width > 760 ? viewport.width - 320 : viewport.width; // the panel beside it, or under it
        assert.ok(size.w === width && size.h >= 300, `the canvas: ${JSON.stringify(size)}`);
      });
      await page.close();
    }

    await t.test('no console errors, page errors or outside requests', () => {
      assert.deepEqual(errors, []);
    });
  } finally {
    await close();
  }
});
