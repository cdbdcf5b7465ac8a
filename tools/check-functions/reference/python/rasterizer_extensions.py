# cases: 15 (tests/cases/15-rasterizer-extensions.json)
"""Chapter 15, "Extending the Rasterizer", in plain Python, from the book's prose: the
checker's reference (tools/check-functions). A normal map's texel decoded and applied
("Normal Mapping"), and the shadow map's comparison and percentage-closer filtering
("Shadow Mapping")."""

import math


def DecodeNormal(texel):
    return [2 * channel / 255 - 1 for channel in texel]


def Dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def Normalized(v):
    length = math.sqrt(Dot(v, v))
    return [each / length for each in v]


def ApplyNormalMap(n, basis, N):
    # T and B made perpendicular to N (and B to T), then n brought out of tangent space.
    T = Normalized([t - N[i] * Dot(N, basis.T) for i, t in enumerate(basis.T)])
    B = Normalized([b - N[i] * Dot(N, basis.B) - T[i] * Dot(T, basis.B)
                    for i, b in enumerate(basis.B)])
    return Normalized([T[i] * n[0] + B[i] * n[1] + N[i] * n[2] for i in range(3)])


def InShadow(stored_depth, depth, bias):
    return stored_depth < depth - bias


def PercentageCloserFilter(in_shadow, fx, fy):
    weights = [(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy]
    return sum(weight for weight, shadowed in zip(weights, in_shadow) if not shadowed)
