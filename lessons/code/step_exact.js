// The exact parabola: with a constant acceleration a, in a time h a ball
// moves by v h + ½ a h², and its velocity changes by a h.
function move(world, balls, h, t) {
  const acc = accelerations(world, balls, t);
  for (let i = 0; i < balls.length; i++) {
    const b = balls[i];
    b.x = b.x + (h * b.vx + (0.5 * h * h) * acc[i].x);
    b.y = b.y + (h * b.vy + (0.5 * h * h) * acc[i].y);
    b.vx = b.vx + h * acc[i].x;
    b.vy = b.vy + h * acc[i].y;
  }
}
