# cases: 13 (tests/cases/13-shading.json)
"""Chapter 13, "Shading", in plain Python, as the book writes it: the checker's
reference (tools/check-functions), one module as a reader writes it on a chapter's
page. Chapter 12's module carried forward without DrawShadedTriangle, which the
chapter's shading replaces, and with a triangle's own normal ("Flat Shading") and
UnProjectVertex ("Phong Shading"), which undoes ProjectVertex for a pixel and its
1/z."""

import collections
import math
import types

Point = collections.namedtuple("Point", "x y h", defaults=(1.0,))  # h: its intensity
Cw, Ch = 600, 600  # the canvas
Vw, Vh, d = 1, 1, 1  # the viewport, at distance d
depth_buffer = []  # depth_buffer[x][y]: 1/z of what is drawn there, 0 for nothing


def PutPixel(x, y, color):
    raise NotImplementedError("the canvas goes here")


# Listing 6-1: the values of d for each whole i from i0 to i1, d0 to d1 in a line. The
# book adds a at each step (d = d + a), which drifts: d0 + a (i - i0) does not
# (docs/conventions.md).
def Interpolate(i0, d0, i1, d1):
    if i0 == i1:
        return [d0]
    values = []
    a = (d1 - d0) / (i1 - i0)
    for i in range(i0, i1 + 1):
        values.append(d0 + a * (i - i0))
    return values


# Listing 6-2: one pixel per step along the axis the line spans most.
def DrawLine(P0, P1, color):
    if abs(P1.x - P0.x) > abs(P1.y - P0.y):
        # The line is horizontal-ish. Make sure x0 < x1
        if P0.x > P1.x:
            P0, P1 = P1, P0
        ys = Interpolate(P0.x, P0.y, P1.x, P1.y)
        for x in range(int(P0.x), int(P1.x) + 1):
            PutPixel(x, ys[x - int(P0.x)], color)
    else:
        # The line is vertical-ish. Make sure y0 < y1
        if P0.y > P1.y:
            P0, P1 = P1, P0
        xs = Interpolate(P0.y, P0.x, P1.y, P1.x)
        for y in range(int(P0.y), int(P1.y) + 1):
            PutPixel(xs[y - int(P0.y)], y, color)


def DrawWireframeTriangle(P0, P1, P2, color):
    DrawLine(P0, P1, color)
    DrawLine(P1, P2, color)
    DrawLine(P2, P0, color)


# The values of a quantity along a triangle's long side (y0 to y2) and its two short
# ones (y0 to y1 to y2), as Listing 7-1 works out x.
def EdgeInterpolate(y0, v0, y1, v1, y2, v2):
    v01 = Interpolate(y0, v0, y1, v1)
    v12 = Interpolate(y1, v1, y2, v2)
    v02 = Interpolate(y0, v0, y2, v2)
    v01.pop()
    return v02, v01 + v12


# "Depth Buffering": Listing 7-1 with 1/z interpolated too, each pixel put only where
# it is nearer than what the depth buffer holds.
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


# Listing 9-1: a viewport point to the canvas point it lands on, a whole pixel (truncated
# toward zero, as docs/conventions.md says of every canvas point).
def ViewportToCanvas(x, y):
    return Point(int(x * Cw / Vw), int(y * Ch / Vh))


# Listing 9-1: a point of the scene (x, y, z) projected onto the canvas.
def ProjectVertex(v):
    return ViewportToCanvas(v[0] * d / v[2], v[1] * d / v[2])


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


# Listing 10-4: scale, then rotate, then translate.
def ApplyTransform(vertex, transform):
    scaled = [each * transform.scale for each in vertex] + [1]
    rotated = MultiplyMV(transform.rotation, scaled)
    return [rotated[i] + transform.translation[i] for i in range(3)]


# Listing 10-5: the camera's inverse rotation times its inverse translation.
def MakeCameraMatrix(position, orientation):
    return MultiplyMM4(Transposed(orientation), MakeTranslationMatrix([-each for each in position]))


def Dot(a, b):
    return sum(x * y for x, y in zip(a, b))


# Listing 11-4: how far a point is in front of a plane (behind it: negative).
def SignedDistance(plane, vertex):
    return Dot(vertex, plane.normal) + plane.D


# Where the segment from A to B crosses the plane.
def Intersection(A, B, plane):
    AB = [b - a for a, b in zip(A, B)]
    t = (-plane.D - Dot(plane.normal, A)) / Dot(plane.normal, AB)
    return [a + t * each for a, each in zip(A, AB)]


# Listing 11-3: the parts of a triangle in front of a plane: none, itself, or one or
# two new triangles, whose new vertices are added to the list.
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
        return [
            types.SimpleNamespace(v=[A, NewVertex(A, B), NewVertex(A, C)], color=triangle.color)
        ]
    C, A, B = first, second, third
    A_prime, B_prime = NewVertex(A, C), NewVertex(B, C)
    return [
        types.SimpleNamespace(v=[A, B, A_prime], color=triangle.color),
        types.SimpleNamespace(v=[A_prime, B, B_prime], color=triangle.color),
    ]


# "Clipping Whole Objects": the centre of the vertices, and the farthest one's distance.
def ComputeBoundingSphere(vertices):
    center = [sum(vertex[i] for vertex in vertices) / len(vertices) for i in range(3)]
    radius = max(math.dist(center, vertex) for vertex in vertices)
    return types.SimpleNamespace(center=center, radius=radius)


def Subtract(a, b):
    return [x - y for x, y in zip(a, b)]


def Cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


# "Classifying Triangles": the camera is behind the triangle's front face.
def IsBackFacing(A, B, C, camera):
    N = Cross(Subtract(B, A), Subtract(C, A))
    V = Subtract(camera, A)
    return Dot(N, V) <= 0


# Listing 12-1: the object keeps the triangles that face the camera.
def CullBackFaces(object, camera):
    V = object.vertices
    object.triangles = [
        T for T in object.triangles if not IsBackFacing(V[T.v[0]], V[T.v[1]], V[T.v[2]], camera)
    ]


# "Flat Shading": the unit normal of the triangle's front face.
def ComputeTriangleNormal(A, B, C):
    N = Cross(Subtract(B, A), Subtract(C, A))
    length = math.sqrt(Dot(N, N))
    return [each / length for each in N]


# "Phong Shading": the point of the scene a pixel (x, y) with depth 1/z shows.
def UnProjectVertex(x, y, inv_z):
    z = 1 / inv_z
    return [x * Vw / Cw * z / d, y * Vh / Ch * z / d, z]
