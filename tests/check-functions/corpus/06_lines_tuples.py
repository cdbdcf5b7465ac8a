"""Chapter 6 in plain Python with points as (x, y) pairs unpacked at the top of
DrawLine, and a list comprehension for Interpolate. Written for the checker's corpus
(tests/check-functions/check_corpus.mjs)."""


def PutPixel(x, y, color):
    raise RuntimeError("no canvas here")


def Interpolate(i0, d0, i1, d1):
    if i0 == i1:
        return [d0]
    a = (d1 - d0) / (i1 - i0)
    return [d0 + a * (i - i0) for i in range(i0, i1 + 1)]


def DrawLine(P0, P1, color):
    x0, y0 = P0[0], P0[1]
    x1, y1 = P1[0], P1[1]
    if abs(x1 - x0) > abs(y1 - y0):
        if x0 > x1:
            x0, y0, x1, y1 = x1, y1, x0, y0
        for x, y in zip(range(x0, x1 + 1), Interpolate(x0, y0, x1, y1)):
            PutPixel(x, y, color)
    else:
        if y0 > y1:
            x0, y0, x1, y1 = x1, y1, x0, y0
        for y, x in zip(range(y0, y1 + 1), Interpolate(y0, x0, y1, x1)):
            PutPixel(x, y, color)
