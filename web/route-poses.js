// Waypoint poses, shared by the Route view and the worker. A waypoint is [x, y, z] (a translation)
// or {position: [x, y, z], rotation} with rotation {quaternion: [w, x, y, z]}, {axis, degrees} or
// {yaw_pitch_roll_degrees: [yaw, pitch, roll]}, as hullkit.checkRoute reads it. A traverse vertex
// v is placed at pivot + R (v - pivot) + position; along a leg the position moves linearly and the
// orientation turns at constant angular speed along the shorter arc (slerp), over the same
// fraction t, as the library's checker moves it. Quaternions are [w, x, y, z] arrays.

export const IDENTITY = Object.freeze([1, 0, 0, 0]);
/** A turning leg is drawn as hulls of sub-intervals of at most this many degrees each. */
export const SUBINTERVAL_DEGREES = 12;

const RAD = Math.PI / 180;
const Z_AXIS = [0, 0, 1];

/** The waypoint's position: the array itself (changing it moves the waypoint). */
export function positionOf(waypoint) {
  return Array.isArray(waypoint) ? waypoint : waypoint.position;
}

/** Whether the waypoint carries a rotation. */
export const isTurned = (waypoint) => !Array.isArray(waypoint) && waypoint.rotation != null;

/** A deep copy of a waypoint list. */
export const copyRoute = (route) => route.map((w) => structuredClone(w));

export function multiply(a, b) {
  return [
    a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
    a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
    a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
    a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0],
  ];
}

/** The turn of `degrees` about `axis` (right-handed). */
function axisAngle(axis, degrees) {
  const length = Math.hypot(...axis);
  const s = Math.sin(0.5 * degrees * RAD) / length;
  return [Math.cos(0.5 * degrees * RAD), s * axis[0], s * axis[1], s * axis[2]];
}

/** The unit quaternion of a waypoint's rotation (the identity for [x, y, z]). */
export function quaternionOf(waypoint) {
  if (!isTurned(waypoint)) return [...IDENTITY];
  const r = waypoint.rotation;
  if (r.quaternion) {
    const length = Math.hypot(...r.quaternion);
    return r.quaternion.map((c) => c / length);
  }
  if (r.axis) return axisAngle(r.axis, r.degrees);
  const [yaw, pitch, roll] = r.yaw_pitch_roll_degrees;
  // Yaw about z, then pitch about the turned y, then roll about the turned x.
  return multiply(multiply(axisAngle(Z_AXIS, yaw), axisAngle([0, 1, 0], pitch)), axisAngle([1, 0, 0], roll));
}

/** [yaw, pitch, roll] in degrees of a unit quaternion (the inverse of yaw_pitch_roll_degrees). */
export function yawPitchRoll([w, x, y, z]) {
  const yaw = Math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z));
  const pitch = Math.asin(Math.max(-1, Math.min(1, 2 * (w * y - z * x))));
  const roll = Math.atan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y));
  return [yaw / RAD, pitch / RAD, roll / RAD];
}

/** An angle in degrees brought into (-180, 180]. */
export function wrapDegrees(degrees) {
  const d = ((degrees % 360) + 360) % 360;
  return d > 180 ? d - 360 : d;
}

/** The waypoint's yaw (its turn about z, in degrees; 0 without a rotation). */
export function yawOf(waypoint) {
  if (!isTurned(waypoint)) return 0;
  const r = waypoint.rotation;
  if (r.axis && r.axis[0] === 0 && r.axis[1] === 0 && r.axis[2] > 0) return wrapDegrees(r.degrees);
  return yawPitchRoll(quaternionOf(waypoint))[0];
}

const tiny = (degrees) => Math.abs(degrees) < 1e-9;

/**
 * The waypoint with its yaw set to `degrees` (pitch and roll kept): a turn about z when that is
 * all it turns, plain [x, y, z] when it no longer turns.
 */
export function withYaw(waypoint, degrees) {
  const position = [...positionOf(waypoint)];
  const yaw = wrapDegrees(degrees);
  const [, pitch, roll] = isTurned(waypoint) ? yawPitchRoll(quaternionOf(waypoint)) : [0, 0, 0];
  if (tiny(pitch) && tiny(roll)) {
    return tiny(yaw) ? position : { position, rotation: { axis: [0, 0, 1], degrees: yaw } };
  }
  return { position, rotation: { yaw_pitch_roll_degrees: [yaw, pitch, roll] } };
}

