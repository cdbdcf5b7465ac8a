// cases: 04 (tests/cases/04-shadows-reflections.json)
// Chapter 4, "Shadows and Reflections", in plain JavaScript, as the book writes it: the
// checker's reference (tools/check-functions), one script as a reader writes it on a
// chapter's page. Chapter 3's script carried forward, with ClosestIntersection (Listing
// 4-2), ComputeLighting with shadows (Listing 4-3), ReflectRay (Listing 4-4) and the
// recursive TraceRay (Listing 4-5).
"use strict";

class Vec3 {
  constructor(x, y, z) { Object.assign(this, { x, y, z }); }
  minus(v) { return new Vec3(this.x - v.x, this.y - v.y, this.z - v.z); }
  plus(v) { return new Vec3(this.x + v.x, this.y + v.y, this.z + v.z); }
  times(k) { return new Vec3(k * this.x, k * this.y, k * this.z); }
  dot(v) { return this.x * v.x + this.y * v.y + this.z * v.z; }
  length() { return Math.sqrt(this.dot(this)); }
}

let Cw = 600, Ch = 600;       // the canvas
let Vw = 1, Vh = 1, d = 1;    // the viewport, at distance d
const EPSILON = 0.001;  // where shadow and reflected rays start, so a point does not hit itself
let scene = { spheres: [], lights: [], background_color: [255, 255, 255] };


// Listing 2-2: a canvas point to the viewport point it looks through.
function CanvasToViewport(x, y) {
  return new Vec3(x * Vw / Cw, y * Vh / Ch, d);
}

// Listing 2-3: the two solutions of t^2<D,D> + 2t<CO,D> + <CO,CO> - r^2 = 0.
function IntersectRaySphere(O, D, sphere) {
  const r = sphere.radius;
  const CO = O.minus(sphere.center);

  const a = D.dot(D);
  const b = 2 * CO.dot(D);
  const c = CO.dot(CO) - r * r;

  const discriminant = b * b - 4 * a * c;
  if (discriminant < 0) return [Infinity, Infinity];

  const t1 = (-b + Math.sqrt(discriminant)) / (2 * a);
  const t2 = (-b - Math.sqrt(discriminant)) / (2 * a);
  return [t1, t2];
}

// Listing 4-2: the nearest sphere the ray meets in [t_min, t_max], and its t.
function ClosestIntersection(O, D, t_min, t_max) {
  let closest_t = Infinity;
  let closest_sphere = null;
  for (const sphere of scene.spheres) {
    const [t1, t2] = IntersectRaySphere(O, D, sphere);
    if (t_min <= t1 && t1 <= t_max && t1 < closest_t) {
      closest_t = t1;
      closest_sphere = sphere;
    }
    if (t_min <= t2 && t2 <= t_max && t2 < closest_t) {
      closest_t = t2;
      closest_sphere = sphere;
    }
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
