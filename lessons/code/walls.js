// The walls of the box. Along each axis a ball's centre must stay between
// lo = r and hi = size - r (with centreOnly, stage 3's bug, r is taken as 0).
// Models: "clamp" puts the ball back on the wall and turns its velocity
// round (times the restitution e); "reverse" only turns the velocity round;
// "mirror" reflects the overshoot back into the box; "exact" is in
// walls_exact.js.
// A ball that lay still on a wall at the start of the sub-step and was only
// pressed into it (by gravity, say) is put back and stays at rest.

// The next number above x: the right side of the middle wall starts there.
function nextUp(x) {
  const bits = new DataView(new ArrayBuffer(8));
  bits.setFloat64(0, x);
  let hi = bits.getUint32(0);
  let lo = bits.getUint32(4);
  if (x >= 0) { // one more in the last place: the bits as a 64-bit number plus 1
    lo = lo + 1;
    if (lo === 4294967296) { lo = 0; hi = hi + 1; }
  } else {
    if (lo === 0) { lo = 4294967295; hi = hi - 1; } else { lo = lo - 1; }
  }
  bits.setUint32(0, hi);
  bits.setUint32(4, lo);
  return bits.getFloat64(0);
}

function clampAxis(ax, e, p, u) {
  if (ax.loOn && p < ax.lo) {
    p = ax.lo;
    if (u < 0) u = -e * u;
  } else if (ax.hiOn && p > ax.hi) {
    p = ax.hi;
    if (u > 0) u = -e * u;
  }
  return [p, u];
}

// Started the sub-step on a wall with no speed across it, and only the
// pull (not a fall) took it onto or into the wall.
function pressedWhileResting(ax, p0, u0, p, u) {
  if (u0 !== 0) {
    return false;
  }
  if (ax.hiOn && p0 === ax.hi) {
    return p > ax.hi || (p === ax.hi && u >= 0);
  }
  if (ax.loOn && p0 === ax.lo) {
    return p < ax.lo || (p === ax.lo && u <= 0);
  }
  return false;
}

function outside(ax, p) {
  return (ax.loOn && p < ax.lo) || (ax.hiOn && p > ax.hi);
}

function bounceOnWalls(world, balls, h) {
  const w = world.walls;
  const middle = 0.5 * world.width;
  const axes = [
    { p: "x", v: "vx", size: world.width, loOn: w.left, hiOn: w.right },
    { p: "y", v: "vy", size: world.height, loOn: w.top, hiOn: w.bottom },
  ];
  for (const axis of axes) {
    const middleHere = axis.p === "x" && w.middle;
    if (!axis.loOn && !axis.hiOn && !middleHere) {
      continue;
    }
    for (const b of balls) {
      const e = w.restitution;
      const r = w.centreOnly ? 0 : b.r;
      let ax = { lo: r, hi: axis.size - r, loOn: axis.loOn, hiOn: axis.hiOn };
      if (middleHere) { // the middle wall bounds the side the ball started on
        if (b.x0 <= middle) {
          ax = { lo: ax.lo, hi: middle - r, loOn: ax.loOn, hiOn: true };
        } else {
          ax = { lo: Math.max(middle + r, nextUp(middle)), hi: ax.hi, loOn: true, hiOn: ax.hiOn };
        }
      }
      if (ax.lo > ax.hi) { // wider than the space it has
        ax.lo = ax.hi = 0.5 * (ax.lo + ax.hi);
      }
      const p0 = b[axis.p + "0"];
      const u0 = b[axis.v + "0"];
      let p = b[axis.p];
      let u = b[axis.v];
      // Lying still on a wall and pressed into it: a resting contact.
      if (pressedWhileResting(ax, p0, u0, p, u)) {
        b[axis.p] = p0;
        b[axis.v] = 0;
        continue;
      }
      if (!outside(ax, p)) {
        continue;
      }
      if (w.model === "exact") {
        [p, u] = exactWall(ax, e, stepPath(world, p0, u0, p, u, h), p0, h, p, u);
      } else if (w.model === "reverse") {
        u = -e * u;
      } else if (w.model === "mirror") {
        if (ax.loOn && p < ax.lo) {
          p = ax.lo + (ax.lo - p);
          if (u < 0) u = -e * u;
        } else if (ax.hiOn && p > ax.hi) {
          p = ax.hi - (p - ax.hi);
          if (u > 0) u = -e * u;
        }
        if (outside(ax, p)) { // overshoot larger than the box
          [p, u] = clampAxis(ax, e, p, u);
        }
      } else {
        [p, u] = clampAxis(ax, e, p, u);
      }
      b[axis.p] = p;
      b[axis.v] = u;
    }
  }
}
afterMove.push(bounceOnWalls);
