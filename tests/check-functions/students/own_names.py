# Chapter 2 as a reader might write it from the book in Python with names of their own
# for the canvas, the viewport and the background (the demos' spheres list). The checker
# cannot know what CANVAS_WIDTH or BACKGROUND hold: it says so, names them, and
# --adapter-template 02 own_names.py prints an adapter that sets them
# (tests/check-functions/check_checkers.sh, docs/students.md).
import math
import sys

CANVAS_WIDTH = 600
CANVAS_HEIGHT = 600
VIEWPORT_SIZE = 1
PROJECTION_PLANE_D = 1
BACKGROUND = (255, 255, 255)
spheres = [
    {"center": (0, -1, 3), "radius": 1, "color": (255, 0, 0)},
    {"center": (2, 0, 4), "radius": 1, "color": (0, 0, 255)},
    {"center": (-2, 0, 4), "radius": 1, "color": (0, 255, 0)},
]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def CanvasToViewport(x, y):
    return (x * VIEWPORT_SIZE / CANVAS_WIDTH, y * VIEWPORT_SIZE / CANVAS_HEIGHT, PROJECTION_PLANE_D)


def IntersectRaySphere(O, D, sphere):
    CO = (O[0] - sphere["center"][0], O[1] - sphere["center"][1], O[2] - sphere["center"][2])
    a = dot(D, D)
    b = 2 * dot(CO, D)
    c = dot(CO, CO) - sphere["radius"] ** 2
    discriminant = b * b - 4 * a * c
    if discriminant < 0:
        return math.inf, math.inf
    return (-b + math.sqrt(discriminant)) / (2 * a), (-b - math.sqrt(discriminant)) / (2 * a)


def TraceRay(O, D, t_min, t_max):
    closest_t, closest_sphere = math.inf, None
    for sphere in spheres:
        for t in IntersectRaySphere(O, D, sphere):
            if t_min <= t <= t_max and t < closest_t:
                closest_t, closest_sphere = t, sphere
    return BACKGROUND if closest_sphere is None else closest_sphere["color"]


def render(path):
    """Figure 2-11 as a P3 file: run as `python3 own_names.py out.ppm`."""
    rows = []
    for y in range(CANVAS_HEIGHT // 2 - 1, -CANVAS_HEIGHT // 2 - 1, -1):
        for x in range(-CANVAS_WIDTH // 2, CANVAS_WIDTH // 2):
            rows.append("%d %d %d" % TraceRay((0, 0, 0), CanvasToViewport(x, y), 1, math.inf))
    with open(path, "w") as out:
        out.write(f"P3\n{CANVAS_WIDTH} {CANVAS_HEIGHT}\n255\n" + "\n".join(rows) + "\n")


# A main block that writes wherever its first argument says, unguarded: the checker
# gives the module no arguments, so it writes nothing.
if len(sys.argv) > 1:
    render(sys.argv[1])
