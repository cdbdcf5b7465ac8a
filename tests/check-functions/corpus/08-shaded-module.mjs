// Chapter 8 as an ES module: a Pt class of my own (x, y, h), PutPixel a settable
// export, Listing 8-1 with an Interpolate that walks whole steps. Written for the
// checker's corpus (tests/check-functions/check_corpus.mjs).
export class Pt {
  constructor(x, y, h = 1) {
    this.x = x;
    this.y = y;
    this.h = h;
  }
}

export let PutPixel = () => {};

export function Interpolate(i0, d0, i1, d1) {
  if (i0 === i1) return [d0];
  const values = [];
  for (let i = i0; i <= i1; i++) values.push(d0 + ((d1 - d0) * (i - i0)) / (i1 - i0));
  return values;
}

function edges(a, b, c, field) {
  const ab = Interpolate(a.y, a[field], b.y, b[field]);
  ab.pop();
  return [Interpolate(a.y, a[field], c.y, c[field]), ab.concat(Interpolate(b.y, b[field], c.y, c[field]))];
}

export function DrawShadedTriangle(P0, P1, P2, color) {
  const [a, b, c] = [P0, P1, P2].sort((p, q) => p.y - q.y);
  const [x02, x012] = edges(a, b, c, "x");
  const [h02, h012] = edges(a, b, c, "h");
  const m = Math.floor(x012.length / 2);
  const longLeft = x02[m] < x012[m];
  for (let y = a.y; y <= c.y; y++) {
    const i = y - a.y;
    const xl = Math.trunc(longLeft ? x02[i] : x012[i]), xr = Math.trunc(longLeft ? x012[i] : x02[i]);
    const hs = Interpolate(xl, longLeft ? h02[i] : h012[i], xr, longLeft ? h012[i] : h02[i]);
    for (let x = xl; x <= xr; x++) PutPixel(x, y, color.map((channel) => channel * hs[x - xl]));
  }
}
