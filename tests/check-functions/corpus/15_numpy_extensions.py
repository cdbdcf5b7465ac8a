"""Chapter 15's small functions with numpy: the tangent basis as a matrix, np.dot for
the bilinear weights of the shadow comparisons. Written for the checker's corpus
(tests/check-functions/check_corpus.mjs); checked where a python3 has numpy."""
import numpy as np


def unit(v):
    return v / np.linalg.norm(v)


def DecodeNormal(texel):
    return np.asarray(texel, dtype=float) * 2 / 255 - 1


def ApplyNormalMap(n, basis, N):
    N = unit(np.asarray(N, dtype=float))
    T = unit(basis.T - (basis.T @ N) * N)
    B = unit(basis.B - (basis.B @ N) * N)
    return unit(np.column_stack([T, B, N]) @ n)


def InShadow(stored_depth, depth, bias):
    return bool(depth - stored_depth > bias)


def PercentageCloserFilter(in_shadow, fx, fy):
    lit = 1.0 - np.asarray(in_shadow, dtype=float)
    weights = np.array([(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy])
    return float(np.dot(lit, weights))
