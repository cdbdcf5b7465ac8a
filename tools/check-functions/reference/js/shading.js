// cases: 13 (tests/cases/13-shading.json)
// Chapter 13, "Shading", in plain JavaScript, as the book writes it: the runner's
// reference (tools/check-functions). A triangle's own normal ("Flat Shading") and
// UnProjectVertex ("Phong Shading"), which undoes ProjectVertex for a pixel and its 1/z;
// the book's globals Cw, Ch, Vw, Vh and d are the ones the checker sets.
"use strict";

function ComputeTriangleNormal(A, B, C) {
  const u = B.map((each, i) => each - A[i]);
  const v = C.map((each, i) => each - A[i]);
  const N = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
  const length = Math.hypot(...N);
  return N.map((each) => each / length);
}

function UnProjectVertex(x, y, inv_z) {
  const z = 1 / inv_z;
  return [x * Vw / Cw * z / d, y * Vh / Ch * z / d, z];
}

module.exports = { ComputeTriangleNormal, UnProjectVertex };
