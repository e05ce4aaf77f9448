// hullkit.readPoints / readPoints2d / readMesh: the CLI's C++ readers through the wasm module.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';

import createHullkit, { HullkitError } from '../../wasm/hullkit.js';

const hullkit = await createHullkit();
const data = (name) => new Uint8Array(readFileSync(new URL(`../data/${name}`, import.meta.url)));
const text = (s) => new TextEncoder().encode(s);

/** A binary little-endian PLY: a unit right triangle at z = 2 plus one unused vertex. */
function binaryPly() {
  const header = text('ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n' +
    'property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n');
  const body = new DataView(new ArrayBuffer(4 * 12 + 1 + 12));
  [0, 0, 2, 1, 0, 2, 0, 1, 2, 5, 5, 5].forEach((v, i) => body.setFloat32(4 * i, v, true));
  body.setUint8(48, 3);
  [0, 1, 2].forEach((v, i) => body.setInt32(49 + 4 * i, v, true));
  const bytes = new Uint8Array(header.length + body.byteLength);
  bytes.set(header);
  bytes.set(new Uint8Array(body.buffer), header.length);
  return bytes;
}

const ASCII_STL = 'solid t\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n' +
  '  endloop\n endfacet\n facet normal 0 0 1\n  outer loop\n   vertex 1 0 0\n   vertex 1 1 0\n   vertex 0 1 0\n' +
  '  endloop\n endfacet\nendsolid t\n';

test('readMesh: a good file of each format', () => {
  const cases = [
    ['cube.obj', data('cube.obj'), 8, 12],
    ['tetra.off', data('tetra.off'), 4, 4],
    ['plate.ply', data('route/plate.ply'), 4, 2],
    ['binary.ply', binaryPly(), 4, 1],
    ['load.stl', data('route/load.stl'), 8, 12],
    ['ascii.stl', text(ASCII_STL), 4, 2],
    ['binary-two-triangles.stl', data('binary-two-triangles.stl'), 4, 2],
  ];
  for (const [name, bytes, vertices, triangles] of cases) {
    const mesh = hullkit.readMesh(bytes, name);
    assert.ok(mesh.vertices instanceof Float64Array, name);
    assert.ok(mesh.triangles instanceof Uint32Array, name);
    assert.equal(mesh.vertices.length, 3 * vertices, name);
    assert.equal(mesh.triangles.length, 3 * triangles, name);
    for (const index of mesh.triangles) assert.ok(index < vertices, name);
  }
  const ply = hullkit.readMesh(binaryPly(), 'binary.ply');
  assert.deepEqual([...ply.vertices], [0, 0, 2, 1, 0, 2, 0, 1, 2, 5, 5, 5]);
  assert.deepEqual([...ply.triangles], [0, 1, 2]);
  // The format comes from the content when the name says nothing; an ArrayBuffer works too.
  assert.equal(hullkit.readMesh(data('cube.obj').slice().buffer, 'upload').triangles.length, 36);
});

