// Frames between frames: positions lerp, rotations slerp; and the slider's time or path fraction.

/** Spherical interpolation of unit quaternions [x, y, z, w] (the short way round), into `out`. */
export function slerp(q0, q1, t, out = [0, 0, 0, 1]) {
  let [x1, y1, z1, w1] = q1;
  let dot = q0[0] * x1 + q0[1] * y1 + q0[2] * z1 + q0[3] * w1;
  if (dot < 0) { x1 = -x1; y1 = -y1; z1 = -z1; w1 = -w1; dot = -dot; }
  let a = 1 - t;
  let b = t;
  if (dot < 0.9995) {
    const angle = Math.acos(dot);
    const s = Math.sin(angle);
    a = Math.sin((1 - t) * angle) / s;
    b = Math.sin(t * angle) / s;
  }
  out[0] = a * q0[0] + b * x1; out[1] = a * q0[1] + b * y1;
  out[2] = a * q0[2] + b * z1; out[3] = a * q0[3] + b * w1;
  const n = Math.hypot(out[0], out[1], out[2], out[3]) || 1;
  for (let i = 0; i < 4; i++) out[i] /= n;
  return out;
}

/** Frame `f` (fractional) of `poses`, `stride` values a frame: `positions` of 3 lerp, and when
 * `stride` is 7 per link, quaternions slerp. Writes `out` (length `stride`). */
export function frameAt(poses, stride, frames, f, out, quaternions) {
  const clamped = Math.min(Math.max(f, 0), frames - 1);
  const i = Math.min(Math.floor(clamped), frames - 1);
  const j = Math.min(i + 1, frames - 1);
  const t = clamped - i;
  const a = i * stride;
  const b = j * stride;
  for (let k = 0; k < stride; k++) out[k] = poses[a + k] + (poses[b + k] - poses[a + k]) * t;
  if (quaternions) {
    const q = [0, 0, 0, 1];
    for (let k = 0; k < stride; k += 7) {
      slerp(poses.subarray(a + k + 3, a + k + 7), poses.subarray(b + k + 3, b + k + 7), t, q);
      out[k + 3] = q[0]; out[k + 4] = q[1]; out[k + 5] = q[2]; out[k + 6] = q[3];
    }
  }
  return out;
}

/** The slider's measure of each frame: the motion's times, else the fraction of path length
 * (through the joint values, else the poses), ascending from 0. */
export function progressOf(motion, stride) {
  const n = motion.frames;
  if (motion.times && motion.times.length === n) return { kind: 'time', values: Float64Array.from(motion.times) };
  const dof = motion.joint_names.length;
  const [values, width] = dof > 0 ? [motion.joints, dof] : [motion.poses, stride];
  const out = new Float64Array(n);
  for (let i = 1; i < n; i++) {
    let s = 0;
    for (let k = 0; k < width; k++) {
      const d = values[i * width + k] - values[(i - 1) * width + k];
      s += d * d;
    }
    out[i] = out[i - 1] + Math.sqrt(s);
  }
  const total = out[n - 1];
  for (let i = 0; i < n; i++) out[i] = total > 0 ? out[i] / total : n > 1 ? i / (n - 1) : 0;
  return { kind: 'fraction', values: out };
}

/** The fractional frame at which the ascending `values` reach `v`. */
export function frameOfValue(values, v) {
  const n = values.length;
  if (n < 2 || v <= values[0]) return 0;
  if (v >= values[n - 1]) return n - 1;
  let lo = 0;
  let hi = n - 1;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (values[mid] <= v) lo = mid; else hi = mid;
  }
  const span = values[hi] - values[lo];
  return lo + (span > 0 ? (v - values[lo]) / span : 0);
}

/** The value at fractional frame `f` (the inverse of `frameOfValue`). */
export function valueOfFrame(values, f) {
  const n = values.length;
  if (n === 0) return 0;
  const c = Math.min(Math.max(f, 0), n - 1);
  const i = Math.min(Math.floor(c), n - 1);
  const j = Math.min(i + 1, n - 1);
  return values[i] + (values[j] - values[i]) * (c - i);
}
