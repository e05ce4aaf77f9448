// The page's server (scripts/serve.js): redirects keep the query, so that a link written by hand
// (http://host:PORT/?view=delaunay) opens the view it names; it serves the page's files alone, the
// allow-list of scripts/site-files.js, which is checked here against the page's actual imports.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { startServer, MIME_TYPES } from '../../scripts/serve.js';
import { siteFiles } from '../../scripts/site-files.js';
import { request, assertRefused, pageGraph, tempDir, withServer } from './serve-helpers.js';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

let server;
let base;

before(async () => {
  server = await startServer({ port: 0 });
  base = `http://127.0.0.1:${server.address().port}`;
});

after(() => new Promise((resolve) => server.close(resolve)));

async function location(p) {
  const { status, headers } = await request(base, p);
  return { status, location: headers.location ?? null };
}

// ------------------------------------------------------------------ redirects

test('the root redirects to /web/ with its query', async () => {
  assert.deepEqual(await location('/?view=delaunay&n=500'), { status: 302, location: '/web/?view=delaunay&n=500' });
  assert.deepEqual(await location('/'), { status: 302, location: '/web/' });
});

test('a directory without its slash redirects with its query', async () => {
  assert.deepEqual(await location('/web?view=route'), { status: 301, location: '/web/?view=route' });
  assert.deepEqual(await location('/web'), { status: 301, location: '/web/' });
  assert.deepEqual(await location('/web/views'), { status: 301, location: '/web/views/' });
  // Never to another host: "//web" is a protocol-relative URL.
  assert.deepEqual(await location('//web?view=route'), { status: 301, location: '/web/?view=route' });
});

test('following the redirect serves the page', async () => {
  const response = await fetch(`${base}/?view=delaunay`);
  assert.equal(response.status, 200);
  assert.equal(new URL(response.url).pathname, '/web/');
  assert.equal(new URL(response.url).search, '?view=delaunay');
  assert.match(await response.text(), /<html/i);
});

test('GET and HEAD only; HEAD has the headers and no body', async () => {
  const head = await request(base, '/web/main.js', 'HEAD');
  assert.equal(head.status, 200);
  assert.equal(head.body.length, 0);
  assert.equal(Number(head.headers['content-length']), fs.statSync(path.join(ROOT, 'web/main.js')).size);
  for (const method of ['POST', 'PUT', 'DELETE', 'OPTIONS']) {
    const r = await request(base, '/web/main.js', method);
    assert.equal(r.status, 405, method);
    assert.equal(r.headers.allow, 'GET, HEAD');
  }
});

// ------------------------------------------------------------------ what is refused

test('the rest of the checkout is refused', async () => {
  await assertRefused(base, [
    '/build/native/CMakeCache.txt',
    '/build/native/hullkit',
    '/build/wasm/CMakeCache.txt',
    '/build/wasm/glm-include/tiny_gltf.h',
    '/build/wasm/glm-include/glm/glm.hpp',
    '/build/', '/build/wasm/', '/node_modules/', '/wasm/', '/scripts/',
    '/scripts/serve.js',
    '/scripts/site-files.js',
    '/node_modules/three/package.json',
    '/node_modules/three/build/three.cjs',
    '/node_modules/three/examples/jsm/controls/TrackballControls.js',
    '/python/setup.py',
    '/python/pyproject.toml',
    '/package.json',
    '/README.md',
    '/.git/config',
    '/.git/HEAD',
    '/wasm/hullkit.d.ts',
    '/wasm/bindings.cpp',
    '/web/screenshot.png', // the README's image, not the page's
    '/native/', '/tests/js/serve.test.js',
  ]);
  // The Python extension, wherever a build left it.
  const extensions = [];
  const find = (dir) => {
    for (const d of fs.readdirSync(dir, { withFileTypes: true })) {
      if (d.isDirectory() && !d.isSymbolicLink()) find(path.join(dir, d.name));
      else if (d.name.endsWith('.so')) extensions.push('/' + path.relative(ROOT, path.join(dir, d.name)).split(path.sep).join('/'));
    }
  };
  for (const dir of ['build', 'python']) if (fs.existsSync(path.join(ROOT, dir))) find(path.join(ROOT, dir));
  await assertRefused(base, extensions);
});

test('encoded traversal, backslashes, NUL bytes and hidden segments are refused', async () => {
  await assertRefused(base, [
    '/web/%2e%2e/package.json',
    '/web/%2E%2E/package.json',
    '/web/..%2fpackage.json',
    '/web/..%2Fpackage.json',
    '/web/../package.json',
    '/web/%2e%2e%2f%2e%2e%2fetc%2fpasswd',
    '/%2e%2e/etc/passwd',
    '/web/%2e%2e/%2e%2e/%2e%2e/%2e%2e/etc/passwd',
    '/web/%252e%252e/package.json',
    '/web/%252e%252e%252fpackage.json',
    '/web/..\\package.json',
    '/web\\..\\package.json',
    '/web/%5c..%5cpackage.json',
    '/web/..%5cpackage.json',
    '/web/main.js%00',
    '/web/main.js%00.html',
    '/web/%00',
    '/web/./main.js',
    '/web/%2e/main.js',
    '//etc/passwd',
    '/web/%', '/web/%zz',
    '/web/.hidden.js',
    '/%2egit/config',
  ]);
});