test('readPoints: point text, rbox and the vertices of meshes', () => {
  assert.deepEqual([...hullkit.readPoints(text('0 0 0\n1, 2, 3\n# note\n4 5 6\n'), 'p.xyz')], [0, 0, 0, 1, 2, 3, 4, 5, 6]);
  assert.deepEqual([...hullkit.readPoints(text('3 rbox 2 D3\n2\n0 0 0\n1 1 1\n'), 'r.txt')], [0, 0, 0, 1, 1, 1]);
  // OBJ and OFF as `hullkit hull` reads them (vertices, faces ignored); PLY and STL through the mesh readers.
  assert.equal(hullkit.readPoints(data('cube.obj'), 'cube.obj').length, 24);
  assert.equal(hullkit.readPoints(text('v 0 0 0\nv 1 0 0\n'), 'cloud.obj').length, 6);  // no faces needed
  assert.deepEqual(hullkit.readPoints(data('tetra.off'), 'tetra.off'), hullkit.readMesh(data('tetra.off'), 'tetra.off').vertices);
  assert.deepEqual(hullkit.readPoints(binaryPly(), 'b.ply'), hullkit.readMesh(binaryPly(), 'b.ply').vertices);
  assert.equal(hullkit.readPoints(data('route/load.stl'), 'load.stl').length, 24);
  // A PLY point cloud (no face element), by name and by content.
  const cloud = text('ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nend_header\n1 2 3\n4 5 6\n');
  assert.deepEqual([...hullkit.readPoints(cloud, 'scan.ply')], [1, 2, 3, 4, 5, 6]);
  assert.deepEqual([...hullkit.readPoints(cloud, 'upload')], [1, 2, 3, 4, 5, 6]);
  assert.deepEqual([...hullkit.readPoints2d(cloud, 'scan.ply')], [1, 2, 4, 5]);
  assert.equal(hullkit.readPoints(data('binary-two-triangles.stl'), 'upload.bin').length, 12);  // by content
  const points = hullkit.readPoints(data('cube.obj'), 'cube.obj');
  assert.equal(hullkit.hull(points).volume, hullkit.hull(hullkit.readMesh(data('cube.obj'), 'cube.obj').vertices).volume);
});

test('readPoints2d: as `hullkit delaunay` reads, and x y of mesh vertices', () => {
  assert.deepEqual([...hullkit.readPoints2d(text('0 0\n1 0\n0 1\n'), 'p.txt')], [0, 0, 1, 0, 0, 1]);
  assert.deepEqual([...hullkit.readPoints2d(text('0 0 9\n1 0 9\n'), 'p.xyz')], [0, 0, 1, 0]);
  assert.deepEqual([...hullkit.readPoints2d(text('2 rbox 3 D2\n3\n0 0\n1 0\n0 1\n'), 'r.txt')], [0, 0, 1, 0, 0, 1]);
  assert.deepEqual([...hullkit.readPoints2d(binaryPly(), 'b.ply')], [0, 0, 1, 0, 0, 1, 5, 5]);
  assert.equal(hullkit.readPoints2d(data('cube.obj'), 'cube.obj').length, 16);
});

test('readers: a malformed file throws a HullkitError naming the problem and the line', () => {
  const badObj = text('v 0 0 0\nv 1 0 0\nv 0 1\nf 1 2 3\n');
  assert.throws(() => hullkit.readMesh(badObj, 'bad.obj'), (error) =>
    error instanceof HullkitError && error.line === 3 && /^bad\.obj:3: .*3 coordinates/.test(error.message));
  assert.throws(() => hullkit.readPoints(badObj, 'bad.obj'), (error) =>
    error instanceof HullkitError && error.line === 3 && /^bad\.obj:3: /.test(error.message));
  assert.throws(() => hullkit.readMesh(text('v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n'), 'bad.obj'),
    (error) => error.line === 4 && /face index 4 out of range/.test(error.message));
  assert.throws(() => hullkit.readPoints2d(text('0 0\n1 x\n'), 'pts.txt'),
    (error) => error instanceof HullkitError && error.line === 2 && /"x"/.test(error.message));
});

test('readers: records an OBJ should not hold are skipped and listed in `warnings`', () => {
  const body = 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n';
  // FCL's test meshes start with a "V F" count line.
  const fcl = text(`4 4\n${body}bogus\nbogus\n`);
  const expected = ['skipped 1 unknown OBJ record "4" (first at line 1)', 'skipped 2 unknown OBJ records "bogus" (first at line 10)'];
  const mesh = hullkit.readMesh(fcl, 'fcl.obj');
  assert.deepEqual(mesh.warnings, expected);
  const clean = hullkit.readMesh(text(body), 'clean.obj');
  assert.deepEqual(clean.warnings, []);
  assert.deepEqual(mesh.vertices, clean.vertices);
  assert.deepEqual(mesh.triangles, clean.triangles);
  const points = hullkit.readPoints(fcl, 'fcl.obj');
  assert.ok(points instanceof Float64Array);
  assert.deepEqual([...points], [...clean.vertices]);
  assert.deepEqual(points.warnings, expected);
  assert.deepEqual(hullkit.readPoints(text(body), 'clean.obj').warnings, []);
  assert.deepEqual(hullkit.readPoints2d(fcl, 'fcl.obj').warnings, expected);
  // A malformed vertex is still an error.
  assert.throws(() => hullkit.readMesh(text('4 4\nv 0 0\n'), 'fcl.obj'), (error) => error.line === 2);
});

