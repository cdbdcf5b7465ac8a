# cases: 03 (tests/cases/03-light.json)
"""Chapter 3, "Light", in plain Python, as the book writes it: the checker's reference
(tools/check-functions), one module as a reader writes it on a chapter's page.
Chapter 2's module carried forward, with ComputeLighting (Listings 3-1 and 3-2) used
by TraceRay (Listing 3-3)."""

import math

Cw, Ch = 600, 600  # the canvas
Vw, Vh, d = 1, 1, 1  # the viewport, at distance d
scene = None
BACKGROUND_COLOR = (255, 255, 255)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def subtract(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def length(v):
    return math.sqrt(dot(v, v))


def scaled(k, v):
    return (k * v[0], k * v[1], k * v[2])


def added(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


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


# Listings 3-1 and 3-2: the light at P with normal N, seen along V; s = -1 is matte.
def ComputeLighting(P, N, V, s):
    i = 0.0
    for light in scene.lights:
        if light.type == "ambient":
            i += light.intensity
            continue
        if light.type == "point":
            L = subtract(light.position, P)
        else:
            L = light.direction

        # Diffuse
        n_dot_l = dot(N, L)
        if n_dot_l > 0:
            i += light.intensity * n_dot_l / (length(N) * length(L))

        # Specular
        if s != -1:
            R = subtract(scaled(2 * dot(N, L), N), L)
            r_dot_v = dot(R, V)
            if r_dot_v > 0:
                i += light.intensity * (r_dot_v / (length(R) * length(V))) ** s
    return i


# Listing 3-3: the nearest sphere's colour, lit.
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

    P = added(O, scaled(closest_t, D))  # the intersection
    N = subtract(P, closest_sphere.center)  # the sphere's normal there
    N = scaled(1 / length(N), N)
    return scaled(
        ComputeLighting(P, N, scaled(-1, D), closest_sphere.specular), closest_sphere.color
    )
