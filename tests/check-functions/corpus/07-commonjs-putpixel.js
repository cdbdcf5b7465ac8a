// Chapter 7 in CommonJS as the book writes it: a global PutPixel over an image of its
// own, points as objects {x, y}, Interpolate and DrawLine carried forward from chapter 6.
// Written for the checker's corpus (tests/check-functions/check_corpus.mjs).
"use strict";

const Cw = 600, Ch = 600;
const image = new Map();

function PutPixel(x, y, color) {
  image.set(`${Math.trunc(x)},${Math.trunc(y)}`, color);
}

function Interpolate(i0, d0, i1, d1) {
  if (i0 === i1) return [d0];
  const values = [];
  const a = (d1 - d0) / (i1 - i0);
  for (let i = i0; i <= i1; i++) values.push(d0 + a * (i - i0));
  return values;
}

function DrawLine(P0, P1, color) {
  if (Math.abs(P1.x - P0.x) > Math.abs(P1.y - P0.y)) {
    if (P0.x > P1.x) [P0, P1] = [P1, P0];
    const ys = Interpolate(P0.x, P0.y, P1.x, P1.y);
    for (let x = P0.x; x <= P1.x; x++) PutPixel(x, ys[x - P0.x], color);
  } else {
    if (P0.y > P1.y) [P0, P1] = [P1, P0];
    const xs = Interpolate(P0.y, P0.x, P1.y, P1.x);
    for (let y = P0.y; y <= P1.y; y++) PutPixel(xs[y - P0.y], y, color);
  }
}

function DrawWireframeTriangle(P0, P1, P2, color) {
  DrawLine(P0, P1, color);
  DrawLine(P1, P2, color);
  DrawLine(P2, P0, color);
}

function DrawFilledTriangle(P0, P1, P2, color) {
  if (P1.y < P0.y) [P0, P1] = [P1, P0];
  if (P2.y < P0.y) [P0, P2] = [P2, P0];
  if (P2.y < P1.y) [P1, P2] = [P2, P1];
  const x01 = Interpolate(P0.y, P0.x, P1.y, P1.x);
  const x12 = Interpolate(P1.y, P1.x, P2.y, P2.x);
  const x02 = Interpolate(P0.y, P0.x, P2.y, P2.x);
  x01.pop();
  const x012 = x01.concat(x12);
  const m = Math.floor(x012.length / 2);
  const [left, right] = x02[m] < x012[m] ? [x02, x012] : [x012, x02];
  for (let y = P0.y; y <= P2.y; y++) {
    for (let x = Math.trunc(left[y - P0.y]); x <= Math.trunc(right[y - P0.y]); x++) PutPixel(x, y, color);
  }
}

module.exports = { Interpolate, DrawLine, DrawWireframeTriangle, DrawFilledTriangle };

if (require.main === module) {
  DrawFilledTriangle({ x: -200, y: -250 }, { x: 200, y: 50 }, { x: 20, y: 250 }, [0, 255, 0]);
  console.log(`${image.size} pixels`);
}
