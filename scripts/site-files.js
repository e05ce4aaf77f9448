// The files the page needs, declared once: the dev server (scripts/serve.js) serves these and
// nothing else, and the static site (scripts/build-site.js → build/site/) holds exactly these.
//
// Paths are relative to the repository root and keep their place in the site, so the page's
// relative URLs (../wasm/hullkit.js, ../build/wasm/hullkit_core.mjs, the import map's
// ../node_modules/three/...) resolve the same way under the dev server and on any static host.
// tests/js/serve.test.js checks this list against the page's actual imports: a new import of
// three.js or of the wasm wrapper fails there until its file is added below.
import fs from 'node:fs/promises';
import path from 'node:path';

/**
 * Folders whose files of these extensions are all the page's own: its HTML, modules and styles.
 * (The page uses no image file: its icon is a data: URL, and web/screenshot.png is the README's.)
 */
export const SITE_DIRS = Object.freeze([
  Object.freeze({ dir: 'web', extensions: Object.freeze(['.html', '.js', '.css']) }),
]);

/** Single files from elsewhere in the repository that the page or its worker imports. */
export const SITE_FILES = Object.freeze([
  // The npm package's wrapper, imported by web/worker.js, and the modules it imports.
  'wasm/hullkit.js',
  'wasm/internal.js',
  'wasm/delaunay.js',
  'wasm/delaunay3.js',
  'wasm/nd.js',
  'wasm/constrained.js',
  'wasm/route.js',
  // The Emscripten loader and the module it fetches next to itself.
  'build/wasm/hullkit_core.mjs',
  'build/wasm/hullkit_core.wasm',
  // three.js: the import map's "three" and the one addon used ("three/addons/" →
  // examples/jsm/), with their relative imports.
  'node_modules/three/build/three.module.js',
  'node_modules/three/build/three.core.js',
  'node_modules/three/examples/jsm/controls/OrbitControls.js',
]);

/**
 * A request path ("/web/main.js", still percent-encoded) as a path relative to the served root
 * ("web/main.js"; "" for the root itself), or null when it must be refused: a malformed escape,
 * a NUL byte, a backslash, or a ".", ".." or hidden (".git") segment, whether written plainly or
 * encoded. Empty segments ("//") are dropped.
 */
export function relativeRequestPath(urlPath) {
  let decoded;
  try {
    decoded = decodeURIComponent(urlPath);
  } catch {
    return null;
  }
  if (decoded.includes('\0') || decoded.includes('\\')) return null;
  const segments = decoded.split('/').filter(Boolean);
  if (segments.some((s) => s.startsWith('.'))) return null;
  return segments.join('/');
}

/** Whether `child` is `parent` or lies inside it (both absolute, resolved). */
function isInside(parent, child) {
  return child === parent || child.startsWith(parent + path.sep);
}

async function realpathOrNull(p) {
  try {
    return await fs.realpath(p);
  } catch {
    return null;
  }
}

async function statOrNull(p) {
  try {
    return await fs.stat(p);
  } catch {
    return null;
  }
}

/**
 * What may be served from a folder: `lookup(rel)` resolves a relative path (as made by
 * relativeRequestPath) to {real, stat} (real: the resolved real path) or null when the path is
 * refused or missing. Every real path is resolved with fs.realpath, so a symbolic link is followed
 * only to a place that is itself allowed.
 *
 *   allowList(root)  the page's files of the repository at `root` (SITE_DIRS and SITE_FILES)
 *   plainFolder(dir) any file inside `dir` (a built site), nothing outside it
 */
export function allowList(root) {
  root = path.resolve(root);
  const declared = new Set(SITE_FILES);
  const dirOf = (rel) => SITE_DIRS.find(({ dir }) => rel === dir || rel.startsWith(dir + '/'));
  const extensionAllowed = (entry, file) => entry.extensions.includes(path.extname(file).toLowerCase());

  /** Whether a real path is one of the declared files or a page file inside a declared folder. */
  async function realAllowed(real, stat) {
    for (const file of SITE_FILES) {
      if ((await realpathOrNull(path.join(root, file))) === real) return true;
    }
    for (const entry of SITE_DIRS) {
      const dirReal = await realpathOrNull(path.join(root, entry.dir));
      if (dirReal && isInside(dirReal, real) && (stat.isDirectory() || extensionAllowed(entry, real))) return true;
    }
    return false;
  }

  return {
    async lookup(rel) {
      const entry = dirOf(rel);
      if (!declared.has(rel) && !entry) return null;
      const real = await realpathOrNull(path.join(root, rel));
      const stat = real && (await statOrNull(real));
      if (!stat || !(stat.isFile() || (entry && stat.isDirectory()))) return null;
      // The name asked for must be a page file too, not only what it points to.
      if (entry && stat.isFile() && !declared.has(rel) && !extensionAllowed(entry, rel)) return null;
      return (await realAllowed(real, stat)) ? { real, stat } : null;
    },
  };
}

export function plainFolder(dir) {
  dir = path.resolve(dir);
  return {
    async lookup(rel) {
      const dirReal = await realpathOrNull(dir);
      const real = await realpathOrNull(path.join(dir, rel));
      if (!dirReal || !real || !isInside(dirReal, real)) return null;
      const stat = await statOrNull(real);
      return stat && (stat.isFile() || stat.isDirectory()) ? { real, stat } : null;
    },
  };
}

/**
 * Every file of the site, as sorted paths relative to `root`, each checked by allowList(root)
 * exactly as the server checks a request. Throws when a declared file is missing (the wasm module
 * or three.js not built or installed yet). Files under SITE_DIRS that the server would refuse
 * (hidden names, other extensions, links out of the folder) are left out.
 */
export async function siteFiles(root) {
  root = path.resolve(root);
  const allowed = allowList(root);
  const files = [];
  for (const file of SITE_FILES) {
    if (!(await allowed.lookup(file))?.stat.isFile()) {
      throw new Error(`${file} is missing (build the wasm module and install the npm dependencies: npm run build)`);
    }
    files.push(file);
  }
  const walk = async (rel) => {
    for (const dirent of await fs.readdir(path.join(root, rel), { withFileTypes: true })) {
      const child = `${rel}/${dirent.name}`;
      if (relativeRequestPath(child) !== child) continue; // hidden or otherwise unservable name
      const found = await allowed.lookup(child);
      if (!found) continue;
      if (found.stat.isDirectory()) {
        if (dirent.isDirectory()) await walk(child); // a link to a folder is not walked twice
      } else {
        files.push(child);
      }
    }
  };
  for (const { dir } of SITE_DIRS) await walk(dir);
  return [...new Set(files)].sort();
}
