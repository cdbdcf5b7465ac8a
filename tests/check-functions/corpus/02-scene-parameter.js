// Chapter 2 with the scene passed to TraceRay as a parameter instead of read as a
// global: a natural design, but not the book's TraceRay(O, D, t_min, t_max). Written for
// the checker's corpus (tests/check-functions/check_corpus.mjs), which expects the one
// line that says so.
"use strict";

const Cw = 600, Ch = 600, Vw = 1, Vh = 1, d = 1;

const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

function CanvasToViewport(x, y) {
  return [x * Vw / Cw, y * Vh / Ch, d];
}

function IntersectRaySphere(O, D, sphere) {
  const CO = sub(O, sphere.center);
  const a = dot(D, D), b = 2 * dot(CO, D), c = dot(CO, CO) - sphere.radius ** 2;
  const disc = b * b - 4 * a * c;
  if (disc < 0) return [Infinity, Infinity];
  return [(-b + Math.sqrt(disc)) / (2 * a), (-b - Math.sqrt(disc)) / (2 * a)];
}

function TraceRay(O, D, t_min, t_max, scene) {
  let closest_t = Infinity, closest = null;
  for (const sphere of scene.spheres) {
    const [t1, t2] = IntersectRaySphere(O, D, sphere);
    if (t1 >= t_min && t1 <= t_max && t1 < closest_t) [closest_t, closest] = [t1, sphere];
    if (t2 >= t_min && t2 <= t_max && t2 < closest_t) [closest_t, closest] = [t2, sphere];
  }
  return closest ? closest.color : scene.background_color;
}

module.exports = { CanvasToViewport, IntersectRaySphere, TraceRay };
