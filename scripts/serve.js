// Dependency-free static file server for the hullkit repository root.
//
//   node scripts/serve.js            -> http://localhost:8080/  (PORT / HOST override)
//
// Also usable as a library (the browser test starts it on an ephemeral port):
//   import { startServer } from './scripts/serve.js';
//   const server = await startServer({ port: 0, root });
import http from 'node:http';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

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
    ...headers,
  });
  res.end(res.req.method === 'HEAD' ? undefined : text);
}

/**
 * Map a request path onto a file system path inside `root`, or return null
 * when the request must be refused (escapes the root, hidden path segment,
 * NUL bytes, malformed escapes).
 */
export function resolveInsideRoot(root, urlPath) {
  let decoded;
  try {
    decoded = decodeURIComponent(urlPath);
  } catch {
    return null;
  }
  if (decoded.includes('\0')) return null;
  const segments = decoded.split(/[\\/]+/).filter(Boolean);
  // No "..", and no dot-files/dot-directories (.git, .env, ...).
  if (segments.some((s) => s.startsWith('.'))) return null;
  const resolved = path.resolve(root, ...segments);
  if (resolved !== root && !resolved.startsWith(root + path.sep)) return null;
  return resolved;
}

function handler(root) {
  return (req, res) => {
    if (req.method !== 'GET' && req.method !== 'HEAD') {
      send(res, 405, 'Method Not Allowed\n', { Allow: 'GET, HEAD' });
      return;
    }
    let pathname, search;
    try {
      ({ pathname, search } = new URL(req.url, 'http://localhost'));
    } catch {
      send(res, 400, 'Bad Request\n');
      return;
    }
    if (pathname === '/') {
      // The query stays: a hand-written link such as /?view=delaunay keeps its view.
      send(res, 302, `Found: /web/${search}\n`, { Location: `/web/${search}` });
      return;
    }
    const filePath = resolveInsideRoot(root, pathname);
    if (filePath === null) {
      send(res, 404, 'Not Found\n');
      return;
    }
    fs.stat(filePath, (err, stat) => {
      if (err) {
        send(res, 404, 'Not Found\n');
        return;
      }
      if (stat.isDirectory()) {
        if (!pathname.endsWith('/')) {
          // Redirect so that relative URLs inside index.html resolve correctly.
          send(res, 301, 'Moved Permanently\n', { Location: pathname + '/' + search });
          return;
        }
        serveFile(req, res, path.join(filePath, 'index.html'));
        return;
      }
      serveFile(req, res, filePath, stat);
    });
  };
}

function serveFile(req, res, filePath, knownStat) {
  const withStat = (stat) => {
    if (!stat.isFile()) {
      send(res, 404, 'Not Found\n');
      return;
    }
    const type = MIME_TYPES[path.extname(filePath).toLowerCase()] ?? 'application/octet-stream';
    const headers = {
      'Content-Type': type,
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
  };
  if (knownStat) withStat(knownStat);
  else {
    fs.stat(filePath, (err, stat) => {
      if (err) send(res, 404, 'Not Found\n');
      else withStat(stat);
    });
  }
}

/**
 * Start the static server. Resolves with the listening http.Server
 * (use `server.address().port` when started with port 0).
 */
export function startServer({ port = 8080, root = DEFAULT_ROOT, host = '127.0.0.1' } = {}) {
  const absRoot = path.resolve(root);
  const server = http.createServer(handler(absRoot));
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
  if (!Number.isInteger(port) || port < 0 || port > 65535) {
    console.error(`serve.js: invalid PORT ${JSON.stringify(process.env.PORT)}`);
    process.exit(2);
  }
  startServer({ port, host }).then(
    (server) => {
      console.log(`hullkit page: http://localhost:${server.address().port}/`);
    },
    (err) => {
      console.error(`serve.js: cannot listen on ${host}:${port}: ${err.message}`);
      process.exit(1);
    },
  );
}
