"""Chapter 5's camera ray and refraction with numpy: the rotation a matrix applied with
@, vectors as arrays. Written for the checker's corpus
(tests/check-functions/check_corpus.mjs); checked where a python3 has numpy."""
import numpy as np

Cw, Ch = 600, 600
Vw, Vh, d = 1.0, 1.0, 1.0
camera = None


def CanvasToViewport(x, y):
    return np.array([x * Vw / Cw, y * Vh / Ch, d])


def CameraRayDirection(x, y):
    return np.array(camera.rotation) @ CanvasToViewport(x, y)


def RefractRay(D, N, n1, n2):
    D = D / np.linalg.norm(D)
    r = n1 / n2
    c = -(N @ D)
    k = 1 - r * r * (1 - c * c)
    if k < 0:
        return None
    out = r * D + (r * c - np.sqrt(k)) * N
    return out / np.linalg.norm(out)
