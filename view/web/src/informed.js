// The informed set {x : |x − start| + |x − goal| ≤ cost}: a prolate spheroid as a transform of
// the unit sphere.

/** Centre, semi-axes [a, b, b] and the rotation [x, y, z, w] taking the x axis to the focal
 * axis, or null when the cost is not a positive finite number. */
export function informedTransform(start, goal, cost) {
  if (!Number.isFinite(cost) || cost <= 0) return null;
  const axis = [goal[0] - start[0], goal[1] - start[1], goal[2] - start[2]];
  const d = Math.hypot(...axis);
  const centre = [0, 1, 2].map((k) => (start[k] + goal[k]) / 2);
  const a = cost / 2;
  const b = Math.sqrt(Math.max(cost * cost - d * d, 0)) / 2;
  let quaternion = [0, 0, 0, 1];
  if (d > 0) {
    const u = axis.map((v) => v / d);
    if (u[0] < -1 + 1e-9) {
      quaternion = [0, 0, 1, 0];
    } else {
      // Half-way quaternion between x and u: (x × u, 1 + x·u), normalised.
      const q = [0, -u[2], u[1], 1 + u[0]];
      const n = Math.hypot(...q);
      quaternion = q.map((v) => v / n);
    }
  }
  return { centre, semiAxes: [a, b, b], quaternion };
}
