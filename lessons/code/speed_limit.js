// A speed limit: a ball faster than max is slowed down to max, keeping
// its direction. (A crude stand-in for drag's terminal speed.)
function limitSpeed(world, balls) {
  const max = world.speedLimit.max;
  for (const b of balls) {
    const speed = Math.sqrt(b.vx * b.vx + b.vy * b.vy);
    const factor = max / speed;
    if (factor < 1) {
      b.vx = b.vx * factor;
      b.vy = b.vy * factor;
    }
  }
}
afterMove.push(limitSpeed);
