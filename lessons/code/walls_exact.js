// The exact wall (stage 5): find WHEN the ball's edge touches the wall
// during the sub-step, bounce there, and follow the path for the rest of
// the sub-step, as often as it meets a wall again.
// The path inside the step is what the update step really does: the Euler
// methods drift in a straight line at d = (p1 - p0) / h and change the
// velocity in one kick; the others follow the parabola p0 + u0 t + ½ a t².

function stepPath(world, p0, u0, p1, u1, h) {
  if (world.integrator === "euler" || world.integrator === "semi-implicit-euler") {
    const d = (p1 - p0) / h;
    return { drift: d, accel: 0, endKick: u1 - d, stepKick: u1 - u0, kickDrift: true,
             midStepDrift: world.integrator === "semi-implicit-euler" };
  }
  return { drift: u0, accel: (u1 - u0) / h, endKick: 0, stepKick: u1 - u0, kickDrift: false, midStepDrift: false };
}

// When does p0 + u t + ½ a t² reach `wall`, moving into it (into = +1 for
// the high wall, -1 for the low one)? The smallest such t in [0, tMax], or NaN.
function wallContactTime(p0, u, a, wall, into, tMax) {
  const A = 0.5 * a;
  const B = u;
  const C = p0 - wall;
  let best = NaN;
  function consider(t) {
    if (!(t >= 0 && t <= tMax) || t >= best) {
      return;
    }
    const towards = into * (u + a * t);
    if (towards > 0 || (towards === 0 && into * a > 0)) {
      best = t;
    }
  }
  if (A === 0) {
    if (B !== 0) {
      consider(-C / B);
    }
    return best;
  }
  const disc = B * B - 4 * A * C;
  if (disc < 0) {
    return best;
  }
  // The roots without cancellation: q = -½ (B + sign(B) √disc), roots q / A and C / q.
  const signB = B < 0 || Object.is(B, -0) ? -1 : 1;
  const q = -0.5 * (B + signB * Math.sqrt(disc));
  if (q !== 0) {
    consider(q / A);
    consider(C / q);
  } else {
    consider(0);
  }
  return best;
}

// Semi-implicit Euler's drift after a bounce with e < 1: the speed at the
// impact is the drift less the kick still to come before mid-step.
function midStepRebound(path, hitSpeed, e, elapsed, h) {
  const kick = path.stepKick / h;
  const toMid = 0.5 * h - elapsed;
  return -e * (hitSpeed - kick * toMid) + kick * toMid;
}

// Under a pull towards the wall with e < 1 the bounces get lower and lower
// and all of them together take 2 s / (g (1 - e)): if that ends within the
// time left, the ball comes to rest on the wall.
function bouncesSettleWithin(speed, pull, e, otherWall, span, within) {
  if (!(pull > 0 && e < 1) || (otherWall && speed * speed >= 2 * pull * span)) {
    return false;
  }
  return 2 * Math.abs(speed) / (pull * (1 - e)) <= within;
}

// Returns [position, velocity] at the end of the sub-step along one axis.
function exactWall(ax, e, path, p0, h, p, u) {
  if (outside(ax, p0)) { // started outside: nothing to solve
    return clampAxis(ax, e, p, u);
  }
  if (ax.lo === ax.hi) { // wedged between two walls
    return [ax.lo, 0];
  }
  const a = path.accel;
  let start = p0;
  let speed = path.drift;
  let left = h;
  let cycleWall = -1; // with e = 1 the motion repeats: skip whole cycles
  let cycleLeft = 0;
  for (let bounce = 0; bounce < 4096; bounce++) {
    if (bounce > 0) {
      const end = start + speed * left + 0.5 * a * left * left;
      if (!outside(ax, end)) {
        return [end, speed + a * left + path.endKick];
      }
    }
    const tLo = ax.loOn ? wallContactTime(start, speed, a, ax.lo, -1, left) : NaN;
    const tHi = ax.hiOn ? wallContactTime(start, speed, a, ax.hi, 1, left) : NaN;
    const hitLo = !isNaN(tLo) && (isNaN(tHi) || tLo <= tHi);
    const t = hitLo ? tLo : tHi;
    if (isNaN(t)) { // the path and the update step disagree: clamp
      return clampAxis(ax, e, p, u);
    }
    const hitSpeed = speed + a * t;
    start = hitLo ? ax.lo : ax.hi;
    speed = path.midStepDrift && e < 1 ? midStepRebound(path, hitSpeed, e, h - left + t, h) : -e * hitSpeed;
    left = Math.max(0, left - t);
    if (hitSpeed === 0) { // touching with no speed: resting on the wall
      return [start, 0];
    }
    const pull = hitLo ? -a : a;
    const otherOn = hitLo ? ax.hiOn : ax.loOn;
    if (bouncesSettleWithin(speed, pull, e, otherOn, ax.hi - ax.lo, left)) {
      return [start, 0];
    }
    // The Euler methods cannot lift a ball off the wall by less than one kick.
    const kickTowards = hitLo ? -path.stepKick : path.stepKick;
    if (path.kickDrift && e < 1 && kickTowards > 0 && Math.abs(speed) <= kickTowards &&
        !(otherOn && Math.abs(speed) * left >= ax.hi - ax.lo)) {
      return [start, 0];
    }
    if (e === 1) {
      const wall = hitLo ? 0 : 1;
      if (cycleWall < 0) {
        cycleWall = wall;
        cycleLeft = left;
      } else if (wall === cycleWall && cycleLeft > left) {
        left = left % (cycleLeft - left);
        cycleWall = 2; // skipped once; the rest bounce by bounce
      }
    }
  }
  return [start, speed + path.endKick]; // out of bounces: at the wall it last left
}
