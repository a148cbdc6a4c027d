// An inverse-square pull (attract) or push from the point (px, py) on every
// ball: |a| = strength / d², along the line from the point to the ball, at
// most maxAccel when that is above 0. At d = 0 there is no direction.
// scaleOf(ball) scales the size for each ball (null: the same for all).
// "unnormalised" is the course's bug: the difference (dx, dy) itself, not
// its direction, times strength / d², so |a| = strength / d.
function addInverseSquare(px, py, strength, attract, maxAccel, scaleOf, unnormalised, state, acc) {
  const sign = attract ? -1 : 1;
  for (let i = 0; i < state.length; i++) {
    const dx = state[i].x - px;
    const dy = state[i].y - py;
    const d2 = dx * dx + dy * dy;
    if (d2 === 0) {
      continue;
    }
    const dist = Math.sqrt(d2);
    let size = unnormalised ? strength / dist : strength / d2;
    if (scaleOf) {
      size = size * scaleOf(state[i]);
    }
    if (maxAccel > 0 && size > maxAccel) {
      size = maxAccel;
    }
    const f = sign * size / dist;
    acc[i].x = acc[i].x + f * dx;
    acc[i].y = acc[i].y + f * dy;
  }
}
