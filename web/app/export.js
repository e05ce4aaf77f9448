// Files out: the page's results as the files the CLI writes (OBJ, OFF, binary STL, glTF .glb, SVG, JSON),
// built from the flat arrays the worker returns and handed to the browser as a download.
//
// Coordinates are written with String(x), the shortest text that reads back as the same double,
// so an exported hull re-read by `hullkit` (or any reader) has exactly the input's coordinates.

/**
 * The used vertices of an indexed triangle list, renumbered in order of first use:
 * {positions: Float64Array (x y z per vertex), triangles: Uint32Array (into positions)}.
 * `dims` is 3 for xyz input, 2 for xy input (z = 0 is written).
 */
export function compact(coords, triangles, dims = 3) {
  const remap = new Map();
  const out = new Uint32Array(triangles.length);
  const used = [];
  for (let i = 0; i < triangles.length; i++) {
    const v = triangles[i];
    let k = remap.get(v);
    if (k === undefined) {
      k = used.length;
      remap.set(v, k);
      used.push(v);
    }
    out[i] = k;
  }
  const positions = new Float64Array(3 * used.length);
  used.forEach((v, k) => {
    positions[3 * k] = coords[dims * v];
    positions[3 * k + 1] = coords[dims * v + 1];
    positions[3 * k + 2] = dims === 3 ? coords[dims * v + 2] : 0;
  });
  return { positions, triangles: out };
}

const xyzLine = (p, k) => `${p[3 * k]} ${p[3 * k + 1]} ${p[3 * k + 2]}`;

/** OFF text: the header, the vertices, then `3 a b c` per triangle. */
export function offText({ positions, triangles }, comment = '') {
  const nv = positions.length / 3;
  const nt = triangles.length / 3;
  const lines = ['OFF'];
  if (comment) lines.push(`# ${comment}`);
  lines.push(`${nv} ${nt} 0`);
  for (let k = 0; k < nv; k++) lines.push(xyzLine(positions, k));
  for (let t = 0; t < nt; t++) lines.push(`3 ${triangles[3 * t]} ${triangles[3 * t + 1]} ${triangles[3 * t + 2]}`);
  return `${lines.join('\n')}\n`;
}

/** Wavefront OBJ text: `v x y z` lines, then `f a b c` with 1-based indices. */
export function objText({ positions, triangles }, comment = '') {
  const lines = [];
  if (comment) lines.push(`# ${comment}`);
  for (let k = 0; k < positions.length / 3; k++) lines.push(`v ${xyzLine(positions, k)}`);
  for (let t = 0; t < triangles.length / 3; t++) {
    lines.push(`f ${triangles[3 * t] + 1} ${triangles[3 * t + 1] + 1} ${triangles[3 * t + 2] + 1}`);
  }
  return `${lines.join('\n')}\n`;
}

/**
 * Binary STL: an 80-byte header, the triangle count, then per triangle its unit normal and three
 * corners as float32 (STL has no higher precision) and a zero attribute word.
 */
export function stlBytes({ positions, triangles }, header = 'hullkit') {
  const nt = triangles.length / 3;
  const buf = new ArrayBuffer(84 + 50 * nt);
  const bytes = new Uint8Array(buf);
  const title = new TextEncoder().encode(header.slice(0, 80));
  bytes.set(title);
  const view = new DataView(buf);
  view.setUint32(80, nt, true);
  let o = 84;
  for (let t = 0; t < nt; t++) {
    const c = [0, 1, 2].map((j) => 3 * triangles[3 * t + j]);
    const u = [0, 1, 2].map((d) => positions[c[1] + d] - positions[c[0] + d]);
    const w = [0, 1, 2].map((d) => positions[c[2] + d] - positions[c[0] + d]);
    const nrm = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]];
    const len = Math.hypot(...nrm) || 1;
    for (const x of nrm) { view.setFloat32(o, x / len, true); o += 4; }
    for (const ci of c) for (let d = 0; d < 3; d++) { view.setFloat32(o, positions[ci + d], true); o += 4; }
    view.setUint16(o, 0, true);
    o += 2;
  }
  return bytes;
}

/**
 * Binary glTF 2.0 (.glb): one mesh with one triangle primitive, the positions as float32 (glTF
 * has no double positions: rounded to the nearest float, like STL) and uint32 indices, as
 * `hullkit hull -o hull.glb` writes it.
 */
