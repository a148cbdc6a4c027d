// Detection, brute force: test every ball against every other ball,
// N (N - 1) tests. Each touching pair is kept once, as (a, b) with a < b.
function findContacts(balls) {
  const contacts = [];
  for (let i = 0; i < balls.length; i++) {
    for (let j = 0; j < balls.length; j++) {
      if (j !== i && touching(balls[i], balls[j]) && i < j) {
        contacts.push([i, j]);
      }
    }
  }
  return contacts;
}
