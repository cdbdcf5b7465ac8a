# cases: 11 (tests/cases/11-clipping.json)
"""Chapter 11, "Clipping", in plain Python, as the book writes it: the checker's reference
(tools/check-functions). SignedDistance (Listing 11-4), the segment's Intersection with
a plane and ClipTriangle ("Clipping Triangles", Listing 11-3), and the bounding sphere
of "Clipping Whole Objects"."""

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


def ClipTriangle(triangle, plane, vertices):
    in_front = [SignedDistance(plane, vertices[i]) >= 0 for i in triangle.v]
    count = sum(in_front)
    if count == 3:
        return [triangle]
    if count == 0:
        return []

    def NewVertex(a, b):  # where the segment from vertex a to vertex b crosses the plane
        vertices.append(Intersection(vertices[a], vertices[b], plane))
        return len(vertices) - 1

    # One in front: A is that one. Two: C is the one behind. The others follow in order.
    k = in_front.index(count == 1)
    first, second, third = (triangle.v[(k + n) % 3] for n in range(3))
    if count == 1:
        A, B, C = first, second, third
        return [types.SimpleNamespace(v=[A, NewVertex(A, B), NewVertex(A, C)], color=triangle.color)]
    C, A, B = first, second, third
    A_prime, B_prime = NewVertex(A, C), NewVertex(B, C)
    return [types.SimpleNamespace(v=[A, B, A_prime], color=triangle.color),
            types.SimpleNamespace(v=[A_prime, B, B_prime], color=triangle.color)]


def ComputeBoundingSphere(vertices):
    center = [sum(vertex[i] for vertex in vertices) / len(vertices) for i in range(3)]
    radius = max(math.dist(center, vertex) for vertex in vertices)
    return types.SimpleNamespace(center=center, radius=radius)
