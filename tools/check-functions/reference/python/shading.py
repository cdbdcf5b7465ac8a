# cases: 13 (tests/cases/13-shading.json)
"""Chapter 13, "Shading", in plain Python, as the book writes it: the checker's reference
(tools/check-functions). A triangle's own normal ("Flat Shading") and UnProjectVertex
("Phong Shading"), which undoes ProjectVertex for a pixel and its 1/z; the book's
globals are module variables."""

import math

Cw, Ch = 600, 600
Vw, Vh, d = 1, 1, 1


def ComputeTriangleNormal(A, B, C):
    u = [b - a for a, b in zip(A, B)]
    v = [c - a for a, c in zip(A, C)]
    N = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    length = math.sqrt(sum(each * each for each in N))
    return [each / length for each in N]


def UnProjectVertex(x, y, inv_z):
    z = 1 / inv_z
    return [x * Vw / Cw * z / d, y * Vh / Ch * z / d, z]
