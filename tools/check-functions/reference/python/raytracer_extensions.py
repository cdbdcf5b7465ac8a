# cases: 05 (tests/cases/05-raytracer-extensions.json)
"""Chapter 5, "Extending the Raytracer", in plain Python: the checker's reference
(tools/check-functions). The camera of Listing 5-1, and refraction, which the book
describes in prose (Snell's law)."""

import math

from basic_rays import dot

Cw, Ch = 600, 600
Vw, Vh, d = 1, 1, 1
camera = None


def CanvasToViewport(x, y):
    return (x * Vw / Cw, y * Vh / Ch, d)


def MultiplyMV(mat, vec):
    return tuple(dot(row, vec) for row in mat)


# Listing 5-1: the viewport's direction through (x, y), turned with the camera.
def CameraRayDirection(x, y):
    return MultiplyMV(camera.rotation, CanvasToViewport(x, y))


# "Refraction": sin a1 / sin a2 = n2 / n1. With D a unit vector, c1 = -<N, D> is the
# cosine of the angle of incidence; the refracted direction is eta D + (eta c1 - c2) N,
# eta = n1 / n2, c2 its angle's cosine; none when sin a2 would exceed 1.
def RefractRay(D, N, n1, n2):
    length = math.sqrt(dot(D, D))
    D = tuple(component / length for component in D)
    eta = n1 / n2
    c1 = -dot(N, D)
    k = 1 - eta * eta * (1 - c1 * c1)
    if k < 0:
        return None  # total internal reflection
    c2 = math.sqrt(k)
    return tuple(eta * d_i + (eta * c1 - c2) * n_i for d_i, n_i in zip(D, N))
