// Wind blows along x. "random": a new value every step; "smoothed": each
// step changes it a little (a random walk kept within ±strength); "noise":
// a smooth function of time; "pointer": blows away from the pointer's side.
// The wind has its own random generator, seeded like the world's.
function drawWind(world) {
  const w = world.wind;
  if (!w.rng) {
    w.rng = makeRandom(seedFromText(world.seed));
    w.slopes = makeNoise(world.seed);
    w.value = 0;
  }
  if (w.mode === "random") {
    w.value = w.strength * symmetric(w.rng);
  } else if (w.mode === "smoothed") {
    const change = w.smoothedStep * w.strength * symmetric(w.rng);
    w.value = Math.min(Math.max(w.value + change, -w.strength), w.strength);
  } else if (w.mode === "pointer") {
    const half = 0.5 * world.width;
    if (world.pointer && world.pointer.inside) {
      const side = Math.min(Math.max((world.pointer.x - half) / half, -1), 1);
      w.value = -w.strength * side;
    } else {
      w.value = 0;
    }
  } else {
    w.value = 0;
  }
}

function windAt(world, t) {
  const w = world.wind;
  if (w.mode === "noise") {
    return w.strength * noise(w.slopes, t * w.frequency);
  }
  return w.value;
}

function wind(world, state, acc, t) {
  const w = windAt(world, t);
  for (let i = 0; i < state.length; i++) {
    acc[i].x = acc[i].x + w * scaleFactor(world.wind.scale, state[i]);
  }
}
stepStarts.push(drawWind);
forces.push(wind);
