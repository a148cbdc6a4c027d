// Homing: every ball is tied to its own home (hx, hy) by a spring,
// a = strength × (home - x).
function homing(world, state, acc) {
  const strength = world.homing.strength;
  for (let i = 0; i < state.length; i++) {
    acc[i].x = acc[i].x + strength * (state[i].hx - state[i].x);
    acc[i].y = acc[i].y + strength * (state[i].hy - state[i].y);
  }
}
forces.push(homing);
