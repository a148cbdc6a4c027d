// Detection, halved: the pair (i, j) is the pair (j, i), so test each pair
// once, j after i: N (N - 1) / 2 tests.
function findContacts(balls) {
  const contacts = [];
  for (let i = 0; i < balls.length; i++) {
    for (let j = i + 1; j < balls.length; j++) {
      if (touching(balls[i], balls[j])) {
        contacts.push([i, j]);
      }
    }
  }
  return contacts;
}
