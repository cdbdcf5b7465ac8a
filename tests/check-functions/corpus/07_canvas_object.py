"""Chapter 7 with a Canvas class whose PutPixel method draws, as the book writes
canvas.PutPixel(x, y, color); points are pairs indexed [0] and [1]. Written for the
checker's corpus (tests/check-functions/check_corpus.mjs)."""


class Canvas:
    def __init__(self, width, height):
        self.width, self.height = width, height
        self.pixels = [[(255, 255, 255)] * width for _ in range(height)]

    def PutPixel(self, x, y, color):
        sx, sy = self.width // 2 + int(x), self.height // 2 - int(y) - 1
        if 0 <= sx < self.width and 0 <= sy < self.height:
            self.pixels[sy][sx] = color


canvas = Canvas(600, 600)


def Interpolate(i0, d0, i1, d1):
    if i0 == i1:
        return [d0]
    values = []
    a = (d1 - d0) / (i1 - i0)

    for i in range(i0, i1 + 1):
        values.append(d0 + a * (i - i0))
    return values


def DrawLine(P0, P1, color):
    x0, y0 = P0[0], P0[1]
    x1, y1 = P1[0], P1[1]
    if abs(x1 - x0) > abs(y1 - y0):
        if x0 > x1:
            x0, y0, x1, y1 = x1, y1, x0, y0
        ys = Interpolate(x0, y0, x1, y1)
        for x in range(x0, x1 + 1):
            canvas.PutPixel(x, ys[x - x0], color)
    else:
        if y0 > y1:
            x0, y0, x1, y1 = x1, y1, x0, y0
        xs = Interpolate(y0, x0, y1, x1)
        for y in range(y0, y1 + 1):
            canvas.PutPixel(xs[y - y0], y, color)


def DrawWireframeTriangle(P0, P1, P2, color):
    DrawLine(P0, P1, color)
    DrawLine(P1, P2, color)
    DrawLine(P2, P0, color)


def DrawFilledTriangle(P0, P1, P2, color):
    if P1[1] < P0[1]:
        P1, P0 = P0, P1
    if P2[1] < P0[1]:
        P2, P0 = P0, P2
    if P2[1] < P1[1]:
        P2, P1 = P1, P2
    x01 = Interpolate(P0[1], P0[0], P1[1], P1[0])
    x12 = Interpolate(P1[1], P1[0], P2[1], P2[0])
    x02 = Interpolate(P0[1], P0[0], P2[1], P2[0])
    x01.pop()
    x012 = x01 + x12
    m = len(x012) // 2
    if x02[m] < x012[m]:
        x_left, x_right = x02, x012
    else:
        x_left, x_right = x012, x02
    for y in range(P0[1], P2[1] + 1):
        for x in range(int(x_left[y - P0[1]]), int(x_right[y - P0[1]]) + 1):
            canvas.PutPixel(x, y, color)
