// `using` with a RouteChecker: compiled by scripts/type_test.sh only where the lib declares
// Symbol.dispose (lib esnext, or esnext.disposable), then run with node (target es2022).
import createHullkit from 'hullkit';
import type { RouteChecker, RouteScene } from 'hullkit';

function check(condition: boolean, what: string): void {
  if (!condition) throw new Error(`type test (using): ${what}`);
}

const hullkit = await createHullkit();
const scene: RouteScene = {
  traverse: { parts: [{ box: { min: [0, 0, 0], max: [1, 1, 1] } }] },
  obstacles: [{ name: 'wall', box: { min: [3, -10, -10], max: [4, 10, 10] } }],
};

let kept: RouteChecker | undefined;
{
  using checker = new hullkit.RouteChecker(scene);
  const report = checker.check([[0, 0, 0], [5, 0, 0]]);
  const leg = report.legs[0];
  check(leg?.status === 'hit' && leg.obstacle === 'wall' && leg.fraction[0] <= leg.fraction[1], 'the cube hits the wall');
  kept = checker;
  check(!kept.deleted, 'live inside the block');
}
check(kept.deleted, 'deleted at the end of the block');

// A RouteChecker is the lib's Disposable; disposing twice is harmless.
const disposable: Disposable = kept;
disposable[Symbol.dispose]();
kept[Symbol.dispose]();

export {};
