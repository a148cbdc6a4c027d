// Semi-implicit Euler: first the velocity, then the position with the NEW
// velocity. Every acceleration is found before any ball moves.
function move(world, balls, h, t) {
  const acc = accelerations(world, balls, t);
  for (let i = 0; i < balls.length; i++) {
    const b = balls[i];
    b.vx = b.vx + h * acc[i].x;
    b.vy = b.vy + h * acc[i].y;
    b.x = b.x + h * b.vx;
    b.y = b.y + h * b.vy;
  }
}
