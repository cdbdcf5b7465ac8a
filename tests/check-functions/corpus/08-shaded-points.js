// Chapter 8 as a plain script: points {x, y, h}, the book's PutPixel, Interpolate from
// chapter 6, DrawShadedTriangle of Listing 8-1 with the row ends truncated first.
// Written for the checker's corpus (tests/check-functions/check_corpus.mjs).
let Cw = 600, Ch = 600;
let PutPixel = (x, y, color) => {};

function Interpolate(i0, d0, i1, d1) {
  if (i0 === i1) return [d0];
  const out = [];
  const a = (d1 - d0) / (i1 - i0);
  for (let i = i0; i <= i1; i++) out.push(d0 + a * (i - i0));
  return out;
}

function DrawShadedTriangle(P0, P1, P2, color) {
  let [a, b, c] = [P0, P1, P2].sort((p, q) => p.y - q.y);
  const x01 = Interpolate(a.y, a.x, b.y, b.x), h01 = Interpolate(a.y, a.h, b.y, b.h);
  const x12 = Interpolate(b.y, b.x, c.y, c.x), h12 = Interpolate(b.y, b.h, c.y, c.h);
  const x02 = Interpolate(a.y, a.x, c.y, c.x), h02 = Interpolate(a.y, a.h, c.y, c.h);
  x01.pop();
  h01.pop();
  const x012 = x01.concat(x12), h012 = h01.concat(h12);
  const m = Math.floor(x012.length / 2);
  const leftIsLong = x02[m] < x012[m];
  const [xl, hl, xr, hr] = leftIsLong ? [x02, h02, x012, h012] : [x012, h012, x02, h02];
  for (let y = a.y; y <= c.y; y++) {
    const left = Math.trunc(xl[y - a.y]), right = Math.trunc(xr[y - a.y]);
    const h = Interpolate(left, hl[y - a.y], right, hr[y - a.y]);
    for (let x = left; x <= right; x++) {
      PutPixel(x, y, color.map((channel) => channel * h[x - left]));
    }
  }
}
