// Detection, sort and sweep: sort the balls by their left edge. Going
// along the sorted list, a ball can only touch the balls whose left edge
// comes before its right edge: stop looking at the first one that does not.
// The pairs found are then put in (a, b) order, as the other detections give them.
function findContacts(balls) {
  const order = [];
  for (let i = 0; i < balls.length; i++) {
    order.push(i);
  }
  order.sort((i, j) => (balls[i].x - balls[i].r) - (balls[j].x - balls[j].r));
  const contacts = [];
  for (let k = 0; k < order.length; k++) {
    const a = balls[order[k]];
    for (let l = k + 1; l < order.length; l++) {
      const b = balls[order[l]];
      if (b.x - b.r > a.x + a.r) {
        break; // every ball after this one starts further right still
      }
      if (touching(a, b)) {
        contacts.push([Math.min(order[k], order[l]), Math.max(order[k], order[l])]);
      }
    }
  }
  contacts.sort((p, q) => p[0] - q[0] || p[1] - q[1]);
  return contacts;
}
