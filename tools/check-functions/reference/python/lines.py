# cases: 06 (tests/cases/06-lines.json)
"""Chapter 6, "Lines", in plain Python, as the book writes it: the checker's reference
(tools/check-functions), one module as a reader writes it on a chapter's page.
Interpolate (Listing 6-1) and DrawLine (Listing 6-2), which draws with the book's
PutPixel (the checker's, or the page's, in its place)."""

import collections

Point = collections.namedtuple("Point", "x y h", defaults=(1.0,))  # h: its intensity
Cw, Ch = 600, 600  # the canvas


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
