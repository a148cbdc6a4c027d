// Stage 29, the collision along the line of impact n: with the approach
// speed vn = (vb - va)·n < 0, the impulse j = -(1 + e) vn / (wa + wb)
// changes va by -wa j n and vb by +wb j n. Along the contact nothing changes.
function respond(e, d, n, wa, wb, a, b) {
  const vn = (b.vx - a.vx) * n.x + (b.vy - a.vy) * n.y;
  const w = wa + wb;
  if (!(vn < 0) || !(w > 0 && Number.isFinite(w))) {
    return;
  }
  const j = -(1 + e) * vn / (wa + wb);
  a.vx = a.vx - (wa * j) * n.x;
  a.vy = a.vy - (wa * j) * n.y;
  b.vx = b.vx + (wb * j) * n.x;
  b.vy = b.vy + (wb * j) * n.y;
}
