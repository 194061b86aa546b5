// The colour map of the search's costs (viridis-like, perceptually ordered) and its range.

const STOPS = [
  [0.267, 0.005, 0.329], [0.283, 0.141, 0.458], [0.254, 0.265, 0.530], [0.207, 0.372, 0.553],
  [0.164, 0.471, 0.558], [0.128, 0.567, 0.551], [0.135, 0.659, 0.518], [0.267, 0.749, 0.441],
  [0.478, 0.821, 0.318], [0.741, 0.873, 0.150], [0.993, 0.906, 0.144],
];

/** Costs at or above this are "unreached" (the Rust side writes ∞ as a large number). */
export const UNREACHED = 1e30;
/** The colour of an unreached cost. */
export const GREY = [0.6, 0.6, 0.6];

/** The colour at `t` in [0, 1] (clamped), as linear-ish RGB in [0, 1]. */
export function colourAt(t) {
  const x = Math.min(Math.max(Number.isFinite(t) ? t : 0, 0), 1) * (STOPS.length - 1);
  const i = Math.min(Math.floor(x), STOPS.length - 2);
  const f = x - i;
  return STOPS[i].map((c, k) => c + (STOPS[i + 1][k] - c) * f);
}

/** [min, max] of the reached costs, or null when none is. */
export function costRange(costs) {
  let lo = Infinity;
  let hi = -Infinity;
  for (const c of costs) {
    if (Number.isFinite(c) && c < UNREACHED) { lo = Math.min(lo, c); hi = Math.max(hi, c); }
  }
  return lo <= hi ? [lo, hi] : null;
}

/** The colour of `cost` within `range` (grey when unreached). */
export function colourOfCost(cost, range) {
  if (!range || !Number.isFinite(cost) || cost >= UNREACHED) return GREY;
  const [lo, hi] = range;
  return colourAt(hi > lo ? (cost - lo) / (hi - lo) : 0.5);
}

/** A CSS linear-gradient of the map, for the legend. */
export function cssGradient() {
  const stops = STOPS.map((c, i) => `rgb(${c.map((v) => Math.round(v * 255)).join(',')}) ${(100 * i) / (STOPS.length - 1)}%`);
  return `linear-gradient(to right, ${stops.join(', ')})`;
}