/** A .gltf of one triangle under a node moved by (10, 20, 30), its buffer as `buffer` ({uri} or {}). */
function triangleGltf(buffer) {
  const bin = new Uint8Array(36 + 6);
  const view = new DataView(bin.buffer);
  [1, 0, 0, 0, 1, 0, 0, 0, 1].forEach((v, i) => view.setFloat32(4 * i, v, true));
  [0, 1, 2].forEach((v, i) => view.setUint16(36 + 2 * i, v, true));
  const json = {
    asset: { version: '2.0' }, scene: 0, scenes: [{ nodes: [0] }], nodes: [{ mesh: 0, translation: [10, 20, 30] }],
    meshes: [{ primitives: [{ attributes: { POSITION: 0 }, indices: 1 }, { attributes: { POSITION: 0 }, mode: 0 }] }],
    accessors: [
      { bufferView: 0, componentType: 5126, count: 3, type: 'VEC3', min: [0, 0, 0], max: [1, 1, 1] },
      { bufferView: 1, componentType: 5123, count: 3, type: 'SCALAR' },
    ],
    bufferViews: [{ buffer: 0, byteLength: 36 }, { buffer: 0, byteOffset: 36, byteLength: 6 }],
    buffers: [{ byteLength: bin.length, ...buffer(bin) }],
  };
  return text(JSON.stringify(json));
}

test('readers: glTF (.glb from writeGlb, .gltf with data: URIs), and writeGlb', () => {
  const xyz = new Float64Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.25, 0.25, 0.25, 0.1, 0.2, 0.3]);
  const result = hullkit.hull(xyz);
  const glb = hullkit.writeGlb(xyz, result);
  assert.ok(glb instanceof Uint8Array);
  assert.equal(new TextDecoder().decode(glb.subarray(0, 4)), 'glTF');
  const mesh = hullkit.readMesh(glb, 'hull.glb');
  assert.deepEqual(mesh.warnings, []);
  // The hull's vertices in order (exact here: every coordinate is a float), its triangles re-indexed.
  assert.deepEqual([...mesh.vertices], [...result.vertices].flatMap((v) => [...xyz.subarray(3 * v, 3 * v + 3)]));
  const position = new Map([...result.vertices].map((v, i) => [v, i]));
  assert.deepEqual([...mesh.triangles], [...result.triangles].map((v) => position.get(v)));
  assert.deepEqual([...hullkit.readPoints(glb, 'upload')], [...mesh.vertices]); // by content
  // Float rounding: 0.1 is not a float.
  const rounded = hullkit.readMesh(hullkit.writeGlb(new Float64Array([0.1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]),
    hullkit.hull(new Float64Array([0.1, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]))), 'r.glb');
  assert.equal(rounded.vertices[0], Math.fround(0.1));
  assert.throws(() => hullkit.writeGlb(new Float64Array([1e39, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0]),
    hullkit.hull(new Float64Array([1e39, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0]))), (error) =>
    error instanceof HullkitError && /does not fit a glTF float32 position/.test(error.message));

  // A .gltf with its buffer embedded: the node's translation applied, the POINTS primitive skipped.
  const embedded = triangleGltf((bin) => ({ uri: `data:application/octet-stream;base64,${Buffer.from(bin).toString('base64')}` }));
  const gltf = hullkit.readMesh(embedded, 'scene.gltf');
  assert.deepEqual([...gltf.vertices], [11, 20, 30, 10, 21, 30, 10, 20, 31]);
  assert.deepEqual([...gltf.triangles], [0, 1, 2]);
  assert.deepEqual(gltf.warnings, ['skipped 1 primitive of mode POINTS (0), only TRIANGLES are read (first: mesh 0, primitive 1)']);
  assert.deepEqual(hullkit.readPoints(embedded, 'scene.gltf').warnings, gltf.warnings);
  // External buffer files cannot be read here: use a .glb.
  assert.throws(() => hullkit.readMesh(triangleGltf(() => ({ uri: 'triangle.bin' })), 'scene.gltf'), (error) =>
    error instanceof HullkitError && /^scene\.gltf: .*"triangle\.bin".*use a \.glb/.test(error.message));
  // A truncated .glb says so.
  assert.throws(() => hullkit.readMesh(glb.subarray(0, glb.length - 8), 'cut.glb'), /cut\.glb: binary glTF is truncated/);
});

