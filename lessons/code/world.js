// The world's step, the part every stage shares.
// A ball is an object {x, y, vx, vy, r, m}: position (px), velocity (px/s),
// radius (px) and mass; q (its charge) and hx, hy (its home) are there for
// the magnetic field and homing. `world` holds the settings and the time.
// The other files add their rules to the four lists below (var, not const:
// each file is a script of its own, and only var is seen by the others).

var forces = [];     // each adds its acceleration: force(world, balls, acc, t)
var stepStarts = []; // each draws this step's random values: draw(world, balls)
var afterMove = [];  // speed limit, walls, collisions: rule(world, balls, h)
var stepEnds = [];   // after the last sub-step (new balls): rule(world, balls)

// The mass of a ball of density 1: a sphere, 4/3 π r³.
function sphereMass(r) {
  return 1 * (4 / 3) * Math.PI * r * r * r;
}

// The acceleration of every ball: start at zero, let every force add to it.
// `state` is a list of {x, y, vx, vy, r, m}: the balls, or a trial state.
function accelerations(world, state, t) {
  const acc = [];
  for (let i = 0; i < state.length; i++) {
    acc.push({ x: 0, y: 0 });
  }
  for (const force of forces) {
    force(world, state, acc, t);
  }
  return acc;
}

// One step of length dt, cut into `substeps` equal pieces.
function step(world, balls) {
  for (const draw of stepStarts) {
    draw(world, balls);
  }
  // Stage 5's bug: with perFrame, every step moves the balls by 1/60 s.
  const length = world.perFrame ? 1 / 60 : world.dt;
  const h = length / world.substeps;
  let subTime = 0;
  for (let k = 0; k < world.substeps; k++) {
    // Where each ball starts the sub-step: the walls need it.
    for (const b of balls) {
      b.x0 = b.x;
      b.y0 = b.y;
      b.vx0 = b.vx;
      b.vy0 = b.vy;
    }
    move(world, balls, h, world.time + subTime);
    subTime = subTime + h;
    for (const rule of afterMove) {
      rule(world, balls, h);
    }
  }
  for (const rule of stepEnds) {
    rule(world, balls);
  }
  addTime(world, world.dt);
}

// time += dt, keeping the rounding error in `timeCarry` (Kahan's sum), so
// the clock does not run ahead of the balls after millions of steps.
function addTime(world, dt) {
  const y = dt - world.timeCarry;
  const sum = world.time + y;
  world.timeCarry = (sum - world.time) - y;
  world.time = sum;
}
