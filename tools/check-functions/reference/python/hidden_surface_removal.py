# cases: 12 (tests/cases/12-hidden-surface-removal.json)
"""Chapter 12, "Hidden Surface Removal", in plain Python, as the book writes it: the
checker's reference (tools/check-functions). The filled triangle with a depth test before
every PutPixel ("Depth Buffering", "Using 1/Z Instead of Z"), classifying a triangle
("Classifying Triangles") and CullBackFaces (Listing 12-1), which keeps the triangles
that face the camera. The book's PutPixel, Cw, Ch and depth_buffer (depth_buffer[x][y]
from the screen's top-left corner, as PutPixel maps a canvas point) are module
variables the checker sets."""

from lines import Interpolate

Cw, Ch = 600, 600
depth_buffer = [[0] * Ch for _ in range(Cw)]


def PutPixel(x, y, color):
    raise NotImplementedError("your canvas goes here")


def EdgeInterpolate(y0, v0, y1, v1, y2, v2):
    v01 = Interpolate(y0, v0, y1, v1)
    v12 = Interpolate(y1, v1, y2, v2)
    v02 = Interpolate(y0, v0, y2, v2)
    v01.pop()
    return v02, v01 + v12


def DrawFilledTriangle(P0, P1, P2, z0, z1, z2, color):
    # Sort the points so that y0 <= y1 <= y2; each depth goes with its point.
    if P1.y < P0.y:
        (P1, z1), (P0, z0) = (P0, z0), (P1, z1)
    if P2.y < P0.y:
        (P2, z2), (P0, z0) = (P0, z0), (P2, z2)
    if P2.y < P1.y:
        (P2, z2), (P1, z1) = (P1, z1), (P2, z2)
    x02, x012 = EdgeInterpolate(P0.y, P0.x, P1.y, P1.x, P2.y, P2.x)
    iz02, iz012 = EdgeInterpolate(P0.y, 1 / z0, P1.y, 1 / z1, P2.y, 1 / z2)
    m = len(x012) // 2
    if x02[m] < x012[m]:
        x_left, x_right, iz_left, iz_right = x02, x012, iz02, iz012
    else:
        x_left, x_right, iz_left, iz_right = x012, x02, iz012, iz02
    for y in range(P0.y, P2.y + 1):
        x_l, x_r = int(x_left[y - P0.y]), int(x_right[y - P0.y])
        iz_segment = Interpolate(x_l, iz_left[y - P0.y], x_r, iz_right[y - P0.y])
        for x in range(x_l, x_r + 1):
            sx, sy = Cw // 2 + x, Ch // 2 - y - 1  # as PutPixel maps it
            if 0 <= sx < Cw and 0 <= sy < Ch and iz_segment[x - x_l] > depth_buffer[sx][sy]:
                PutPixel(x, y, color)
                depth_buffer[sx][sy] = iz_segment[x - x_l]


def Subtract(a, b):
    return [x - y for x, y in zip(a, b)]


def Cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def Dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def IsBackFacing(A, B, C, camera):
    N = Cross(Subtract(B, A), Subtract(C, A))
    V = Subtract(camera, A)
    return Dot(N, V) <= 0


def CullBackFaces(object, camera):
    V = object.vertices
    object.triangles = [T for T in object.triangles
                        if not IsBackFacing(V[T.v[0]], V[T.v[1]], V[T.v[2]], camera)]
