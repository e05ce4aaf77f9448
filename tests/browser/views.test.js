// The page's views in headless Debian Chromium (the Delaunay 3D view here only at phone width; the
// rest of it in delaunay3.test.js): each opens from its URL and from the view
// switch, draws on the canvas (pixels, at desktop and phone width) with no console error,
// back/forward move between views; the Delaunay view's counts obey 2n − h − 2; the Route view's
// thin plate is a hit that 20-step sampling misses; its turning presets show the verdicts of
// hullkit.checkRoute, a waypoint's yaw ring turns it and a link keeps the turn. Saves
// docs/hull.png, docs/delaunay.png and docs/route.png.
//
//   node --test tests/browser/
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { ROOT, openBrowser, decodePng, pixel, averageColor } from './helpers.js';
import createHullkit from '../../wasm/hullkit.js';
import { presetScene } from '../../web/route-scenes.js';

const DESKTOP = { width: 1280, height: 800 };
const PHONE = { width: 390, height: 844 };
const TIMEOUT = 30_000;
const DOCS = path.join(ROOT, 'docs');

/** Pixel counts of a canvas screenshot: differing from the background, and by colour family. */
function census(img, region = { x0: 0, y0: 0, x1: img.width, y1: img.height }) {
  const background = averageColor(img, 2, img.height - 10, 8, 8); // bottom-left corner
  const counts = { total: 0, differing: 0, teal: 0, amber: 0, green: 0, red: 0, violet: 0, pink: 0, grey: 0 };
  for (let y = region.y0; y < region.y1; y++) {
    for (let x = region.x0; x < region.x1; x++) {
      const [r, g, b] = pixel(img, x, y);
      counts.total++;
      if (Math.abs(r - background[0]) + Math.abs(g - background[1]) + Math.abs(b - background[2]) > 30) counts.differing++;
      if (g - r > 40 && b - r > 40) counts.teal++;
      if (r > 190 && g > 120 && g < 220 && b < 130 && r - b > 100) counts.amber++;
      if (g > 110 && g - r > 40 && g - b > 25) counts.green++;
      if (r > 110 && r - g > 60 && r - b > 50) counts.red++;
      if (r > 120 && b > 150 && g < 0.8 * Math.min(r, b)) counts.violet++;
      if (r > 200 && g < 150 && b > 120 && b < 200) counts.pink++;
      if (r > 120 && Math.abs(r - g) < 20 && Math.abs(g - b) < 30 && b > 130) counts.grey++;
    }
  }
  return counts;
}

async function settled(page) {
  await page.waitForFunction(() => ['ready', 'error'].includes(document.body.dataset.state), null, { timeout: TIMEOUT, polling: 50 });
  return page.evaluate(() => document.body.dataset.state);
}

async function canvasImage(page) {
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  return decodePng(await page.locator('#canvas').screenshot());
}

/** The Delaunay stats panel as numbers. */
async function delaunayCounts(page) {
  const read = (id) => page.$eval(id, (el) => Number(el.textContent.replace(/,/g, '')));
  return { n: await read('#dl-stat-n'), triangles: await read('#dl-stat-triangles'), hull: await read('#dl-stat-hull'), duplicates: await read('#dl-stat-dup') };
}

/** Waits for run > `before` of the given window hook. */
async function nextRun(page, hook, before) {
  await page.waitForFunction(([h, b]) => (window[h]?.run ?? 0) > b && document.body.dataset.state !== 'computing', [hook, before], { timeout: TIMEOUT, polling: 50 });
  return page.evaluate((h) => window[h], hook);
}

