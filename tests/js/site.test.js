// The static site (scripts/build-site.js): the allow-list's files and nothing else, copied (no
// links), and a page whose URLs all resolve inside the site when a plain static server mounts it
// under a sub-path. tests/browser/site.test.js loads build/site/ in Chromium.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { buildSite, SITE_EXTRAS } from '../../scripts/build-site.js';
import { siteFiles } from '../../scripts/site-files.js';
import { pageGraph, request, tempDir, withServer } from './serve-helpers.js';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

/** Every entry under `dir`, as sorted relative paths (folders left out, links kept as entries). */
function listTree(dir, rel = '') {
  return fs.readdirSync(path.join(dir, rel), { withFileTypes: true }).flatMap((d) => {
    const child = rel ? `${rel}/${d.name}` : d.name;
    return d.isDirectory() ? listTree(dir, child) : [child];
  }).sort();
}

test('the site holds the allow-list\'s files, copied, and a redirect to web/', async (t) => {
  const out = path.join(tempDir(t), 'site');
  const written = await buildSite({ out });
  const expected = [...(await siteFiles(ROOT)), ...SITE_EXTRAS].sort();
  assert.deepEqual(written, expected);
  assert.deepEqual(listTree(out), expected, 'nothing else in the folder');
  for (const file of await siteFiles(ROOT)) {
    assert.ok(fs.lstatSync(path.join(out, file)).isFile(), `${file} is a file, not a link`);
    assert.ok(fs.readFileSync(path.join(out, file)).equals(fs.readFileSync(path.join(ROOT, file))), `${file} copied as is`);
  }
  assert.match(fs.readFileSync(path.join(out, 'index.html'), 'utf8'), /location\.replace\('web\/' \+ location\.search/);
});

test('served under /demo/ by a plain static server, every URL of the page resolves inside the site', async (t) => {
  const out = path.join(tempDir(t), 'site');
  await buildSite({ out });
  const origin = await withServer(t, { folder: out, prefix: '/demo/' });
  const graph = await pageGraph(`${origin}/demo/web/?view=route`, `${origin}/demo/`);
  assert.deepEqual([...graph.keys()].sort(), await siteFiles(ROOT));
  const top = await request(origin, '/demo/?view=delaunay');
  assert.equal(top.status, 200);
  assert.match(String(top.body), /url=web\//);
});

test('a rebuild replaces an earlier site; other folders are never emptied', async (t) => {
  const dir = tempDir(t);
  const out = path.join(dir, 'site');
  await buildSite({ out });
  fs.writeFileSync(path.join(out, 'web', 'stale.js'), '');
  await buildSite({ out });
  assert.equal(fs.existsSync(path.join(out, 'web', 'stale.js')), false, 'a stale file is gone');

  const other = path.join(dir, 'other');
  fs.mkdirSync(other);
  fs.writeFileSync(path.join(other, 'keep.txt'), 'keep');
  await assert.rejects(buildSite({ out: other }), /not a site built before/);
  assert.equal(fs.readFileSync(path.join(other, 'keep.txt'), 'utf8'), 'keep');
  await assert.rejects(buildSite({ out: ROOT }), /holds the repository/);
  await assert.rejects(buildSite({ out: path.dirname(ROOT) }), /holds the repository/);
});
