// Stage 26, the naive 1D try: if the two balls approach along x, turn both
// horizontal velocities round. Momentum is kept only by luck.
function respond(e, d, n, wa, wb, a, b) {
  if (!((b.vx - a.vx) * d.x < 0)) {
    return;
  }
  a.vx = -a.vx;
  b.vx = -b.vx;
}
