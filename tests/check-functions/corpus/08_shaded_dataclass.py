"""Chapter 8 with a Point dataclass of my own (x, y, h) and the intensities carried
beside x through the sort; the row ends truncated before h is interpolated across.
Written for the checker's corpus (tests/check-functions/check_corpus.mjs)."""
from dataclasses import dataclass


@dataclass
class Point:
    x: int
    y: int
    h: float = 1.0


def PutPixel(x, y, color):
    raise RuntimeError("the canvas goes here")


def Interpolate(i0, d0, i1, d1):
    if i0 == i1:
        return [d0]
    step = (d1 - d0) / (i1 - i0)
    return [d0 + step * (i - i0) for i in range(i0, i1 + 1)]


def DrawShadedTriangle(P0, P1, P2, color):
    P0, P1, P2 = sorted((P0, P1, P2), key=lambda p: p.y)
    x01, h01 = Interpolate(P0.y, P0.x, P1.y, P1.x), Interpolate(P0.y, P0.h, P1.y, P1.h)
    x12, h12 = Interpolate(P1.y, P1.x, P2.y, P2.x), Interpolate(P1.y, P1.h, P2.y, P2.h)
    x02, h02 = Interpolate(P0.y, P0.x, P2.y, P2.x), Interpolate(P0.y, P0.h, P2.y, P2.h)
    x012, h012 = x01[:-1] + x12, h01[:-1] + h12
    middle = len(x012) // 2
    if x02[middle] < x012[middle]:
        left, right = (x02, h02), (x012, h012)
    else:
        left, right = (x012, h012), (x02, h02)
    for y in range(P0.y, P2.y + 1):
        row = y - P0.y
        xl, xr = int(left[0][row]), int(right[0][row])
        hs = Interpolate(xl, left[1][row], xr, right[1][row])
        for x in range(xl, xr + 1):
            PutPixel(x, y, tuple(channel * hs[x - xl] for channel in color))
