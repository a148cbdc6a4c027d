// A point that pulls (attract) or pushes (repel) every ball: the
// inverse-square rule of inverse_square.js from the point's place, its size
// scaled for each ball as the lesson says (scale.js).
function pointForce(world, state, acc) {
  const p = world.point;
  const scaleOf = p.scale === "none" ? null : (ball) => scaleFactor(p.scale, ball);
  addInverseSquare(p.x, p.y, p.strength, p.kind === "attract", p.maxAccel, scaleOf, p.unnormalised, state, acc);
}
forces.push(pointForce);
