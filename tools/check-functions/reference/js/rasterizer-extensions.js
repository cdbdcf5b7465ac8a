// cases: 15 (tests/cases/15-rasterizer-extensions.json)
// Chapter 15, "Extending the Rasterizer", in plain JavaScript, from the book's prose: the
// checker's reference (tools/check-functions). A normal map's texel decoded and applied
// ("Normal Mapping"), and the shadow map's comparison and percentage-closer filtering
// ("Shadow Mapping").
"use strict";

const Dot = (a, b) => a.reduce((sum, each, i) => sum + each * b[i], 0);
const Normalized = (v) => v.map((each) => each / Math.sqrt(Dot(v, v)));

function DecodeNormal(texel) {
  return texel.map((channel) => 2 * channel / 255 - 1);
}

function ApplyNormalMap(n, basis, N) {
  // T and B made perpendicular to N (and B to T), then n brought out of tangent space.
  const T = Normalized(basis.T.map((t, i) => t - N[i] * Dot(N, basis.T)));
  const B = Normalized(basis.B.map((b, i) => b - N[i] * Dot(N, basis.B) - T[i] * Dot(T, basis.B)));
  return Normalized([0, 1, 2].map((i) => T[i] * n[0] + B[i] * n[1] + N[i] * n[2]));
}

function InShadow(stored_depth, depth, bias) {
  return stored_depth < depth - bias;
}

function PercentageCloserFilter(in_shadow, fx, fy) {
  const weights = [(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy];
  return weights.reduce((sum, weight, k) => sum + (in_shadow[k] ? 0 : weight), 0);
}

module.exports = { DecodeNormal, ApplyNormalMap, InShadow, PercentageCloserFilter };
