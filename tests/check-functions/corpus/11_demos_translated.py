"""Chapter 11 translated from the book's clipping demo (demos/raster-10.html on) into
Python: a triangle's corners in `indexes`, a plane's `distance`, and
ClipTriangle(triangle, plane, triangles, vertexes) appending what it keeps to
`triangles`. Written for the checker's corpus (tests/check-functions/check_corpus.mjs)."""

import math
from types import SimpleNamespace


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def SignedDistance(plane, vertex):
    return dot(plane.normal, vertex) + plane.distance


def Intersection(A, B, plane):
    AB = [b - a for a, b in zip(A, B)]
    t = (-plane.distance - dot(plane.normal, A)) / dot(plane.normal, AB)
    return [a + t * d for a, d in zip(A, AB)]


def ClipTriangle(triangle, plane, triangles, vertexes):
    corners = list(triangle.indexes)
    in_front = [SignedDistance(plane, vertexes[i]) >= 0 for i in corners]
    count = sum(in_front)

    def new_vertex(a, b):
        vertexes.append(Intersection(vertexes[a], vertexes[b], plane))
        return len(vertexes) - 1

    def clipped(indexes):
        return SimpleNamespace(indexes=indexes, color=triangle.color)

    if count == 3:
        triangles.append(triangle)
    elif count == 1:
        k = in_front.index(True)
        A, B, C = corners[k], corners[(k + 1) % 3], corners[(k + 2) % 3]
        triangles.append(clipped([A, new_vertex(A, B), new_vertex(A, C)]))
    elif count == 2:
        k = in_front.index(False)
        C, A, B = corners[k], corners[(k + 1) % 3], corners[(k + 2) % 3]
        A_prime = new_vertex(A, C)
        B_prime = new_vertex(B, C)
        triangles.append(clipped([A, B, A_prime]))
        triangles.append(clipped([A_prime, B, B_prime]))


def ComputeBoundingSphere(vertexes):
    n = len(vertexes)
    center = [sum(v[i] for v in vertexes) / n for i in range(3)]
    radius = max(math.dist(v, center) for v in vertexes)
    return center, radius
