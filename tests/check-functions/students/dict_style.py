# Chapter 2 as a reader might write it from the book in plain Python: the spheres are
# dicts, vectors are tuples, and the book's globals are module variables. The checker
# runs it without an adapter (tests/check-functions/check_runners.sh, docs/students.md).
import math

Cw, Ch = 600, 600
Vw, Vh, d = 1, 1, 1
BACKGROUND_COLOR = (255, 255, 255)
scene = {
    "spheres": [
        {"center": (0, -1, 3), "radius": 1, "color": (255, 0, 0)},
        {"center": (2, 0, 4), "radius": 1, "color": (0, 0, 255)},
        {"center": (-2, 0, 4), "radius": 1, "color": (0, 255, 0)},
    ]
}


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def subtract(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def CanvasToViewport(x, y):
    return (x * Vw / Cw, y * Vh / Ch, d)


def IntersectRaySphere(O, D, sphere):
    r = sphere["radius"]
    CO = subtract(O, sphere["center"])
    a = dot(D, D)
    b = 2 * dot(CO, D)
    c = dot(CO, CO) - r * r
    discriminant = b * b - 4 * a * c
    if discriminant < 0:
        return math.inf, math.inf
    t1 = (-b + math.sqrt(discriminant)) / (2 * a)
    t2 = (-b - math.sqrt(discriminant)) / (2 * a)
    return t1, t2


def TraceRay(O, D, t_min, t_max):
    closest_t = math.inf
    closest_sphere = None
    for sphere in scene["spheres"]:
        t1, t2 = IntersectRaySphere(O, D, sphere)
        if t_min <= t1 <= t_max and t1 < closest_t:
            closest_t, closest_sphere = t1, sphere
        if t_min <= t2 <= t_max and t2 < closest_t:
            closest_t, closest_sphere = t2, sphere
    if closest_sphere is None:
        return BACKGROUND_COLOR
    return closest_sphere["color"]
