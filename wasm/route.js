// >>> HELPERS: before building, testing or touching git, read /work/HELPERS_RULES.md (lead removes this line).
// hullkit.checkRoute and RouteChecker: the JS side of native/include/hullkit/route.hpp.
import { HullkitError } from './internal.js';

export function checkRoute() {
  throw new HullkitError('checkRoute: not built yet');
}

export class RouteChecker {
  constructor() {
    throw new HullkitError('RouteChecker: not built yet');
  }
}
