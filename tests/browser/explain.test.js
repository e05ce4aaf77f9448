// "What am I looking at?" and the page's small things, in headless Debian Chromium: each view's
// explanation opens in the page (a modal dialog filled from web/app/explain.js) with its text,
// by keyboard and by touch, closes with Esc (or Close) and gives focus back, fits a desktop
// (1400 × 900) and a phone (390 × 844, touch) screen, and nothing asks for README.md; numbers out
// of range in the URL become the nearest valid value and the URL says so; the step-through
// sliders are labelled, the candidate rule's text is not clipped, legend swatches keep apart
// from their text, and a touch screen is told to pinch. Screenshots of each view with its
// explanation open: $TMPDIR/hullkit-explain/{desktop,phone}-VIEW.png.
//
//   node --test tests/browser/explain.test.js
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { openBrowser } from './helpers.js';
import { EXPLANATIONS } from '../../web/app/explain.js';

const DESKTOP = { width: 1400, height: 900 };
const PHONE = { width: 390, height: 844 };
const TIMEOUT = 30_000;
const SHOTS = path.join(os.tmpdir(), 'hullkit-explain');
const VIEWS = [
  ['hull', '?view=hull&dist=ball&n=60&seed=1'],
  ['delaunay', '?view=delaunay&set=uniform&n=40&seed=1'],
  ['delaunay3', '?view=delaunay3&dist=ball&n=60&seed=1'],
  ['route', '?view=route'],
];

async function settled(page) {
  await page.waitForFunction(() => ['ready', 'error'].includes(document.body.dataset.state), null, { timeout: TIMEOUT, polling: 50 });
  return page.evaluate(() => document.body.dataset.state);
}

/** The text a paragraph of an explanation shows (its HTML without tags and entities). */
const shownText = (html) => html.replace(/<[^>]+>/g, '').replace(/&amp;/g, '&').replace(/\s+/g, ' ').trim();

const dialogOpen = (page) => page.evaluate(() => document.getElementById('explain').open);
const focusIn = (page) => page.evaluate(() => {
  const el = document.activeElement;
  return { inDialog: Boolean(el?.closest('#explain')), explain: el?.dataset?.explain ?? null, id: el?.id ?? '' };
});

/** Checks the open dialog against the entry of `view` and that it fits `viewport`. */
async function checkOpen(page, view, viewport) {
  const entry = EXPLANATIONS[view];
  await page.waitForFunction(() => document.getElementById('explain').open, null, { timeout: 5000 });
  assert.equal(await page.getAttribute('#explain', 'data-explains'), view);
  const dialog = page.getByRole('dialog', { name: entry.title });
  assert.equal(await dialog.isVisible(), true, `a dialog named "${entry.title}"`);
  const text = (await page.innerText('#explain-body')).replace(/\s+/g, ' ');
  for (const { heading, paragraphs } of entry.sections) {
    assert.ok(text.toLowerCase().includes(heading.toLowerCase()), `${view}: heading "${heading}"`);
    for (const p of paragraphs) assert.ok(text.includes(shownText(p)), `${view}: "${shownText(p).slice(0, 60)}…"`);
  }
  assert.equal((await focusIn(page)).inDialog, true, 'focus moves into the dialog');
  const box = await page.locator('#explain').boundingBox();
  assert.ok(box.x >= 0 && box.y >= 0 && box.x + box.width <= viewport.width && box.y + box.height <= viewport.height,
    `${view}: the dialog fits the screen: ${JSON.stringify(box)}`);
  // Its text scrolls inside it: the end of the explanation can be reached.
  const scroll = await page.$eval('#explain-body', (el) => {
    el.scrollTop = el.scrollHeight;
    const last = el.lastElementChild.getBoundingClientRect();
    const frame = el.getBoundingClientRect();
    el.scrollTop = 0;
    return { lastBottom: last.bottom, frameBottom: frame.bottom };
  });
  assert.ok(scroll.lastBottom <= scroll.frameBottom + 1, `${view}: the explanation scrolls to its end: ${JSON.stringify(scroll)}`);
}

