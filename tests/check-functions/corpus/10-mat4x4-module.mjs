// Chapter 10 as an ES module with the demos' kind of matrix, a Mat4x4 class holding its
// rows in `data`, and vertices as arrays. Written for the checker's corpus
// (tests/check-functions/check_corpus.mjs).
export class Mat4x4 {
  constructor(data) {
    this.data = data;
  }
  times(other) {
    const rows = [0, 1, 2, 3].map((i) => [0, 1, 2, 3].map((j) =>
      [0, 1, 2, 3].reduce((sum, k) => sum + this.data[i][k] * other.data[k][j], 0)));
    return new Mat4x4(rows);
  }
  apply(v) {
    return [0, 1, 2, 3].map((i) => this.data[i].reduce((sum, value, k) => sum + value * v[k], 0));
  }
  transposed() {
    return new Mat4x4([0, 1, 2, 3].map((i) => [0, 1, 2, 3].map((j) => this.data[j][i])));
  }
}

export function MakeTranslationMatrix(t) {
  return new Mat4x4([[1, 0, 0, t[0]], [0, 1, 0, t[1]], [0, 0, 1, t[2]], [0, 0, 0, 1]]);
}

export function MakeScalingMatrix(s) {
  return new Mat4x4([[s, 0, 0, 0], [0, s, 0, 0], [0, 0, s, 0], [0, 0, 0, 1]]);
}

export function MakeOYRotationMatrix(degrees) {
  const radians = (degrees * Math.PI) / 180;
  const cos = Math.cos(radians), sin = Math.sin(radians);
  return new Mat4x4([[cos, 0, -sin, 0], [0, 1, 0, 0], [sin, 0, cos, 0], [0, 0, 0, 1]]);
}

export function ApplyTransform(vertex, transform) {
  const scaled = vertex.map((c) => c * transform.scale);
  const rotated = transform.rotation.apply([...scaled, 1]);
  return rotated.slice(0, 3).map((c, i) => c + transform.translation[i]);
}

export function MakeCameraMatrix(position, orientation) {
  return orientation.transposed().times(MakeTranslationMatrix(position.map((c) => -c)));
}
