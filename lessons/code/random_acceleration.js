// A random acceleration per ball, each component in [-strength, strength).
// Drawn once per step (x then y, ball by ball); "fixed" draws it only once.
// "uncentred" is the course's first program: strength * Math.random(), in
// [0, strength), which always pushes right and down.
function drawRandomAcceleration(world, balls) {
  const r = world.randomAccel;
  if (!r.rng) {
    r.rng = makeRandom(seedFromText(world.seed));
    r.values = [];
  }
  const from = r.fixed ? Math.min(r.values.length, balls.length) : 0;
  r.values.length = Math.min(r.values.length, balls.length);
  for (let i = from; i < balls.length; i++) {
    const x = r.strength * (r.uncentred ? unit(r.rng) : symmetric(r.rng));
    const y = r.strength * (r.uncentred ? unit(r.rng) : symmetric(r.rng));
    r.values[i] = { x: x, y: y };
  }
}

function randomAcceleration(world, state, acc) {
  const values = world.randomAccel.values;
  if (values.length !== acc.length) {
    return;
  }
  for (let i = 0; i < acc.length; i++) {
    acc[i].x = acc[i].x + values[i].x;
    acc[i].y = acc[i].y + values[i].y;
  }
}
stepStarts.push(drawRandomAcceleration);
forces.push(randomAcceleration);
