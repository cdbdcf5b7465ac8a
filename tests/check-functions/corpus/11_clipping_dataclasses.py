"""Chapter 11 with dataclasses for planes and triangles of my own (the checker's records
are read by field), vectors as tuples, the book's order of the clipped triangles.
Written for the checker's corpus (tests/check-functions/check_corpus.mjs)."""
from dataclasses import dataclass
import math


@dataclass
class Triangle:
    v: list
    color: tuple


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def SignedDistance(plane, vertex):
    return dot(plane.normal, vertex) + plane.D


def Intersection(A, B, plane):
    AB = tuple(b - a for a, b in zip(A, B))
    t = (-plane.D - dot(plane.normal, A)) / dot(plane.normal, AB)
    return tuple(a + t * ab for a, ab in zip(A, AB))


def ClipTriangle(triangle, plane, vertices):
    inside = [SignedDistance(plane, vertices[i]) >= 0 for i in triangle.v]
    count = sum(inside)
    if count == 3:
        return [triangle]
    if count == 0:
        return []

    def new_vertex(i, j):
        vertices.append(Intersection(vertices[i], vertices[j], plane))
        return len(vertices) - 1

    if count == 1:
        k = inside.index(True)
        A, B, C = (triangle.v[(k + n) % 3] for n in range(3))
        return [Triangle([A, new_vertex(A, B), new_vertex(A, C)], triangle.color)]
    k = inside.index(False)
    A, B, C = triangle.v[(k + 1) % 3], triangle.v[(k + 2) % 3], triangle.v[k]
    A2, B2 = new_vertex(A, C), new_vertex(B, C)
    return [Triangle([A, B, A2], triangle.color), Triangle([A2, B, B2], triangle.color)]


def ComputeBoundingSphere(vertices):
    n = len(vertices)
    center = tuple(sum(v[i] for v in vertices) / n for i in range(3))
    radius = max(math.dist(center, v) for v in vertices)
    return center, radius
