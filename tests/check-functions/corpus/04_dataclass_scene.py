"""Chapter 4 with dataclasses for spheres and lights and a Scene object holding them;
vectors are tuples, recursion counts down to 0. Written for the checker's corpus
(tests/check-functions/check_corpus.mjs)."""
from dataclasses import dataclass, field
import math

Vector = tuple[float, float, float]
EPSILON = 0.001


@dataclass
class Sphere:
    center: Vector
    radius: float
    color: Vector
    specular: float = -1
    reflective: float = 0


@dataclass
class Light:
    type: str
    intensity: float
    position: Vector = (0, 0, 0)
    direction: Vector = (0, 0, 0)


@dataclass
class Scene:
    spheres: list = field(default_factory=list)
    lights: list = field(default_factory=list)
    background_color: Vector = (0, 0, 0)


scene = Scene()


def add(a, b):
    return tuple(p + q for p, q in zip(a, b))


def sub(a, b):
    return tuple(p - q for p, q in zip(a, b))


def mul(k, v):
    return tuple(k * c for c in v)


def dot(a, b):
    return sum(p * q for p, q in zip(a, b))


def norm(v):
    return math.sqrt(dot(v, v))


def IntersectRaySphere(O, D, sphere):
    CO = sub(O, sphere.center)
    a, b, c = dot(D, D), 2 * dot(CO, D), dot(CO, CO) - sphere.radius**2
    disc = b * b - 4 * a * c
    if disc < 0:
        return math.inf, math.inf
    return (-b + math.sqrt(disc)) / (2 * a), (-b - math.sqrt(disc)) / (2 * a)


def ClosestIntersection(O, D, t_min, t_max):
    closest_t, closest = math.inf, None
    for sphere in scene.spheres:
        for t in IntersectRaySphere(O, D, sphere):
            if t_min <= t <= t_max and t < closest_t:
                closest_t, closest = t, sphere
    return closest, closest_t


def ReflectRay(R, N):
    return sub(mul(2 * dot(N, R), N), R)


def ComputeLighting(P, N, V, s):
    total = 0.0
    for light in scene.lights:
        if light.type == "ambient":
            total += light.intensity
            continue
        L, t_max = (sub(light.position, P), 1) if light.type == "point" else (light.direction, math.inf)
        if ClosestIntersection(P, L, EPSILON, t_max)[0] is not None:
            continue
        if dot(N, L) > 0:
            total += light.intensity * dot(N, L) / (norm(N) * norm(L))
        if s != -1:
            R = ReflectRay(L, N)
            if dot(R, V) > 0:
                total += light.intensity * (dot(R, V) / (norm(R) * norm(V))) ** s
    return total


def TraceRay(O, D, t_min, t_max, recursion_depth):
    sphere, t = ClosestIntersection(O, D, t_min, t_max)
    if sphere is None:
        return scene.background_color
    P = add(O, mul(t, D))
    N = sub(P, sphere.center)
    N = mul(1 / norm(N), N)
    local = mul(ComputeLighting(P, N, mul(-1, D), sphere.specular), sphere.color)
    if recursion_depth <= 0 or sphere.reflective <= 0:
        return local
    reflected = TraceRay(P, ReflectRay(mul(-1, D), N), EPSILON, math.inf, recursion_depth - 1)
    return add(mul(1 - sphere.reflective, local), mul(sphere.reflective, reflected))
