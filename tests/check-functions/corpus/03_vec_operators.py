"""Chapter 3 with a Vec class of my own that overloads +, -, * and @ (the dot product),
and a light's kind read from its `type`. Written for the checker's corpus
(tests/check-functions/check_corpus.mjs)."""
import math


class Vec:
    def __init__(self, x, y, z):
        self.x, self.y, self.z = x, y, z

    def __add__(self, other):
        return Vec(self.x + other.x, self.y + other.y, self.z + other.z)

    def __sub__(self, other):
        return Vec(self.x - other.x, self.y - other.y, self.z - other.z)

    def __mul__(self, k):
        return Vec(self.x * k, self.y * k, self.z * k)

    __rmul__ = __mul__

    def __matmul__(self, other):
        return self.x * other.x + self.y * other.y + self.z * other.z

    def __abs__(self):
        return math.sqrt(self @ self)


Cw = Ch = 600
Vw = Vh = d = 1
BACKGROUND_COLOR = (255, 255, 255)
scene = None


def CanvasToViewport(x, y):
    return Vec(x * Vw / Cw, y * Vh / Ch, d)


def IntersectRaySphere(O, D, sphere):
    CO = O - sphere.center
    a, b, c = D @ D, 2 * (CO @ D), CO @ CO - sphere.radius * sphere.radius
    discriminant = b * b - 4 * a * c
    if discriminant < 0:
        return math.inf, math.inf
    return (-b + math.sqrt(discriminant)) / (2 * a), (-b - math.sqrt(discriminant)) / (2 * a)


def ComputeLighting(P, N, V, s):
    i = 0.0
    for light in scene.lights:
        if light.type == "ambient":
            i += light.intensity
            continue
        L = light.position - P if light.type == "point" else light.direction
        if N @ L > 0:
            i += light.intensity * (N @ L) / (abs(N) * abs(L))
        if s != -1:
            R = 2 * (N @ L) * N - L
            if R @ V > 0:
                i += light.intensity * ((R @ V) / (abs(R) * abs(V))) ** s
    return i


def TraceRay(O, D, t_min, t_max):
    closest_t, closest = math.inf, None
    for sphere in scene.spheres:
        for t in IntersectRaySphere(O, D, sphere):
            if t_min <= t <= t_max and t < closest_t:
                closest_t, closest = t, sphere
    if closest is None:
        return BACKGROUND_COLOR
    P = O + closest_t * D
    N = P - closest.center
    N = N * (1 / abs(N))
    i = ComputeLighting(P, N, D * -1, closest.specular)
    return tuple(i * channel for channel in closest.color)