test('readers: a truncated binary STL says so', () => {
  const stl = data('binary-two-triangles.stl');
  for (const read of ['readMesh', 'readPoints']) {
    assert.throws(() => hullkit[read](stl.subarray(0, stl.length - 20), 'cut.stl'), (error) =>
      error instanceof HullkitError && /^cut\.stl: binary STL is truncated: .*184 bytes.*got 164/.test(error.message));
  }
  assert.throws(() => hullkit.readMesh(stl.subarray(0, 60), 'cut.stl'), /truncated: at least 84 bytes/);
});

test('readers: no points is no error (the hull of nothing has dimension -1), as the command line has it', () => {
  for (const bytes of [new Uint8Array(0), text('# nothing\n'), text('x,y,z\n')]) {
    const points = hullkit.readPoints(bytes, 'empty.xyz');
    assert.equal(points.length, 0);
    assert.equal(hullkit.hull(points).dimension, -1);
    assert.equal(hullkit.readPoints2d(bytes, 'empty.xy').length, 0);
  }
});

test('readers: a byte-order mark and a CSV header row are skipped (a warning says so); nan names its line and point', () => {
  const points = hullkit.readPoints(text('\uFEFFx,y,z\n0,0,0\n1,0,0\n0,1,0\n'), 'p.csv');
  assert.deepEqual([...points], [0, 0, 0, 1, 0, 0, 0, 1, 0]);
  assert.deepEqual(points.warnings, ['skipped header line 1: x,y,z']);
  const xy = hullkit.readPoints2d(text('\uFEFFx,y\n0,0\n1,0\n'), 'p.csv');
  assert.deepEqual([...xy], [0, 0, 1, 0]);
  assert.deepEqual(xy.warnings, ['skipped header line 1: x,y']);
  assert.throws(() => hullkit.readPoints(text('0 0 0\n1 nan 0\n'), 'p.xyz'),
    (error) => error.line === 2 && error.message === 'p.xyz:2: coordinate "nan" of point 1 is not a finite number');
  assert.throws(() => hullkit.readPoints2d(text('0 0\n1e400 0\n'), 'p.xy'),
    (error) => error.line === 2 && error.message === 'p.xy:2: coordinate "1e400" of point 1 is out of the double range');
});

test('readers: argument checks', () => {
  assert.throws(() => hullkit.readPoints('0 0 0', 'p.xyz'), TypeError);
  assert.throws(() => hullkit.readMesh(data('cube.obj'), 42), TypeError);
  // Without a name the messages say <bytes>.
  assert.throws(() => hullkit.readMesh(text('v 0 0 0\nv 1 0 0\nv 0 1\nf 1 2 3\n')),
    (error) => error.line === 3 && error.message.startsWith('<bytes>:3: '));
});
