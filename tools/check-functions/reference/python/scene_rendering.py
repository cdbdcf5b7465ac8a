# cases: 10 (tests/cases/10-scene-rendering.json)
"""Chapter 10, "Describing and Rendering a Scene", in plain Python, as the book writes
it: the checker's reference (tools/check-functions). The homogeneous matrices of
"Homogeneous Coordinates", ApplyTransform (Listing 10-4) and MakeCameraMatrix (Listing
10-5); a matrix is a list of its rows, and a matrix times a point takes (x, y, z, 1)."""

import math


def MakeTranslationMatrix(translation):
    x, y, z = translation
    return [[1, 0, 0, x], [0, 1, 0, y], [0, 0, 1, z], [0, 0, 0, 1]]


def MakeScalingMatrix(scale):
    return [[scale, 0, 0, 0], [0, scale, 0, 0], [0, 0, scale, 0], [0, 0, 0, 1]]


def MakeOYRotationMatrix(degrees):
    cos, sin = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return [[cos, 0, -sin, 0], [0, 1, 0, 0], [sin, 0, cos, 0], [0, 0, 0, 1]]


def MultiplyMM4(A, B):
    return [[sum(A[i][k] * B[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def MultiplyMV(M, v):
    return [sum(M[i][k] * v[k] for k in range(4)) for i in range(4)]


def Transposed(M):
    return [[M[j][i] for j in range(4)] for i in range(4)]


def ApplyTransform(vertex, transform):
    scaled = [each * transform.scale for each in vertex] + [1]
    rotated = MultiplyMV(transform.rotation, scaled)
    return [rotated[i] + transform.translation[i] for i in range(3)]


def MakeCameraMatrix(position, orientation):
    return MultiplyMM4(Transposed(orientation), MakeTranslationMatrix([-each for each in position]))
