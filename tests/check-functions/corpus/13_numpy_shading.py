"""Chapter 13's two small functions with numpy: np.cross and np.linalg.norm, the
canvas and viewport as the book's globals. Written for the checker's corpus
(tests/check-functions/check_corpus.mjs); checked where a python3 has numpy."""
import numpy as np

Cw, Ch = 600, 600
Vw, Vh, d = 1.0, 1.0, 1.0


def UnProjectVertex(x, y, inv_z):
    z = 1 / inv_z
    return np.array([x * Vw / Cw * z / d, y * Vh / Ch * z / d, z])


def ComputeTriangleNormal(A, B, C):
    n = np.cross(B - A, C - A)
    return n / np.linalg.norm(n)
