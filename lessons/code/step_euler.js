// Explicit Euler: the position moves with the OLD velocity, then the
// velocity changes. Swap the two pairs of lines and it is semi-implicit Euler.
function move(world, balls, h, t) {
  const acc = accelerations(world, balls, t);
  for (let i = 0; i < balls.length; i++) {
    const b = balls[i];
    b.x = b.x + h * b.vx;
    b.y = b.y + h * b.vy;
    b.vx = b.vx + h * acc[i].x;
    b.vy = b.vy + h * acc[i].y;
  }
}
