// cases: 12 (tests/cases/12-hidden-surface-removal.json)
// Chapter 12, "Hidden Surface Removal", in plain JavaScript, as the book writes it: the
// checker's reference (tools/check-functions). The filled triangle with a depth test
// before every PutPixel ("Depth Buffering", "Using 1/Z Instead of Z"), classifying a
// triangle ("Classifying Triangles") and CullBackFaces (Listing 12-1), which keeps the
// triangles that face the camera. The book's globals PutPixel, Cw, Ch and depth_buffer
// (depth_buffer[x][y] from the screen's top-left corner, as PutPixel maps a canvas
// point) are the ones the checker sets.
"use strict";

const { Interpolate } = require("./lines.js");

function EdgeInterpolate(y0, v0, y1, v1, y2, v2) {
  const v01 = Interpolate(y0, v0, y1, v1);
  const v12 = Interpolate(y1, v1, y2, v2);
  const v02 = Interpolate(y0, v0, y2, v2);
  v01.pop();
  return [v02, v01.concat(v12)];
}

function DrawFilledTriangle(P0, P1, P2, z0, z1, z2, color) {
  // Sort the points so that y0 <= y1 <= y2; each depth goes with its point.
  if (P1.y < P0.y) [P0, P1, z0, z1] = [P1, P0, z1, z0];
  if (P2.y < P0.y) [P0, P2, z0, z2] = [P2, P0, z2, z0];
  if (P2.y < P1.y) [P1, P2, z1, z2] = [P2, P1, z2, z1];
  const [x02, x012] = EdgeInterpolate(P0.y, P0.x, P1.y, P1.x, P2.y, P2.x);
  const [iz02, iz012] = EdgeInterpolate(P0.y, 1 / z0, P1.y, 1 / z1, P2.y, 1 / z2);
  const m = Math.floor(x012.length / 2);
  const [xLeft, xRight, izLeft, izRight] = x02[m] < x012[m] ? [x02, x012, iz02, iz012] : [x012, x02, iz012, iz02];
  for (let y = P0.y; y <= P2.y; ++y) {
    const xl = Math.trunc(xLeft[y - P0.y]), xr = Math.trunc(xRight[y - P0.y]);
    const izSegment = Interpolate(xl, izLeft[y - P0.y], xr, izRight[y - P0.y]);
    for (let x = xl; x <= xr; ++x) {
      const sx = Math.floor(Cw / 2) + x, sy = Math.floor(Ch / 2) - y - 1;  // as PutPixel maps it
      if (sx >= 0 && sx < Cw && sy >= 0 && sy < Ch && izSegment[x - xl] > depth_buffer[sx][sy]) {
        PutPixel(x, y, color);
        depth_buffer[sx][sy] = izSegment[x - xl];
      }
    }
  }
}

const Subtract = (a, b) => a.map((each, i) => each - b[i]);
const Cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const Dot = (a, b) => a.reduce((sum, each, i) => sum + each * b[i], 0);

function IsBackFacing(A, B, C, camera) {
  const N = Cross(Subtract(B, A), Subtract(C, A));
  const V = Subtract(camera, A);
  return Dot(N, V) <= 0;
}

function CullBackFaces(object, camera) {
  const V = object.vertices;
  object.triangles = object.triangles.filter((T) => !IsBackFacing(V[T.v[0]], V[T.v[1]], V[T.v[2]], camera));
}

module.exports = { DrawFilledTriangle, IsBackFacing, CullBackFaces };
