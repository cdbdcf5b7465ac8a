# cases: 12 (tests/cases/12-hidden-surface-removal.json)
"""Chapter 12, "Hidden Surface Removal", in plain Python, as the book writes it: the
runner's reference (tools/check-functions). Classifying a triangle ("Classifying
Triangles") and CullBackFaces (Listing 12-1), which keeps the triangles that face the
camera."""


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
