// cases: 02 (tests/cases/02-basic-rays.json)
// Chapter 2, "Basic Raytracing", in plain JavaScript, as the book writes it: the
// checker's reference (tools/check-functions), one script as a reader writes it on a
// chapter's page. Vectors are a small class of its own, and the book's globals are the
// script's top-level names, which the checker sets before each case (and builds the
// cases' vectors with Vec3: it has x, y and z).
"use strict";

class Vec3 {
  constructor(x, y, z) { Object.assign(this, { x, y, z }); }
  minus(v) { return new Vec3(this.x - v.x, this.y - v.y, this.z - v.z); }
  dot(v) { return this.x * v.x + this.y * v.y + this.z * v.z; }
}

let Cw = 600, Ch = 600;       // the canvas
let Vw = 1, Vh = 1, d = 1;    // the viewport, at distance d
let scene = { spheres: [], background_color: [255, 255, 255] };


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

// Listing 2-4: the colour of the nearest sphere the ray meets in [t_min, t_max].
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
  return closest_sphere === null ? scene.background_color : closest_sphere.color;
}
