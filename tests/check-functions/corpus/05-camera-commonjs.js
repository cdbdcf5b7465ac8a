// Chapter 5's camera ray and refraction in CommonJS: the camera an object of the
// book's fields, vectors as arrays, RefractRay giving null on total internal
// reflection. Written for the checker's corpus (tests/check-functions/check_corpus.mjs).
"use strict";

let Cw = 600, Ch = 600, Vw = 1, Vh = 1, d = 1;
let camera = { position: [0, 0, 0], rotation: [[1, 0, 0], [0, 1, 0], [0, 0, 1]] };

const dot = (a, b) => a.reduce((sum, value, i) => sum + value * b[i], 0);
const unit = (v) => v.map((c) => c / Math.sqrt(dot(v, v)));

function CanvasToViewport(x, y) {
  return [(x * Vw) / Cw, (y * Vh) / Ch, d];
}

function CameraRayDirection(x, y) {
  const viewport = CanvasToViewport(x, y);
  return camera.rotation.map((row) => dot(row, viewport));
}

function RefractRay(D, N, n1, n2) {
  const I = unit(D);
  const eta = n1 / n2;
  const cosI = -dot(N, I);
  const sin2T = eta * eta * (1 - cosI * cosI);
  if (sin2T > 1) return null;
  const cosT = Math.sqrt(1 - sin2T);
  return unit(I.map((c, i) => eta * c + (eta * cosI - cosT) * N[i]));
}

module.exports = { CanvasToViewport, CameraRayDirection, RefractRay };
