// hullkit.delaunay, find and voronoi: the JS side of native/include/hullkit/delaunay.hpp.
import { HullkitError } from './internal.js';

export const DELAUNAY_ALGORITHMS = ['incremental', 'giftwrap'];

export function delaunay() {
  throw new HullkitError('delaunay: not built yet');
}

export function delaunayFind() {
  throw new HullkitError('find: not built yet');
}

export function delaunayVoronoi() {
  throw new HullkitError('voronoi: not built yet');
}
