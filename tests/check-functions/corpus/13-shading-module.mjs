// Chapter 13's two small functions as an ES module with a Vector class of its own
// (with cross, length and scaled), the book's settings exported. Written for the
// checker's corpus (tests/check-functions/check_corpus.mjs).
export class Vector {
  constructor(x, y, z) {
    Object.assign(this, { x, y, z });
  }
  minus(o) {
    return new Vector(this.x - o.x, this.y - o.y, this.z - o.z);
  }
  cross(o) {
    return new Vector(this.y * o.z - this.z * o.y, this.z * o.x - this.x * o.z, this.x * o.y - this.y * o.x);
  }
  length() {
    return Math.hypot(this.x, this.y, this.z);
  }
  scaled(k) {
    return new Vector(k * this.x, k * this.y, k * this.z);
  }
}

export let Cw = 600, Ch = 600, Vw = 1, Vh = 1, d = 1;

// ProjectVertex undone: the canvas point (x, y) at 1/z back in the scene.
export function UnProjectVertex(x, y, inv_z) {
  const z = 1 / inv_z;
  return new Vector((x * Vw / Cw) * z / d, (y * Vh / Ch) * z / d, z);
}

export function ComputeTriangleNormal(A, B, C) {
  const n = B.minus(A).cross(C.minus(A));
  return n.scaled(1 / n.length());
}
