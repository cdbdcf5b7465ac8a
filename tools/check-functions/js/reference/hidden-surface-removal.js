// cases: 12 (tests/cases/12-hidden-surface-removal.json)
// Chapter 12, "Hidden Surface Removal", in plain JavaScript, as the book writes it: the
// runner's reference (tools/check-functions). Classifying a triangle ("Classifying
// Triangles") and CullBackFaces (Listing 12-1), which keeps the triangles that face the
// camera.
"use strict";

const Subtract = (a, b) => a.map((each, i) => each - b[i]);
const Cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const Dot = (a, b) => a.reduce((sum, each, i) => sum + each * b[i], 0);

function IsBackFacing(A, B, C, camera) {
  const N = Cross(Subtract(B, A), Subtract(C, A));
  const V = Subtract(camera, A);
  return Dot(N, V) <= 0;
}

function CullBackFaces(object, camera) {
  const V = object.vertices;
  object.triangles = object.triangles.filter((T) => !IsBackFacing(V[T.v[0]], V[T.v[1]], V[T.v[2]], camera));
}

module.exports = { IsBackFacing, CullBackFaces };
