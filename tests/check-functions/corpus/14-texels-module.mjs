// Chapter 14's texel look-ups as an ES module: texture[i][j] with i the column, the
// last texel used past the edges, colours blended channel by channel. Written for the
// checker's corpus (tests/check-functions/check_corpus.mjs).
const clamp = (i, size) => Math.min(Math.max(i, 0), size - 1);
const at = (texture, i, j) => texture[clamp(i, texture.width)][clamp(j, texture.height)];
const blend = (a, b, t) => [0, 1, 2].map((k) => a[k] + (b[k] - a[k]) * t);

export function GetTexelNearest(texture, tx, ty) {
  return at(texture, Math.floor(tx), Math.floor(ty));
}

export function GetTexel(texture, tx, ty) {
  const i = Math.floor(tx), j = Math.floor(ty);
  const fx = tx - i, fy = ty - j;
  const top = blend(at(texture, i, j), at(texture, i + 1, j), fx);
  const bottom = blend(at(texture, i, j + 1), at(texture, i + 1, j + 1), fx);
  return blend(top, bottom, fy);
}
