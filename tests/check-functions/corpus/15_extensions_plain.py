"""Chapter 15's small functions in plain Python: tuples, a normalize of my own, and the
four shadow-map comparisons weighed as in bilinear filtering. Written for the checker's
corpus (tests/check-functions/check_corpus.mjs)."""
import math


def dot(a, b):
    return sum(p * q for p, q in zip(a, b))


def normalize(v):
    length = math.sqrt(dot(v, v))
    return tuple(c / length for c in v)


def without(v, n):
    """v made perpendicular to n."""
    k = dot(v, n) / dot(n, n)
    return tuple(a - k * b for a, b in zip(v, n))


def DecodeNormal(texel):
    r, g, b = texel
    return (2 * r / 255 - 1, 2 * g / 255 - 1, 2 * b / 255 - 1)


def ApplyNormalMap(n, basis, N):
    T = normalize(without(basis.T, N))
    B = normalize(without(basis.B, N))
    N = normalize(N)
    return normalize(tuple(n[0] * t + n[1] * b + n[2] * z for t, b, z in zip(T, B, N)))


def InShadow(stored_depth, depth, bias):
    return stored_depth + bias < depth


def PercentageCloserFilter(in_shadow, fx, fy):
    top_left, top_right, bottom_left, bottom_right = (0.0 if s else 1.0 for s in in_shadow)
    top = top_left + (top_right - top_left) * fx
    bottom = bottom_left + (bottom_right - bottom_left) * fx
    return top + (bottom - top) * fy
