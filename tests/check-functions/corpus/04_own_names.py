"""Chapter 4 with names of my own: SPHERES and LIGHTS lists and a BACKGROUND, plain
tuples for vectors, the book's functions. Checked with the adapter that
--adapter-template 04 prints for it (04_own_names_adapter.py), as written by the
template. Written for the checker's corpus (tests/check-functions/check_corpus.mjs)."""
import math

BACKGROUND = (0, 0, 0)
SPHERES = [
    {"center": (0, -1, 3), "radius": 1, "color": (255, 0, 0), "specular": 500, "reflective": 0.2},
]
LIGHTS = [{"type": "ambient", "intensity": 0.2}]
SHADOW_EPSILON = 0.001


def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def mul(k, a):
    return tuple(k * x for x in a)


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def length(a):
    return math.sqrt(dot(a, a))


def IntersectRaySphere(O, D, sphere):
    CO = sub(O, sphere["center"])
    a = dot(D, D)
    b = 2 * dot(CO, D)
    c = dot(CO, CO) - sphere["radius"] ** 2
    disc = b * b - 4 * a * c
    if disc < 0:
        return math.inf, math.inf
    return (-b + math.sqrt(disc)) / (2 * a), (-b - math.sqrt(disc)) / (2 * a)


def ClosestIntersection(O, D, t_min, t_max):
    best_t, best = math.inf, None
    for sphere in SPHERES:
        for t in IntersectRaySphere(O, D, sphere):
            if t_min <= t <= t_max and t < best_t:
                best_t, best = t, sphere
    return best, best_t


def ReflectRay(R, N):
    return sub(mul(2 * dot(N, R), N), R)


def ComputeLighting(P, N, V, s):
    i = 0.0
    for light in LIGHTS:
        if light["type"] == "ambient":
            i += light["intensity"]
            continue
        if light["type"] == "point":
            L, t_max = sub(light["position"], P), 1
        else:
            L, t_max = light["direction"], math.inf
        blocker, _ = ClosestIntersection(P, L, SHADOW_EPSILON, t_max)
        if blocker is not None:
            continue
        if dot(N, L) > 0:
            i += light["intensity"] * dot(N, L) / (length(N) * length(L))
        if s != -1:
            R = ReflectRay(L, N)
            if dot(R, V) > 0:
                i += light["intensity"] * (dot(R, V) / (length(R) * length(V))) ** s
    return i


def TraceRay(O, D, t_min, t_max, recursion_depth):
    sphere, t = ClosestIntersection(O, D, t_min, t_max)
    if sphere is None:
        return BACKGROUND
    P = add(O, mul(t, D))
    N = sub(P, sphere["center"])
    N = mul(1 / length(N), N)
    local = mul(ComputeLighting(P, N, mul(-1, D), sphere["specular"]), sphere["color"])
    r = sphere["reflective"]
    if recursion_depth <= 0 or r <= 0:
        return local
    reflected = TraceRay(P, ReflectRay(mul(-1, D), N), SHADOW_EPSILON, math.inf, recursion_depth - 1)
    return add(mul(1 - r, local), mul(r, reflected))
