// Chapter 11 as an ES module: vectors as arrays, helpers of its own, triangles made
// with a spread of the one clipped. Written for the checker's corpus
// (tests/check-functions/check_corpus.mjs).
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const lerp = (a, b, t) => a.map((c, i) => c + t * (b[i] - c));

export function SignedDistance(plane, vertex) {
  return dot(plane.normal, vertex) + plane.D;
}

export function Intersection(A, B, plane) {
  const t = (-plane.D - dot(plane.normal, A)) / (dot(plane.normal, B) - dot(plane.normal, A));
  return lerp(A, B, t);
}

export function ClipTriangle(triangle, plane, vertices) {
  const [i0, i1, i2] = triangle.v;
  const front = [i0, i1, i2].map((i) => SignedDistance(plane, vertices[i]) >= 0);
  const inFront = front.filter(Boolean).length;
  if (inFront === 3) return [triangle];
  if (inFront === 0) return [];
  const order = (k) => [0, 1, 2].map((n) => triangle.v[(k + n) % 3]);
  const cut = (p, q) => vertices.push(Intersection(vertices[p], vertices[q], plane)) - 1;
  if (inFront === 1) {
    const [A, B, C] = order(front.indexOf(true));
    return [{ ...triangle, v: [A, cut(A, B), cut(A, C)] }];
  }
  const [C, A, B] = order(front.indexOf(false));
  const A2 = cut(A, C), B2 = cut(B, C);
  return [{ ...triangle, v: [A, B, A2] }, { ...triangle, v: [A2, B, B2] }];
}

export function ComputeBoundingSphere(vertices) {
  const center = [0, 1, 2].map((i) => vertices.reduce((sum, v) => sum + v[i], 0) / vertices.length);
  const radius = Math.max(...vertices.map((v) => Math.hypot(v[0] - center[0], v[1] - center[1], v[2] - center[2])));
  return [center, radius];
}
