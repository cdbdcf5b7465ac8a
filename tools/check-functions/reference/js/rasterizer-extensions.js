// cases: 15 (tests/cases/15-rasterizer-extensions.json)
// Chapter 15, "Extending the Rasterizer", in plain JavaScript, as the book writes it:
// the checker's reference (tools/check-functions), one script as a reader writes it on
// a chapter's page. Chapter 14's script carried forward, with a normal map's texel
// decoded and applied ("Normal Mapping"), and the shadow map's comparison and
// percentage-closer filtering ("Shadow Mapping"), from the book's prose.
"use strict";

let Cw = 600, Ch = 600;       // the canvas
let Vw = 1, Vh = 1, d = 1;    // the viewport, at distance d
let PutPixel = () => { throw new Error("the canvas goes here"); };
let depth_buffer = [];  // depth_buffer[x][y]: 1/z of what is drawn there, 0 for nothing

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

// The values of a quantity along a triangle's long side (y0 to y2) and its two short
// ones (y0 to y1 to y2), as Listing 7-1 works out x.
function EdgeInterpolate(y0, v0, y1, v1, y2, v2) {
  const v01 = Interpolate(y0, v0, y1, v1);
  const v12 = Interpolate(y1, v1, y2, v2);
  const v02 = Interpolate(y0, v0, y2, v2);
  v01.pop();
  return [v02, v01.concat(v12)];
}

// "Depth Buffering": Listing 7-1 with 1/z interpolated too, each pixel put only where it
// is nearer than what the depth buffer holds.
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

function Dot(a, b) {
  return a.reduce((sum, each, i) => sum + each * b[i], 0);
}

// Listing 11-4: how far a point is in front of a plane (behind it: negative).
function SignedDistance(plane, vertex) {
  return Dot(vertex, plane.normal) + plane.D;
}

// Where the segment from A to B crosses the plane.
function Intersection(A, B, plane) {
  const AB = B.map((each, i) => each - A[i]);
  const t = (-plane.D - Dot(plane.normal, A)) / Dot(plane.normal, AB);
  return A.map((each, i) => each + t * AB[i]);
}

// Listing 11-3: the parts of a triangle in front of a plane: none, itself, or one or two
// new triangles, whose new vertices are added to the list.
function ClipTriangle(triangle, plane, vertices) {
  const inFront = triangle.v.map((i) => SignedDistance(plane, vertices[i]) >= 0);
  const count = inFront.filter(Boolean).length;
  if (count === 3) return [triangle];
  if (count === 0) return [];
  // Where the segment from vertex a to vertex b crosses the plane.
  const NewVertex = (a, b) => vertices.push(Intersection(vertices[a], vertices[b], plane)) - 1;
  // One in front: A is that one. Two: C is the one behind. The others follow in order.
  const k = inFront.indexOf(count === 1);
  const [first, second, third] = [0, 1, 2].map((n) => triangle.v[(k + n) % 3]);
  const { color } = triangle;
  if (count === 1) {
    const [A, B, C] = [first, second, third];
    return [{ v: [A, NewVertex(A, B), NewVertex(A, C)], color }];
  }
  const [C, A, B] = [first, second, third];
  const APrime = NewVertex(A, C), BPrime = NewVertex(B, C);
  return [{ v: [A, B, APrime], color }, { v: [APrime, B, BPrime], color }];
}

// "Clipping Whole Objects": the centre of the vertices, and the farthest one's distance.
function ComputeBoundingSphere(vertices) {
  const center = [0, 1, 2].map((i) => vertices.reduce((sum, v) => sum + v[i], 0) / vertices.length);
  const radius = Math.max(...vertices.map((v) => Math.hypot(...v.map((each, i) => each - center[i]))));
  return { center, radius };
}

function Subtract(a, b) {
  return a.map((each, i) => each - b[i]);
}

function Cross(a, b) {
  return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
}

// "Classifying Triangles": the camera is behind the triangle's front face.
function IsBackFacing(A, B, C, camera) {
  const N = Cross(Subtract(B, A), Subtract(C, A));
  const V = Subtract(camera, A);
  return Dot(N, V) <= 0;
}

// Listing 12-1: the object keeps the triangles that face the camera.
function CullBackFaces(object, camera) {
  const V = object.vertices;
  object.triangles = object.triangles.filter((T) => !IsBackFacing(V[T.v[0]], V[T.v[1]], V[T.v[2]], camera));
}

// "Flat Shading": the unit normal of the triangle's front face.
function ComputeTriangleNormal(A, B, C) {
  const N = Cross(Subtract(B, A), Subtract(C, A));
  const length = Math.hypot(...N);
  return N.map((each) => each / length);
}

// "Phong Shading": the point of the scene a pixel (x, y) with depth 1/z shows.
function UnProjectVertex(x, y, inv_z) {
  const z = 1 / inv_z;
  return [x * Vw / Cw * z / d, y * Vh / Ch * z / d, z];
}

// The texel in column i, row j, a texel past the last column or row being the last one.
function Texel(texture, i, j) {
  const clamp = (value, last) => Math.min(Math.max(value, 0), last);
  return texture[clamp(i, texture.width - 1)][clamp(j, texture.height - 1)];
}

// "Painting a Crate": the texel that holds (tx, ty).
function GetTexelNearest(texture, tx, ty) {
  return Texel(texture, Math.floor(tx), Math.floor(ty));
}

function Mix(a, b, t) {
  return a.map((each, k) => each + t * (b[k] - each));
}

// "Bilinear Filtering": the four texels around (tx, ty), mixed by how near each is.
function GetTexel(texture, tx, ty) {
  const i = Math.floor(tx), j = Math.floor(ty);
  const fx = tx - i, fy = ty - j;
  const TL = Texel(texture, i, j), TR = Texel(texture, i + 1, j);
  const BL = Texel(texture, i, j + 1), BR = Texel(texture, i + 1, j + 1);
  return Mix(Mix(TL, TR, fx), Mix(BL, BR, fx), fy);
}

function Normalized(v) {
  return v.map((each) => each / Math.sqrt(Dot(v, v)));
}

// "Normal Mapping": a texel's colour read as a vector, each channel from -1 to 1.
function DecodeNormal(texel) {
  return texel.map((channel) => 2 * channel / 255 - 1);
}

// "Normal Mapping": T and B made perpendicular to N (and B to T), then n brought out of
// tangent space.
function ApplyNormalMap(n, basis, N) {
  const T = Normalized(basis.T.map((t, i) => t - N[i] * Dot(N, basis.T)));
  const B = Normalized(basis.B.map((b, i) => b - N[i] * Dot(N, basis.B) - T[i] * Dot(T, basis.B)));
  return Normalized([0, 1, 2].map((i) => T[i] * n[0] + B[i] * n[1] + N[i] * n[2]));
}

// "Shadow Mapping": the point is behind what the light sees there, by more than the bias.
function InShadow(stored_depth, depth, bias) {
  return stored_depth < depth - bias;
}

// "Shadow Mapping": how lit a point is between four shadow-map texels (top-left,
// top-right, bottom-left, bottom-right), each weighted by its nearness.
function PercentageCloserFilter(in_shadow, fx, fy) {
  const weights = [(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy];
  return weights.reduce((sum, weight, k) => sum + (in_shadow[k] ? 0 : weight), 0);
}
