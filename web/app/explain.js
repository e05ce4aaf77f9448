// "What am I looking at?": each view's explanation, written for the page, shown in the page's
// <dialog id="explain"> (a modal: Esc or Close shuts it and focus goes back to the button that
// opened it). Nothing is fetched: the text lives here.
//
// A view gets its explanation by adding one entry to EXPLANATIONS under its name and a button
// with data-explain="NAME" in its panel (any element with data-explain opens it, also one added
// later). An entry is {title, sections: [{heading, paragraphs: [HTML, ...]}]}; the paragraphs are
// this module's own HTML (inline markup only: <em>, <strong>, <code>).

export const EXPLANATIONS = {
  hull: {
    title: 'The convex hull in 3D',
    sections: [
      {
        heading: 'What is drawn',
        paragraphs: [
          'A cloud of points in 3D and its <strong>convex hull</strong>: the smallest convex polytope that holds them all, as if the points were wrapped in cling film. Its faces are translucent teal, its vertices (the extreme points) amber, the points inside grey.',
          'Up to 1 000 000 points; above 150 000 interior points only every k-th is drawn (the status line says so), so orbiting stays smooth. Drag to orbit, zoom and pan; <em>Reset view</em> fits the hull again.',
        ],
      },
      {
        heading: 'The controls',
        paragraphs: [
          '<em>Distribution</em> picks the points: in a cube or a ball, on a sphere (every point is a hull vertex), in a square (coplanar: the hull is a polygon), near-coplanar (z ± 1e-13), integer grids, a rotated grid, coordinates you paste, or a file you open or drop on the page. <em>Points</em> (the slider is logarithmic) and <em>Seed</em> make the same points again.',
          '<em>Algorithm</em>: quickhull, O(n log n), or the seed document\'s gift wrapping, O(n·h) for h hull vertices (the page asks before a long run). With gift wrapping, <em>Side tests</em> can use the seed\'s epsilon instead of exact predicates; each such run is compared with an exact one, and extreme points the epsilon missed are drawn pink. <em>Merge coplanar faces</em> gives the hull\'s faces as polygons instead of triangles. The hull exports as OBJ, OFF, STL or glTF.',
        ],
      },
      {
        heading: 'Why it is exact',
        paragraphs: [
          'Every decision "is this point above, on or below that plane" is an exact <code>orient3d</code> test: a fast floating-point filter with a proven error bound, and exact arithmetic when the filter cannot decide. A point counts as outside a face only when it is strictly above it, so a cube\'s face centres and edge midpoints are never vertices, and the result is the same natively and in WebAssembly.',
          'The rotated grid shows what an epsilon does: rounding moves the face points slightly off the face planes, so the exact hull has many more than 8 vertices, while the seed\'s epsilon snaps them back (and may miss true vertices of near-coplanar input).',
        ],
      },
      {
        heading: 'Gift wrapping, step by step',
        paragraphs: [
          'The seed\'s algorithm: (1) the point with the largest x is surely a hull vertex; (2) a first edge from it has every other point on one side of a plane through it; (3) take an open edge from the stack and look for the point whose triangle with it has every other point on its inner side; (4) scan the points: one above the candidate\'s plane replaces the candidate. An accepted face puts its new edges on the stack; the hull is closed when the stack is empty.',
          'For up to 300 points, <em>Step through</em> replays the gift wrap recorded by the C++ core: the edge being wrapped (pink), the open edges (amber), the candidate, the point that replaced it (white) and the accepted faces (teal). The <em>Candidate rule</em> picks the one-pass scan or the seed\'s literal rule, which restarts the scan after each replacement. Played to its end, it shows exactly the hull computed at once.',
        ],
      },
    ],
  },
  delaunay: {
    title: 'Delaunay triangulation by lifting',
    sections: [
      {
        heading: 'What is drawn',
        paragraphs: [
          'Points in the plane, each lifted onto the paraboloid z = x² + y² (the 3D pane), and the <strong>Delaunay triangulation</strong> of the plane, seen from above in the other pane: the triangulation in which no point lies inside any triangle\'s circumcircle, which makes the smallest angle as large as it can be.',
          'The shaded lower faces of the lifted points\' convex hull, projected straight down, are exactly the Delaunay triangles. Hover a triangle to see its empty circumcircle (its lift lies in the plane of the lifted face); Voronoi cells, the regions nearest to each point, on request. <em>Layout</em> can also blend the paraboloid over the plane in one view.',
        ],
      },
      {
        heading: 'The controls',
        paragraphs: [
          '<em>Point set</em>: uniform, gaussian, a square grid, the grid rotated by 30°, points on a circle, or the seed\'s Figure 1 (a sphere flattened onto x–y); 3 to 50 000 points, or a file. Click in the plane to add points (they are kept in the link); <em>Clear clicks</em> removes them. The triangles are exported as OFF or SVG.',
          '<em>Algorithm</em>: incremental insertion, or gift wrapping the lifted points as the seed does (O(n²): every lifted point is a hull vertex; at most 5 000 points). Both give identical triangles. The count always obeys triangles = 2n − h − 2 for n points with h on the hull.',
        ],
      },
      {
        heading: 'Why lifting works, exactly',
        paragraphs: [
          'A point d lies inside the circle through a, b and c exactly when its lift lies below the plane through their lifts. So "is d below the lifted plane" is the 2D in-circle test, and the page decides it with exact <code>incircle</code> and <code>orient2d</code> on the original coordinates, never on rounded lifted ones. Grids, points on a circle and near-duplicates all get a true Delaunay triangulation with no zero-area triangle.',
          'Cocircular points (a grid\'s squares, a circle) have more than one Delaunay triangulation; one rule picks the same one for both algorithms. Exact duplicates are merged into their first copy and counted.',
        ],
      },
      {
        heading: 'The lifted gift wrap, step by step',
        paragraphs: [
          'For up to 300 points, <em>Step through</em> replays the seed\'s gift wrap on the lifted points, recorded by the C++ core, on the paraboloid and in the plane at once: a point replaces the candidate when it lies strictly inside the candidate\'s circle, which is to say its lift lies below the candidate\'s plane.',
        ],
      },
      {
        heading: 'Constraints: polygons with holes, quality meshes',
        paragraphs: [
          '<em>Triangulation</em> switches to a <strong>constrained Delaunay triangulation</strong> of a polygon with holes, starting with a sample. Click in the plane to add vertices, click the first vertex again (or press Enter) to close a ring; the rings drawn next are holes (even-odd rule). Drag a vertex to move it: the triangulation follows. A GeoJSON polygon or a Triangle <code>.poly</code> file opens too.',
          'Every polygon edge is an edge of the result (orange, thick), the other edges are as Delaunay as the polygon allows, and only the inside is kept; where edges cross, the crossing is added as a point (violet). The note counts the polygon edges that the plain Delaunay triangulation of the same vertices lacks: it would cut across them. On the paraboloid, the lifted constrained triangles fold above the lower hull where a constraint forced an edge in.',
          '<em>Quality mesh</em> adds Steiner points (violet) until no angle is below the <em>minimum angle</em> (up to 34°) and no triangle is larger than the <em>maximum area</em>, except next to input angles too small to allow it; <em>conforming</em> makes every triangle Delaunay; <em>keep segments whole</em> adds no point on the rings (Triangle\'s -Y) or on any segment (-YY), leaving the angle bound unmet next to them where it has to. The note gives the smallest angle measured. A <code>.poly</code> file is read as Triangle reads it: its segments are constraints, and the triangles outside them and around its hole points are removed.',
        ],
      },
    ],
  },
  delaunay3: {
    title: 'Delaunay tetrahedralization by lifting to 4D',
    sections: [
      {
        heading: 'What is drawn',
        paragraphs: [
          'Points in 3D and their <strong>Delaunay tetrahedralization</strong>: tetrahedra that fill the convex hull of the points, meet face to face, and whose circumspheres (the sphere through a tetrahedron\'s four corners) hold no point inside. Each tetrahedron is drawn shrunk towards its centroid, so that the ones behind it show through the gaps, and a plane cuts the cloud open.',
          'Hover a tetrahedron to see its circumsphere, translucent pink, with the points on it in white: always its four corners, and more where points are cospherical (a grid\'s cubes: eight corners on one sphere). Click a point to see its <strong>Voronoi cell</strong>, violet: the region of space nearer to it than to any other point, with its volume. A point on the convex hull has an unbounded cell; the page says so and draws the part near the points. On a touch screen, a tap does both.',
        ],
      },
      {
        heading: 'The controls',
        paragraphs: [
          '<em>Distribution</em>: the Hull view\'s point sets (in a cube or a ball, on a sphere, coplanar, near-coplanar, integer grids, a rotated grid, pasted coordinates) or a file you open or drop on the page; 1 to 200 000 points. 100 000 points (about 670 000 tetrahedra) stay interactive: the tetrahedralization runs in the worker with its progress shown, and the shrink and the cut are applied by the graphics card.',
          '<em>Sites</em>: <em>nearest</em> draws the Delaunay tetrahedralization; <em>furthest</em> the upper facets of the same lifted hull instead, the <strong>furthest-site</strong> tetrahedralization: its circumspheres hold every point, its corners are the hull\'s extreme points only (the points inside are in no tetrahedron), and each point\'s cell is where it is the farthest point, always unbounded. It is the same insertion with every in-sphere answer reversed.',
          '<em>Shrink</em> scales each tetrahedron about its centroid. <em>Cut</em> hides whole tetrahedra whose centroid lies beyond the plane, or clips them at the plane (a three.js clipping plane), or shows them all. <em>Move</em>, <em>Turn</em> and <em>Tilt</em> place the plane; drag its amber handle in the view to move it along its normal. Points beyond the plane are hidden with the tetrahedra. The link keeps the points and these settings.',
        ],
      },
      {
        heading: 'Lifting to 4D, exactly',
        paragraphs: [
          'The seed\'s lifting, one dimension up: lift each point (x, y, z) to (x, y, z, x² + y² + z²) on a paraboloid in 4D. The lower facets of the convex hull of the lifted points are tetrahedra, and projected back down they are exactly the Delaunay tetrahedra: a point lies inside the sphere through a, b, c and d exactly when its lift lies below the hyperplane through their lifts.',
          'So every decision is one of two exact predicates on the original coordinates, never on rounded lifted ones: <code>orient3d</code> (which side of the plane through three points a fourth lies on) and <code>insphere</code> (inside, on or outside the sphere through four points). A fast floating-point filter decides almost always; exact arithmetic decides the rest.',
          'Five or more cospherical points (grids, points on a sphere) have more than one Delaunay tetrahedralization. The tie is broken by a symbolic perturbation: each lift is raised by an infinitesimal that grows with the point\'s place in (x, y, z) order, and an in-sphere test that is exactly zero is decided by the first nonzero term of that perturbation. There is never a flat tetrahedron, and the same points give the same tetrahedra in any order, natively and in WebAssembly.',
        ],
      },
      {
        heading: 'Voronoi cells',
        paragraphs: [
          'The Voronoi diagram is dual to the tetrahedralization: its vertices are the centres of the empty spheres (tetrahedra on one sphere share one, decided by the exact in-sphere test), and the face between two points is dual to the Delaunay edge joining them. The worker computes the whole diagram after each tetrahedralization (the time is in the stats); the volumes are rounded, which faces and vertices exist is exact.',
        ],
      },
    ],
  },
  route: {
    title: 'Route checking with swept hulls',
    sections: [
      {
        heading: 'What is drawn',
        paragraphs: [
          'A <strong>traverse</strong> (a crane load, a part, a tool: one or more triangle meshes) is carried along a route of waypoints past obstacles. Each leg moves it in a straight line and may turn it. The volume each leg sweeps is drawn green when the leg is clear and red when it hits, with the traverse ghosted in amber where it first touches.',
          'The table gives each leg\'s status, the fraction of the leg where the first contact happens, the obstacle met, the clearance (the smallest distance over the leg) and what N-step sampling finds; <em>overlay N-step sampling</em> draws those sampled poses.',
        ],
      },
      {
        heading: 'The controls',
        paragraphs: [
          'The presets: a crane load through a doorway, a thin plate that 20-step sampling steps over, an L-shaped part passing around a post, a slewing crane, and a long bar turned to pass a doorway (or turning too late, and hitting). Drag a waypoint (sphere) over the ground, drag the ring around it to turn it about z, add and remove waypoints. <em>Margin</em>: a leg is clear only when the traverse stays more than that far from every obstacle. An opened mesh becomes another obstacle or the traverse. The route is kept in the link; report and scene export as JSON.',
        ],
      },
      {
        heading: 'The extruded traverse',
        paragraphs: [
          'The seed\'s idea: everything the traverse sweeps while it moves in a straight line lies inside the convex hull of its vertices at both ends of the leg (the traverse extruded along the leg). When those hulls stay clear of every obstacle the leg is clear, however thin the obstacle, where sampling can step right over it. Where a hull comes too close, each triangle\'s own swept prism is tested exactly, so a part that passes around a post is not reported as a hit.',
          'A turning leg turns at constant angular speed along the shorter arc. Over a short piece of it, a point at distance r from the axis stays within r·Δθ²/8 of the straight segment between its two end positions, so the sweep lies in the hull of the two end poses grown by that much: the checker certifies such pieces and splits those it cannot, and the page draws a turning leg as the hulls of those pieces.',
        ],
      },
      {
        heading: 'Why it misses nothing',
        paragraphs: [
          'Exact predicates decide every contact, and what cannot be certified clear is reported as a hit (a tangential graze is marked grazing): a leg is never called clear wrongly. The first contact is bracketed to within 1e-9 of the leg (1e-7 when it turns). The scene\'s hulls and bounding-volume tree are built once, so dragging a waypoint re-checks the route alone.',
        ],
      },
    ],
  },
};

