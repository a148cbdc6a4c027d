// A point that pulls (attract) or pushes (repel) every ball with
// |a| = strength / d², along the line from the point to the ball,
// at most maxAccel when that is above 0. At d = 0 there is no direction.
// "unnormalised" is the course's bug: the difference (dx, dy) itself, not
// its direction, times strength / d², so |a| = strength / d.
function pointForce(world, state, acc) {
  const p = world.point;
  const sign = p.kind === "attract" ? -1 : 1;
  for (let i = 0; i < state.length; i++) {
    const dx = state[i].x - p.x;
    const dy = state[i].y - p.y;
    const d2 = dx * dx + dy * dy;
    if (d2 === 0) {
      continue;
    }
    const dist = Math.sqrt(d2);
    let size = p.unnormalised ? p.strength / dist : p.strength / d2;
    if (p.scale !== "none") {
      size = size * scaleFactor(p.scale, state[i]);
    }
    if (p.maxAccel > 0 && size > p.maxAccel) {
      size = p.maxAccel;
    }
    const f = sign * size / dist;
    acc[i].x = acc[i].x + f * dx;
    acc[i].y = acc[i].y + f * dy;
  }
}
forces.push(pointForce);
