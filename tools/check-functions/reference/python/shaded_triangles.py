# cases: 08 (tests/cases/08-shaded-triangles.json)
"""Chapter 8, "Shaded Triangles", in plain Python, as the book writes it: the runner's
reference (tools/check-functions). DrawShadedTriangle (Listing 8-1): each vertex has
an intensity h, interpolated along the edges and across each row."""

from lines import Interpolate


def PutPixel(x, y, color):
    raise NotImplementedError("your canvas goes here")


# Listing 8-1: Listing 7-1 with h carried along.
def DrawShadedTriangle(P0, P1, P2, color):
    # Sort the points so that y0 <= y1 <= y2
    if P1.y < P0.y:
        P1, P0 = P0, P1
    if P2.y < P0.y:
        P2, P0 = P0, P2
    if P2.y < P1.y:
        P2, P1 = P1, P2

    # Compute the x coordinates and h values of the triangle edges
    x01 = Interpolate(P0.y, P0.x, P1.y, P1.x)
    h01 = Interpolate(P0.y, P0.h, P1.y, P1.h)
    x12 = Interpolate(P1.y, P1.x, P2.y, P2.x)
    h12 = Interpolate(P1.y, P1.h, P2.y, P2.h)
    x02 = Interpolate(P0.y, P0.x, P2.y, P2.x)
    h02 = Interpolate(P0.y, P0.h, P2.y, P2.h)

    # Concatenate the short sides
    x01.pop()
    x012 = x01 + x12
    h01.pop()
    h012 = h01 + h12

    # Determine which is left and which is right
    m = len(x012) // 2
    if x02[m] < x012[m]:
        x_left, h_left, x_right, h_right = x02, h02, x012, h012
    else:
        x_left, h_left, x_right, h_right = x012, h012, x02, h02

    # Draw the horizontal segments
    for y in range(P0.y, P2.y + 1):
        x_l = int(x_left[y - P0.y])
        x_r = int(x_right[y - P0.y])
        h_segment = Interpolate(x_l, h_left[y - P0.y], x_r, h_right[y - P0.y])
        for x in range(x_l, x_r + 1):
            shaded_color = tuple(channel * h_segment[x - x_l] for channel in color)
            PutPixel(x, y, shaded_color)
