// How strongly a force acts on a ball of this size, compared with the
// 10 px reference ball: "none" the same for all, "radius" 10 / r,
// "mass" (a force, not an acceleration) m_ref / m.
function scaleFactor(scale, ball) {
  if (scale === "mass") {
    return sphereMass(10) * (1 / ball.m);
  }
  if (scale === "radius") {
    return 10 * (1 / ball.r);
  }
  return 1;
}
