# cases: 07 (tests/cases/07-filled-triangles.json)
"""Chapter 7, "Filled Triangles", in plain Python, as the book writes it: the runner's
reference (tools/check-functions). DrawWireframeTriangle and DrawFilledTriangle
(Listing 7-1), drawing with the book's PutPixel (the checker puts its own in its place)."""

import lines
from lines import Interpolate


def PutPixel(x, y, color):
    raise NotImplementedError("your canvas goes here")


def DrawLine(P0, P1, color):
    lines.PutPixel = PutPixel  # chapter 6's DrawLine draws where this module does
    lines.DrawLine(P0, P1, color)


def DrawWireframeTriangle(P0, P1, P2, color):
    DrawLine(P0, P1, color)
    DrawLine(P1, P2, color)
    DrawLine(P2, P0, color)


# Listing 7-1: for each row, from the long side to the two short ones.
def DrawFilledTriangle(P0, P1, P2, color):
    # Sort the points so that y0 <= y1 <= y2
    if P1.y < P0.y:
        P1, P0 = P0, P1
    if P2.y < P0.y:
        P2, P0 = P0, P2
    if P2.y < P1.y:
        P2, P1 = P1, P2

    # Compute the x coordinates of the triangle edges
    x01 = Interpolate(P0.y, P0.x, P1.y, P1.x)
    x12 = Interpolate(P1.y, P1.x, P2.y, P2.x)
    x02 = Interpolate(P0.y, P0.x, P2.y, P2.x)

    # Concatenate the short sides
    x01.pop()
    x012 = x01 + x12

    # Determine which is left and which is right
    m = len(x012) // 2
    if x02[m] < x012[m]:
        x_left, x_right = x02, x012
    else:
        x_left, x_right = x012, x02

    # Draw the horizontal segments
    for y in range(P0.y, P2.y + 1):
        for x in range(int(x_left[y - P0.y]), int(x_right[y - P0.y]) + 1):
            PutPixel(x, y, color)