/** Shown text of the canvas hint (the hull and route views). */
const hintText = (page) => page.$eval('.overlay-hint', (el) => el.innerText.trim());

test('"What am I looking at?" in the page; URL numbers made valid; stepper labels and legends', { timeout: 300_000 }, async (t) => {
  const { browser, base, errors, watch, close } = await openBrowser();
  fs.mkdirSync(SHOTS, { recursive: true });
  const requested = [];
  const record = (page) => page.on('request', (req) => requested.push(req.url()));
  try {
    await t.test('desktop: each view\'s explanation opens from the keyboard, holds its text and closes with Esc', async () => {
      const page = await browser.newPage({ viewport: DESKTOP, deviceScaleFactor: 1 });
      watch(page);
      record(page);
      for (const [view, query] of VIEWS) {
        await page.goto(`${base}${query}`);
        assert.equal(await settled(page), 'ready');
        assert.deepEqual(await page.$$eval('a[href]', (links) => links.map((a) => a.getAttribute('href')).filter((h) => /readme/i.test(h))), [],
          'no link leaves the page for the README');
        const button = page.locator(`.view-panel[data-for="${view}"] [data-explain="${view}"]`);
        assert.equal(await button.isVisible(), true, `${view}: the button is shown`);
        assert.equal(await button.evaluate((el) => el.tagName), 'BUTTON', 'a button, not a link');
        await button.focus();
        await page.keyboard.press('Enter');
        await checkOpen(page, view, DESKTOP);
        await page.screenshot({ path: path.join(SHOTS, `desktop-${view}.png`) });
        await page.keyboard.press('Escape');
        await page.waitForFunction(() => !document.getElementById('explain').open, null, { timeout: 5000 });
        assert.deepEqual(await focusIn(page), { inDialog: false, explain: view, id: '' }, `${view}: focus returns to the button`);
      }
      // Every view of the view switch has its button and its explanation (a new view adds both).
      const views = await page.$$eval('[data-view-link]', (links) => links.map((a) => a.dataset.viewLink));
      const buttons = await page.$$eval('[data-explain]', (els) => els.map((el) => el.dataset.explain));
      assert.deepEqual([...buttons].sort(), [...views].sort(), 'one "What am I looking at?" per view');
      for (const view of views) assert.ok(EXPLANATIONS[view], `web/app/explain.js explains ${view}`);
      // Close and a click beside the dialog shut it too.
      const button = page.locator('[data-explain="route"]');
      await button.click();
      await checkOpen(page, 'route', DESKTOP);
      await page.click('#explain-close');
      assert.equal(await dialogOpen(page), false, 'Close shuts it');
      assert.equal((await focusIn(page)).explain, 'route');
      await button.click();
      await page.mouse.click(10, DESKTOP.height - 10); // on the backdrop
      assert.equal(await dialogOpen(page), false, 'a click outside shuts it');
      assert.match(await hintText(page), /scroll to zoom · right-drag to pan/, 'mouse wording with a mouse');
      await page.close();
    });

    await t.test('phone (390 × 844, touch): each explanation opens with a tap, fits the screen, closes with Esc', async () => {
      const context = await browser.newContext({ viewport: PHONE, deviceScaleFactor: 1, hasTouch: true, isMobile: true });
      const page = await context.newPage();
      watch(page);
      record(page);
      for (const [view, query] of VIEWS) {
        await page.goto(`${base}${query}`);
        assert.equal(await settled(page), 'ready');
        if (view !== 'delaunay') {
          const hint = await hintText(page);
          assert.match(hint, /pinch to zoom · two-finger drag to pan/, `${view}: touch wording on a touch screen`);
          assert.doesNotMatch(hint, /scroll|right-drag/);
        }
        const button = page.locator(`.view-panel[data-for="${view}"] [data-explain="${view}"]`);
        await button.scrollIntoViewIfNeeded();
        await button.tap();
        await checkOpen(page, view, PHONE);
        // The viewport only: a full-page capture resizes the page and drops the touch emulation.
        await page.screenshot({ path: path.join(SHOTS, `phone-${view}.png`) });
        await page.keyboard.press('Escape');
        await page.waitForFunction(() => !document.getElementById('explain').open, null, { timeout: 5000 });
        assert.equal((await focusIn(page)).explain, view, `${view}: focus returns to the button`);
      }
      await context.close();
    });

    await t.test('out-of-range numbers in the URL become the nearest valid value, and the URL says so', async () => {
      const page = await browser.newPage({ viewport: DESKTOP, deviceScaleFactor: 1 });
      watch(page);
      record(page);
      const param = (key) => new URL(page.url()).searchParams.get(key);

      // Delaunay: n = -5 is 3 points (one triangle), not 0 points "on one line".
      await page.goto(`${base}?view=delaunay&set=uniform&n=-5&seed=2`);
      assert.equal(await settled(page), 'ready', await page.textContent('#dl-error'));
      let info = await page.evaluate(() => window.hullkitDelaunay);
      assert.deepEqual([info.n, info.triangles, info.hull], [3, 1, 3]);
      assert.equal(await page.inputValue('#dl-n'), '3');
      assert.equal(param('n'), '3');
      assert.doesNotMatch(await page.textContent('#dl-status'), /one line/);
      // Too many: the most the view takes; a negative seed: 0.
      await page.goto(`${base}?view=delaunay&set=uniform&n=60000&seed=-3`);
      assert.equal(await settled(page), 'ready', await page.textContent('#dl-error'));
      info = await page.evaluate(() => window.hullkitDelaunay);
      assert.deepEqual([info.n, info.seed], [50_000, 0]);
      assert.deepEqual([await page.inputValue('#dl-n'), await page.inputValue('#dl-seed')], ['50000', '0']);
      assert.deepEqual([param('n'), param('seed')], ['50000', '0']);
      // Typed values the same way.
      const before = info.run;
      await page.fill('#dl-n', '-5');
      await page.press('#dl-n', 'Enter');
      await page.waitForFunction((b) => window.hullkitDelaunay.run > b && document.body.dataset.state === 'ready', before, { timeout: TIMEOUT });
      assert.equal(await page.inputValue('#dl-n'), '3');
      assert.equal(param('n'), '3');

      // Hull: n = -5 is one point; a seed past 2^32 − 1 is 2^32 − 1.
      await page.goto(`${base}?view=hull&dist=ball&n=-5&seed=99999999999`);
      assert.equal(await settled(page), 'ready', await page.textContent('#error'));
      const stats = await page.evaluate(() => window.hullkitStats);
      assert.equal(stats.n, 1);
      assert.deepEqual([await page.inputValue('#n'), await page.inputValue('#seed')], ['1', '4294967295']);
      assert.deepEqual([param('n'), param('seed')], ['1', '4294967295']);
      // Too many: 1 000 000, already in the URL while gift wrapping asks before starting.
      await page.goto(`${base}?view=hull&dist=sphere&n=5000000&algo=giftwrap`);
      await page.waitForSelector('#warning', { state: 'visible', timeout: TIMEOUT });
      assert.equal(await page.inputValue('#n'), '1000000');
      assert.deepEqual([param('n'), param('algo')], ['1000000', 'giftwrap']);

      // Route: no fewer than 1 sample, at most 200; a margin below 0 is 0.
      await page.goto(`${base}?view=route&preset=thin-plate&samples=0&margin=-2`);
      assert.equal(await settled(page), 'ready', await page.textContent('#rt-error'));
      assert.equal((await page.evaluate(() => window.hullkitRoute)).samples, 1);
      assert.deepEqual([await page.inputValue('#rt-samples'), await page.inputValue('#rt-margin')], ['1', '0']);
      assert.deepEqual([param('samples'), param('margin'), param('preset')], ['1', '0', 'thin-plate']);
      await page.goto(`${base}?view=route&samples=5000`);
      assert.equal(await settled(page), 'ready', await page.textContent('#rt-error'));
      assert.equal((await page.evaluate(() => window.hullkitRoute)).samples, 200);
      assert.equal(param('samples'), '200');
      await page.close();
    });

    for (const [name, viewport] of [['desktop', DESKTOP], ['phone', PHONE]]) {
      await t.test(`${name}: the step-through sliders are labelled, the candidate rule is not clipped, swatches keep apart`, async () => {
        const page = await browser.newPage({ viewport, deviceScaleFactor: 1 });
        watch(page);
        record(page);
        await page.goto(`${base}?view=hull&dist=ball&n=60&seed=1`);
        assert.equal(await settled(page), 'ready');
        // The rule's every option fits the select (its text against the room left of the arrow).
        const fits = await page.$eval('#step-scan', (select) => {
          const cs = getComputedStyle(select);
          const ctx = document.createElement('canvas').getContext('2d');
          ctx.font = `${cs.fontStyle} ${cs.fontWeight} ${cs.fontSize} ${cs.fontFamily}`;
          const room = select.clientWidth - parseFloat(cs.paddingLeft) - parseFloat(cs.paddingRight) - 20; // 20 px: the arrow
          return [...select.options].map((o) => ({ text: o.text, width: Math.ceil(ctx.measureText(o.text).width), room, title: o.title }));
        });
        t.diagnostic(`candidate rule: ${JSON.stringify(fits)}`);
        for (const o of fits) {
          assert.ok(o.width <= o.room, `"${o.text}" (${o.width} px) fits the select (${o.room} px)`);
          assert.ok(o.title.length > o.text.length, 'its whole description is its title');
        }
        assert.equal(await page.getByLabel('Candidate rule').count(), 1, 'the rule has a visible label');

        await page.click('#step-start');
        await page.waitForSelector('#step-controls', { state: 'visible', timeout: TIMEOUT });
        await page.click('#step-play'); // pause
        for (const [id, name] of [['step-pos', /position/i], ['step-speed', /speed/i]]) {
          const slider = page.getByRole('slider', { name });
          assert.equal(await slider.getAttribute('id'), id, `#${id} is the slider named ${name}`);
          assert.ok((await slider.getAttribute('aria-label')).length > 5, `#${id} has an aria-label`);
          const label = page.locator(`label[for="${id}"]`);
          assert.equal(await label.isVisible(), true, `#${id} has a visible label`);
          assert.match(await label.innerText(), name);
        }

        // Legends: a gap between each swatch and its text.
        const gaps = await page.$$eval('.step-legend li, .legend li', (items) => items.filter((li) => li.offsetParent).map((li) => {
          const swatch = li.querySelector('.swatch').getBoundingClientRect();
          const range = document.createRange();
          const text = [...li.childNodes].find((n) => n.nodeType === Node.TEXT_NODE && n.textContent.trim());
          range.selectNodeContents(text);
          return { text: text.textContent.trim(), gap: range.getBoundingClientRect().left - swatch.right };
        }));
        assert.ok(gaps.length >= 8, `legend entries found: ${gaps.length}`);
        for (const { text, gap } of gaps) assert.ok(gap >= 4, `"${text}": ${gap} px between swatch and text`);
        await page.close();
      });
    }

    await t.test('nothing asks for README.md; no console errors, page errors or outside requests', () => {
      assert.ok(requested.length > 20, `requests seen: ${requested.length}`);
      assert.deepEqual(requested.filter((url) => /readme/i.test(url)), []);
      assert.deepEqual(errors, []);
    });
  } finally {
    await close();
  }
});
