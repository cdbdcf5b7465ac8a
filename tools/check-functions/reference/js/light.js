// cases: 03 (tests/cases/03-light.json)
// Chapter 3, "Light", in plain JavaScript, as the book writes it: the checker's
// reference (tools/check-functions), one script as a reader writes it on a chapter's
// page. Chapter 2's script carried forward, with ComputeLighting (Listings 3-1 and 3-2)
// used by TraceRay (Listing 3-3).
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
    if (t_min <= t1 && t1 <= t_max && t1 < closest_t) {
      closest_t = t1;
      closest_sphere = sphere;
    }
    if (t_min <= t2 && t2 <= t_max && t2 < closest_t) {
      closest_t = t2;
      closest_sphere = sphere;
    }
  }
  if (closest_sphere === null) return scene.background_color;

  const P = O.plus(D.times(closest_t));  // the intersection
  let N = P.minus(closest_sphere.center);  // the sphere's normal there
  N = N.times(1 / N.length());
  const i = ComputeLighting(P, N, D.times(-1), closest_sphere.specular);
  return closest_sphere.color.map((channel) => channel * i);
}
