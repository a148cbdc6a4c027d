// The pointer pulls every ball while it hovers over the box and pushes
// while the button is held: strength / d², at most maxAccel, like a point
// force that follows the mouse. With no pointer over the box it does nothing.
function pointerForce(world, state, acc) {
  const p = world.pointer;
  if (!p || !p.inside) {
    return;
  }
  const sign = p.pressed ? 1 : -1; // pressed: push away; hovering: pull
  for (let i = 0; i < state.length; i++) {
    const dx = state[i].x - p.x;
    const dy = state[i].y - p.y;
    const d2 = dx * dx + dy * dy;
    if (d2 === 0) {
      continue;
    }
    const dist = Math.sqrt(d2);
    let size = world.pointerForce.strength / d2;
    if (world.pointerForce.maxAccel > 0 && size > world.pointerForce.maxAccel) {
      size = world.pointerForce.maxAccel;
    }
    const f = sign * size / dist;
    acc[i].x = acc[i].x + f * dx;
    acc[i].y = acc[i].y + f * dy;
  }
}
forces.push(pointerForce);
