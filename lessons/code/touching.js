// Do two balls touch? Their centres are closer than the sum of the radii.
// Compared as squares, so no square root is taken for every pair.
function touching(a, b) {
  const dx = b.x - a.x;
  const dy = b.y - a.y;
  const s = a.r + b.r;
  return dx * dx + dy * dy < s * s;
}
