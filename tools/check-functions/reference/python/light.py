# cases: 03 (tests/cases/03-light.json)
"""Chapter 3, "Light", in plain Python, as the book writes it: the checker's reference
(tools/check-functions). Chapter 2's functions, and ComputeLighting (Listings 3-1 and
3-2) used by TraceRay (Listing 3-3)."""

import math

from basic_rays import IntersectRaySphere, dot, subtract

scene = None
BACKGROUND_COLOR = (255, 255, 255)


def length(v):
    return math.sqrt(dot(v, v))


def scaled(k, v):
    return (k * v[0], k * v[1], k * v[2])


def added(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


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
    return scaled(ComputeLighting(P, N, scaled(-1, D), closest_sphere.specular), closest_sphere.color)