export function glbBytes({ positions, triangles }, name = 'convex hull') {
  const nv = positions.length / 3;
  const ni = triangles.length;
  const floats = Float32Array.from(positions); // rounded to the nearest float
  const min = nv ? [Infinity, Infinity, Infinity] : [0, 0, 0];
  const max = nv ? [-Infinity, -Infinity, -Infinity] : [0, 0, 0];
  for (let k = 0; k < nv; k++) {
    for (let d = 0; d < 3; d++) {
      min[d] = Math.min(min[d], floats[3 * k + d]);
      max[d] = Math.max(max[d], floats[3 * k + d]);
    }
  }
  const binLength = 12 * nv + 4 * ni;
  const json = {
    asset: { version: '2.0', generator: 'hullkit page' },
    scene: 0,
    scenes: [{ nodes: nv ? [0] : [] }],
  };
  if (nv) {
    const primitive = { attributes: { POSITION: 0 }, mode: ni ? 4 : 0 };
    if (ni) primitive.indices = 1;
    Object.assign(json, {
      nodes: [{ mesh: 0, name }],
      meshes: [{ name, primitives: [primitive] }],
      accessors: [{ bufferView: 0, componentType: 5126, count: nv, type: 'VEC3', min, max }],
      bufferViews: [{ buffer: 0, byteOffset: 0, byteLength: 12 * nv, target: 34962 }],
      buffers: [{ byteLength: binLength }],
    });
    if (ni) {
      json.accessors.push({ bufferView: 1, componentType: 5125, count: ni, type: 'SCALAR' });
      json.bufferViews.push({ buffer: 0, byteOffset: 12 * nv, byteLength: 4 * ni, target: 34963 });
    }
  }
  const text = new TextEncoder().encode(JSON.stringify(json));
  const jsonLength = Math.ceil(text.length / 4) * 4; // padded with spaces
  const total = 12 + 8 + jsonLength + (nv ? 8 + binLength : 0);
  const bytes = new Uint8Array(total);
  const view = new DataView(bytes.buffer);
  view.setUint32(0, 0x46546c67, true); // "glTF"
  view.setUint32(4, 2, true);
  view.setUint32(8, total, true);
  view.setUint32(12, jsonLength, true);
  view.setUint32(16, 0x4e4f534a, true); // "JSON"
  bytes.fill(0x20, 20, 20 + jsonLength);
  bytes.set(text, 20);
  if (nv) {
    let o = 20 + jsonLength;
    view.setUint32(o, binLength, true);
    view.setUint32(o + 4, 0x004e4942, true); // "BIN\0"
    o += 8;
    for (let i = 0; i < floats.length; i++, o += 4) view.setFloat32(o, floats[i], true);
    for (let i = 0; i < ni; i++, o += 4) view.setUint32(o, triangles[i], true);
  }
  return bytes;
}

const escapeXml = (s) => String(s).replace(/[<>&"]/g, (ch) => ({ '<': '&lt;', '>': '&gt;', '&': '&amp;', '"': '&quot;' })[ch]);

/**
 * An SVG picture of a 2D triangulation (y up, as the points are given): triangles as one path,
 * the hull outline, the points, and optionally Voronoi cells ({offsets, xy} as the worker gives).
 */
export function triangulationSvg({ xy, triangles, hull, cells = null, title = 'Delaunay triangulation' }) {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (let i = 0; i < xy.length; i += 2) {
    x0 = Math.min(x0, xy[i]); x1 = Math.max(x1, xy[i]);
    y0 = Math.min(y0, xy[i + 1]); y1 = Math.max(y1, xy[i + 1]);
  }
  if (!(x0 <= x1)) { x0 = y0 = 0; x1 = y1 = 1; }
  const span = Math.max(x1 - x0, y1 - y0) || 1;
  const size = 800;
  const pad = 20;
  const s = (size - 2 * pad) / span;
  const px = (x) => (pad + (x - x0) * s).toFixed(2);
  const py = (y) => (size - pad - (y - y0) * s).toFixed(2); // y up
  const pt = (i) => `${px(xy[2 * i])} ${py(xy[2 * i + 1])}`;
  let tri = '';
  for (let t = 0; t < triangles.length; t += 3) tri += `M${pt(triangles[t])}L${pt(triangles[t + 1])}L${pt(triangles[t + 2])}Z`;
  const hullPath = hull.length ? `M${[...hull].map(pt).join('L')}Z` : '';
  let cellPath = '';
  if (cells) {
    for (let c = 0; c + 1 < cells.offsets.length; c++) {
      const a = cells.offsets[c], b = cells.offsets[c + 1];
      if (b - a < 3) continue;
      const corners = [];
      for (let k = a; k < b; k++) corners.push(`${px(cells.xy[2 * k])} ${py(cells.xy[2 * k + 1])}`);
      cellPath += `M${corners.join('L')}Z`;
    }
  }
  const dots = [];
  for (let i = 0; i < xy.length / 2; i++) dots.push(`<circle cx="${px(xy[2 * i])}" cy="${py(xy[2 * i + 1])}" r="2"/>`);
  return `<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 ${size} ${size}" width="${size}" height="${size}">
<title>${escapeXml(title)}</title>
<rect width="100%" height="100%" fill="#ffffff"/>
${cellPath ? `<path d="${cellPath}" fill="none" stroke="#d9822b" stroke-width="0.8"/>\n` : ''}<path d="${tri}" fill="#e8f6f8" stroke="#2a7f8c" stroke-width="0.6" stroke-linejoin="round"/>
${hullPath ? `<path d="${hullPath}" fill="none" stroke="#0d3b42" stroke-width="1.6"/>\n` : ''}<g fill="#0d1117">${dots.join('')}</g>
</svg>
`;
}

/** Offers `data` (string or bytes) as a download named `name`. */
export function download(name, data, type = 'application/octet-stream') {
  const url = URL.createObjectURL(new Blob([data], { type }));
  const a = document.createElement('a');
  a.href = url;
  a.download = name;
  a.hidden = true;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}
