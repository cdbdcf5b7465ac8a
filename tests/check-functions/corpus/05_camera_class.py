"""Chapter 5's camera and refraction, with a Camera class and small vector helpers of
my own; RefractRay gives None on total internal reflection. Written for the checker's
corpus (tests/check-functions/check_corpus.mjs)."""
import math

Cw, Ch = 600, 600
Vw, Vh, d = 1, 1, 1


class Camera:
    def __init__(self, position, rotation):
        self.position = position
        self.rotation = rotation  # three rows


camera = Camera((0, 0, 0), ((1, 0, 0), (0, 1, 0), (0, 0, 1)))


def dot(a, b):
    return sum(p * q for p, q in zip(a, b))


def scale(k, v):
    return tuple(k * c for c in v)


def plus(a, b):
    return tuple(p + q for p, q in zip(a, b))


def unit(v):
    return scale(1 / math.sqrt(dot(v, v)), v)


def CanvasToViewport(x, y):
    return (x * Vw / Cw, y * Vh / Ch, d)


def CameraRayDirection(x, y):
    direction = CanvasToViewport(x, y)
    return tuple(dot(row, direction) for row in camera.rotation)


def RefractRay(D, N, n1, n2):
    """Snell's law for a unit N on D's side: the refracted unit direction, or None."""
    D = unit(D)
    cos_in = -dot(N, D)
    ratio = n1 / n2
    k = 1 - ratio * ratio * (1 - cos_in * cos_in)
    if k < 0:
        return None
    return unit(plus(scale(ratio, D), scale(ratio * cos_in - math.sqrt(k), N)))
