// Float32 positions for drawing, shared by the page's views and the worker (no three.js here):
// points centred (so that data far from the origin keeps its precision on the GPU) and the
// Delaunay 3D view's tetrahedra as the per-instance corners its shader draws.

/**
 * Float32 positions relative to the centre of the finite points' bounding box
 * (so that data far from the origin keeps its precision on the GPU), the
 * radius of the sphere around that centre containing them all, and the centre.
 */
export function centredPositions(xyz) {
  const n = Math.floor(xyz.length / 3);
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < n; i++) {
    const x = xyz[3 * i], y = xyz[3 * i + 1], z = xyz[3 * i + 2];
    if (!Number.isFinite(x) || !Number.isFinite(y) || !Number.isFinite(z)) continue;
    if (x < lo[0]) lo[0] = x; if (x > hi[0]) hi[0] = x;
    if (y < lo[1]) lo[1] = y; if (y > hi[1]) hi[1] = y;
    if (z < lo[2]) lo[2] = z; if (z > hi[2]) hi[2] = z;
  }
  const centre = lo[0] <= hi[0] ? lo.map((l, k) => (l + hi[k]) / 2) : [0, 0, 0];
  const positions = new Float32Array(3 * n);
  let r2 = 0;
  for (let i = 0; i < n; i++) {
    const x = xyz[3 * i] - centre[0], y = xyz[3 * i + 1] - centre[1], z = xyz[3 * i + 2] - centre[2];
    positions[3 * i] = x;
    positions[3 * i + 1] = y;
    positions[3 * i + 2] = z;
    const d = x * x + y * y + z * z;
    if (d > r2 && Number.isFinite(d)) r2 = d;
  }
  const radius = Math.sqrt(r2);
  return { positions, radius: radius > 0 ? radius : 1, centre };
}

/**
 * The outward faces of a positively oriented tetrahedron a, b, c, d (orient3d(a, b, c, d) > 0:
 * d on the side the normal (b - a) × (c - a) points to): face k is opposite corner k, its corners
 * counter-clockwise seen from outside.
 */
export const TETRAHEDRON_FACES = Object.freeze([[1, 2, 3], [0, 3, 2], [0, 1, 3], [0, 2, 1]].map(Object.freeze));
const FACE_CORNERS = TETRAHEDRON_FACES.flat();

/**
 * Tetrahedra per mesh the page draws: each mesh's buffers go to the GPU in a frame of their own,
 * so a large tetrahedralization never holds up the main thread in one long upload.
 */
export const TETRAHEDRA_PER_MESH = 65536;

/**
 * What the Delaunay 3D view draws of a tetrahedralization of `xyz` (a delaunay3() result: its
 * dimension, tetrahedra, neighbors, triangles, representative), built in the worker so that the
 * page's main thread only hands the arrays to the GPU: the centred `positions`, `centre` and
 * `radius`; `corners`, 4 vertices (12 floats) per tetrahedron, its corners' positions (a triangle
 * of coplanar points is a flat tetrahedron whose fourth corner is its centroid), `middles` the
 * centroid at each of them and `faces` (12 indices per tetrahedron: its 4 outward triangles,
 * TETRAHEDRON_FACES, counted from the first vertex of its mesh of TETRAHEDRA_PER_MESH); `boundary`, 4 t + k for each face k of tetrahedron t on the hull (no
 * neighbour); `distinct`, the points that are not duplicates, and their `pointPositions`.
 */
export function tetrahedraDrawing(xyz, { dimension, tetrahedra, neighbors, triangles, representative }) {
  const { positions, radius, centre } = centredPositions(xyz);
  const solids = dimension === 3 ? tetrahedra.length / 4 : dimension === 2 ? triangles.length / 3 : 0;
  const corners = new Float32Array(12 * solids);
  if (dimension === 3) {
    for (let i = 0; i < tetrahedra.length; i++) {
      const v = 3 * tetrahedra[i];
      corners[3 * i] = positions[v];
      corners[3 * i + 1] = positions[v + 1];
      corners[3 * i + 2] = positions[v + 2];
    }
  } else {
    for (let t = 0; t < solids; t++) {
      for (let k = 0; k < 3; k++) {
        const v = 3 * triangles[3 * t + k];
        for (let a = 0; a < 3; a++) {
          corners[12 * t + 3 * k + a] = positions[v + a];
          corners[12 * t + 9 + a] += positions[v + a] / 3;
        }
      }
    }
  }
  const middles = new Float32Array(corners.length);
  const faces = new Uint32Array(12 * solids);
  for (let t = 0; t < solids; t++) {
    for (let a = 0; a < 3; a++) {
      const m = (corners[12 * t + a] + corners[12 * t + 3 + a] + corners[12 * t + 6 + a] + corners[12 * t + 9 + a]) / 4;
      for (let k = 0; k < 4; k++) middles[12 * t + 3 * k + a] = m;
    }
    for (let j = 0; j < 12; j++) faces[12 * t + j] = 4 * (t % TETRAHEDRA_PER_MESH) + FACE_CORNERS[j];
  }
  let hullFaces = 0;
  if (dimension === 3) for (let i = 0; i < neighbors.length; i++) hullFaces += neighbors[i] === -1;
  const boundary = new Int32Array(hullFaces);
  if (dimension === 3) for (let i = 0, k = 0; i < neighbors.length; i++) if (neighbors[i] === -1) boundary[k++] = i;
  let count = 0;
  for (let i = 0; i < representative.length; i++) count += representative[i] === i;
  const distinct = new Uint32Array(count);
  const pointPositions = new Float32Array(3 * count);
  for (let i = 0, k = 0; i < representative.length; i++) {
    if (representative[i] !== i) continue;
    distinct[k] = i;
    pointPositions.set(positions.subarray(3 * i, 3 * i + 3), 3 * k++);
  }
  return { positions, centre, radius, corners, middles, faces, boundary, distinct, pointPositions };
}
