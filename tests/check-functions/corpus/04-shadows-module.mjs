// Chapter 4 as an ES module: vectors as arrays with small exported helpers, the scene
// declared and exported, shadows and mirrors as the book writes them. Written for the
// checker's corpus (tests/check-functions/check_corpus.mjs).
export const EPSILON = 0.001;
export const scene = { spheres: [], lights: [], background_color: [0, 0, 0] };

export const add = (a, b) => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
export const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
export const mul = (k, v) => [k * v[0], k * v[1], k * v[2]];
export const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
export const len = (v) => Math.sqrt(dot(v, v));

export function IntersectRaySphere(O, D, sphere) {
  const CO = sub(O, sphere.center);
  const a = dot(D, D), b = 2 * dot(CO, D), c = dot(CO, CO) - sphere.radius ** 2;
  const disc = b * b - 4 * a * c;
  if (disc < 0) return [Infinity, Infinity];
  return [(-b + Math.sqrt(disc)) / (2 * a), (-b - Math.sqrt(disc)) / (2 * a)];
}

export function ClosestIntersection(O, D, t_min, t_max) {
  let closest_t = Infinity, closest_sphere = null;
  for (const sphere of scene.spheres) {
    for (const t of IntersectRaySphere(O, D, sphere)) {
      if (t >= t_min && t <= t_max && t < closest_t) [closest_t, closest_sphere] = [t, sphere];
    }
  }
  return [closest_sphere, closest_t];
}

export function ReflectRay(R, N) {
  return sub(mul(2 * dot(N, R), N), R);
}

export function ComputeLighting(P, N, V, s) {
  let i = 0;
  for (const light of scene.lights) {
    if (light.type === "ambient") {
      i += light.intensity;
      continue;
    }
    const [L, t_max] = light.type === "point" ? [sub(light.position, P), 1] : [light.direction, Infinity];
    const [blocker] = ClosestIntersection(P, L, EPSILON, t_max);
    if (blocker) continue;
    const nl = dot(N, L);
    if (nl > 0) i += (light.intensity * nl) / (len(N) * len(L));
    if (s !== -1) {
      const R = ReflectRay(L, N);
      const rv = dot(R, V);
      if (rv > 0) i += light.intensity * Math.pow(rv / (len(R) * len(V)), s);
    }
  }
  return i;
}

export function TraceRay(O, D, t_min, t_max, recursion_depth) {
  const [sphere, t] = ClosestIntersection(O, D, t_min, t_max);
  if (!sphere) return scene.background_color;
  const P = add(O, mul(t, D));
  const N = mul(1 / len(sub(P, sphere.center)), sub(P, sphere.center));
  const local = mul(ComputeLighting(P, N, mul(-1, D), sphere.specular), sphere.color);
  const r = sphere.reflective;
  if (recursion_depth <= 0 || r <= 0) return local;
  const reflected = TraceRay(P, ReflectRay(mul(-1, D), N), EPSILON, Infinity, recursion_depth - 1);
  return add(mul(1 - r, local), mul(r, reflected));
}
