#!/usr/bin/env python3
"""Hostile model files against --model (program/model_file.h, docs/testing.md "Models of
one's own"): each a file of kilobytes or megabytes that once took gigabytes or hours,
now refused in one line with exit status 2, or drawn, within its memory bound (the
chapter's peak resident memory, from GNU time) and a minute of processor time. Built
with AddressSanitizer (CGFS_SANITIZED=1), whose shadow memory and quarantine of freed
blocks add hundreds of MB, the memory is not bounded: the plain build's run bounds it.
Quick cases in chapters 5 and 14, drawn small (the test command); with --slow, every
chapter that takes --model, at the programs' size, the files at the bounds (the largest
model, triangles piled as high as they may be) and the slow ones (the deep checks'
models part).

Usage: check_hostile_models.py BUILD_DIR WORK_DIR [--slow]"""

import math
import os
import shutil
import struct
import subprocess
import sys
import time
import zlib

TRIANGLE = "v 0 0 0\nv 1 0 0\nv 0 1 0\n"


def png(path, side):
    """A grey PNG of side x side pixels, written with zlib (no imaging library)."""
    row = b"\x00" + b"\x80" * (3 * side)
    data = zlib.compress(row * side, 9)

    def chunk(kind, body):
        return (
            struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
        )

    header = struct.pack(">IIBBBBB", side, side, 8, 2, 0, 0, 0)
    with open(path, "wb") as out:
        out.write(
            b"\x89PNG\r\n\x1a\n"
            + chunk(b"IHDR", header)
            + chunk(b"IDAT", data)
            + chunk(b"IEND", b"")
        )


def sphere(path, n, m, head):
    """A UV sphere of n x m quads, with normals and texture coordinates: 2 n m triangles
    (at n, m = 866, 433: 749 956, the most a model may have, in 76 MB)."""
    with open(path, "w") as out:
        out.write(head)
        for i in range(m + 1):
            s, c = math.sin(math.pi * i / m), math.cos(math.pi * i / m)
            ring = [
                (
                    s * math.cos(2 * math.pi * j / n),
                    c,
                    s * math.sin(2 * math.pi * j / n),
                )
                for j in range(n)
            ]
            out.write(
                "".join(
                    f"v {x:.6f} {y:.6f} {z:.6f}\nvn {x:.5f} {y:.5f} {z:.5f}\n" for x, y, z in ring
                )
            )
            out.write("".join(f"vt {j / n:.5f} {i / m:.5f}\n" for j in range(n)))
        for i in range(m):
            for j in range(n):
                a, b = i * n + j + 1, i * n + (j + 1) % n + 1
                c, d = a + n, b + n
                out.write(
                    f"f {a}/{a}/{a} {b}/{b}/{b} {d}/{d}/{d}\nf {a}/{a}/{a} {d}/{d}/{d} {c}/{c}/{c}\n"
                )


