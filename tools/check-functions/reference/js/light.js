// cases: 03 (tests/cases/03-light.json)
// Chapter 3, "Light", in plain JavaScript, as the book writes it: the runner's
// reference (tools/check-functions). Chapter 2's functions, and ComputeLighting
// (Listings 3-1 and 3-2) used by TraceRay (Listing 3-3).
"use strict";

const { Vec3, IntersectRaySphere } = require("./basic-rays.js");

Vec3.prototype.plus = function (v) { return new Vec3(this.x + v.x, this.y + v.y, this.z + v.z); };
Vec3.prototype.times = function (k) { return new Vec3(k * this.x, k * this.y, k * this.z); };
Vec3.prototype.length = function () { return Math.sqrt(this.dot(this)); };

let scene = { spheres: [], lights: [], background_color: [255, 255, 255] };


// Listings 3-1 and 3-2: the light at P with normal N, seen along V; s = -1 is matte.
function ComputeLighting(P, N, V, s) {
  let i = 0;
  for (const light of scene.lights) {
    if (light.type === "ambient") {
      i += light.intensity;
      continue;
    }
    const L = light.type === "point" ? light.position.minus(P) : light.direction;

    // Diffuse
    const n_dot_l = N.dot(L);
    if (n_dot_l > 0) i += light.intensity * n_dot_l / (N.length() * L.length());

    // Specular
    if (s !== -1) {
      const R = N.times(2 * N.dot(L)).minus(L);
      const r_dot_v = R.dot(V);
      if (r_dot_v > 0) i += light.intensity * Math.pow(r_dot_v / (R.length() * V.length()), s);
    }
  }
  return i;
}

// Listing 3-3: the nearest sphere's colour, lit.
function TraceRay(O, D, t_min, t_max) {
  let closest_t = Infinity;
  let closest_sphere = null;
  for (const sphere of scene.spheres) {
    const [t1, t2] = IntersectRaySphere(O, D, sphere);
    if (t_min <= t1 && t1 <= t_max && t1 < closest_t) [closest_t, closest_sphere] = [t1, sphere];
    if (t_min <= t2 && t2 <= t_max && t2 < closest_t) [closest_t, closest_sphere] = [t2, sphere];
  }
  if (closest_sphere === null) return scene.background_color;

  const P = O.plus(D.times(closest_t));  // the intersection
  let N = P.minus(closest_sphere.center);  // the sphere's normal there
  N = N.times(1 / N.length());
  const i = ComputeLighting(P, N, D.times(-1), closest_sphere.specular);
  return closest_sphere.color.map((channel) => channel * i);
}

module.exports = { Vec3, ComputeLighting, TraceRay };
