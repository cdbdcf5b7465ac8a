// cases: 11 (tests/cases/11-clipping.json)
// Chapter 11, "Clipping", in plain JavaScript, as the book writes it: the runner's
// reference (tools/check-functions). SignedDistance (Listing 11-4), the segment's
// Intersection with a plane and ClipTriangle ("Clipping Triangles", Listing 11-3), and
// the bounding sphere of "Clipping Whole Objects".
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

function ClipTriangle(triangle, plane, vertices) {
  const inFront = triangle.v.map((i) => SignedDistance(plane, vertices[i]) >= 0);
  const count = inFront.filter(Boolean).length;
  if (count === 3) return [triangle];
  if (count === 0) return [];
  // Where the segment from vertex a to vertex b crosses the plane.
  const NewVertex = (a, b) => vertices.push(Intersection(vertices[a], vertices[b], plane)) - 1;
  // One in front: A is that one. Two: C is the one behind. The others follow in order.
  const k = inFront.indexOf(count === 1);
  const [first, second, third] = [0, 1, 2].map((n) => triangle.v[(k + n) % 3]);
  const { color } = triangle;
  if (count === 1) {
    const [A, B, C] = [first, second, third];
    return [{ v: [A, NewVertex(A, B), NewVertex(A, C)], color }];
  }
  const [C, A, B] = [first, second, third];
  const APrime = NewVertex(A, C), BPrime = NewVertex(B, C);
  return [{ v: [A, B, APrime], color }, { v: [APrime, B, BPrime], color }];
}

function ComputeBoundingSphere(vertices) {
  const center = [0, 1, 2].map((i) => vertices.reduce((sum, v) => sum + v[i], 0) / vertices.length);
  const radius = Math.max(...vertices.map((v) => Math.hypot(...v.map((each, i) => each - center[i]))));
  return { center, radius };
}

module.exports = { SignedDistance, Intersection, ClipTriangle, ComputeBoundingSphere };
