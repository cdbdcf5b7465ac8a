// Chapter 3 in CommonJS, vectors as plain arrays with small helper functions, the book's
// globals, exports at the end. Written for the checker's corpus
// (tests/check-functions/check_corpus.mjs).
"use strict";

let Cw = 600, Ch = 600;
let Vw = 1, Vh = 1, d = 1;
let BACKGROUND_COLOR = [255, 255, 255];
let scene = { spheres: [], lights: [] };

const add = (a, b) => a.map((v, i) => v + b[i]);
const sub = (a, b) => a.map((v, i) => v - b[i]);
const mul = (k, a) => a.map((v) => k * v);
const dot = (a, b) => a.reduce((sum, v, i) => sum + v * b[i], 0);
const len = (a) => Math.sqrt(dot(a, a));

function CanvasToViewport(x, y) {
  return [x * Vw / Cw, y * Vh / Ch, d];
}

function IntersectRaySphere(O, D, sphere) {
  const CO = sub(O, sphere.center);
  const a = dot(D, D), b = 2 * dot(CO, D), c = dot(CO, CO) - sphere.radius * sphere.radius;
  const disc = b * b - 4 * a * c;
  if (disc < 0) return [Infinity, Infinity];
  return [(-b + Math.sqrt(disc)) / (2 * a), (-b - Math.sqrt(disc)) / (2 * a)];
}

function ComputeLighting(P, N, V, s) {
  let i = 0;
  for (const light of scene.lights) {
    if (light.type === "ambient") {
      i += light.intensity;
      continue;
    }
    const L = light.type === "point" ? sub(light.position, P) : light.direction;
    const nl = dot(N, L);
    if (nl > 0) i += light.intensity * nl / (len(N) * len(L));
    if (s !== -1) {
      const R = sub(mul(2 * dot(N, L), N), L);
      const rv = dot(R, V);
      if (rv > 0) i += light.intensity * Math.pow(rv / (len(R) * len(V)), s);
    }
  }
  return i;
}

function TraceRay(O, D, t_min, t_max) {
  let closest_t = Infinity, closest_sphere = null;
  for (const sphere of scene.spheres) {
    const [t1, t2] = IntersectRaySphere(O, D, sphere);
    if (t1 >= t_min && t1 <= t_max && t1 < closest_t) { closest_t = t1; closest_sphere = sphere; }
    if (t2 >= t_min && t2 <= t_max && t2 < closest_t) { closest_t = t2; closest_sphere = sphere; }
  }
  if (!closest_sphere) return BACKGROUND_COLOR;
  const P = add(O, mul(closest_t, D));
  let N = sub(P, closest_sphere.center);
  N = mul(1 / len(N), N);
  return mul(ComputeLighting(P, N, mul(-1, D), closest_sphere.specular), closest_sphere.color);
}

module.exports = { CanvasToViewport, IntersectRaySphere, ComputeLighting, TraceRay };
