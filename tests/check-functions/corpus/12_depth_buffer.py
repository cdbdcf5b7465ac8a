"""Chapter 12 in plain Python: back faces judged by the book's test and culled from the
object in place, and Listing 7-1 with a 1/z depth buffer indexed as PutPixel maps a
point to the screen. Written for the checker's corpus
(tests/check-functions/check_corpus.mjs)."""

Cw, Ch = 600, 600
depth_buffer = [[0] * Ch for _ in range(Cw)]


def PutPixel(x, y, color):
    pass  # the canvas goes here


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def IsBackFacing(A, B, C, camera):
    normal = cross(sub(B, A), sub(C, A))
    return dot(normal, sub(camera, A)) <= 0


def CullBackFaces(object, camera):
    vertices = object.vertices
    object.triangles = [t for t in object.triangles
                        if not IsBackFacing(vertices[t.v[0]], vertices[t.v[1]], vertices[t.v[2]], camera)]
    return object


def Interpolate(i0, d0, i1, d1):
    if i0 == i1:
        return [d0]
    a = (d1 - d0) / (i1 - i0)
    return [d0 + a * (i - i0) for i in range(i0, i1 + 1)]


def edges(P0, P1, P2, values):
    """x and 1/z along the long side, and along the two short ones joined."""
    (a0, a1, a2) = values
    long_side = Interpolate(P0.y, a0, P2.y, a2)
    short = Interpolate(P0.y, a0, P1.y, a1)[:-1] + Interpolate(P1.y, a1, P2.y, a2)
    return long_side, short


def DrawFilledTriangle(P0, P1, P2, z0, z1, z2, color):
    corners = sorted([(P0, z0), (P1, z1), (P2, z2)], key=lambda corner: corner[0].y)
    (P0, z0), (P1, z1), (P2, z2) = corners
    x02, x012 = edges(P0, P1, P2, (P0.x, P1.x, P2.x))
    iz02, iz012 = edges(P0, P1, P2, (1 / z0, 1 / z1, 1 / z2))
    m = len(x012) // 2
    if x02[m] < x012[m]:
        x_left, x_right, iz_left, iz_right = x02, x012, iz02, iz012
    else:
        x_left, x_right, iz_left, iz_right = x012, x02, iz012, iz02
    for y in range(P0.y, P2.y + 1):
        xl, xr = int(x_left[y - P0.y]), int(x_right[y - P0.y])
        row = Interpolate(xl, iz_left[y - P0.y], xr, iz_right[y - P0.y])
        for x in range(xl, xr + 1):
            sx, sy = Cw // 2 + x, Ch // 2 - y - 1
            if row[x - xl] > depth_buffer[sx][sy]:
                depth_buffer[sx][sy] = row[x - xl]
                PutPixel(x, y, color)