test('the hull, Delaunay and route views', { timeout: 120_000 }, async (t) => {
  const { browser, base, errors, watch, close } = await openBrowser();
  fs.mkdirSync(DOCS, { recursive: true });
  try {
    const page = await browser.newPage({ viewport: DESKTOP, deviceScaleFactor: 1 });
    watch(page);

    await t.test('?view=delaunay opens the Delaunay view and draws both panes', async () => {
      await page.goto(`${base}?view=delaunay&set=uniform&n=500&seed=3`);
      assert.equal(await settled(page), 'ready', await page.textContent('#dl-error'));
      assert.equal(await page.evaluate(() => document.body.dataset.view), 'delaunay');
      assert.equal(await page.isVisible('#dl-controls'), true);
      assert.equal(await page.isVisible('#controls'), false, 'the hull controls are hidden');
      const img = await canvasImage(page);
      const half = Math.floor(img.width / 2);
      const left = census(img, { x0: 0, y0: 0, x1: half, y1: img.height });
      const right = census(img, { x0: half, y0: 0, x1: img.width, y1: img.height });
      t.diagnostic(`delaunay panes: left ${JSON.stringify(left)} right ${JSON.stringify(right)}`);
      assert.ok(left.teal > 0.05 * left.total, 'the shaded lower hull faces fill the 3D pane');
      assert.ok(left.amber > 200 && right.amber > 200, 'lifted and planar points are drawn');
      assert.ok(right.differing > 0.15 * right.total, 'the triangulation covers the plane pane');
    });

    await t.test('Delaunay: triangles = 2n − h − 2 for every point set, clicks add points', async () => {
      const sets = [['uniform', 500], ['gaussian', 400], ['grid', 144], ['circle', 60], ['figure1', 1024]];
      for (const [set, n] of sets) {
        const before = await page.evaluate(() => window.hullkitDelaunay?.run ?? 0);
        await page.selectOption('#dl-set', set);
        await page.fill('#dl-n', String(n));
        await page.click('#dl-compute');
        const info = await nextRun(page, 'hullkitDelaunay', before);
        const c = await delaunayCounts(page);
        t.diagnostic(`${set}: ${JSON.stringify(c)} (${info.ms.toFixed(1)} ms)`);
        assert.equal(c.n, n, `${set}: n`);
        assert.equal(c.duplicates, 0);
        assert.ok(c.hull >= 3 && c.hull <= n, `${set}: hull size ${c.hull}`);
        assert.equal(c.triangles, 2 * c.n - c.hull - 2, `${set}: a triangulation of n points with h on the hull has 2n − h − 2 triangles`);
        if (set === 'circle') assert.equal(c.hull, n, 'every point on a circle is a hull point');
        if (set === 'grid') assert.equal(c.hull, 44, 'a 12 × 12 grid has 44 boundary points');
      }
      // A click in the plane pane adds a point (and keeps the count law).
      const before = await page.evaluate(() => window.hullkitDelaunay.run);
      const box = await page.locator('.pane-2d').boundingBox();
      await page.mouse.click(box.x + box.width * 0.52, box.y + box.height * 0.47);
      const info = await nextRun(page, 'hullkitDelaunay', before);
      const c = await delaunayCounts(page);
      assert.equal(info.added, 1);
      assert.equal(c.n, 1025);
      assert.equal(c.triangles, 2 * c.n - c.hull - 2);
      assert.match(page.url(), /add=/, 'the clicked point is kept in the URL');
      // Back: the state before the click (the same counts as then); forward: the click again.
      let run = info.run;
      await page.goBack();
      const back = await nextRun(page, 'hullkitDelaunay', run);
      assert.deepEqual([back.n, back.added, back.set], [1024, 0, 'figure1'], 'back undoes the click');
      assert.equal(await page.inputValue('#dl-set'), 'figure1');
      run = back.run;
      await page.goForward();
      const forward = await nextRun(page, 'hullkitDelaunay', run);
      assert.deepEqual([forward.n, forward.triangles, forward.hull], [1025, c.triangles, c.hull], 'forward redoes it');
    });

    await t.test('Delaunay: the Voronoi toggle and the blended layout draw', async () => {
      const before = await page.evaluate(() => window.hullkitDelaunay.run);
      await page.selectOption('#dl-set', 'uniform');
      await page.fill('#dl-n', '200');
      await page.click('#dl-compute');
      await nextRun(page, 'hullkitDelaunay', before);
      const plain = census(await canvasImage(page)).violet;
      // Hovering a triangle shows its circumcircle, empty of input points.
      const box = await page.locator('.pane-2d').boundingBox();
      await page.mouse.move(box.x + box.width * 0.4, box.y + box.height * 0.55);
      await page.waitForFunction(() => window.hullkitDelaunayHover, null, { timeout: 5000 });
      const hover = await page.evaluate(() => window.hullkitDelaunayHover);
      assert.ok(hover.r > 0 && hover.corners.length === 3, JSON.stringify(hover));
      const xy = await page.evaluate(() => window.hullkitDelaunay.points);
      for (let i = 0; i < xy.length / 2; i++) {
        if (hover.corners.includes(i)) continue;
        assert.ok(Math.hypot(xy[2 * i] - hover.x, xy[2 * i + 1] - hover.y) > hover.r * (1 - 1e-9), `point ${i} inside the circumcircle`);
      }
      const pink = census(await canvasImage(page)).pink;
      t.diagnostic(`circumcircle: ${JSON.stringify(hover)}, ${pink} pink pixels`);
      assert.ok(pink > 100, 'the circumcircle is drawn');
      await page.mouse.move(5, 5);
      const run = await page.evaluate(() => window.hullkitDelaunay.run);
      await page.check('#dl-show-voronoi');
      const info = await nextRun(page, 'hullkitDelaunay', run);
      assert.equal(info.voronoi, true);
      const withCells = census(await canvasImage(page)).violet;
      t.diagnostic(`violet pixels: ${plain} without, ${withCells} with Voronoi cells`);
      assert.ok(withCells > plain + 500, 'Voronoi cells drawn');
      await page.mouse.move(box.x + box.width * 0.4, box.y + box.height * 0.55);
      await page.waitForFunction(() => window.hullkitDelaunayHover, null, { timeout: 5000 });
      await page.screenshot({ path: path.join(DOCS, 'delaunay.png') });
      await page.mouse.move(5, 5);
      await page.selectOption('#dl-layout', 'blend');
      const blended = census(await canvasImage(page));
      assert.ok(blended.teal > 0.03 * blended.total && blended.amber > 100, `blended view draws: ${JSON.stringify(blended)}`);
      assert.match(page.url(), /layout=blend/);
      await page.selectOption('#dl-layout', 'side');
      await page.uncheck('#dl-show-voronoi');
    });

    await t.test('the view switch opens the Route view; the doorway preset draws clear and hit sweeps', async () => {
      await page.click('[data-view-link="route"]');
      assert.equal(await settled(page), 'ready', await page.textContent('#rt-error'));
      assert.match(page.url(), /view=route/);
      assert.equal(await page.evaluate(() => document.body.dataset.view), 'route');
      const info = await page.evaluate(() => window.hullkitRoute);
      t.diagnostic(`doorway: ${JSON.stringify(info)}`);
      assert.equal(info.preset, 'doorway');
      assert.deepEqual(info.legs.map((l) => l.status), ['clear', 'clear', 'hit'], 'through the doorway clear, into the crate a hit');
      assert.equal(info.legs[2].obstacle, 'crate');
      const rows = await page.$$eval('#rt-legs tbody tr', (trs) => trs.map((tr) => tr.dataset.status));
      assert.deepEqual(rows, ['clear', 'clear', 'hit'], 'the table shows one row per leg');
      const c = census(await canvasImage(page));
      t.diagnostic(`route canvas: ${JSON.stringify(c)}`);
      assert.ok(c.green > 2000, 'clear swept hulls drawn green');
      assert.ok(c.red > 300, 'the hit swept hull drawn red');
      await page.screenshot({ path: path.join(DOCS, 'route.png') });
    });

    await t.test('?view=route&preset=thin-plate: a hit that 20-step sampling misses', async () => {
      await page.goto(`${base}?view=route&preset=thin-plate`);
      assert.equal(await settled(page), 'ready', await page.textContent('#rt-error'));
      assert.equal(await page.evaluate(() => document.body.dataset.view), 'route');
      assert.equal(await page.inputValue('#rt-preset'), 'thin-plate');
      const info = await page.evaluate(() => window.hullkitRoute);
      t.diagnostic(`thin plate: ${JSON.stringify(info)}`);
      assert.equal(info.samples, 20);
      assert.equal(info.legs[0].status, 'hit');
      assert.equal(info.legs[0].obstacle, 'plate');
      assert.equal(info.legs[0].sampledHit, false, '20-step sampling finds nothing');
      const [lo, hi] = info.legs[0].fraction;
      // The block's front face (x = 0.2) meets the plate (x = 5.25) at fraction 5.05 / 10.
      assert.ok(lo <= 0.505 && hi >= 0.505 && hi - lo < 1e-6, `first contact in [${lo}, ${hi}]`);
      assert.equal(await page.textContent('#rt-legs tbody tr:first-child td:nth-child(6)'), 'missed');
      const without = census(await canvasImage(page));
      await page.check('#rt-show-samples');
      const withOverlay = census(await canvasImage(page));
      t.diagnostic(`grey pixels: ${without.grey} without, ${withOverlay.grey} with the overlay`);
      assert.ok(withOverlay.grey > without.grey + 300, 'the sampled poses are drawn');
      assert.equal(await page.evaluate(() => window.hullkitRoute.overlay), true);
      assert.match(page.url(), /overlay=1/);
      assert.match(await page.textContent('#rt-status'), /20-step sampling finds 0 of 1: it misses 1/);
    });

    await t.test('Route: the L-shaped part passes around the post, clear', async () => {
      const before = await page.evaluate(() => window.hullkitRoute.run);
      await page.selectOption('#rt-preset', 'l-post');
      const info = await nextRun(page, 'hullkitRoute', before);
      t.diagnostic(`L and post: ${JSON.stringify(info)}`);
      assert.equal(info.clear, true);
      assert.ok(info.legs.every((l) => l.status === 'clear' && Math.abs(l.clearance - 1) < 1e-9), 'clearance 1 on both legs');
    });

    await t.test('Route: a dragged waypoint re-checks; waypoints are added and removed', async () => {
      await page.selectOption('#rt-preset', 'thin-plate');
      await page.uncheck('#rt-show-samples');
      await page.waitForFunction(() => window.hullkitRoute.preset === 'thin-plate' && document.body.dataset.state === 'ready');
      const before = await page.evaluate(() => window.hullkitRoute.run);
      await page.click('#rt-add');
      let info = await nextRun(page, 'hullkitRoute', before);
      assert.equal(info.waypoints, 4);
      assert.equal(await page.isDisabled('#rt-remove'), false, 'the new waypoint is selected');
      const run = info.run;
      await page.click('#rt-remove');
      info = await nextRun(page, 'hullkitRoute', run);
      assert.equal(info.waypoints, 3);
      // Drag the middle waypoint's handle sideways: the check follows.
      const start = await page.evaluate(() => window.hullkitRoute.run);
      const at = await page.evaluate(() => window.hullkitRouteHandle(1));
      assert.ok(at, 'the middle waypoint has a handle');
      await page.mouse.move(at.x, at.y);
      await page.mouse.down();
      await page.mouse.move(at.x - 60, at.y + 40, { steps: 4 });
      await page.mouse.up();
      info = await nextRun(page, 'hullkitRoute', start);
      assert.ok(info.run > start, 'the route was re-checked while dragging');
      assert.match(page.url(), /route=/, 'the dragged route is kept in the URL');
    });

    await t.test('the Hull view from the switch; back/forward move between views', async () => {
      await page.click('[data-view-link="hull"]');
      assert.equal(await settled(page), 'ready');
      assert.equal(await page.evaluate(() => document.body.dataset.view), 'hull');
      assert.match(page.url(), /view=hull/);
      assert.equal(await page.evaluate(() => window.hullkitStats.n), 2000, 'the default hull');
      const hull = census(await canvasImage(page));
      assert.ok(hull.teal > 0.05 * hull.total && hull.amber > 50, `the hull draws: ${JSON.stringify(hull)}`);
      await page.screenshot({ path: path.join(DOCS, 'hull.png') });
      await page.goBack();
      await page.waitForFunction(() => document.body.dataset.view === 'route');
      assert.equal(await page.getAttribute('[data-view-link="route"]', 'aria-current'), 'page');
      assert.equal(await page.isVisible('#rt-controls'), true);
      await page.goForward();
      await page.waitForFunction(() => document.body.dataset.view === 'hull');
      assert.equal(await page.isVisible('#controls'), true);
      assert.equal(await page.isVisible('#rt-controls'), false);
    });

    await t.test('each view draws at phone width (390 × 844)', async () => {
      const phone = await browser.newPage({ viewport: PHONE, deviceScaleFactor: 1 });
      watch(phone);
      await phone.goto(`${base}?view=hull`);
      for (const view of ['hull', 'delaunay', 'delaunay3', 'route']) {
        if (view !== 'hull') await phone.click(`[data-view-link="${view}"]`);
        await phone.waitForFunction((v) => document.body.dataset.view === v, view);
        assert.equal(await settled(phone), 'ready', `${view} at phone width`);
        const size = await phone.locator('#canvas').evaluate((c) => ({ w: c.clientWidth, h: c.clientHeight }));
        assert.ok(size.w === PHONE.width && size.h >= 300, `the canvas spans the phone's width: ${JSON.stringify(size)}`);
        const c = census(await canvasImage(phone));
        t.diagnostic(`${view} at phone width: ${JSON.stringify(c)}`);
        assert.ok(c.differing > 0.1 * c.total, `${view} draws at phone width`);
        const overflow = await phone.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
        assert.ok(overflow <= 0, `no horizontal scrolling (${overflow} px)`);
        await phone.screenshot({ path: path.join(os.tmpdir(), `hullkit-${view}-phone.png`) });
      }
      await phone.close();
    });

    await t.test('no console errors, page errors or outside requests', () => {
      assert.deepEqual(errors, []);
    });
  } finally {
    await close();
  }
});

