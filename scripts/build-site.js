// Writes the demo page as a static site: build/site/ (or the folder given) holds the files of
// scripts/site-files.js, the same list the dev server serves, and nothing else but a redirecting
// index.html and an empty .nojekyll.
//
//   node scripts/build-site.js [OUT]        (bash scripts/build.sh site; npm run build)
//
// The layout mirrors the repository (web/index.html, wasm/hullkit.js, build/wasm/hullkit_core.*,
// node_modules/three/...) rather than flattening it: the page's modules reach each other by
// relative URLs (../wasm/hullkit.js, ../build/wasm/hullkit_core.mjs, the import map's
// ../node_modules/three/...), and wasm/hullkit.js is the npm package's own file, so mirroring
// needs no rewritten file and the site behaves exactly as the page under `npm start`, at the
// root of a host or under any sub-path. index.html at the top sends a visitor to web/ with the
// query (?view=delaunay) kept. .nojekyll stops GitHub Pages' Jekyll step from dropping
// node_modules/.
import fs from 'node:fs/promises';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { siteFiles } from './site-files.js';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');

export const REDIRECT_HTML = `<!doctype html>
<html lang="en">
<head>
  <meta charset="utf-8">
  <title>hullkit</title>
  <script>location.replace('web/' + location.search + location.hash);</script>
  <meta http-equiv="refresh" content="0; url=web/">
</head>
<body><p><a href="web/">hullkit</a></p></body>
</html>
`;

/** The files written besides those of the allow-list. */
export const SITE_EXTRAS = Object.freeze(['.nojekyll', 'index.html']);

/**
 * Builds the site from the repository at `root` into `out` (emptied first). Resolves with the
 * list of files written, relative to `out`.
 */
export async function buildSite({ root = ROOT, out = path.join(ROOT, 'build', 'site') } = {}) {
  root = path.resolve(root);
  out = path.resolve(out);
  const files = await siteFiles(root);
  await emptySiteFolder(root, out);
  for (const file of files) {
    await fs.mkdir(path.join(out, path.dirname(file)), { recursive: true });
    // The real file's bytes (copyFile follows a link that siteFiles allowed), never a link.
    await fs.copyFile(await fs.realpath(path.join(root, file)), path.join(out, file));
  }
  await fs.writeFile(path.join(out, 'index.html'), REDIRECT_HTML);
  await fs.writeFile(path.join(out, '.nojekyll'), '');
  return [...files, ...SITE_EXTRAS].sort();
}

/** Removes `out` before a build, refusing a folder that holds the repository or is no earlier site. */
async function emptySiteFolder(root, out) {
  if (root === out || root.startsWith(out + path.sep)) throw new Error(`refusing to replace ${out}: it holds the repository`);
  const entries = await fs.readdir(out).catch(() => []);
  if (entries.length > 0 && !entries.includes('.nojekyll')) {
    throw new Error(`refusing to replace ${out}: not empty and not a site built before (no .nojekyll)`);
  }
  await fs.rm(out, { recursive: true, force: true });
}

const isMain = process.argv[1] && import.meta.url === pathToFileURL(path.resolve(process.argv[1])).href;
if (isMain) {
  const out = path.resolve(process.argv[2] ?? path.join(ROOT, 'build', 'site'));
  buildSite({ out }).then(
    (files) => console.log(`build-site: ${files.length} files in ${path.relative(process.cwd(), out) || '.'}`),
    (err) => {
      console.error(`build-site: ${err.message}`);
      process.exit(1);
    },
  );
}
