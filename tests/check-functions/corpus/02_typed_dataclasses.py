# Chapter 2 in typed Python: dataclasses under postponed annotations, a Vec3 with
# operators, the scene kept as a list of spheres. Written for the checker's corpus
# (tests/check-functions/check_corpus.mjs).
from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass
class Vec3:
    x: float
    y: float
    z: float

    def __sub__(self, other: Vec3) -> Vec3:
        return Vec3(self.x - other.x, self.y - other.y, self.z - other.z)

    def dot(self, other: Vec3) -> float:
        return self.x * other.x + self.y * other.y + self.z * other.z


@dataclass
class Sphere:
    center: Vec3
    radius: float
    color: tuple[int, int, int]


Cw: int = 600
Ch: int = 600
Vw: float = 1.0
Vh: float = 1.0
d: float = 1.0
BACKGROUND_COLOR = (255, 255, 255)
scene: list[Sphere] = []


def CanvasToViewport(x: float, y: float) -> Vec3:
    return Vec3(x * Vw / Cw, y * Vh / Ch, d)


def IntersectRaySphere(O: Vec3, D: Vec3, sphere: Sphere) -> tuple[float, float]:
    r = sphere.radius
    CO = O - sphere.center
    a = D.dot(D)
    b = 2 * CO.dot(D)
    c = CO.dot(CO) - r * r
    disc = b * b - 4 * a * c
    if disc < 0:
        return math.inf, math.inf
    t1 = (-b + math.sqrt(disc)) / (2 * a)
    t2 = (-b - math.sqrt(disc)) / (2 * a)
    return t1, t2


def TraceRay(O: Vec3, D: Vec3, t_min: float, t_max: float):
    closest_t = math.inf
    closest_sphere = None
    for sphere in scene:
        t1, t2 = IntersectRaySphere(O, D, sphere)
        if t_min <= t1 <= t_max and t1 < closest_t:
            closest_t, closest_sphere = t1, sphere
        if t_min <= t2 <= t_max and t2 < closest_t:
            closest_t, closest_sphere = t2, sphere
    if closest_sphere is None:
        return BACKGROUND_COLOR
    return closest_sphere.color


if __name__ == "__main__":
    for sphere in scene:
        print(sphere)
