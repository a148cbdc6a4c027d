// A spring (an elastic band) to the anchor: a = -k (x - anchor).
function spring(world, state, acc) {
  const s = world.spring;
  for (let i = 0; i < state.length; i++) {
    acc[i].x = acc[i].x - s.k * (state[i].x - s.x);
    acc[i].y = acc[i].y - s.k * (state[i].y - s.y);
  }
}
forces.push(spring);
