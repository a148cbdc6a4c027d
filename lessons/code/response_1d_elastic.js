// Stage 27, the 1D collision with both masses: along x, with u = b.vx - a.vx
// the impulse j = -(1 + e) u / (wa + wb) changes a.vx by -wa j and b.vx by
// +wb j (w = 1 / m). Momentum is kept; for e = 1 the energy too.
function impulse1D(e, wa, wb, ua, ub) {
  const j = -(1 + e) * (ub - ua) / (wa + wb);
  return [ua - wa * j, ub + wb * j];
}

function respond(e, d, n, wa, wb, a, b) {
  const w = wa + wb;
  if (!((b.vx - a.vx) * d.x < 0) || !(w > 0 && Number.isFinite(w))) {
    return;
  }
  [a.vx, b.vx] = impulse1D(e, wa, wb, a.vx, b.vx);
}
