// cases: 10 (tests/cases/10-scene-rendering.json)
// Chapter 10, "Describing and Rendering a Scene", in plain JavaScript, as the book writes
// it: the checker's reference (tools/check-functions). The homogeneous matrices of
// "Homogeneous Coordinates", ApplyTransform (Listing 10-4) and MakeCameraMatrix (Listing
// 10-5); a matrix is an array of its rows, and a matrix times a point takes (x, y, z, 1).
"use strict";

function MakeTranslationMatrix([x, y, z]) {
  return [[1, 0, 0, x], [0, 1, 0, y], [0, 0, 1, z], [0, 0, 0, 1]];
}

function MakeScalingMatrix(scale) {
  return [[scale, 0, 0, 0], [0, scale, 0, 0], [0, 0, scale, 0], [0, 0, 0, 1]];
}

function MakeOYRotationMatrix(degrees) {
  const cos = Math.cos(degrees * Math.PI / 180), sin = Math.sin(degrees * Math.PI / 180);
  return [[cos, 0, -sin, 0], [0, 1, 0, 0], [sin, 0, cos, 0], [0, 0, 0, 1]];
}

const range4 = [0, 1, 2, 3];

function MultiplyMM4(A, B) {
  return range4.map((i) => range4.map((j) => range4.reduce((sum, k) => sum + A[i][k] * B[k][j], 0)));
}

function MultiplyMV(M, v) {
  return range4.map((i) => range4.reduce((sum, k) => sum + M[i][k] * v[k], 0));
}

function Transposed(M) {
  return range4.map((i) => range4.map((j) => M[j][i]));
}

function ApplyTransform(vertex, transform) {
  const scaled = [...vertex.map((each) => each * transform.scale), 1];
  const rotated = MultiplyMV(transform.rotation, scaled);
  return [0, 1, 2].map((i) => rotated[i] + transform.translation[i]);
}

function MakeCameraMatrix(position, orientation) {
  return MultiplyMM4(Transposed(orientation), MakeTranslationMatrix(position.map((each) => -each)));
}

module.exports = {
  MakeTranslationMatrix, MakeScalingMatrix, MakeOYRotationMatrix, ApplyTransform, MakeCameraMatrix,
};
