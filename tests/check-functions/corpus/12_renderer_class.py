"""Chapter 12 written around a Renderer object that owns the depth buffer; the book's
functions at module level hand over to it, and the renderer reads the module's
depth_buffer and PutPixel when it draws. Written for the checker's corpus
(tests/check-functions/check_corpus.mjs)."""
import sys

Cw, Ch = 600, 600
depth_buffer = None


def PutPixel(x, y, color):
    raise RuntimeError("the canvas goes here")


class Renderer:
    @staticmethod
    def edge_values(y0, a0, y1, a1, y2, a2):
        long_side = Renderer.line(y0, a0, y2, a2)
        short = Renderer.line(y0, a0, y1, a1)[:-1] + Renderer.line(y1, a1, y2, a2)
        return long_side, short

    @staticmethod
    def line(i0, d0, i1, d1):
        if i0 == i1:
            return [d0]
        return [d0 + (d1 - d0) * (i - i0) / (i1 - i0) for i in range(i0, i1 + 1)]

    def fill(self, corners, color):
        module = sys.modules[__name__]
        (p0, w0), (p1, w1), (p2, w2) = sorted(corners, key=lambda c: c[0].y)
        x_long, x_short = self.edge_values(p0.y, p0.x, p1.y, p1.x, p2.y, p2.x)
        w_long, w_short = self.edge_values(p0.y, w0, p1.y, w1, p2.y, w2)
        middle = len(x_short) // 2
        long_is_left = x_long[middle] < x_short[middle]
        for y in range(p0.y, p2.y + 1):
            k = y - p0.y
            (xl, wl), (xr, wr) = ((x_long[k], w_long[k]), (x_short[k], w_short[k]))[:: 1 if long_is_left else -1]
            xl, xr = int(xl), int(xr)
            ws = self.line(xl, wl, xr, wr)
            for x in range(xl, xr + 1):
                column, row = Cw // 2 + x, Ch // 2 - y - 1
                if ws[x - xl] > module.depth_buffer[column][row]:
                    module.depth_buffer[column][row] = ws[x - xl]
                    module.PutPixel(x, y, color)


renderer = Renderer()


def IsBackFacing(A, B, C, camera):
    ab = [B[i] - A[i] for i in range(3)]
    ac = [C[i] - A[i] for i in range(3)]
    n = (ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2], ab[0] * ac[1] - ab[1] * ac[0])
    return sum(n[i] * (camera[i] - A[i]) for i in range(3)) <= 0


def CullBackFaces(object, camera):
    V = object.vertices
    return [t for t in object.triangles if not IsBackFacing(V[t.v[0]], V[t.v[1]], V[t.v[2]], camera)]


def DrawFilledTriangle(P0, P1, P2, z0, z1, z2, color):
    renderer.fill([(P0, 1 / z0), (P1, 1 / z1), (P2, 1 / z2)], color)
