# cases: 09 (tests/cases/09-perspective-projection.json)
"""Chapter 9, "Perspective Projection", in plain Python, as the book writes it: the
checker's reference (tools/check-functions). ViewportToCanvas and ProjectVertex
(Listing 9-1); the book's globals are module variables."""

Cw, Ch = 600, 600
Vw, Vh, d = 1, 1, 1


def ViewportToCanvas(x, y):
    return (x * Cw / Vw, y * Ch / Vh)


def ProjectVertex(v):
    return ViewportToCanvas(v.x * d / v.z, v.y * d / v.z)
