// Chapter 6 as an ES module: points as objects {x, y}, PutPixel a settable export, the
// book's Interpolate and DrawLine. Written for the checker's corpus
// (tests/check-functions/check_corpus.mjs).
export let PutPixel = (x, y, color) => {
  throw new Error("no canvas yet");
};

export function Interpolate(i0, d0, i1, d1) {
  if (i0 === i1) return [d0];
  const slope = (d1 - d0) / (i1 - i0);
  return Array.from({ length: i1 - i0 + 1 }, (_, k) => d0 + slope * k);
}

export function DrawLine(P0, P1, color) {
  let [a, b] = [P0, P1];
  if (Math.abs(b.x - a.x) > Math.abs(b.y - a.y)) {
    if (a.x > b.x) [a, b] = [b, a];
    const ys = Interpolate(a.x, a.y, b.x, b.y);
    for (let x = a.x; x <= b.x; x++) PutPixel(x, ys[x - a.x], color);
  } else {
    if (a.y > b.y) [a, b] = [b, a];
    const xs = Interpolate(a.y, a.x, b.y, b.x);
    for (let y = a.y; y <= b.y; y++) PutPixel(xs[y - a.y], y, color);
  }
}
