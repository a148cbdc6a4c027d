// The collision pass, after the walls: find the touching pairs, then for
// each pair in (a, b) order: the response changes the velocities, and the
// push-apart moves the two balls out of each other.
// The line of impact n runs from a's centre to b's, taken from the positions
// at detection, so it does not depend on which pair went first.
// (Stage 23-25 only flag the touching balls: respond is then null.)
function collide(world, balls) {
  const contacts = findContacts(balls);
  for (const b of balls) {
    b.colliding = false;
  }
  for (const [i, j] of contacts) {
    balls[i].colliding = true;
    balls[j].colliding = true;
  }
  if (contacts.length === 0 || typeof respond !== "function") {
    return;
  }
  const detected = balls.map((b) => ({ x: b.x, y: b.y }));
  const e = world.collisions.restitution;
  for (const [i, j] of contacts) {
    const a = balls[i];
    const b = balls[j];
    const s = a.r + b.r;
    const wa = 1 / a.m;
    const wb = 1 / b.m;
    const d = { x: detected[j].x - detected[i].x, y: detected[j].y - detected[i].y };
    const n = lineOfImpact(d, s, i, j);
    respond(e, d, n, wa, wb, a, b);
    const depth = s - Math.sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y));
    if (depth > 0) {
      pushApart(world, a, b, n, wa, wb, depth);
    }
  }
}

// From a to b, one pixel long. Two balls on one point get a fixed
// direction of their own (well spread over the pairs, not random).
function lineOfImpact(d, s, i, j) {
  const len = Math.sqrt(d.x * d.x + d.y * d.y);
  if (len > 1e-12 * s && Number.isFinite(len)) {
    return { x: d.x / len, y: d.y / len };
  }
  const u = i * 0.7548776662466927 + j * 0.5698402909980532;
  const angle = 2 * Math.PI * (u - Math.floor(u));
  return { x: Math.cos(angle), y: Math.sin(angle) };
}
afterMove.push(collide);
