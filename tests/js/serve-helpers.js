// Shared by tests/js/serve.test.js and tests/js/site.test.js: servers on temporary folders, raw
// HTTP requests, and the walk over everything the page loads (its HTML, import map, styles and
// modules, resolved as the browser would), fetched from a running server.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import ts from 'typescript';
import { startServer } from '../../scripts/serve.js';

/** A temporary folder, removed when test `t` ends. */
export function tempDir(t) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'hullkit-serve-'));
  t.after(() => fs.rmSync(dir, { recursive: true, force: true }));
  return dir;
}

/** startServer(options) on a free port, closed when test `t` ends: resolves with its origin. */
export async function withServer(t, options) {
  const server = await startServer({ port: 0, ...options });
  t.after(() => new Promise((resolve) => server.close(resolve)));
  return `http://127.0.0.1:${server.address().port}`;
}

/**
 * One request with the path sent byte for byte (fetch would resolve "/web/%2e%2e/" and
 * backslashes before sending): {status, headers, body (Buffer)}.
 */
export function request(origin, rawPath, method = 'GET') {
  const { hostname, port } = new URL(origin);
  return new Promise((resolve, reject) => {
    const req = http.request({ hostname, port, path: rawPath, method }, (res) => {
      const chunks = [];
      res.on('data', (c) => chunks.push(c));
      res.on('end', () => resolve({ status: res.statusCode, headers: res.headers, body: Buffer.concat(chunks) }));
    });
    req.on('error', reject);
    req.end();
  });
}

/** Asserts that each path is answered 404 by the server at `origin`. */
export async function assertRefused(origin, paths) {
  for (const p of paths) {
    const { status } = await request(origin, p);
    assert.equal(status, 404, `${p} must be refused`);
  }
}

/** The import map of an HTML text: {specifier: address}. */
function importMapOf(html) {
  const maps = [...html.matchAll(/<script\b[^>]*\btype\s*=\s*["']?importmap["']?[^>]*>([\s\S]*?)<\/script>/gi)];
  assert.ok(maps.length <= 1, 'one import map');
  return maps.length ? JSON.parse(maps[0][1]).imports ?? {} : {};
}

/** The URLs an HTML text loads (scripts, style sheets, icons, images), not links to follow. */
function htmlReferences(html) {
  const refs = [];
  for (const [tag] of html.matchAll(/<(?:script|link|img|source)\b[^>]*>/gi)) {
    const attr = (name) => tag.match(new RegExp(`\\b${name}\\s*=\\s*"([^"]*)"`, 'i'))?.[1];
    if (/^<link/i.test(tag) && !/\b(stylesheet|icon|modulepreload|preload|manifest)\b/i.test(attr('rel') ?? '')) continue;
    const ref = attr('src') ?? attr('href');
    if (ref !== undefined) refs.push(ref);
  }
  return refs;
}

/** What a CSS text loads: url(...) and @import. */
function cssReferences(css) {
  return [...css.matchAll(/url\(\s*(['"]?)([^'")]+)\1\s*\)|@import\s+(['"])([^'"]+)\3/g)].map((m) => m[2] ?? m[4]);
}

/**
 * The module specifiers a JavaScript text loads, from its syntax tree (comments and JSDoc types
 * such as import('./hullkit.d.ts') are not imports): static imports and re-exports, import()
 * of a string, and new URL('...', import.meta.url) (workers, the wasm file, a dynamic import of
 * a computed URL).
 */
function jsReferences(text, fileName) {
  const source = ts.createSourceFile(fileName, text, ts.ScriptTarget.Latest, false, ts.ScriptKind.JS);
  const specs = [];
  const isMetaUrl = (n) => n && ts.isPropertyAccessExpression(n) && n.name.text === 'url' && ts.isMetaProperty(n.expression);
  const visit = (node) => {
    if ((ts.isImportDeclaration(node) || ts.isExportDeclaration(node)) && node.moduleSpecifier) {
      specs.push({ spec: node.moduleSpecifier.text, kind: 'module' });
    } else if (ts.isCallExpression(node) && node.expression.kind === ts.SyntaxKind.ImportKeyword && ts.isStringLiteralLike(node.arguments[0])) {
      specs.push({ spec: node.arguments[0].text, kind: 'module' });
    } else if (ts.isNewExpression(node) && ts.isIdentifier(node.expression) && node.expression.text === 'URL'
      && node.arguments?.length === 2 && ts.isStringLiteralLike(node.arguments[0]) && isMetaUrl(node.arguments[1])) {
      specs.push({ spec: node.arguments[0].text, kind: 'url' });
    }
    ts.forEachChild(node, visit);
  };
  visit(source);
  return specs;
}

/** A module specifier resolved as the browser would with this import map, or null for node: ones. */
function resolveSpecifier(spec, kind, parentUrl, importMap, pageUrl) {
  if (kind === 'url' || /^(\.{0,2}\/)/.test(spec)) return new URL(spec, parentUrl).href;
  if (spec.startsWith('node:')) return null; // wasm/hullkit.js reads the .wasm itself under Node only
  if (Object.hasOwn(importMap, spec)) return new URL(importMap[spec], pageUrl).href;
  const prefix = Object.keys(importMap).filter((k) => k.endsWith('/') && spec.startsWith(k)).sort((a, b) => b.length - a.length)[0];
  assert.ok(prefix, `bare specifier "${spec}" in ${parentUrl} is not in the page's import map`);
  return new URL(importMap[prefix] + spec.slice(prefix.length), pageUrl).href;
}

/**
 * Everything the page at `pageUrl` loads, fetched from the server and followed: a Map from each
 * file's path relative to `mount` (where the files are served; "index.html" for a folder URL) to
 * its response. Each file must come back 200 from inside `mount`.
 */
export async function pageGraph(pageUrl, mount = new URL('/', pageUrl).href) {
  const files = new Map();
  const seen = new Set();
  const queue = [[pageUrl, 'the page']];
  let importMap = {};
  while (queue.length) {
    const [url, from] = queue.shift();
    if (seen.has(url)) continue;
    seen.add(url);
    assert.ok(url.startsWith(mount), `${url} (loaded by ${from}) is outside ${mount}`);
    const u = new URL(url);
    const response = await request(u.origin, u.pathname + u.search);
    assert.equal(response.status, 200, `${u.pathname} (loaded by ${from}) must be served`);
    const rel = url.slice(mount.length).replace(/[?#].*$/, '');
    files.set(rel === '' || rel.endsWith('/') ? `${rel}index.html` : rel, response);
    const text = response.body.toString('utf8');
    const type = response.headers['content-type'];
    const add = (ref) => queue.push([ref, u.pathname]);
    if (type.startsWith('text/html')) {
      importMap = importMapOf(text);
      for (const ref of htmlReferences(text)) if (!ref.startsWith('data:')) add(new URL(ref, url).href);
    } else if (type.startsWith('text/css')) {
      for (const ref of cssReferences(text)) if (!ref.startsWith('data:')) add(new URL(ref, url).href);
    } else if (type.startsWith('text/javascript')) {
      for (const { spec, kind } of jsReferences(text, u.pathname)) {
        const resolved = resolveSpecifier(spec, kind, url, importMap, pageUrl);
        if (resolved !== null) add(resolved);
      }
    }
  }
  return files;
}
