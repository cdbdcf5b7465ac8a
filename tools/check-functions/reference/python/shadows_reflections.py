# cases: 04 (tests/cases/04-shadows-reflections.json)
"""Chapter 4, "Shadows and Reflections", in plain Python, as the book writes it: the
checker's reference (tools/check-functions), one module as a reader writes it on a
chapter's page. Chapter 3's module carried forward, with ClosestIntersection (Listing
4-2), ComputeLighting with shadows (Listing 4-3), ReflectRay (Listing 4-4) and the
recursive TraceRay (Listing 4-5)."""

import math

Cw, Ch = 600, 600  # the canvas
Vw, Vh, d = 1, 1, 1  # the viewport, at distance d
scene = None
BACKGROUND_COLOR = (255, 255, 255)
EPSILON = 0.001  # where shadow and reflected rays start, so a point does not hit itself


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


# Listing 4-2: the nearest sphere the ray meets in [t_min, t_max], and its t.
def ClosestIntersection(O, D, t_min, t_max):
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
    return closest_sphere, closest_t


# Listing 4-3: chapter 3's lighting, skipping the lights something hides from P.
def ComputeLighting(P, N, V, s):
    i = 0.0
    for light in scene.lights:
        if light.type == "ambient":
            i += light.intensity
            continue
        if light.type == "point":
            L = subtract(light.position, P)
            t_max = 1
        else:
            L = light.direction
            t_max = math.inf

        # Shadow check
        shadow_sphere, shadow_t = ClosestIntersection(P, L, EPSILON, t_max)
        if shadow_sphere is not None:
            continue

        # Diffuse
        n_dot_l = dot(N, L)
        if n_dot_l > 0:
            i += light.intensity * n_dot_l / (length(N) * length(L))

        # Specular
        if s != -1:
            R = ReflectRay(L, N)
            r_dot_v = dot(R, V)
            if r_dot_v > 0:
                i += light.intensity * (r_dot_v / (length(R) * length(V))) ** s
    return i


# Listing 4-4: R mirrored about N.
def ReflectRay(R, N):
    return subtract(scaled(2 * dot(N, R), N), R)


# Listing 4-5: the local colour, and what the surface reflects, recursion_depth deep.
def TraceRay(O, D, t_min, t_max, recursion_depth):
    closest_sphere, closest_t = ClosestIntersection(O, D, t_min, t_max)
    if closest_sphere is None:
        return scene.background_color

    # The local colour
    P = added(O, scaled(closest_t, D))
    N = subtract(P, closest_sphere.center)
    N = scaled(1 / length(N), N)
    local_color = scaled(
        ComputeLighting(P, N, scaled(-1, D), closest_sphere.specular), closest_sphere.color
    )

    # At the recursion limit, or on a surface that is not reflective, we are done
    r = closest_sphere.reflective
    if recursion_depth <= 0 or r <= 0:
        return local_color

    # The reflected colour
    R = ReflectRay(scaled(-1, D), N)
    reflected_color = TraceRay(P, R, EPSILON, math.inf, recursion_depth - 1)
    return added(scaled(1 - r, local_color), scaled(r, reflected_color))
