// The random generator: the 64-bit Mersenne Twister (mt19937_64), the same
// numbers as the C++ engine's std::mt19937_64, bit for bit. JavaScript
// numbers hold only 53 bits exactly, so a 64-bit number is kept as two
// 32-bit halves, {hi, lo}, and every operation works on the halves.

function u64(hi, lo) {
  return { hi: hi >>> 0, lo: lo >>> 0 };
}

function xor64(a, b) {
  return u64(a.hi ^ b.hi, a.lo ^ b.lo);
}

function and64(a, b) {
  return u64(a.hi & b.hi, a.lo & b.lo);
}

function shiftRight64(a, k) {
  if (k >= 32) {
    return u64(0, a.hi >>> (k - 32));
  }
  return u64(a.hi >>> k, (a.lo >>> k) | (a.hi << (32 - k)));
}

function shiftLeft64(a, k) {
  if (k >= 32) {
    return u64(a.lo << (k - 32), 0);
  }
  return u64((a.hi << k) | (a.lo >>> (32 - k)), a.lo << k);
}

// a × b, keeping the low 64 bits: long multiplication in 16-bit digits.
function multiply64(a, b) {
  const x = [a.lo & 0xffff, a.lo >>> 16, a.hi & 0xffff, a.hi >>> 16];
  const y = [b.lo & 0xffff, b.lo >>> 16, b.hi & 0xffff, b.hi >>> 16];
  const digit = [0, 0, 0, 0];
  let carry = 0;
  for (let k = 0; k < 4; k++) {
    let sum = carry;
    for (let i = 0; i <= k; i++) {
      sum = sum + x[i] * y[k - i];
    }
    digit[k] = sum % 65536;
    carry = Math.floor(sum / 65536);
  }
  return u64(digit[3] * 65536 + digit[2], digit[1] * 65536 + digit[0]);
}

function addSmall64(a, n) {
  const lo = a.lo + n;
  return lo >= 4294967296 ? u64(a.hi + 1, lo - 4294967296) : u64(a.hi, lo);
}

// A seed written in decimal ("12"): any 64-bit number.
function seedFromText(text) {
  let seed = u64(0, 0);
  for (const c of String(text)) {
    seed = addSmall64(multiply64(seed, u64(0, 10)), c.charCodeAt(0) - 48);
  }
  return seed;
}

function makeRandom(seed) {
  const mt = [seed];
  const f = u64(0x5851F42D, 0x4C957F2D); // 6364136223846793005
  for (let i = 1; i < 312; i++) {
    const prev = mt[i - 1];
    mt.push(addSmall64(multiply64(f, xor64(prev, shiftRight64(prev, 62))), i));
  }
  return { mt: mt, index: 312 };
}

// A generator that goes on from where another one got to: its 312 numbers
// (written in decimal) and how many of them it has used.
function randomFromState(words, index) {
  return { mt: words.map(seedFromText), index: index };
}

// Mixes all 312 numbers into the next 312.
function twist(rng) {
  const mt = rng.mt;
  const matrix = u64(0xB5026F5A, 0xA96619E9);
  for (let i = 0; i < 312; i++) {
    // The top bit of this number's low half and 31 bits of the next one.
    const y = u64(mt[i].hi, (mt[i].lo & 0x80000000) | (mt[(i + 1) % 312].lo & 0x7fffffff));
    let next = xor64(mt[(i + 156) % 312], shiftRight64(y, 1));
    if (y.lo & 1) {
      next = xor64(next, matrix);
    }
    mt[i] = next;
  }
  rng.index = 0;
}

// The next 64-bit number, as {hi, lo}.
function nextRandom(rng) {
  if (rng.index >= 312) {
    twist(rng);
  }
  let y = rng.mt[rng.index];
  rng.index = rng.index + 1;
  y = xor64(y, and64(shiftRight64(y, 29), u64(0x55555555, 0x55555555)));
  y = xor64(y, and64(shiftLeft64(y, 17), u64(0x71D67FFF, 0xEDA60000)));
  y = xor64(y, and64(shiftLeft64(y, 37), u64(0xFFF7EEE0, 0x00000000)));
  y = xor64(y, shiftRight64(y, 43));
  return y;
}

// A number in [0, 1): the top 53 bits of the next number, times 2^-53
// (what Math.random() gives, from the engine's own generator).
function unit(rng) {
  const y = nextRandom(rng);
  const top53 = y.hi * 2097152 + (y.lo >>> 11); // the number >> 11, exact in a double
  return top53 * Math.pow(2, -53);
}

// A number in [-1, 1): 2u - 1, centred on zero.
function symmetric(rng) {
  return 2 * unit(rng) - 1;
}
