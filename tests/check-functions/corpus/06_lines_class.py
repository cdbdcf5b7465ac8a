"""Chapter 6 written as a small class: a Canvas that keeps its pixels and draws lines
with the book's Interpolate; module-level functions under the book's names hand over
to one canvas. Points are (x, y) tuples. Written for the checker's corpus
(tests/check-functions/check_corpus.mjs)."""


class Canvas:
    def __init__(self, width, height):
        self.width, self.height = width, height
        self.pixels = {}

    def PutPixel(self, x, y, color):
        self.pixels[(int(x), int(y))] = color

    def draw_line(self, P0, P1, color):
        (x0, y0), (x1, y1) = P0[:2], P1[:2]
        if abs(x1 - x0) > abs(y1 - y0):
            if x0 > x1:
                (x0, y0), (x1, y1) = (x1, y1), (x0, y0)
            ys = Interpolate(x0, y0, x1, y1)
            for x in range(x0, x1 + 1):
                self.PutPixel(x, ys[x - x0], color)
        else:
            if y0 > y1:
                (x0, y0), (x1, y1) = (x1, y1), (x0, y0)
            xs = Interpolate(y0, x0, y1, x1)
            for y in range(y0, y1 + 1):
                self.PutPixel(xs[y - y0], y, color)


canvas = Canvas(600, 600)


def Interpolate(i0, d0, i1, d1):
    if i0 == i1:
        return [d0]
    a = (d1 - d0) / (i1 - i0)
    return [d0 + a * (i - i0) for i in range(i0, i1 + 1)]


def DrawLine(P0, P1, color):
    canvas.draw_line(P0, P1, color)


if __name__ == "__main__":
    DrawLine((-200, -100), (240, 120), (0, 0, 0))
    print(len(canvas.pixels), "pixels")