/** Said under every explanation: how the page computes. */
const COMMON = 'Everything is computed in a Web Worker by hullkit\'s C++ core compiled to WebAssembly (the module the npm package ships), so the page never freezes; the link holds the view and its options.';

/** Fills the dialog with the explanation of `name`; false when there is none. */
function render(dialog, name) {
  const entry = EXPLANATIONS[name];
  if (!entry) return false;
  dialog.querySelector('#explain-title').textContent = entry.title;
  const body = dialog.querySelector('#explain-body');
  body.replaceChildren();
  for (const { heading, paragraphs } of entry.sections) {
    const section = document.createElement('section');
    const h = document.createElement('h3');
    h.textContent = heading;
    section.append(h);
    for (const html of paragraphs) {
      const p = document.createElement('p');
      p.innerHTML = html;
      section.append(p);
    }
    body.append(section);
  }
  const note = document.createElement('p');
  note.className = 'explain-common';
  note.textContent = COMMON;
  body.append(note);
  body.scrollTop = 0;
  dialog.dataset.explains = name;
  return true;
}

/**
 * Wires the dialog: a click on any [data-explain] element opens the explanation it names; Esc,
 * Close or a click outside the dialog close it, and focus returns to the opener.
 * Test hook: <dialog id="explain" data-explains="NAME"> names the explanation shown.
 */
export function setUpExplain() {
  const dialog = document.getElementById('explain');
  if (!dialog) return;
  let opener = null;

  function open(name, from) {
    if (!render(dialog, name)) return;
    opener = from ?? document.activeElement;
    if (!dialog.open) dialog.showModal();
    dialog.querySelector('#explain-close').focus();
  }

  document.addEventListener('click', (event) => {
    const trigger = event.target.closest?.('[data-explain]');
    if (!trigger) return;
    event.preventDefault();
    open(trigger.dataset.explain, trigger);
  });
  dialog.querySelector('#explain-close').addEventListener('click', () => dialog.close());
  // The dialog's box is its inner frame: a click on the dialog element itself is on the backdrop.
  dialog.addEventListener('click', (event) => {
    if (event.target === dialog) dialog.close();
  });
  dialog.addEventListener('close', () => {
    if (opener?.isConnected) opener.focus();
    opener = null;
  });
}
