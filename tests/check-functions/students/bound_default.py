# Chapter 2 in Python with the book's names, but TraceRay takes its spheres as a default
# argument, spheres=SPHERES: the list is bound when the def runs, so nothing set later,
# by the checker or an adapter, reaches it. The checker names that default and the change
# that fixes it (tests/check-functions/check_checkers.sh, docs/students.md).
import math

Cw, Ch = 600, 600
Vw, Vh, d = 1, 1, 1
BACKGROUND_COLOR = (255, 255, 255)
SPHERES = [{"center": (0, -1, 3), "radius": 1, "color": (255, 0, 0)}]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def CanvasToViewport(x, y):
    return (x * Vw / Cw, y * Vh / Ch, d)


def IntersectRaySphere(O, D, sphere):
    CO = tuple(o - c for o, c in zip(O, sphere["center"]))
    a, b = dot(D, D), 2 * dot(CO, D)
    c = dot(CO, CO) - sphere["radius"] ** 2
    discriminant = b * b - 4 * a * c
    if discriminant < 0:
        return math.inf, math.inf
    return (-b + math.sqrt(discriminant)) / (2 * a), (-b - math.sqrt(discriminant)) / (2 * a)


def TraceRay(O, D, t_min, t_max, spheres=SPHERES):
    closest_t, closest_sphere = math.inf, None
    for sphere in spheres:
        for t in IntersectRaySphere(O, D, sphere):
            if t_min <= t <= t_max and t < closest_t:
                closest_t, closest_sphere = t, sphere
    return BACKGROUND_COLOR if closest_sphere is None else closest_sphere["color"]
