// The Route view's preset scenes (in the JSON form `hullkit route` and hullkit.checkRoute read,
// z up, metres) and the geometry helpers the view and the worker share. Waypoints that turn are
// {position, rotation: {axis: [0, 0, 1], degrees}} (yaw); the others plain [x, y, z].

/** Box {min, max} as a closed mesh: 8 corners, 12 outward triangles. */
const BOX_TRIANGLES = [
  [0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], // bottom (z min), top
  [0, 1, 5], [0, 5, 4], [1, 2, 6], [1, 6, 5], // y min, x max
  [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7], // y max, x min
];

function boxCorners({ min, max }) {
  const out = [];
  for (const z of [min[2], max[2]]) {
    out.push(min[0], min[1], z, max[0], min[1], z, max[0], max[1], z, min[0], max[1], z);
  }
  return out;
}

/** A part's or obstacle's vertices as a flat array x0 y0 z0 ... */
export function partVertices(part) {
  return part.box ? boxCorners(part.box) : part.vertices.flat();
}

/** Its triangles as a flat index array. */
export function partTriangles(part) {
  return (part.box ? BOX_TRIANGLES : part.triangles).flat();
}

/** A closed prism: the simple polygon `outline` ([[x, y], ...] counter-clockwise) from z0 to z1. */
function prism(name, outline, z0, z1, fan) {
  const k = outline.length;
  const vertices = [...outline.map(([x, y]) => [x, y, z0]), ...outline.map(([x, y]) => [x, y, z1])];
  const triangles = [];
  for (const [a, b, c] of fan) {
    triangles.push([a, c, b], [a + k, b + k, c + k]);
  }
  for (let i = 0; i < k; i++) {
    const j = (i + 1) % k;
    triangles.push([i, j, j + k], [i, j + k, i + k]);
  }
  return { name, vertices, triangles };
}

const box = (name, min, max) => ({ name, box: { min, max } });
/** A waypoint turned `degrees` about z (the traverse's pivot). */
const yawed = (position, degrees) => ({ position, rotation: { axis: [0, 0, 1], degrees } });

/** A bar 3 long across the way (along y) and a wall with a doorway 1.2 wide at x in [4, 4.3]. */
const barAndDoorway = (route) => ({
  traverse: { pivot: [0, 0, 1.05], parts: [box('bar', [-0.15, -1.5, 0.9], [0.15, 1.5, 1.2])] },
  route,
  obstacles: [
    box('wall left', [4, -4, 0], [4.3, -0.6, 3]),
    box('wall right', [4, 0.6, 0], [4.3, 4, 3]),
    box('lintel', [4, -0.6, 2.1], [4.3, 0.6, 3]),
  ],
  margin: 0.05,
});

export const PRESETS = {
  doorway: {
    label: 'crane load through a doorway',
    note: 'A load under its spreader bar is carried through a doorway in a wall, then set down by a crate.',
    samples: 20,
    scene: {
      traverse: { parts: [
        box('load', [-0.6, -0.4, 0], [0.6, 0.4, 0.8]),
        box('spreader', [-0.8, -0.08, 1.5], [0.8, 0.08, 1.65]),
      ] },
      route: [[-1, -3, 0.1], [1.8, 0, 0.1], [6.5, 0, 0.1], [8.6, 2.3, 0.1]],
      obstacles: [
        box('wall left', [4, -4, 0], [4.3, -0.85, 3]),
        box('wall right', [4, 0.85, 0], [4.3, 4, 3]),
        box('lintel', [4, -0.85, 2.2], [4.3, 0.85, 3]),
        box('crate', [8, 2.6, 0], [9.2, 3.6, 1.1]),
      ],
      margin: 0.05,
    },
  },
  'thin-plate': {
    label: 'thin plate that 20-step sampling misses',
    note: 'A zero-thickness plate sits between two of the 21 poses of 20-step sampling: every pose is clear, the leg is not.',
    samples: 20,
    scene: {
      traverse: { parts: [box('block', [-0.2, -0.2, 0.8], [0.2, 0.2, 1.2])] },
      route: [[0, 0, 0], [10, 0, 0], [10, 3, 0]],
      obstacles: [
        { name: 'plate', vertices: [[5.25, -1, 0], [5.25, 1, 0], [5.25, 1, 2], [5.25, -1, 2]], triangles: [[0, 1, 2], [0, 2, 3]] },
      ],
      margin: 0,
    },
  },
  'l-post': {
    label: 'L-shaped part around a post',
    note: 'The post passes through the notch of the L: the L\'s own hull (and so its swept hull) overlaps the post, yet the part never touches it.',
    samples: 20,
    scene: {
      traverse: { parts: [prism('L part', [[0, 0], [3, 0], [3, 0.5], [0.5, 0.5], [0.5, 3], [0, 3]], 0.2, 1.2,
        [[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 5]])] },
      route: [[-2.5, 0, 0], [0, 0, 0], [0, -2.5, 0]],
      obstacles: [box('post', [1.5, 1.5, 0], [2, 2, 2.2])],
      margin: 0.05,
    },
  },
  'slewing-crane': {
    label: 'slewing crane past a mast (turning)',
    note: 'A tower crane slews 120° about its tower while it hoists 1.5 m (the jib and the load turn together about the pivot on the cat head). ' +
      'The load swings round outside the site hut (the hull of the two end poses alone would cut through the hut) but catches the mast late in the turn; slewing 85° clears it.',
    samples: 20,
    scene: {
      traverse: { pivot: [0, 0, 10.2], parts: [
        box('jib', [-0.6, -0.4, 8], [14, 0.4, 8.8]),
        box('counter-jib', [-5, -0.5, 8.1], [-0.6, 0.5, 8.6]),
        box('counterweight', [-5, -0.8, 6.9], [-3.6, 0.8, 8.1]),
        box('cat head', [-0.5, -0.5, 8.8], [0.5, 0.5, 10.2]),
        box('hoist rope', [10.95, -0.05, 2.2], [11.05, 0.05, 8]),
        box('load', [10.2, -0.7, 1.2], [11.8, 0.7, 2.2]),
      ] },
      route: [[0, 0, 0], yawed([0, 0, 1.5], 120)],
      obstacles: [
        box('tower', [-0.9, -0.9, 0], [0.9, 0.9, 7.6]),
        box('site hut', [3, 4.5, 0], [5.5, 7.5, 2.8]),
        box('mast', [-1.3, 10.7, 0], [-0.7, 11.3, 4.2]),
      ],
      margin: 0.05,
    },
  },
  'bar-turn': {
    label: 'long bar turned to pass a doorway',
    note: 'A bar 3 long cannot pass a doorway 1.2 wide across the way: it turns 90° about its middle first, passes lengthwise and turns back beyond the wall.',
    samples: 20,
    scene: barAndDoorway([[0, 0, 0], yawed([1.5, 0, 0], 90), yawed([7, 0, 0], 90), [8.5, 0, 0]]),
  },
  'bar-turn-late': {
    label: 'long bar turning in the doorway: hit',
    note: 'The same bar turns while it moves through the doorway: about 38° into its turn, 40% of the way along, its end catches the wall.',
    samples: 20,
    scene: barAndDoorway([[0, 0, 0], yawed([7, 0, 0], 90)]),
  },
};

/** A deep copy of preset `name`'s scene. */
export function presetScene(name) {
  return structuredClone((PRESETS[name] ?? PRESETS.doorway).scene);
}
