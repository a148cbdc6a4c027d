// Stage 28, the naive 2D try: the 1D collision on x and on y separately,
// on each axis where the balls approach. An off-centre hit goes wrong.
function impulse1D(e, wa, wb, ua, ub) {
  const j = -(1 + e) * (ub - ua) / (wa + wb);
  return [ua - wa * j, ub + wb * j];
}

function respond(e, d, n, wa, wb, a, b) {
  const w = wa + wb;
  if (!(w > 0 && Number.isFinite(w))) {
    return;
  }
  if ((b.vx - a.vx) * d.x < 0) {
    [a.vx, b.vx] = impulse1D(e, wa, wb, a.vx, b.vx);
  }
  if ((b.vy - a.vy) * d.y < 0) {
    [a.vy, b.vy] = impulse1D(e, wa, wb, a.vy, b.vy);
  }
}
