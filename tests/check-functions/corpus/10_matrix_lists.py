"""Chapter 10's transforms with 4x4 matrices as lists of rows and a small matmul of my
own; points are homogeneous only inside ApplyTransform. Written for the checker's corpus
(tests/check-functions/check_corpus.mjs)."""
import math


def matmul(A, B):
    return [[sum(A[i][k] * B[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def transposed(M):
    return [[M[j][i] for j in range(4)] for i in range(4)]


def times_point(M, p):
    return [sum(M[i][k] * p[k] for k in range(4)) for i in range(4)]


def MakeTranslationMatrix(translation):
    tx, ty, tz = translation
    return [[1, 0, 0, tx], [0, 1, 0, ty], [0, 0, 1, tz], [0, 0, 0, 1]]


def MakeScalingMatrix(scale):
    return [[scale, 0, 0, 0], [0, scale, 0, 0], [0, 0, scale, 0], [0, 0, 0, 1]]


def MakeOYRotationMatrix(degrees):
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return [[c, 0, -s, 0], [0, 1, 0, 0], [s, 0, c, 0], [0, 0, 0, 1]]


def ApplyTransform(vertex, transform):
    p = [vertex[0] * transform.scale, vertex[1] * transform.scale, vertex[2] * transform.scale, 1]
    p = times_point(transform.rotation, p)
    return [p[0] + transform.translation[0], p[1] + transform.translation[1], p[2] + transform.translation[2]]


def MakeCameraMatrix(position, orientation):
    back = MakeTranslationMatrix([-position[0], -position[1], -position[2]])
    return matmul(transposed(orientation), back)
