// Spawning over time: at the end of each step, with the chance perStep, one
// more random ball appears, until the world holds maxCount balls. Spawning
// has a generator of its own, so new balls do not change the wind.
function uniform(rng, lo, hi) {
  const y = nextRandom(rng);
  const u = (y.hi * 2097152 + (y.lo >>> 11)) * Math.pow(2, -53); // in [0, 1)
  return lo + (hi - lo) * u;
}

function randomBall(spawn, world, rng) {
  const r = uniform(rng, spawn.minRadius, spawn.maxRadius);
  // Fully inside the box when asked (and when it fits), else anywhere.
  const mx = spawn.fullyInside ? Math.min(r, 0.5 * world.width) : 0;
  const my = spawn.fullyInside ? Math.min(r, 0.5 * world.height) : 0;
  // y is drawn before x, as the engine does (sim/world/scene.cpp): the
  // order of two draws changes which ball comes out.
  const y = uniform(rng, my, world.height - my);
  const x = uniform(rng, mx, world.width - mx);
  const speed = uniform(rng, spawn.minSpeed, spawn.maxSpeed);
  const angle = uniform(rng, 0, 2 * Math.PI);
  // Its colour k, and its home for homing: the k-th of `colours` points on
  // a circle round the centre of the box.
  const k = Math.min(spawn.colours - 1, Math.floor(uniform(rng, 0, spawn.colours)));
  let hx = 0.5 * world.width;
  let hy = 0.5 * world.height;
  if (spawn.colours > 1) {
    const around = 0.3 * Math.min(world.width, world.height);
    const turn = 2 * Math.PI * k / spawn.colours;
    hx = hx + around * Math.cos(turn);
    hy = hy + around * Math.sin(turn);
  }
  const ball = { x: x, y: y, vx: 0, vy: 0, r: r, m: sphereMass(r), q: 1, hx: hx, hy: hy };
  if (spawn.horizontal) {
    ball.vx = Math.cos(angle) < 0 ? -speed : speed;
  } else {
    ball.vx = speed * Math.cos(angle);
    ball.vy = speed * Math.sin(angle);
  }
  return ball;
}

function spawnOverTime(world, balls) {
  const spawn = world.spawn;
  if (!spawn.rng) {
    spawn.rng = makeRandom(xor64(seedFromText(spawn.seed), u64(0, 0x5bd1e995)));
  }
  if (spawn.perStep <= 0 || balls.length >= spawn.maxCount) {
    return;
  }
  if (uniform(spawn.rng, 0, 1) >= spawn.perStep) {
    return;
  }
  balls.push(randomBall(spawn, world, spawn.rng));
}
stepEnds.push(spawnOverTime);
