"""Chapter 3 with numpy: vectors are arrays, lengths from numpy.linalg.norm, the
scene a dict. Written for the checker's corpus (tests/check-functions/check_corpus.mjs);
checked where the python3 on PATH has numpy."""
import numpy as np

Cw, Ch = 600, 600
Vw, Vh, d = 1.0, 1.0, 1.0
BACKGROUND_COLOR = np.array([255.0, 255.0, 255.0])
scene = {"spheres": [], "lights": []}


def CanvasToViewport(x, y):
    return np.array([x * Vw / Cw, y * Vh / Ch, d])


def IntersectRaySphere(O, D, sphere):
    CO = O - sphere["center"]
    a, b, c = D @ D, 2 * (CO @ D), CO @ CO - sphere["radius"] ** 2
    disc = b * b - 4 * a * c
    if disc < 0:
        return np.inf, np.inf
    return (-b + np.sqrt(disc)) / (2 * a), (-b - np.sqrt(disc)) / (2 * a)


def ComputeLighting(P, N, V, s):
    i = 0.0
    for light in scene["lights"]:
        if light["type"] == "ambient":
            i += light["intensity"]
            continue
        L = light["position"] - P if light["type"] == "point" else light["direction"]
        if N @ L > 0:
            i += light["intensity"] * (N @ L) / (np.linalg.norm(N) * np.linalg.norm(L))
        if s != -1:
            R = 2 * N * (N @ L) - L
            if R @ V > 0:
                i += light["intensity"] * ((R @ V) / (np.linalg.norm(R) * np.linalg.norm(V))) ** s
    return i


def TraceRay(O, D, t_min, t_max):
    closest_t, closest = np.inf, None
    for sphere in scene["spheres"]:
        for t in IntersectRaySphere(O, D, sphere):
            if t_min <= t <= t_max and t < closest_t:
                closest_t, closest = t, sphere
    if closest is None:
        return BACKGROUND_COLOR
    P = O + closest_t * D
    N = P - closest["center"]
    N = N / np.linalg.norm(N)
    return ComputeLighting(P, N, -D, closest["specular"]) * closest["color"]
