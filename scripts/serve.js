// Dependency-free static file server for the hullkit page.
//
//   node scripts/serve.js             -> http://localhost:8080/  (PORT / HOST override)
//   node scripts/serve.js build/site  -> serves a built site folder as any static host would
//
// From the repository it serves the page's files alone, the allow-list of scripts/site-files.js
// (web/, the wasm module and its wrapper, the three.js files the page imports): everything else
// (build trees, scripts, node_modules, .git, links out of those files) is 404. A folder given on
// the command line (or as `folder`) is served whole, but nothing outside it, through links neither.
//
// Also usable as a library (the browser tests start it on an ephemeral port):
//   import { startServer } from './scripts/serve.js';
//   const server = await startServer({ port: 0, root });                // the page, from a checkout
//   const server = await startServer({ port: 0, folder, prefix: '/demo/' }); // a folder at /demo/
import http from 'node:http';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { allowList, plainFolder, relativeRequestPath } from './site-files.js';

const DEFAULT_ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');

export const MIME_TYPES = {
  '.html': 'text/html; charset=utf-8',
  '.htm': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json; charset=utf-8',
  '.map': 'application/json; charset=utf-8',
  '.wasm': 'application/wasm',
  '.png': 'image/png',
  '.svg': 'image/svg+xml',
  '.ico': 'image/x-icon',
  '.txt': 'text/plain; charset=utf-8',
  '.md': 'text/plain; charset=utf-8',
};

function send(res, status, body, headers = {}) {
  const text = body ?? '';
  res.writeHead(status, {
    'Content-Type': 'text/plain; charset=utf-8',
    'Content-Length': Buffer.byteLength(text),
    'Cache-Control': 'no-store',
    'X-Content-Type-Options': 'nosniff',
    ...headers,
  });
  res.end(res.req.method === 'HEAD' ? undefined : text);
}

/**
 * Request handler. `files.lookup(rel)` decides what exists (see site-files.js); `prefix` is where
 * the files are mounted ("/" or e.g. "/demo/"); `home` the path the prefix itself redirects to
 * ("web/" for the repository), or null to serve the prefix folder's index.html.
 */
function handler(files, prefix, home) {
  return async (req, res) => {
    if (req.method !== 'GET' && req.method !== 'HEAD') {
      send(res, 405, 'Method Not Allowed\n', { Allow: 'GET, HEAD' });
      return;
    }
    // The path exactly as sent (the URL parser would resolve "/web/%2e%2e/" before we could refuse
    // it, and read "//host/..." as a host); the query through the parser, which percent-encodes it.
    let pathname, search;
    try {
      if (!req.url.startsWith('/')) throw new Error('not an origin-form request target');
      pathname = req.url.split('?', 1)[0];
      search = new URL(req.url, 'http://localhost').search;
    } catch {
      send(res, 400, 'Bad Request\n');
      return;
    }
    if (prefix !== '/' && pathname === prefix.slice(0, -1)) {
      send(res, 301, 'Moved Permanently\n', { Location: prefix + search });
      return;
    }
    if (!pathname.startsWith(prefix)) {
      send(res, 404, 'Not Found\n');
      return;
    }
    if (pathname === prefix && home !== null) {
      // The query stays: a hand-written link such as /?view=delaunay keeps its view.
      send(res, 302, `Found: ${prefix}${home}${search}\n`, { Location: `${prefix}${home}${search}` });
      return;
    }
    const rel = relativeRequestPath(pathname.slice(prefix.length));
    let found;
    try {
      found = rel === null ? null : await files.lookup(rel);
      if (found?.stat.isDirectory()) {
        if (!pathname.endsWith('/')) {
          // Redirect so that relative URLs inside index.html resolve correctly. The location is
          // rebuilt from the checked path: "//web" must not send the browser to the host "web".
          const location = prefix + rel.split('/').map(encodeURIComponent).join('/') + '/';
          send(res, 301, 'Moved Permanently\n', { Location: location + search });
          return;
        }
        found = await files.lookup(rel ? `${rel}/index.html` : 'index.html');
      }
    } catch {
      send(res, 500, 'Internal Server Error\n');
      return;
    }
    if (!found?.stat.isFile()) {
      send(res, 404, 'Not Found\n');
      return;
    }
    serveFile(req, res, found.real, found.stat);
  };
}

function serveFile(req, res, filePath, stat) {
  const headers = {
    'Content-Type': MIME_TYPES[path.extname(filePath).toLowerCase()] ?? 'application/octet-stream',
    'Content-Length': stat.size,
    'Cache-Control': 'no-store',
    'X-Content-Type-Options': 'nosniff',
  };
  if (req.method === 'HEAD') {
    res.writeHead(200, headers);
    res.end();
    return;
  }
  const stream = fs.createReadStream(filePath);
  stream.once('open', () => {
    res.writeHead(200, headers);
    stream.pipe(res);
  });
  stream.once('error', () => {
    if (!res.headersSent) send(res, 404, 'Not Found\n');
    else res.destroy();
  });
}

/**
 * Start the static server. Resolves with the listening http.Server (use
 * `server.address().port` when started with port 0).
 *   root    the repository whose page is served (allow-list; `/` redirects to `/web/`)
 *   folder  instead: a folder served whole (a built site; `/` serves its index.html)
 *   prefix  where it is mounted, "/" by default (e.g. "/demo/", as a host serving a sub-path)
 */
export function startServer({ port = 8080, root = DEFAULT_ROOT, folder, prefix = '/', host = '127.0.0.1' } = {}) {
  if (!prefix.startsWith('/') || !prefix.endsWith('/')) throw new Error(`prefix must start and end with "/": ${prefix}`);
  const files = folder === undefined ? allowList(root) : plainFolder(folder);
  const server = http.createServer(handler(files, prefix, folder === undefined ? 'web/' : null));
  return new Promise((resolve, reject) => {
    server.once('error', reject);
    server.listen(port, host, () => {
      server.off('error', reject);
      resolve(server);
    });
  });
}

const isMain = process.argv[1] && import.meta.url === pathToFileURL(path.resolve(process.argv[1])).href;
if (isMain) {
  const port = process.env.PORT !== undefined && process.env.PORT !== '' ? Number(process.env.PORT) : 8080;
  const host = process.env.HOST || '127.0.0.1';
  const folder = process.argv[2];
  if (!Number.isInteger(port) || port < 0 || port > 65535) {
    console.error(`serve.js: invalid PORT ${JSON.stringify(process.env.PORT)}`);
    process.exit(2);
  }
  if (folder !== undefined && !fs.statSync(folder, { throwIfNoEntry: false })?.isDirectory()) {
    console.error(`serve.js: ${folder} is not a folder`);
    process.exit(2);
  }
  startServer({ port, host, folder }).then(
    (server) => {
      console.log(`hullkit page${folder === undefined ? '' : ` (${folder})`}: http://localhost:${server.address().port}/`);
    },
    (err) => {
      console.error(`serve.js: cannot listen on ${host}:${port}: ${err.message}`);
      process.exit(1);
    },
  );
}
