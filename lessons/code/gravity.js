// Gravity: the same acceleration g for every ball, heavy or light.
function gravity(world, state, acc) {
  for (let i = 0; i < state.length; i++) {
    acc[i].x = acc[i].x + world.gravity.x;
    acc[i].y = acc[i].y + world.gravity.y;
  }
}
forces.push(gravity);