def cases(slow):
    """(name, tier, expected, {file name: text or a function writing it})"""
    many = 2_000 if not slow else 20_000
    yield "tags", "quick", "drawn", {
        "m.obj": TRIANGLE + "t a 8192/8192/8192\n" * many + "f 1 2 3\n"
    }
    yield "short-faces", "quick", "drawn", {
        "m.obj": TRIANGLE + "f 1\nf 1 2\nf\n" * 200_000 + "f 1 2 3\n"
    }
    yield "lines-and-points", "quick", "drawn", {
        "m.obj": TRIANGLE + "l 1 2 3\np 1 2 3\n" * 200_000 + "f 1 2 3\n"
    }
    yield "group-names", "quick", "drawn", {
        "m.obj": TRIANGLE + "g" + " n" * 2_000_000 + "\nf 1 2 3\n"
    }
    strip = "".join(f"v {k} {k % 2} 0\n" for k in range(100_002))
    yield "groups", "quick", "drawn", {
        "m.obj": strip + "".join(f"g a\nf {k} {k + 1} {k + 2}\n" for k in range(1, 100_001))
    }
    yield "materials", "quick", "drawn", {
        "m.obj": "mtllib m.mtl\n" + TRIANGLE + "usemtl m\nf 1 2 3\n",
        "m.mtl": "newmtl m\n" * 1_000_000,
    }
    yield "library-spellings", "quick", "drawn", {
        "m.obj": "".join("mtllib " + "./" * k + "m.mtl\n" for k in range(1, 2_001))
        + TRIANGLE
        + "usemtl m\nf 1 2 3\n",
        "m.mtl": "newmtl m\nKd 1 0 0\n" + "# padding\n" * 100_000,
    }
    yield "missing-libraries", "quick", "drawn", {
        "m.obj": "mtllib gone.mtl\n" * 300_000 + TRIANGLE + "f 1 2 3\n"
    }
    yield "material-switches", "quick", "refused", {
        "m.obj": "mtllib m.mtl\n" + TRIANGLE + "usemtl a\nf 1 2 3\nusemtl b\nf 1 2 3\n" * 40_000,
        "m.mtl": "newmtl a\nnewmtl b\n",
    }
    textured = "mtllib m.mtl\n" + TRIANGLE + "vt 0 0\nvt 1 0\nvt 0 1\n"
    yield "one-texture-many-materials", "quick", "drawn", {
        "m.obj": textured + "".join(f"usemtl m{k}\nf 1/1 2/2 3/3\n" for k in range(300)),
        "m.mtl": "".join(f"newmtl m{k}\nmap_Kd t.png\n" for k in range(300)),
        "t.png": lambda path: png(path, 2048),
    }
    yield "many-textures", "quick", "drawn", {
        "m.obj": textured + "".join(f"usemtl m{k}\nf 1/1 2/2 3/3\n" for k in range(400)),
        "m.mtl": "".join(f"newmtl m{k}\nmap_Kd t{k}.png\n" for k in range(400)),
        **{f"t{k}.png": (lambda k: lambda path: png(path, 4 + k % 7))(k) for k in range(400)},
    }
    big = "".join(f"v {k} {k % 7} {k % 5}\n" for k in range(1_000_000))
    yield "textured-parts", "slow", "drawn", {
        "m.obj": "mtllib m.mtl\n"
        + big
        + "vt 0 0\nvt 1 0\nvt 0 1\n"
        + "".join(
            f"usemtl m{k}\nf {3 * k + 1}/1 {3 * k + 2}/2 {3 * k + 3}/3\n" for k in range(400)
        ),
        "m.mtl": "".join(f"newmtl m{k}\nmap_Kd t{k}.png\n" for k in range(400)),
        **{f"t{k}.png": (lambda k: lambda path: png(path, 4 + k % 7))(k) for k in range(400)},
    }
    yield "coincident", "quick", "refused", {"m.obj": TRIANGLE + "f 1 2 3\n" * 100_000}
    yield "coincident-at-the-bound", "slow", "drawn", {"m.obj": TRIANGLE + "f 1 2 3\n" * 1_565}
    slivers = "".join(
        f"v {k * 1e-4} 0 0\nv {1 + k * 1e-4} 1 0\nv {1 + k * 1e-4} 1.002 0\n" for k in range(1_560)
    )
    yield "slivers-at-the-bound", "slow", "drawn", {
        "m.obj": slivers + "".join(f"f {3 * k + 1} {3 * k + 2} {3 * k + 3}\n" for k in range(1_560))
    }
    yield "largest-textured", "slow", "drawn", {
        "m.obj": lambda path: sphere(path, 866, 433, "mtllib m.mtl\nusemtl m\n"),
        "m.mtl": "newmtl m\nmap_Kd t.png\n",
        "t.png": lambda path: png(path, 2048),
    }
    yield "index-wraps", "quick", "refused", {"m.obj": TRIANGLE + "f 1 2 4294967299\n"}
    yield "index-digits", "quick", "refused", {"m.obj": TRIANGLE + "f 1 2 99999999999\n"}
    yield "huge-coordinates", "quick", "drawn", {
        "m.obj": "v 0 0 0\nv 1e150 0 0\nv 0 1e150 0\nf 1 2 3\n"
    }


QUICK_CHAPTERS = ["05-raytracer-extensions", "14-textures"]
# The quick cases draw at 150 x 150: what the files once blew up (reading, the model's
# arrays, the hierarchy, the textures) is the same at any size; --slow draws at the
# programs' 600 x 600.
QUICK_SIZE = ["--size", "150x150"]
MODEL_CHAPTERS = [
    "05-raytracer-extensions",
    "10-scene-rendering",
    "11-clipping",
    "12-hidden-surface-removal",
    "13-shading",
    "14-textures",
    "15-rasterizer-extensions",
    "17-fast-hierarchy",
]
# The peak memory a case may take: a small file's (a 2048 x 2048 texture and its mip
# chain are 134 MB of it), and the largest model's (measured at 885 MB, docs/testing.md).
SMALL_BOUND_MB = 300
LARGEST_BOUND_MB = 1000
# A hang is cut at this wall-clock time; a case must also end within the minute of
# processor time its bound promises (user and system, which a busy machine does not
# lengthen: the slowest, the coincident triangles at the bound, takes 6 s on the
# project's 2-core machine). The cut is twice the minute: a case within its minute is
# cut only when the machine gives it less than half a core for two minutes.
CUT_SECONDS = 120
MINUTE = 60
SANITIZED = os.environ.get("CGFS_SANITIZED") == "1"

