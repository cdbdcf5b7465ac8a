// Chapter 11's clipping in CommonJS, vectors read as objects (v.x, v.y, v.z) and made
// as objects; ClipTriangle appends the new vertices to the list and returns the
// triangles, following Listing 11-3. Written for the checker's corpus
// (tests/check-functions/check_corpus.mjs).
"use strict";

const dot = (a, b) => a.x * b.x + a.y * b.y + a.z * b.z;
const minus = (a, b) => ({ x: a.x - b.x, y: a.y - b.y, z: a.z - b.z });
const along = (a, t, d) => ({ x: a.x + t * d.x, y: a.y + t * d.y, z: a.z + t * d.z });

function SignedDistance(plane, vertex) {
  return dot(plane.normal, vertex) + plane.D;
}

function Intersection(A, B, plane) {
  const AB = minus(B, A);
  const t = (-plane.D - dot(plane.normal, A)) / dot(plane.normal, AB);
  return along(A, t, AB);
}

function ClipTriangle(triangle, plane, vertices) {
  const v = triangle.v;
  const d = v.map((i) => SignedDistance(plane, vertices[i]));
  const inside = d.filter((each) => each >= 0).length;
  if (inside === 3) return [triangle];
  if (inside === 0) return [];
  const add = (point) => vertices.push(point) - 1;
  if (inside === 1) {
    const a = d.findIndex((each) => each >= 0);
    const [A, B, C] = [v[a], v[(a + 1) % 3], v[(a + 2) % 3]];
    const B2 = add(Intersection(vertices[A], vertices[B], plane));
    const C2 = add(Intersection(vertices[A], vertices[C], plane));
    return [{ v: [A, B2, C2], color: triangle.color }];
  }
  const c = d.findIndex((each) => each < 0);
  const [A, B, C] = [v[(c + 1) % 3], v[(c + 2) % 3], v[c]];
  const A2 = add(Intersection(vertices[A], vertices[C], plane));
  const B2 = add(Intersection(vertices[B], vertices[C], plane));
  return [{ v: [A, B, A2], color: triangle.color }, { v: [A2, B, B2], color: triangle.color }];
}

function ComputeBoundingSphere(vertices) {
  const center = vertices.reduce((sum, p) => along(sum, 1 / vertices.length, p), { x: 0, y: 0, z: 0 });
  const radius = Math.max(...vertices.map((p) => Math.sqrt(dot(minus(p, center), minus(p, center)))));
  return { center, radius };
}

module.exports = { SignedDistance, Intersection, ClipTriangle, ComputeBoundingSphere };