/**
 * The motion along the leg from waypoint `a` to `b`: {p0, p1, q0, axis, phi, degrees}, phi half
 * the angle turned (0 for a leg that does not turn), degrees the angle turned.
 */
export function legMotion(a, b) {
  const q0 = quaternionOf(a);
  let q1 = quaternionOf(b);
  const motion = { p0: positionOf(a), p1: positionOf(b), q0, axis: Z_AXIS, phi: 0, degrees: 0 };
  if (q0[0] * q1[0] + q0[1] * q1[1] + q0[2] * q1[2] + q0[3] * q1[3] < 0) q1 = q1.map((c) => -c); // the shorter arc
  const relative = multiply([q0[0], -q0[1], -q0[2], -q0[3]], q1);
  const s = Math.hypot(relative[1], relative[2], relative[3]);
  if (!(s > 1e-15)) return motion;
  motion.axis = [relative[1] / s, relative[2] / s, relative[3] / s];
  motion.phi = Math.atan2(s, Math.max(relative[0], 0));
  motion.degrees = (2 * motion.phi) / RAD;
  return motion;
}

/** {position, quaternion} at fraction t of a leg's motion. */
export function poseAt(motion, t) {
  const position = motion.p0.map((x, k) => x + t * (motion.p1[k] - x));
  if (motion.phi === 0) return { position, quaternion: motion.q0 };
  const s = Math.sin(t * motion.phi);
  return { position, quaternion: multiply(motion.q0, [Math.cos(t * motion.phi), s * motion.axis[0], s * motion.axis[1], s * motion.axis[2]]) };
}

/** How many sub-intervals a leg's swept volume is drawn as: one per SUBINTERVAL_DEGREES turned, at least 1. */
export const subintervalCount = (motion) => Math.max(1, Math.ceil(motion.degrees / SUBINTERVAL_DEGREES - 1e-9));

/** v turned by the unit quaternion q. */
export function rotate([w, x, y, z], [vx, vy, vz]) {
  // v + 2 w (u × v) + 2 u × (u × v), u = (x, y, z)
  const cx = y * vz - z * vy, cy = z * vx - x * vz, cz = x * vy - y * vx;
  return [
    vx + 2 * (w * cx + y * cz - z * cy),
    vy + 2 * (w * cy + z * cx - x * cz),
    vz + 2 * (w * cz + x * cy - y * cx),
  ];
}

/** The point `v` of the traverse (its own coordinates) placed at `pose` about `pivot`. */
export function placePoint(v, pivot, { position, quaternion }) {
  const r = rotate(quaternion, [v[0] - pivot[0], v[1] - pivot[1], v[2] - pivot[2]]);
  return [pivot[0] + r[0] + position[0], pivot[1] + r[1] + position[1], pivot[2] + r[2] + position[2]];
}

/** The flat vertices x0 y0 z0 ... placed at `pose`, written into `out` from index `at`. */
export function placeVertices(vertices, pivot, pose, out, at = 0) {
  for (let i = 0; i < vertices.length; i += 3) {
    const p = placePoint([vertices[i], vertices[i + 1], vertices[i + 2]], pivot, pose);
    out[at + i] = p[0];
    out[at + i + 1] = p[1];
    out[at + i + 2] = p[2];
  }
  return out;
}

/** The waypoint's pose {position, quaternion}. */
export const poseOf = (waypoint) => ({ position: positionOf(waypoint), quaternion: quaternionOf(waypoint) });

/** A waypoint at `position` with orientation `quaternion`: plain, turned about z, or a quaternion. */
export function waypointAt(position, quaternion) {
  const [yaw, pitch, roll] = yawPitchRoll(quaternion);
  if (Math.abs(pitch) < 1e-9 && Math.abs(roll) < 1e-9) return withYaw(position, Number(yaw.toFixed(6)));
  return { position, rotation: { quaternion: [...quaternion] } };
}