test('links inside web/ that lead out of the allowed files are refused', async (t) => {
  const dir = tempDir(t);
  const root = path.join(dir, 'repo');
  const outside = path.join(dir, 'outside');
  fs.mkdirSync(path.join(root, 'web'), { recursive: true });
  fs.mkdirSync(outside);
  fs.writeFileSync(path.join(root, 'web', 'index.html'), '<!doctype html><html></html>\n');
  fs.writeFileSync(path.join(root, 'web', 'ok.js'), 'export {};\n');
  fs.writeFileSync(path.join(root, 'web', 'notes.txt'), 'not a page file\n');
  fs.writeFileSync(path.join(root, 'package.json'), '{}\n');
  fs.writeFileSync(path.join(outside, 'secret.js'), 'export const secret = 1;\n');
  fs.symlinkSync(path.join(outside, 'secret.js'), path.join(root, 'web', 'secret.js'));
  fs.symlinkSync(outside, path.join(root, 'web', 'out'));
  fs.symlinkSync(path.join(root, 'package.json'), path.join(root, 'web', 'package.js'));
  fs.symlinkSync('/etc', path.join(root, 'web', 'etc'));
  fs.symlinkSync(path.join(root, 'web', 'notes.txt'), path.join(root, 'web', 'notes.js'));
  // A declared file may be reached through a link (npm link), but only itself.
  fs.mkdirSync(path.join(outside, 'three', 'build'), { recursive: true });
  fs.writeFileSync(path.join(outside, 'three', 'build', 'three.module.js'), 'export {};\n');
  fs.writeFileSync(path.join(outside, 'three', 'package.json'), '{}\n');
  fs.mkdirSync(path.join(root, 'node_modules'));
  fs.symlinkSync(path.join(outside, 'three'), path.join(root, 'node_modules', 'three'));

  const origin = await withServer(t, { root });
  assert.equal((await request(origin, '/web/ok.js')).status, 200);
  assert.equal((await request(origin, '/web/')).status, 200);
  assert.equal((await request(origin, '/node_modules/three/build/three.module.js')).status, 200);
  await assertRefused(origin, [
    '/web/secret.js',
    '/web/out/secret.js',
    '/web/out/',
    '/web/package.js',
    '/web/etc/passwd',
    '/web/etc/hostname',
    '/web/notes.txt',
    '/web/notes.js',
    '/node_modules/three/package.json',
    '/package.json',
    '/wasm/hullkit.js', // declared, but missing here
  ]);
});

// ------------------------------------------------------------------ a plain folder

test('a folder is served whole at a prefix, nothing outside it', async (t) => {
  const dir = tempDir(t);
  const site = path.join(dir, 'site');
  fs.mkdirSync(path.join(site, 'web'), { recursive: true });
  fs.writeFileSync(path.join(site, 'index.html'), '<!doctype html><title>top</title>\n');
  fs.writeFileSync(path.join(site, 'web', 'index.html'), '<!doctype html><title>page</title>\n');
  fs.writeFileSync(path.join(site, 'web', 'data.bin'), 'bytes');
  fs.writeFileSync(path.join(dir, 'secret.txt'), 'secret\n');
  fs.symlinkSync(path.join(dir, 'secret.txt'), path.join(site, 'web', 'secret.txt'));
  fs.symlinkSync(dir, path.join(site, 'up'));

  const origin = await withServer(t, { folder: site, prefix: '/demo/' });
  assert.deepEqual((await request(origin, '/demo?view=route')).headers.location, '/demo/?view=route');
  assert.match(String((await request(origin, '/demo/?view=route')).body), /<title>top</);
  assert.deepEqual((await request(origin, '/demo/web')).headers.location, '/demo/web/');
  assert.match(String((await request(origin, '/demo/web/')).body), /<title>page</);
  const bin = await request(origin, '/demo/web/data.bin');
  assert.equal(bin.status, 200);
  assert.equal(bin.headers['content-type'], 'application/octet-stream');
  await assertRefused(origin, [
    '/', '/index.html', '/web/',
    '/demo/web/secret.txt', '/demo/up/secret.txt', '/demo/up/',
    '/demo/%2e%2e/secret.txt', '/demo/..%2fsecret.txt', '/demo/web/..\\..\\secret.txt',
  ]);
});

// ------------------------------------------------------------------ what the page needs

test('every file the page loads is served with its MIME type, and the allow-list holds exactly those', async () => {
  const graph = await pageGraph(`${base}/web/`);
  for (const [file, response] of graph) {
    assert.equal(response.headers['content-type'], MIME_TYPES[path.extname(file)], `MIME type of ${file}`);
    assert.equal(response.headers['x-content-type-options'], 'nosniff');
    assert.equal(response.headers['cache-control'], 'no-store');
  }
  const served = [...graph.keys()].sort();
  // The walk reached the worker's imports: the wasm module and its wrapper, and three.js.
  for (const file of ['web/worker.js', 'wasm/hullkit.js', 'build/wasm/hullkit_core.mjs', 'build/wasm/hullkit_core.wasm', 'node_modules/three/build/three.module.js']) {
    assert.ok(served.includes(file), `the walk reaches ${file}`);
  }
  // Nothing missing from the allow-list (the requests above would have failed) and nothing more.
  assert.deepEqual(await siteFiles(ROOT), served, 'scripts/site-files.js lists exactly the files the page loads');
});
