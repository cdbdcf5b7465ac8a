"""Chapter 9 with vertices and points as small classes of my own with attributes
(v.x, v.y, v.z; p.x, p.y), the book's settings as module globals. Written for the
checker's corpus (tests/check-functions/check_corpus.mjs)."""
from dataclasses import dataclass

Cw, Ch = 600, 600
Vw, Vh, d = 1, 1, 1


@dataclass
class Vertex:
    x: float
    y: float
    z: float


@dataclass
class Point:
    x: int
    y: int


def ViewportToCanvas(x, y):
    return Point(int(x * Cw / Vw), int(y * Ch / Vh))


def ProjectVertex(v):
    return ViewportToCanvas(v.x * d / v.z, v.y * d / v.z)


if __name__ == "__main__":
    print(ProjectVertex(Vertex(1, 1, 5)))