// ------------------------------------------------------------------ the Route view's turning legs

/** What the page's hook says of each leg, next to what hullkit.checkRoute says of the same scene. */
function assertSameVerdicts(info, expected, what) {
  assert.equal(info.legs.length, expected.legs.length, `${what}: legs`);
  assert.equal(info.clear, expected.clear, `${what}: verdict`);
  expected.legs.forEach((leg, i) => {
    const shown = info.legs[i];
    assert.equal(shown.status, leg.status, `${what}: leg ${i + 1} status`);
    assert.equal(shown.obstacle, leg.obstacle ?? null, `${what}: leg ${i + 1} obstacle`);
    assert.equal(shown.grazing, Boolean(leg.grazing), `${what}: leg ${i + 1} graze`);
    if (leg.status === 'hit') {
      assert.ok(Math.abs(shown.fraction[0] - leg.fraction[0]) < 1e-7, `${what}: leg ${i + 1} first contact ${shown.fraction[0]} vs ${leg.fraction[0]}`);
      assert.deepEqual(shown.rotation?.map((c) => c.toFixed(6)) ?? null, leg.rotation?.map((c) => c.toFixed(6)) ?? null, `${what}: leg ${i + 1} orientation at first contact`);
    }
  });
}

test('the Route view turns the traverse', { timeout: 180_000 }, async (t) => {
  const hullkit = await createHullkit();
  const { browser, base, errors, watch, close } = await openBrowser();
  try {
    const page = await browser.newPage({ viewport: DESKTOP, deviceScaleFactor: 1 });
    watch(page);
    const openRoute = async (query) => {
      await page.goto(`${base}?view=route&${query}`);
      assert.equal(await settled(page), 'ready', await page.textContent('#rt-error'));
      await page.waitForFunction(() => window.hullkitRoute, null, { timeout: TIMEOUT });
      return page.evaluate(() => window.hullkitRoute);
    };
    const sceneShown = () => page.evaluate(() => window.hullkitRouteScene());
    const rowStatuses = () => page.$$eval('#rt-legs tbody tr td:nth-child(2)', (tds) => tds.map((td) => td.textContent));

    await t.test('the crane and doorway presets show the verdicts of hullkit.checkRoute', async () => {
      const cases = [
        ['slewing-crane', ['hit'], 'mast', [10]],
        ['bar-turn', ['clear', 'clear', 'clear'], null, [8, 1, 8]],
        ['bar-turn-late', ['hit'], 'wall left', [8]],
      ];
      let info = await openRoute('preset=slewing-crane');
      const crane = info.legs[0];
      for (const [preset, statuses, obstacle, subintervals] of cases) {
        if (info.preset !== preset) {
          const before = info.run;
          await page.selectOption('#rt-preset', preset);
          info = await nextRun(page, 'hullkitRoute', before);
        }
        t.diagnostic(`${preset}: ${JSON.stringify(info)}`);
        const scene = await sceneShown();
        const { route, margin, ...rest } = scene;
        const { route: presetRoute, margin: presetMargin, ...presetRest } = presetScene(preset);
        assert.deepEqual(rest, presetRest, `${preset}: the page checks the preset's scene`);
        assert.deepEqual([route, margin], [presetRoute, presetMargin], `${preset}: with its route and margin`);
        assert.ok(route.some((w) => !Array.isArray(w) && w.rotation), `${preset}: the route turns`);
        const expected = hullkit.checkRoute(scene, { samples: 20 });
        assertSameVerdicts(info, expected, preset);
        assert.deepEqual(info.legs.map((l) => l.status), statuses, `${preset}: verdicts`);
        if (obstacle) assert.equal(info.legs.find((l) => l.status === 'hit').obstacle, obstacle);
        assert.deepEqual(info.legs.map((l) => l.subintervals), subintervals, `${preset}: sub-intervals drawn per leg`);
        assert.deepEqual(await rowStatuses(), statuses, `${preset}: the legs table`);
        const c = census(await canvasImage(page));
        t.diagnostic(`${preset} canvas: ${JSON.stringify(c)}`);
        if (statuses.includes('hit')) {
          assert.ok(c.red > 1000, `${preset}: the hit leg's sub-interval hulls drawn red`);
          assert.ok(c.amber > 100, `${preset}: the traverse ghosted at first contact`);
        } else {
          assert.ok(c.green > 3000 && c.red < 200, `${preset}: clear legs drawn green`);
        }
      }
      assert.equal(crane.turn, 120);
      // The jib's yaw at first contact: about 90° of the 120° turn (w = cos(yaw / 2)).
      const yaw = (2 * Math.atan2(crane.rotation[3], crane.rotation[0]) * 180) / Math.PI;
      assert.ok(yaw > 85 && yaw < 95, `the load catches the mast at yaw ${yaw}`);
    });

    await t.test('dragging a waypoint\'s yaw ring re-checks the turned route', async () => {
      let info = await openRoute('preset=bar-turn');
      assert.deepEqual(info.yaws, [0, 90, 90, 0]);
      assert.deepEqual(await page.$$eval('#rt-waypoints tbody tr', (trs) => trs.map((tr) => Number(tr.dataset.yaw))), [0, 90, 90, 0]);
      // Turn waypoint 3 (beyond the doorway) back by 90° on its ring: the bar now turns while it
      // passes the doorway.
      const start = info.run;
      const at = await page.evaluate(() => window.hullkitRouteRing(2, 90));
      await page.mouse.move(at.x, at.y);
      await page.mouse.down();
      for (let a = 80; a >= 0; a -= 10) {
        const p = await page.evaluate((deg) => window.hullkitRouteRing(2, deg), a);
        await page.mouse.move(p.x, p.y, { steps: 2 });
      }
      await page.mouse.up();
      // The last check drawn is that of the route as the drag left it (yaw near 0).
      await page.waitForFunction((run) => window.hullkitRoute.run > run && Math.abs(window.hullkitRoute.yaws[2]) < 3 &&
        document.body.dataset.state === 'ready', start, { timeout: TIMEOUT, polling: 50 });
      info = await page.evaluate(() => window.hullkitRoute);
      t.diagnostic(`after turning the ring: ${JSON.stringify(info)}`);
      assert.ok(Math.abs(info.yaws[2]) < 3, `waypoint 3's yaw is about 0°: ${info.yaws[2]}`);
      assert.deepEqual(info.yaws.filter((_, i) => i !== 2), [0, 90, 0], 'the other waypoints keep their yaw');
      assert.deepEqual(info.legs.map((l) => l.status), ['clear', 'hit', 'clear'], 'turning in the doorway hits');
      assert.equal(info.legs[1].obstacle, 'wall left');
      assert.ok(info.legs[1].subintervals >= 7, 'the turning leg is drawn as sub-interval hulls');
      const scene = await sceneShown();
      assertSameVerdicts(info, hullkit.checkRoute(scene, { samples: 20 }), 'ring-turned route');
      assert.match(page.url(), /route=/, 'the turned route is kept in the URL');
      assert.equal(await page.inputValue('#rt-waypoints tbody tr:nth-child(3) input'), String(Number(info.yaws[2].toFixed(2))));
      // Typing a yaw turns the waypoint too: 90° again, and the route is clear again.
      const typed = info.run;
      await page.fill('#rt-waypoints tbody tr:nth-child(3) input', '90');
      await page.press('#rt-waypoints tbody tr:nth-child(3) input', 'Enter');
      info = await nextRun(page, 'hullkitRoute', typed);
      assert.deepEqual(info.yaws, [0, 90, 90, 0]);
      assert.deepEqual(info.legs.map((l) => l.status), ['clear', 'clear', 'clear']);
    });

    await t.test('a link with a turned waypoint restores its rotation', async () => {
      const link = 'preset=bar-turn&route=0,0,0;1.5,0,0,90;7,0,0,30;8.5,0,0';
      await openRoute(link);
      for (const reload of [false, true]) {
        if (reload) {
          await page.reload();
          assert.equal(await settled(page), 'ready');
          await page.waitForFunction(() => window.hullkitRoute, null, { timeout: TIMEOUT });
        }
        const info = await page.evaluate(() => window.hullkitRoute);
        assert.deepEqual(info.yaws, [0, 90, 30, 0], `the yaws from the link${reload ? ' after a reload' : ''}`);
        const scene = await sceneShown();
        assert.deepEqual(scene.route[2], { position: [7, 0, 0], rotation: { axis: [0, 0, 1], degrees: 30 } });
        assert.deepEqual(scene.route[3], [8.5, 0, 0], 'a waypoint without a turn stays [x, y, z]');
        assertSameVerdicts(info, hullkit.checkRoute(scene, { samples: 20 }), 'linked route');
        assert.deepEqual(info.legs.map((l) => l.status), ['clear', 'hit', 'clear']);
        assert.equal(await page.inputValue('#rt-waypoints tbody tr:nth-child(3) input'), '30');
      }
      // The link the page writes for a turn made in it opens the same turn.
      const before = await page.evaluate(() => window.hullkitRoute.run);
      await page.fill('#rt-waypoints tbody tr:nth-child(2) input', '-45.5');
      await page.press('#rt-waypoints tbody tr:nth-child(2) input', 'Enter');
      const turned = await nextRun(page, 'hullkitRoute', before);
      const written = new URL(page.url()).searchParams.get('route');
      assert.equal(written, '0,0,0;1.5,0,0,-45.5;7,0,0,30;8.5,0,0');
      const other = await browser.newPage({ viewport: DESKTOP, deviceScaleFactor: 1 });
      watch(other);
      await other.goto(page.url());
      assert.equal(await settled(other), 'ready');
      await other.waitForFunction(() => window.hullkitRoute);
      const reopened = await other.evaluate(() => window.hullkitRoute);
      assert.deepEqual(reopened.yaws, turned.yaws);
      assert.deepEqual(reopened.legs.map((l) => l.status), turned.legs.map((l) => l.status));
      await other.close();
      // A link without turns still writes (and reads) plain x,y,z waypoints.
      await openRoute('preset=thin-plate&route=0,0,0;10,0.5,0;10,3,0');
      assert.deepEqual((await sceneShown()).route, [[0, 0, 0], [10, 0.5, 0], [10, 3, 0]]);
    });

    await t.test('the legs table shows a graze distinctly', async () => {
      const shown = await page.evaluate(async () => {
        const { legRows, legStatusText } = await import('./views/route-panel.js');
        const graze = { status: 'hit', grazing: true, obstacle: 'post', part: 'bar', triangle: 1, fraction: [0.4682, 0.4683], position: [0, 0, 0], rotation: [0.74, 0, 0, 0.67] };
        const [row] = legRows({ legs: [graze] }, [180], [15]);
        return { text: legStatusText(graze), plain: legStatusText({ ...graze, grazing: undefined }), cell: row.children[1].textContent, grazing: row.dataset.grazing, status: row.dataset.status, title: row.title };
      });
      assert.equal(shown.text, 'hit (graze)');
      assert.equal(shown.plain, 'hit');
      assert.equal(shown.cell, 'hit (graze)');
      assert.deepEqual([shown.status, shown.grazing], ['hit', 'true']);
      assert.match(shown.title, /graze/);
      assert.match(shown.title, /turns 180°, drawn as 15 sub-interval hulls/);
    });

    await t.test('no console errors, page errors or outside requests', () => {
      assert.deepEqual(errors, []);
    });
  } finally {
    await close();
  }
});
