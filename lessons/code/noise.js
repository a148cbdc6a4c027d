// Smooth random noise in [-1, 1] for the "noise" wind: a random slope at
// every whole number, blended smoothly in between (1D gradient noise).
function makeNoise(seed) {
  const rng = makeRandom(xor64(seedFromText(seed), u64(0x9e3779b9, 0x7f4a7c15)));
  const slopes = [];
  for (let i = 0; i < 256; i++) {
    slopes.push(symmetric(rng));
  }
  return slopes;
}

function noise(slopes, t) {
  const cell = Math.floor(t);
  const f = t - cell;
  const i = ((cell % 256) + 256) % 256;
  const g0 = slopes[i];
  const g1 = slopes[(i + 1) % 256];
  const fade = f * f * f * (f * (f * 6 - 15) + 10);
  const v0 = g0 * f;
  const v1 = g1 * (f - 1);
  return Math.min(Math.max(2 * (v0 + fade * (v1 - v0)), -1), 1);
}
