// The pointer pulls every ball while it hovers over the box and pushes
// while the button is held: the inverse-square rule of inverse_square.js,
// like a point force that follows the mouse. With no pointer over the box
// it does nothing.
function pointerForce(world, state, acc) {
  const p = world.pointer;
  if (!p || !p.inside) {
    return;
  }
  const f = world.pointerForce;
  addInverseSquare(p.x, p.y, f.strength, !p.pressed, f.maxAccel, null, false, state, acc);
}
forces.push(pointerForce);
