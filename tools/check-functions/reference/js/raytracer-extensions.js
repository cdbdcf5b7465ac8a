// cases: 05 (tests/cases/05-raytracer-extensions.json)
// Chapter 5, "Extending the Raytracer", in plain JavaScript: the checker's reference
// (tools/check-functions). The camera of Listing 5-1, and refraction, which the book
// describes in prose (Snell's law).
"use strict";

const { Vec3 } = require("./basic-rays.js");
require("./light.js");  // Vec3's plus, times and length

let Cw = 600, Ch = 600, Vw = 1, Vh = 1, d = 1;
let camera = { position: new Vec3(0, 0, 0), rotation: [[1, 0, 0], [0, 1, 0], [0, 0, 1]] };


const CanvasToViewport = (x, y) => new Vec3(x * Vw / Cw, y * Vh / Ch, d);
const MultiplyMV = (mat, v) => new Vec3(...mat.map((row) => row[0] * v.x + row[1] * v.y + row[2] * v.z));

// Listing 5-1: the viewport's direction through (x, y), turned with the camera.
function CameraRayDirection(x, y) {
  return MultiplyMV(camera.rotation, CanvasToViewport(x, y));
}

// "Refraction": sin a1 / sin a2 = n2 / n1; none on total internal reflection.
function RefractRay(D, N, n1, n2) {
  D = D.times(1 / D.length());
  const eta = n1 / n2;
  const c1 = -N.dot(D);
  const k = 1 - eta * eta * (1 - c1 * c1);
  if (k < 0) return null;  // total internal reflection
  return D.times(eta).plus(N.times(eta * c1 - Math.sqrt(k)));
}

module.exports = { Vec3, CameraRayDirection, RefractRay };
