// Chapter 12 in CommonJS: back-face culling that returns the kept triangles, and
// DrawFilledTriangle with 1/z tested against depth_buffer[x][y] (x and y from 0).
// Written for the checker's corpus (tests/check-functions/check_corpus.mjs).
"use strict";

let Cw = 600, Ch = 600;
let depth_buffer = [];
let PutPixel = () => {};

const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

function IsBackFacing(A, B, C, camera) {
  return dot(cross(sub(B, A), sub(C, A)), sub(camera, A)) <= 0;
}

function CullBackFaces(object, camera) {
  const { vertices } = object;
  return object.triangles.filter(({ v }) => !IsBackFacing(vertices[v[0]], vertices[v[1]], vertices[v[2]], camera));
}

function Interpolate(i0, d0, i1, d1) {
  if (i0 === i1) return [d0];
  const out = [];
  for (let i = i0; i <= i1; i++) out.push(d0 + ((d1 - d0) / (i1 - i0)) * (i - i0));
  return out;
}

function sides(p, q, r, a, b, c) {
  const pq = Interpolate(p.y, a, q.y, b);
  pq.pop();
  return [Interpolate(p.y, a, r.y, c), pq.concat(Interpolate(q.y, b, r.y, c))];
}

function DrawFilledTriangle(P0, P1, P2, z0, z1, z2, color) {
  const [[p, zp], [q, zq], [r, zr]] = [[P0, z0], [P1, z1], [P2, z2]].sort((a, b) => a[0].y - b[0].y);
  const [x02, x012] = sides(p, q, r, p.x, q.x, r.x);
  const [w02, w012] = sides(p, q, r, 1 / zp, 1 / zq, 1 / zr);
  const m = Math.floor(x012.length / 2);
  const [xl, xr, wl, wr] = x02[m] < x012[m] ? [x02, x012, w02, w012] : [x012, x02, w012, w02];
  for (let y = p.y; y <= r.y; y++) {
    const i = y - p.y;
    const left = Math.trunc(xl[i]), right = Math.trunc(xr[i]);
    const w = Interpolate(left, wl[i], right, wr[i]);
    for (let x = left; x <= right; x++) {
      const sx = Cw / 2 + x, sy = Ch / 2 - y - 1;
      if (w[x - left] > depth_buffer[sx][sy]) {
        depth_buffer[sx][sy] = w[x - left];
        PutPixel(x, y, color);
      }
    }
  }
}

module.exports = { IsBackFacing, CullBackFaces, Interpolate, DrawFilledTriangle };
