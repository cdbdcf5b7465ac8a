// cases: 10 (tests/cases/10-scene-rendering.json)
// Chapter 10, "Describing and Rendering a Scene", in plain JavaScript, as the book
// writes it: the checker's reference (tools/check-functions), one script as a reader
// writes it on a chapter's page. Chapter 9's script carried forward, with the
// homogeneous matrices of "Homogeneous Coordinates", ApplyTransform (Listing 10-4) and
// MakeCameraMatrix (Listing 10-5); a matrix is an array of its rows, and a matrix times
// a point takes (x, y, z, 1).
"use strict";

let Cw = 600, Ch = 600;       // the canvas
let Vw = 1, Vh = 1, d = 1;    // the viewport, at distance d
let PutPixel = () => { throw new Error("the canvas goes here"); };

// Listing 6-1: the values of d for each whole i from i0 to i1, d0 to d1 in a line. The
// book adds a at each step (d = d + a), which drifts: d0 + a (i - i0) does not
// (docs/conventions.md).
function Interpolate(i0, d0, i1, d1) {
  if (i0 === i1) return [d0];
  const values = [];
  const a = (d1 - d0) / (i1 - i0);
  for (let i = i0; i <= i1; i++) values.push(d0 + a * (i - i0));
  return values;
}

// Listing 6-2: one pixel per step along the axis the line spans most.
function DrawLine(P0, P1, color) {
  if (Math.abs(P1.x - P0.x) > Math.abs(P1.y - P0.y)) {
    // The line is horizontal-ish. Make sure x0 < x1
    if (P0.x > P1.x) [P0, P1] = [P1, P0];
    const ys = Interpolate(P0.x, P0.y, P1.x, P1.y);
    for (let x = P0.x; x <= P1.x; x++) PutPixel(x, ys[x - P0.x], color);
  } else {
    // The line is vertical-ish. Make sure y0 < y1
    if (P0.y > P1.y) [P0, P1] = [P1, P0];
    const xs = Interpolate(P0.y, P0.x, P1.y, P1.x);
    for (let y = P0.y; y <= P1.y; y++) PutPixel(xs[y - P0.y], y, color);
  }
}

function DrawWireframeTriangle(P0, P1, P2, color) {
  DrawLine(P0, P1, color);
  DrawLine(P1, P2, color);
  DrawLine(P2, P0, color);
}

// Listing 7-1: for each row, from the long side to the two short ones.
function DrawFilledTriangle(P0, P1, P2, color) {
  // Sort the points so that y0 <= y1 <= y2
  if (P1.y < P0.y) [P1, P0] = [P0, P1];
  if (P2.y < P0.y) [P2, P0] = [P0, P2];
  if (P2.y < P1.y) [P2, P1] = [P1, P2];

  // Compute the x coordinates of the triangle edges
  const x01 = Interpolate(P0.y, P0.x, P1.y, P1.x);
  const x12 = Interpolate(P1.y, P1.x, P2.y, P2.x);
  const x02 = Interpolate(P0.y, P0.x, P2.y, P2.x);

  // Concatenate the short sides
  x01.pop();
  const x012 = x01.concat(x12);

  // Determine which is left and which is right
  const m = Math.floor(x012.length / 2);
  const [x_left, x_right] = x02[m] < x012[m] ? [x02, x012] : [x012, x02];

  // Draw the horizontal segments
  for (let y = P0.y; y <= P2.y; y++) {
    for (let x = Math.trunc(x_left[y - P0.y]); x <= Math.trunc(x_right[y - P0.y]); x++) {
      PutPixel(x, y, color);
    }
  }
}

// Listing 8-1: Listing 7-1 with h carried along.
function DrawShadedTriangle(P0, P1, P2, color) {
  // Sort the points so that y0 <= y1 <= y2
  if (P1.y < P0.y) [P1, P0] = [P0, P1];
  if (P2.y < P0.y) [P2, P0] = [P0, P2];
  if (P2.y < P1.y) [P2, P1] = [P1, P2];

  // Compute the x coordinates and h values of the triangle edges
  const x01 = Interpolate(P0.y, P0.x, P1.y, P1.x);
  const h01 = Interpolate(P0.y, P0.h, P1.y, P1.h);
  const x12 = Interpolate(P1.y, P1.x, P2.y, P2.x);
  const h12 = Interpolate(P1.y, P1.h, P2.y, P2.h);
  const x02 = Interpolate(P0.y, P0.x, P2.y, P2.x);
  const h02 = Interpolate(P0.y, P0.h, P2.y, P2.h);

  // Concatenate the short sides
  x01.pop();
  const x012 = x01.concat(x12);
  h01.pop();
  const h012 = h01.concat(h12);

  // Determine which is left and which is right
  const m = Math.floor(x012.length / 2);
  const [x_left, h_left, x_right, h_right] =
    x02[m] < x012[m] ? [x02, h02, x012, h012] : [x012, h012, x02, h02];

  // Draw the horizontal segments
  for (let y = P0.y; y <= P2.y; y++) {
    const x_l = Math.trunc(x_left[y - P0.y]);
    const x_r = Math.trunc(x_right[y - P0.y]);
    const h_segment = Interpolate(x_l, h_left[y - P0.y], x_r, h_right[y - P0.y]);
    for (let x = x_l; x <= x_r; x++) {
      PutPixel(x, y, color.map((channel) => channel * h_segment[x - x_l]));
    }
  }
}

// Listing 9-1: a viewport point to the canvas point it lands on, a whole pixel (truncated
// toward zero, as docs/conventions.md says of every canvas point).
function ViewportToCanvas(x, y) {
  return { x: Math.trunc(x * Cw / Vw), y: Math.trunc(y * Ch / Vh) };
}

// Listing 9-1: a point of the scene (an array [x, y, z]) projected onto the canvas.
function ProjectVertex(v) {
  return ViewportToCanvas(v[0] * d / v[2], v[1] * d / v[2]);
}

function MakeTranslationMatrix([x, y, z]) {
  return [[1, 0, 0, x], [0, 1, 0, y], [0, 0, 1, z], [0, 0, 0, 1]];
}

function MakeScalingMatrix(scale) {
  return [[scale, 0, 0, 0], [0, scale, 0, 0], [0, 0, scale, 0], [0, 0, 0, 1]];
}

function MakeOYRotationMatrix(degrees) {
  const cos = Math.cos(degrees * Math.PI / 180), sin = Math.sin(degrees * Math.PI / 180);
  return [[cos, 0, -sin, 0], [0, 1, 0, 0], [sin, 0, cos, 0], [0, 0, 0, 1]];
}

const range4 = [0, 1, 2, 3];

function MultiplyMM4(A, B) {
  return range4.map((i) => range4.map((j) => range4.reduce((sum, k) => sum + A[i][k] * B[k][j], 0)));
}

function MultiplyMV(M, v) {
  return range4.map((i) => range4.reduce((sum, k) => sum + M[i][k] * v[k], 0));
}

function Transposed(M) {
  return range4.map((i) => range4.map((j) => M[j][i]));
}

// Listing 10-4: scale, then rotate, then translate.
function ApplyTransform(vertex, transform) {
  const scaled = [...vertex.map((each) => each * transform.scale), 1];
  const rotated = MultiplyMV(transform.rotation, scaled);
  return [0, 1, 2].map((i) => rotated[i] + transform.translation[i]);
}

// Listing 10-5: the camera's inverse rotation times its inverse translation.
function MakeCameraMatrix(position, orientation) {
  return MultiplyMM4(Transposed(orientation), MakeTranslationMatrix(position.map((each) => -each)));
}
