"""Chapter 14's texel look-ups: the nearest texel and the bilinear blend, clamped at the
last row and column, colours as tuples. Written for the checker's corpus
(tests/check-functions/check_corpus.mjs)."""
import math


def clamp_index(i, size):
    return max(0, min(int(i), size - 1))


def GetTexelNearest(texture, tx, ty):
    return texture[clamp_index(math.floor(tx), texture.width)][clamp_index(math.floor(ty), texture.height)]


def mix(a, b, t):
    return tuple((1 - t) * p + t * q for p, q in zip(a, b))


def GetTexel(texture, tx, ty):
    fx, fy = tx - math.floor(tx), ty - math.floor(ty)
    i, j = math.floor(tx), math.floor(ty)
    column = lambda n: clamp_index(n, texture.width)
    row = lambda n: clamp_index(n, texture.height)
    top_left, top_right = texture[column(i)][row(j)], texture[column(i + 1)][row(j)]
    bottom_left, bottom_right = texture[column(i)][row(j + 1)], texture[column(i + 1)][row(j + 1)]
    return mix(mix(top_left, top_right, fx), mix(bottom_left, bottom_right, fx), fy)
