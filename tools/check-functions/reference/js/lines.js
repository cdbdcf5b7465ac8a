// cases: 06 (tests/cases/06-lines.json)
// Chapter 6, "Lines", in plain JavaScript, as the book writes it: the checker's
// reference (tools/check-functions), one script as a reader writes it on a chapter's
// page. Interpolate (Listing 6-1) and DrawLine (Listing 6-2), which draws with the
// book's PutPixel (the checker's, or the page's, in its place).
"use strict";

let Cw = 600, Ch = 600;  // the canvas
let PutPixel = () => { throw new Error("the canvas goes here"); };

// Listing 6-1: the values of d for each whole i from i0 to i1, d0 to d1 in a line. The
// book adds a at each step (d = d + a), which drifts: d0 + a (i - i0) does not
// (docs/conventions.md).
function Interpolate(i0, d0, i1, d1) {
  if (i0 === i1) return [d0];
  const values = [];
  const a = (d1 - d0) / (i1 - i0);
  for (let i = i0; i <= i1; i++) values.push(d0 + a * (i - i0));
  return values;
}

// Listing 6-2: one pixel per step along the axis the line spans most.
function DrawLine(P0, P1, color) {
  if (Math.abs(P1.x - P0.x) > Math.abs(P1.y - P0.y)) {
    // The line is horizontal-ish. Make sure x0 < x1
    if (P0.x > P1.x) [P0, P1] = [P1, P0];
    const ys = Interpolate(P0.x, P0.y, P1.x, P1.y);
    for (let x = P0.x; x <= P1.x; x++) PutPixel(x, ys[x - P0.x], color);
  } else {
    // The line is vertical-ish. Make sure y0 < y1
    if (P0.y > P1.y) [P0, P1] = [P1, P0];
    const xs = Interpolate(P0.y, P0.x, P1.y, P1.x);
    for (let y = P0.y; y <= P1.y; y++) PutPixel(xs[y - P0.y], y, color);
  }
}
