// Push-apart: two balls that overlap by `depth` are moved apart along n,
// each by its share of the inverse masses (a light ball moves more). A ball
// that would end up outside a wall it was inside stops at the wall, and its
// partner takes what it could not.
function insideWalls(world, x, y, r) {
  const w = world.walls;
  return (!w.left || x >= r) && (!w.right || x <= world.width - r) &&
         (!w.top || y >= r) && (!w.bottom || y <= world.height - r);
}

// Puts `after` back on a wall that `before` was inside; true if it did.
function keepInsideWalls(world, before, after, r) {
  const w = world.walls;
  const on = [[w.left, w.right], [w.top, w.bottom]];
  const size = [world.width, world.height];
  const keys = ["x", "y"];
  let moved = false;
  for (let k = 0; k < 2; k++) {
    let lo = r;
    let hi = size[k] - r;
    if (lo > hi) {
      lo = hi = 0.5 * size[k];
    }
    const c = keys[k];
    if (on[k][0] && before[c] >= lo && after[c] < lo) {
      after[c] = lo;
      moved = true;
    }
    if (on[k][1] && before[c] <= hi && after[c] > hi) {
      after[c] = hi;
      moved = true;
    }
  }
  return moved;
}

function pushApart(world, a, b, n, wa, wb, depth) {
  const w = wa + wb;
  const shareA = (w > 0 && Number.isFinite(w)) ? wa / w : 0.5;
  const moveA = depth * shareA;
  const qa = { x: a.x - moveA * n.x, y: a.y - moveA * n.y };
  const qb = { x: b.x + (depth - moveA) * n.x, y: b.y + (depth - moveA) * n.y };
  if (insideWalls(world, qa.x, qa.y, a.r) && insideWalls(world, qb.x, qb.y, b.r)) {
    a.x = qa.x; a.y = qa.y;
    b.x = qb.x; b.y = qb.y;
    return;
  }
  // Near a wall: a moves first and may stop there; b takes the rest, and
  // if b stops too, a takes what is still missing.
  const pa = { x: a.x, y: a.y };
  const pb = { x: b.x, y: b.y };
  const qa1 = { x: pa.x - moveA * n.x, y: pa.y - moveA * n.y };
  const movedA = keepInsideWalls(world, pa, qa1, a.r) ? (pa.x - qa1.x) * n.x + (pa.y - qa1.y) * n.y : moveA;
  const qb1 = { x: pb.x + (depth - movedA) * n.x, y: pb.y + (depth - movedA) * n.y };
  let qaEnd = qa1;
  if (keepInsideWalls(world, pb, qb1, b.r)) {
    const missing = depth - movedA - ((qb1.x - pb.x) * n.x + (qb1.y - pb.y) * n.y);
    if (missing > 0) {
      const qa2 = { x: qa1.x - missing * n.x, y: qa1.y - missing * n.y };
      keepInsideWalls(world, qa1, qa2, a.r);
      qaEnd = qa2;
    }
  }
  a.x = qaEnd.x; a.y = qaEnd.y;
  b.x = qb1.x; b.y = qb1.y;
}
