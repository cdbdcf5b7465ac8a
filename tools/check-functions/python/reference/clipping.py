# cases: 11 (tests/cases/11-clipping.json)
"""Chapter 11, "Clipping", in plain Python, as the book writes it: the runner's reference
(tools/check-functions). SignedDistance (Listing 11-4), the segment's Intersection with
a plane ("Clipping Triangles") and the bounding sphere of "Clipping Whole Objects"."""

import math
import types


def Dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def SignedDistance(plane, vertex):
    return Dot(vertex, plane.normal) + plane.D


def Intersection(A, B, plane):
    AB = [b - a for a, b in zip(A, B)]
    t = (-plane.D - Dot(plane.normal, A)) / Dot(plane.normal, AB)
    return [a + t * each for a, each in zip(A, AB)]


def ComputeBoundingSphere(vertices):
    center = [sum(vertex[i] for vertex in vertices) / len(vertices) for i in range(3)]
    radius = max(math.dist(center, vertex) for vertex in vertices)
    return types.SimpleNamespace(center=center, radius=radius)
