# cases: 02 (tests/cases/02-basic-rays.json)
"""Chapter 2, "Basic Raytracing", in plain Python, as the book writes it: the checker's
reference (tools/check-functions), one module as a reader writes it on a chapter's
page. The book's globals are module variables; vectors and colours are tuples."""

import math

Cw, Ch = 600, 600  # the canvas
Vw, Vh, d = 1, 1, 1  # the viewport, at distance d
scene = None
BACKGROUND_COLOR = (255, 255, 255)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def subtract(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


# Listing 2-2: a canvas point to the viewport point it looks through.
def CanvasToViewport(x, y):
    return (x * Vw / Cw, y * Vh / Ch, d)


# Listing 2-3: the two solutions of t^2<D,D> + 2t<CO,D> + <CO,CO> - r^2 = 0.
def IntersectRaySphere(O, D, sphere):
    r = sphere.radius
    CO = subtract(O, sphere.center)

    a = dot(D, D)
    b = 2 * dot(CO, D)
    c = dot(CO, CO) - r * r

    discriminant = b * b - 4 * a * c
    if discriminant < 0:
        return math.inf, math.inf

    t1 = (-b + math.sqrt(discriminant)) / (2 * a)
    t2 = (-b - math.sqrt(discriminant)) / (2 * a)
    return t1, t2


# Listing 2-4: the colour of the nearest sphere the ray meets in [t_min, t_max].
def TraceRay(O, D, t_min, t_max):
    closest_t = math.inf
    closest_sphere = None
    for sphere in scene.spheres:
        t1, t2 = IntersectRaySphere(O, D, sphere)
        if t_min <= t1 <= t_max and t1 < closest_t:
            closest_t = t1
            closest_sphere = sphere
        if t_min <= t2 <= t_max and t2 < closest_t:
            closest_t = t2
            closest_sphere = sphere
    if closest_sphere is None:
        return BACKGROUND_COLOR
    return closest_sphere.color
