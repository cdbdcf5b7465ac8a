// Chapter 15's small functions as a plain script with array helpers: decoding a normal
// map's texel, applying it in the tangent basis, the shadow map's test and its
// percentage-closer filter. Written for the checker's corpus
// (tests/check-functions/check_corpus.mjs).
"use strict";

const scale = (k, v) => v.map((c) => k * c);
const add = (...vs) => vs.reduce((sum, v) => sum.map((c, i) => c + v[i]));
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const normalize = (v) => scale(1 / Math.sqrt(dot(v, v)), v);

function DecodeNormal(texel) {
  return [0, 1, 2].map((i) => (2 * texel[i]) / 255 - 1);
}

function ApplyNormalMap(n, basis, N) {
  // T and B made perpendicular to N first (Gram-Schmidt), then n out of tangent space.
  const T = normalize(add(basis.T, scale(-dot(basis.T, N) / dot(N, N), N)));
  const B = normalize(add(basis.B, scale(-dot(basis.B, N) / dot(N, N), N)));
  return normalize(add(scale(n[0], T), scale(n[1], B), scale(n[2], normalize(N))));
}

function InShadow(stored_depth, depth, bias) {
  return stored_depth < depth - bias;
}

function PercentageCloserFilter(in_shadow, fx, fy) {
  const lit = in_shadow.map((shadowed) => (shadowed ? 0 : 1));
  const top = lit[0] * (1 - fx) + lit[1] * fx;
  const bottom = lit[2] * (1 - fx) + lit[3] * fx;
  return top * (1 - fy) + bottom * fy;
}
