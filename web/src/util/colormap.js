// The "turbo" colormap (Mikhailov 2019, polynomial fit): s in [0, 1] -> r, g, b in [0, 1].

function clamp01(x) {
  return x < 0 ? 0 : x > 1 ? 1 : x;
}

/** Writes turbo(s) into out[offset..offset+2]. */
export function turbo(s, out, offset) {
  const x = clamp01(s);
  const x2 = x * x, x3 = x2 * x, x4 = x3 * x, x5 = x4 * x;
  out[offset] = clamp01(0.13572138 + 4.6153926 * x - 42.66032258 * x2 + 132.13108234 * x3 -
    152.94239396 * x4 + 59.28637943 * x5);
  out[offset + 1] = clamp01(0.09140261 + 2.19418839 * x + 4.84296658 * x2 - 14.18503333 * x3 +
    4.27729857 * x4 + 2.82956604 * x5);
  out[offset + 2] = clamp01(0.1066733 + 12.64194608 * x - 60.58204836 * x2 + 110.36276771 * x3 -
    89.90310912 * x4 + 27.34824973 * x5);
}

/** turbo sampled at `n` steps (sRGB values, r g b triplets). */
export function turboTable(n = 256) {
  const table = new Float32Array(3 * n);
  for (let i = 0; i < n; i++) turbo(i / (n - 1), table, 3 * i);
  return table;
}
