// Every pair of balls pulls together: F = G m1 m2 d / (d² + ε²)^(3/2),
// with softening ε so that a very close pass stays gentle. Each pair is
// computed once and acts on both balls, in opposite directions.
function mutualGravity(world, state, acc) {
  const G = world.mutualGravity.G;
  const eps2 = world.mutualGravity.softening * world.mutualGravity.softening;
  for (let i = 0; i < state.length; i++) {
    let aix = 0;
    let aiy = 0;
    for (let j = i + 1; j < state.length; j++) {
      const dx = state[j].x - state[i].x;
      const dy = state[j].y - state[i].y;
      const r2 = dx * dx + dy * dy;
      if (r2 === 0) {
        continue;
      }
      const s2 = r2 + eps2;
      const f = G / (s2 * Math.sqrt(s2));
      aix = aix + (f * state[j].m) * dx;
      aiy = aiy + (f * state[j].m) * dy;
      acc[j].x = acc[j].x - (f * state[i].m) * dx;
      acc[j].y = acc[j].y - (f * state[i].m) * dy;
    }
    acc[i].x = acc[i].x + aix;
    acc[i].y = acc[i].y + aiy;
  }
}
forces.push(mutualGravity);
