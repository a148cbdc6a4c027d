// A magnetic field B out of the screen turns a moving charge q without
// changing its speed: a = w (vy, -vx) with w = B m_ref q / m.
function magnetic(world, state, acc) {
  const B = world.magnetic.B;
  for (let i = 0; i < state.length; i++) {
    const w = (B * sphereMass(10)) * (state[i].q * (1 / state[i].m));
    acc[i].x = acc[i].x + w * state[i].vy;
    acc[i].y = acc[i].y - w * state[i].vx;
  }
}
forces.push(magnetic);
