// Chapter 3 as a reader might write it in the style of the book's demo pages, as a plain
// Node script: module-level constants with the demos' names, the Vec and Color helpers,
// lights with Light.AMBIENT / POINT / DIRECTIONAL, nothing exported, and TraceRay taking
// its spheres as a default parameter. The book's closed intervals, t_min <= t <= t_max.
// The checker finds its functions by the book's names and sets the demos' names before
// each case (tests/check-functions/check_checkers.sh, docs/students.md).
"use strict";

const fs = require("fs");

function Vec(x, y, z) {
  return {
    x, y, z,
    dot(v) { return this.x * v.x + this.y * v.y + this.z * v.z; },
    add(v) { return new Vec(this.x + v.x, this.y + v.y, this.z + v.z); },
    sub(v) { return new Vec(this.x - v.x, this.y - v.y, this.z - v.z); },
    mul(k) { return new Vec(this.x * k, this.y * k, this.z * k); },
    length() { return Math.sqrt(this.dot(this)); },
  };
}

function Color(r, g, b) {
  return { r, g, b, mul(k) { return new Color(this.r * k, this.g * k, this.b * k); } };
}

function Light(ltype, intensity, position) {
  return { ltype, intensity, position };
}
Light.AMBIENT = 0;
Light.POINT = 1;
Light.DIRECTIONAL = 2;

const canvas = { width: 600, height: 600 };
const viewport_size = 1;
const projection_plane_z = 1;
const background_color = new Color(255, 255, 255);
const spheres = [
  { center: new Vec(0, -1, 3), radius: 1, color: new Color(255, 0, 0), specular: 500 },
  { center: new Vec(2, 0, 4), radius: 1, color: new Color(0, 0, 255), specular: 500 },
  { center: new Vec(-2, 0, 4), radius: 1, color: new Color(0, 255, 0), specular: 10 },
  { center: new Vec(0, -5001, 0), radius: 5000, color: new Color(255, 255, 0), specular: 1000 },
];
const lights = [
  new Light(Light.AMBIENT, 0.2),
  new Light(Light.POINT, 0.6, new Vec(2, 1, 0)),
  new Light(Light.DIRECTIONAL, 0.2, new Vec(1, 4, 4)),
];

function CanvasToViewport(p2d) {
  return new Vec(p2d[0] * viewport_size / canvas.width, p2d[1] * viewport_size / canvas.height, projection_plane_z);
}

function IntersectRaySphere(origin, direction, sphere) {
  const oc = origin.sub(sphere.center);
  const k1 = direction.dot(direction);
  const k2 = 2 * oc.dot(direction);
  const k3 = oc.dot(oc) - sphere.radius * sphere.radius;
  const discriminant = k2 * k2 - 4 * k1 * k3;
  if (discriminant < 0) return [Infinity, Infinity];
  return [(-k2 + Math.sqrt(discriminant)) / (2 * k1), (-k2 - Math.sqrt(discriminant)) / (2 * k1)];
}

function ComputeLighting(point, normal, view, specular) {
  let intensity = 0;
  for (const light of lights) {
    if (light.ltype === Light.AMBIENT) {
      intensity += light.intensity;
      continue;
    }
    const vec_l = light.ltype === Light.POINT ? light.position.sub(point) : light.position;
    const n_dot_l = normal.dot(vec_l);
    if (n_dot_l > 0) intensity += light.intensity * n_dot_l / (normal.length() * vec_l.length());
    if (specular !== -1) {
      const vec_r = normal.mul(2 * n_dot_l).sub(vec_l);
      const r_dot_v = vec_r.dot(view);
      if (r_dot_v > 0) intensity += light.intensity * Math.pow(r_dot_v / (vec_r.length() * view.length()), specular);
    }
  }
  return intensity;
}

function TraceRay(origin, direction, min_t, max_t, scene = spheres) {
  let closest_t = Infinity;
  let closest_sphere = null;
  for (const sphere of scene) {
    for (const t of IntersectRaySphere(origin, direction, sphere)) {
      if (min_t <= t && t <= max_t && t < closest_t) {
        closest_t = t;
        closest_sphere = sphere;
      }
    }
  }
  if (closest_sphere === null) return background_color;
  const point = origin.add(direction.mul(closest_t));
  let normal = point.sub(closest_sphere.center);
  normal = normal.mul(1 / normal.length());
  return closest_sphere.color.mul(ComputeLighting(point, normal, direction.mul(-1), closest_sphere.specular));
}

// The main loop, writing Figure 3-16 as a P3 file wherever the first argument says,
// unguarded: the checker gives the script no arguments, so it writes nothing.
if (process.argv[2]) {
  const rows = [];
  for (let y = canvas.height / 2 - 1; y >= -canvas.height / 2; y--) {
    for (let x = -canvas.width / 2; x < canvas.width / 2; x++) {
      const c = TraceRay(new Vec(0, 0, 0), CanvasToViewport([x, y]), 1, Infinity);
      rows.push([c.r, c.g, c.b].map((v) => Math.round(Math.min(255, Math.max(0, v)))).join(" "));
    }
  }
  fs.writeFileSync(process.argv[2], `P3\n${canvas.width} ${canvas.height}\n255\n${rows.join("\n")}\n`);
}
