// Runge-Kutta 4: four trial slopes across the step, weighted 1, 2, 2, 1.
// A trial state is a copy of the balls with other positions and velocities.
function trial(balls, prev, acc, f) {
  const state = [];
  for (let i = 0; i < balls.length; i++) {
    const b = balls[i];
    state.push({
      x: b.x + f * prev[i].vx,  // position: start + f × the previous trial's velocity
      y: b.y + f * prev[i].vy,
      vx: b.vx + f * acc[i].x, // velocity: start + f × the previous trial's acceleration
      vy: b.vy + f * acc[i].y,
      r: b.r, m: b.m, q: b.q, hx: b.hx, hy: b.hy,
    });
  }
  return state;
}

function move(world, balls, h, t) {
  const s0 = balls;
  const a0 = accelerations(world, s0, t);
  const s1 = trial(balls, s0, a0, 0.5 * h);
  const a1 = accelerations(world, s1, t + 0.5 * h);
  const s2 = trial(balls, s1, a1, 0.5 * h);
  const a2 = accelerations(world, s2, t + 0.5 * h);
  const s3 = trial(balls, s2, a2, h);
  const a3 = accelerations(world, s3, t + h);
  for (let i = 0; i < balls.length; i++) {
    const b = balls[i];
    const dx = ((s0[i].vx + 2 * s1[i].vx) + 2 * s2[i].vx) + s3[i].vx;
    const dy = ((s0[i].vy + 2 * s1[i].vy) + 2 * s2[i].vy) + s3[i].vy;
    const dvx = ((a0[i].x + 2 * a1[i].x) + 2 * a2[i].x) + a3[i].x;
    const dvy = ((a0[i].y + 2 * a1[i].y) + 2 * a2[i].y) + a3[i].y;
    b.x = b.x + (h / 6) * dx;
    b.y = b.y + (h / 6) * dy;
    b.vx = b.vx + (h / 6) * dvx;
    b.vy = b.vy + (h / 6) * dvy;
  }
}
