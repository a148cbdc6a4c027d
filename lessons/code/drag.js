// Drag slows a ball down: linear a = -c v, quadratic a = -c |v| v.
// With scale "none" every ball has c = k; otherwise c = k × scaleFactor,
// so with "mass" a heavy ball slows down less.
function drag(world, state, acc) {
  const d = world.drag;
  for (let i = 0; i < state.length; i++) {
    const b = state[i];
    const a = acc[i];
    const speed = Math.sqrt(b.vx * b.vx + b.vy * b.vy);
    if (d.scale === "none") {
      if (d.law === "linear") {
        a.x = a.x - d.k * b.vx;
        a.y = a.y - d.k * b.vy;
      } else {
        a.x = a.x - d.k * (b.vx * speed);
        a.y = a.y - d.k * (b.vy * speed);
      }
    } else {
      const c = d.k * scaleFactor(d.scale, b);
      if (d.law === "linear") {
        a.x = a.x - b.vx * c;
        a.y = a.y - b.vy * c;
      } else {
        a.x = a.x - b.vx * (c * speed);
        a.y = a.y - b.vy * (c * speed);
      }
    }
  }
}
forces.push(drag);
