// Chapter 9 as an ES module: the book's v.x on a vertex, exported settings, and the
// usual main guard on import.meta.url. Written for the checker's corpus
// (tests/check-functions/check_corpus.mjs).
import { fileURLToPath } from "node:url";

export let Cw = 600, Ch = 600;
export let Vw = 1, Vh = 1, d = 1;

export function ViewportToCanvas(x, y) {
  return { x: Math.trunc(x * Cw / Vw), y: Math.trunc(y * Ch / Vh) };
}

export function ProjectVertex(v) {
  return ViewportToCanvas(v.x * d / v.z, v.y * d / v.z);
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const cube = [[1, 1, 5], [-1, 1, 5], [-1, -1, 5], [1, -1, 5]];
  console.log(cube.map(([x, y, z]) => ProjectVertex({ x, y, z })));
}
