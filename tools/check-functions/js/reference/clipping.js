// cases: 11 (tests/cases/11-clipping.json)
// Chapter 11, "Clipping", in plain JavaScript, as the book writes it: the runner's
// reference (tools/check-functions). SignedDistance (Listing 11-4), the segment's
// Intersection with a plane ("Clipping Triangles") and the bounding sphere of "Clipping
// Whole Objects".
"use strict";

const Dot = (a, b) => a.reduce((sum, each, i) => sum + each * b[i], 0);

function SignedDistance(plane, vertex) {
  return Dot(vertex, plane.normal) + plane.D;
}

function Intersection(A, B, plane) {
  const AB = B.map((each, i) => each - A[i]);
  const t = (-plane.D - Dot(plane.normal, A)) / Dot(plane.normal, AB);
  return A.map((each, i) => each + t * AB[i]);
}

function ComputeBoundingSphere(vertices) {
  const center = [0, 1, 2].map((i) => vertices.reduce((sum, v) => sum + v[i], 0) / vertices.length);
  const radius = Math.max(...vertices.map((v) => Math.hypot(...v.map((each, i) => each - center[i]))));
  return { center, radius };
}

module.exports = { SignedDistance, Intersection, ComputeBoundingSphere };
