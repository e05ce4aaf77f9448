// The page's server (scripts/serve.js): redirects keep the query, so that a link written by hand
// (http://host:PORT/?view=delaunay) opens the view it names; files outside the root are refused.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { startServer } from '../../scripts/serve.js';

let server;
let base;

before(async () => {
  server = await startServer({ port: 0 });
  base = `http://127.0.0.1:${server.address().port}`;
});

after(() => new Promise((resolve) => server.close(resolve)));

async function location(path) {
  const response = await fetch(base + path, { redirect: 'manual' });
  await response.arrayBuffer();
  return { status: response.status, location: response.headers.get('location') };
}

test('the root redirects to /web/ with its query', async () => {
  assert.deepEqual(await location('/?view=delaunay&n=500'), { status: 302, location: '/web/?view=delaunay&n=500' });
  assert.deepEqual(await location('/'), { status: 302, location: '/web/' });
});

test('a directory without its slash redirects with its query', async () => {
  assert.deepEqual(await location('/web?view=route'), { status: 301, location: '/web/?view=route' });
  assert.deepEqual(await location('/web'), { status: 301, location: '/web/' });
});

test('following the redirect serves the page', async () => {
  const response = await fetch(`${base}/?view=delaunay`);
  assert.equal(response.status, 200);
  assert.equal(new URL(response.url).pathname, '/web/');
  assert.equal(new URL(response.url).search, '?view=delaunay');
  assert.match(await response.text(), /<html/i);
});

test('paths outside the root and hidden files are refused', async () => {
  for (const path of ['/%2e%2e/etc/passwd', '/.git/config', '/web/%00']) {
    const response = await fetch(base + path, { redirect: 'manual' });
    await response.arrayBuffer();
    assert.equal(response.status, 404, path);
  }
});
