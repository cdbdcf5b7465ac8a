# cases: 14 (tests/cases/14-textures.json)
"""Chapter 14, "Textures", in plain Python, as the book writes it: the checker's reference
(tools/check-functions). The nearest texel ("Painting a Crate") and GetTexel's bilinear
filtering ("Bilinear Filtering"); texture[i][j] is column i, row j, and a texel past
the last column or row is the last one."""

import math


def Texel(texture, i, j):
    return texture[min(max(i, 0), texture.width - 1)][min(max(j, 0), texture.height - 1)]


def GetTexelNearest(texture, tx, ty):
    return Texel(texture, math.floor(tx), math.floor(ty))


def Mix(a, b, t):
    return [x + t * (y - x) for x, y in zip(a, b)]


def GetTexel(texture, tx, ty):
    i, j = math.floor(tx), math.floor(ty)
    fx, fy = tx - i, ty - j
    TL, TR = Texel(texture, i, j), Texel(texture, i + 1, j)
    BL, BR = Texel(texture, i, j + 1), Texel(texture, i + 1, j + 1)
    return Mix(Mix(TL, TR, fx), Mix(BL, BR, fx), fy)
