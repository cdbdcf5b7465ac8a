// Chapter 13's two small functions in CommonJS, vectors as arrays, returning objects
// {x, y, z}. Written for the checker's corpus (tests/check-functions/check_corpus.mjs).
"use strict";

let Cw = 600, Ch = 600, Vw = 1, Vh = 1, d = 1;

function UnProjectVertex(x, y, inv_z) {
  const z = 1 / inv_z;
  return { x: ((x * Vw) / Cw) * (z / d), y: ((y * Vh) / Ch) * (z / d), z };
}

function ComputeTriangleNormal(A, B, C) {
  const u = [B[0] - A[0], B[1] - A[1], B[2] - A[2]];
  const v = [C[0] - A[0], C[1] - A[1], C[2] - A[2]];
  const n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
  const length = Math.hypot(...n);
  return { x: n[0] / length, y: n[1] / length, z: n[2] / length };
}

module.exports = { UnProjectVertex, ComputeTriangleNormal };