failed = False


def check(what, ok):
    global failed
    print(("ok: " if ok else "FAIL: ") + what)
    failed = failed or not ok


def run(command):
    """(exit status, standard error's lines, peak resident MB, processor seconds) of a
    program, its peak and time measured by GNU time (a child's own: not this process's,
    which wait4 would count since a spawned child starts as a copy of it); cut at
    CUT_SECONDS of the wall clock."""
    start = time.monotonic()
    try:
        done = subprocess.run(
            ["/usr/bin/time", "-f", "cgfs-peak-kb %M %U %S", *command],
            stdout=subprocess.DEVNULL,
            stderr=subprocess.PIPE,
            timeout=CUT_SECONDS,
        )
    except subprocess.TimeoutExpired as cut:
        lines = (cut.stderr or b"").decode(errors="replace").splitlines()
        return -9, lines, 0, time.monotonic() - start  # (cut: more than its minute)
    lines = done.stderr.decode(errors="replace").splitlines()
    peak = [line for line in lines if line.startswith("cgfs-peak-kb ")]
    lines = [
        line
        for line in lines
        if not line.startswith("cgfs-peak-kb ") and not line.startswith("Command exited")
    ]
    kb, user, system = peak[-1].split()[1:] if peak else (0, 0, 0)
    return done.returncode, lines, int(kb) / 1024, float(user) + float(system)


def main():
    build, work = sys.argv[1], sys.argv[2]
    slow = "--slow" in sys.argv[3:]
    if not os.access("/usr/bin/time", os.X_OK):
        print("FAIL: no /usr/bin/time (GNU time, Debian's 'time': scripts/setup installs it)")
        return 1
    shutil.rmtree(work, ignore_errors=True)
    for name, tier, expected, files in cases(slow):
        if tier == "slow" and not slow:
            continue
        where = os.path.join(work, name)
        os.makedirs(where)
        for file, content in files.items():
            if callable(content):
                content(os.path.join(where, file))
            else:
                with open(os.path.join(where, file), "w") as out:
                    out.write(content)
        bound = LARGEST_BOUND_MB if name.startswith("largest") else SMALL_BOUND_MB
        for chapter in MODEL_CHAPTERS if slow else QUICK_CHAPTERS:
            output = os.path.join(work, "out", f"{name}-{chapter}")
            status, lines, peak, took = run(
                [
                    os.path.join(build, chapter),
                    "--model",
                    os.path.join(where, "m.obj"),
                    "--output",
                    output,
                    *([] if slow else QUICK_SIZE),
                ]
            )
            said = f"{name}, {chapter}: exit {status}, {len(lines)} lines, {peak:.0f} MB, {took:.1f} s of processor"
            if expected == "refused":
                ok = status == 2 and len(lines) == 1 and f"{chapter}: error: " in lines[0]
                check(f"{said}: refused in one line ({lines[0] if lines else ''})", ok)
            else:
                warnings = [line for line in lines if ": warning: " in line]
                ok = status == 0 and warnings == lines and len(set(warnings)) == len(warnings) <= 4
                check(f"{said}: drawn, each warning said once", ok)
                if not ok:
                    print("\n".join(lines[:5]))
            if SANITIZED:
                check(
                    f"{said}: within a minute (memory not bounded: sanitized)",
                    took <= MINUTE,
                )
            else:
                check(
                    f"{said}: at most {bound} MB and a minute",
                    peak <= bound and took <= MINUTE,
                )
    for option in ("--model", "--texture"):
        status, lines, _, _ = run(
            [
                os.path.join(build, "14-textures"),
                option,
                "",
                "--output",
                os.path.join(work, "out", "empty"),
            ]
        )
        check(
            f"{option} '': exit 2 and one line ({lines[0] if lines else ''})",
            status == 2 and len(lines) == 1,
        )
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
