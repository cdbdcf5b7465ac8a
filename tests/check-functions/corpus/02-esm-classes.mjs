// Chapter 2 as an ES module with classes: a Vec3 with methods, spheres made by a Sphere
// class, the book's settings exported, and a main guard that draws when it is run.
// Written for the checker's corpus (tests/check-functions/check_corpus.mjs).
import { fileURLToPath } from "node:url";

export class Vec3 {
  constructor(x, y, z) {
    this.x = x;
    this.y = y;
    this.z = z;
  }
  minus(v) {
    return new Vec3(this.x - v.x, this.y - v.y, this.z - v.z);
  }
  dot(v) {
    return this.x * v.x + this.y * v.y + this.z * v.z;
  }
}

export class Sphere {
  constructor(center, radius, color) {
    Object.assign(this, { center, radius, color });
  }
}

export let Cw = 600, Ch = 600;
export let Vw = 1, Vh = 1, d = 1;
export const scene = {
  spheres: [new Sphere(new Vec3(0, -1, 3), 1, [255, 0, 0]), new Sphere(new Vec3(2, 0, 4), 1, [0, 0, 255])],
  background_color: [255, 255, 255],
};

export function CanvasToViewport(x, y) {
  return new Vec3((x * Vw) / Cw, (y * Vh) / Ch, d);
}

export function IntersectRaySphere(O, D, sphere) {
  const CO = O.minus(sphere.center);
  const a = D.dot(D);
  const b = 2 * CO.dot(D);
  const c = CO.dot(CO) - sphere.radius * sphere.radius;
  const discriminant = b * b - 4 * a * c;
  if (discriminant < 0) return [Infinity, Infinity];
  const root = Math.sqrt(discriminant);
  return [(-b + root) / (2 * a), (-b - root) / (2 * a)];
}

export function TraceRay(O, D, t_min, t_max) {
  let closest = Infinity;
  let hit = null;
  for (const sphere of scene.spheres) {
    for (const t of IntersectRaySphere(O, D, sphere)) {
      if (t >= t_min && t <= t_max && t < closest) {
        closest = t;
        hit = sphere;
      }
    }
  }
  return hit ? hit.color : scene.background_color;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  let drawn = 0;
  for (let x = -Cw / 2; x < Cw / 2; x += 50) {
    for (let y = -Ch / 2; y < Ch / 2; y += 50) {
      if (TraceRay(new Vec3(0, 0, 0), CanvasToViewport(x, y), 1, Infinity) !== scene.background_color) drawn++;
    }
  }
  console.log(`${drawn} samples hit a sphere`);
}
