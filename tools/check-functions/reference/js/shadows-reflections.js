// cases: 04 (tests/cases/04-shadows-reflections.json)
// Chapter 4, "Shadows and Reflections", in plain JavaScript, as the book writes it: the
// checker's reference (tools/check-functions). ClosestIntersection (Listing 4-2),
// ComputeLighting with shadows (Listing 4-3), ReflectRay (Listing 4-4) and the
// recursive TraceRay (Listing 4-5).
"use strict";

const { Vec3, IntersectRaySphere } = require("./basic-rays.js");
require("./light.js");  // Vec3's plus, times and length

const EPSILON = 0.001;  // where shadow and reflected rays start, so a point does not hit itself
let scene = { spheres: [], lights: [], background_color: [0, 0, 0] };


// Listing 4-2: the nearest sphere the ray meets in [t_min, t_max], and its t.
function ClosestIntersection(O, D, t_min, t_max) {
  let closest_t = Infinity;
  let closest_sphere = null;
  for (const sphere of scene.spheres) {
    const [t1, t2] = IntersectRaySphere(O, D, sphere);
    if (t_min <= t1 && t1 <= t_max && t1 < closest_t) [closest_t, closest_sphere] = [t1, sphere];
    if (t_min <= t2 && t2 <= t_max && t2 < closest_t) [closest_t, closest_sphere] = [t2, sphere];
  }
  return [closest_sphere, closest_t];
}

// Listing 4-3: chapter 3's lighting, skipping the lights something hides from P.
function ComputeLighting(P, N, V, s) {
  let i = 0;
  for (const light of scene.lights) {
    if (light.type === "ambient") {
      i += light.intensity;
      continue;
    }
    const [L, t_max] = light.type === "point" ? [light.position.minus(P), 1] : [light.direction, Infinity];

    // Shadow check
    const [shadow_sphere] = ClosestIntersection(P, L, EPSILON, t_max);
    if (shadow_sphere !== null) continue;

    // Diffuse
    const n_dot_l = N.dot(L);
    if (n_dot_l > 0) i += light.intensity * n_dot_l / (N.length() * L.length());

    // Specular
    if (s !== -1) {
      const R = ReflectRay(L, N);
      const r_dot_v = R.dot(V);
      if (r_dot_v > 0) i += light.intensity * Math.pow(r_dot_v / (R.length() * V.length()), s);
    }
  }
  return i;
}

// Listing 4-4: R mirrored about N.
function ReflectRay(R, N) {
  return N.times(2 * N.dot(R)).minus(R);
}

// Listing 4-5: the local colour, and what the surface reflects, recursion_depth deep.
function TraceRay(O, D, t_min, t_max, recursion_depth) {
  const [closest_sphere, closest_t] = ClosestIntersection(O, D, t_min, t_max);
  if (closest_sphere === null) return scene.background_color;

  // The local colour
  const P = O.plus(D.times(closest_t));
  let N = P.minus(closest_sphere.center);
  N = N.times(1 / N.length());
  const i = ComputeLighting(P, N, D.times(-1), closest_sphere.specular);
  const local_color = closest_sphere.color.map((channel) => channel * i);

  // At the recursion limit, or on a surface that is not reflective, we are done
  const r = closest_sphere.reflective;
  if (recursion_depth <= 0 || r <= 0) return local_color;

  // The reflected colour
  const R = ReflectRay(D.times(-1), N);
  const reflected_color = TraceRay(P, R, EPSILON, Infinity, recursion_depth - 1);
  return local_color.map((channel, k) => channel * (1 - r) + reflected_color[k] * r);
}

module.exports = { Vec3, ClosestIntersection, ComputeLighting, ReflectRay, TraceRay };
