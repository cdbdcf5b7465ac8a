#!/usr/bin/env python3
"""Checks a Python chapter of "Computer Graphics from Scratch" one book function at a time.

    check-functions.py CHAPTER YOUR_MODULE.py [--adapter YOUR_ADAPTER.py] [--time-limit S]
    check-functions.py --adapter-template

CHAPTER is a chapter's number or folder name (02, 02-basic-rays). For every book
function of the chapter that has cases in tests/cases/CHAPTER.json (the cases our C++
tests run), the runner calls your function by the book's name with the book's
parameters and prints whether it passed, failed (with the inputs, what was expected,
what yours returned and the mistake the case catches) or is not written yet.

The book's data reach your code as the default adapter below makes them: vectors as
named tuples (x, y, z), points as (x, y, h), colours as tuples, 4x4 matrices as tuples
of rows, textures as texture[i][j] (column i, row j), spheres, lights, planes, models,
transforms and scenes as records with the book's fields, read either way
(sphere.radius or sphere["radius"], light.type == "point", plane.normal, plane.D,
model.triangles[k].v, transform.scale), and the book's globals (Cw, Ch, Vw, Vh, d,
scene, BACKGROUND_COLOR) set on your module before each case. An adapter file of yours
may define any of the functions of DefaultAdapter (same names, as plain functions) to
build your own types or set your own globals instead; --adapter-template prints one to
fill in (docs/students.md has an example).

Your code runs in a process of its own, which this one judges from outside: it is sent
each case's inputs and reports what your function returned; the verdict, against the
expected values it never sees, is made here. A case that runs past the time limit, or a
process that ends or says nothing more, fails, and a new process goes on with the next
case. Exit status: 0 every case of every written function passed, 1 a case failed or
your module does not load, 2 the command line is wrong. Nothing is written anywhere.
"""

import argparse
import collections
import importlib.util
import json
import math
import os
import re
import select
import subprocess
import sys
import time
import traceback
import types
from pathlib import Path

sys.dont_write_bytecode = True  # never a __pycache__ in the student's folder

CASES_DIR = Path(__file__).resolve().parents[3] / "tests" / "cases"


class Usage(Exception):
    """A wrong command line: one line, exit status 2."""


class LoadError(Exception):
    """The student's module or adapter does not load: one line, exit status 1."""


def number(value):
    """A number of the cases: JSON's (a whole number stays an int, as the book's
    pixel coordinates and indices are), or "inf" / "-inf"."""
    if value == "inf":
        return math.inf
    if value == "-inf":
        return -math.inf
    return value if isinstance(value, int) and not isinstance(value, bool) else float(value)


def numbers(value):
    return tuple(number(each) for each in value)


def decoded(value):
    """A case's JSON with "inf" and "-inf" made numbers, so that adapters see numbers only."""
    if value in ("inf", "-inf"):
        return number(value)
    if isinstance(value, list):
        return [decoded(each) for each in value]
    if isinstance(value, dict):
        return {key: decoded(each) for key, each in value.items()}
    return value


Point = collections.namedtuple("Point", "x y h", defaults=(1.0,))  # h: chapter 8's intensity
Vector = collections.namedtuple("Vector", "x y z")


def channel(value):
    """A colour channel as a canvas keeps it: clamped to 0..255, rounded half up."""
    if not value > 0:
        return 0
    if value >= 255:
        return 255
    whole = math.trunc(value)
    return whole + 1 if value - whole >= 0.5 else whole


class Canvas:
    """What a drawing function puts, as a canvas of the case's size keeps it: each pixel's
    x and y truncated toward zero (docs/conventions.md), its colour clamped to 0..255 and
    rounded, the last colour put at a pixel kept, pixels outside the canvas dropped."""

    def __init__(self, width, height):
        self.width, self.height = width, height
        self.pixels = {}

    def PutPixel(self, x, y, color):
        x, y = math.trunc(x), math.trunc(y)
        if -self.width // 2 <= x < self.width // 2 and -self.height // 2 <= y < self.height // 2:
            self.pixels[(x, y)] = [channel(c) for c in color]

    def drawn(self):
        return [[x, y, *self.pixels[(x, y)]] for x, y in sorted(self.pixels)]


class Record(types.SimpleNamespace):
    """One of the book's records (a sphere, a light, a scene...): its fields read as
    attributes or as a dict's keys, sphere.radius or sphere["radius"], as a chapter written
    from the book in plain Python may read them."""

    def __getitem__(self, name):
        try:
            return getattr(self, name)
        except AttributeError:
            raise KeyError(name) from None

    def __setitem__(self, name, value):
        setattr(self, name, value)

    def __contains__(self, name):
        return hasattr(self, name)

    def __iter__(self):
        return iter(vars(self))

    def __len__(self):
        return len(vars(self))

    def get(self, name, default=None):
        return getattr(self, name, default)

    def keys(self):
        return vars(self).keys()

    def values(self):
        return vars(self).values()

    def items(self):
        return vars(self).items()


class Texture:
    """texture[i][j]: the texel in column i, row j, as the book indexes a texture."""

    def __init__(self, width, height, texels):
        self.width, self.height = width, height
        self.columns = [[texels[j * width + i] for j in range(height)] for i in range(width)]

    def __getitem__(self, i):
        return self.columns[i]


class DefaultAdapter:
    """How the book's data reach your code, and how your results come back."""

    @staticmethod
    def vector(value):
        return Vector(*numbers(value))

    @staticmethod
    def point(value):
        return Point(*numbers(value))

    @staticmethod
    def color(value):
        return numbers(value)

    @staticmethod
    def matrix(rows):
        """A 4x4 matrix as the book writes it: a tuple of its rows."""
        return tuple(numbers(row) for row in rows)

    @classmethod
    def vectors(cls, value):
        return [cls.vector(each) for each in value]

    @classmethod
    def plane(cls, value):
        return Record(normal=cls.vector(value["normal"]), D=number(value["D"]))

    @staticmethod
    def booleans(value):
        return [bool(each) for each in value]

    @classmethod
    def tangent_basis(cls, value):
        """A triangle's tangent T and bitangent B (chapter 15's normal mapping)."""
        return Record(T=cls.vector(value["T"]), B=cls.vector(value["B"]))

    @classmethod
    def triangle(cls, value):
        """A triangle of a model: v, three indices into its vertex list, and color."""
        return Record(v=list(value["v"]), color=cls.color(value["color"]))

    @classmethod
    def model(cls, value):
        """A model: its vertices and its triangles."""
        return Record(vertices=cls.vectors(value["vertices"]),
                                     triangles=[cls.triangle(each) for each in value["triangles"]])

    @classmethod
    def texture(cls, value):
        """A texture as the book reads it, texture[i][j] the texel in column i, row j (rows
        from the top), with its width and height."""
        return Texture(value["width"], value["height"], [cls.color(each) for each in value["texels"]])

    @classmethod
    def transform(cls, value):
        return Record(
            scale=number(value["scale"]), rotation=cls.matrix(value["rotation"]),
            translation=cls.vector(value["translation"]))

    @classmethod
    def sphere(cls, value):
        return Record(
            center=cls.vector(value["center"]), radius=number(value["radius"]),
            color=cls.color(value["color"]), specular=number(value.get("specular", -1)),
            reflective=number(value.get("reflective", 0)))

    @classmethod
    def light(cls, value):
        return Record(
            type=value["type"], intensity=number(value["intensity"]),
            position=cls.vector(value.get("position", [0, 0, 0])),
            direction=cls.vector(value.get("direction", [0, 0, 0])))

    @classmethod
    def scene(cls, value):
        return Record(
            spheres=[cls.sphere(each) for each in value.get("spheres", [])],
            lights=[cls.light(each) for each in value.get("lights", [])],
            background_color=cls.color(value.get("background_color", [255, 255, 255])))

    @classmethod
    def setup(cls, module, given):
        """Sets the book's globals that a case gives on your module; for a drawing
        function, PutPixel is the checker's (given["canvas"]["PutPixel"])."""
        if "canvas" in given:
            module.Cw, module.Ch = given["canvas"]["width"], given["canvas"]["height"]
            if "PutPixel" in given["canvas"]:
                module.PutPixel = given["canvas"]["PutPixel"]
        if "viewport" in given:
            viewport = given["viewport"]
            module.Vw, module.Vh = number(viewport["width"]), number(viewport["height"])
            module.d = number(viewport["d"])
        if "scene" in given:
            module.scene = cls.scene(given["scene"])
            module.BACKGROUND_COLOR = module.scene.background_color
        if given.get("depth_buffer") == "empty":  # chapter 12: 0 is 1/z infinitely far
            width, height = given["canvas"]["width"], given["canvas"]["height"]
            module.depth_buffer = [[0] * height for _ in range(width)]  # [x][y], x, y >= 0
        if "camera" in given:  # chapter 5: its rotation a 3x3 matrix, row by row
            module.camera = Record(
                position=cls.vector(given["camera"]["position"]),
                rotation=tuple(tuple(numbers(row)) for row in given["camera"]["rotation"]))

    @classmethod
    def result(cls, kind, value, given):
        """Your function's result as the list of numbers the case expects: a number, a
        vector or colour, two roots, or ClosestIntersection's sphere (by its index in
        the case's scene, -1 for none) and t."""
        if kind == "number":
            return [float(value)]
        if kind == "numbers":
            return [float(each) for each in value]
        if kind == "canvas_point":  # as a canvas takes it: truncated toward zero
            x, y = (value.x, value.y) if hasattr(value, "x") else value[:2]
            return [math.trunc(x), math.trunc(y)]
        if kind == "matrix":  # row by row, as the book writes it
            rows = value.tolist() if hasattr(value, "tolist") else value
            return [float(each) for row in rows for each in row]
        if kind == "boolean":
            if not isinstance(value, bool):
                raise TypeError("not True or False")
            return [float(value)]
        if kind == "triangles":  # a model (its triangles) or a list of triangles: their indices
            triangles = value.triangles if hasattr(value, "triangles") else value
            return [float(i) for each in triangles for i in (each.v if hasattr(each, "v") else each)]
        if kind == "corners":  # each triangle's corners, its indices looked up in the vertex
            vertices = given["arguments"]["vertices"]  # list the function was given
            return [number for each in value for i in (each.v if hasattr(each, "v") else each)
                    for number in cls.result("vector", vertices[i], given)]
        if kind == "bounding_sphere":  # its centre, then its radius
            center, radius = (value.center, value.radius) if hasattr(value, "center") else value
            return cls.result("vector", center, given) + [float(radius)]
        if kind == "vector_or_none":
            return [] if value is None else cls.result("vector", value, given)
        if kind == "closest":
            sphere, t = value
            return [cls.index_of(sphere, given), float(t)]
        if all(hasattr(value, axis) for axis in "xyz"):
            value = (value.x, value.y, value.z)
        return [float(each) for each in value]

    @classmethod
    def index_of(cls, sphere, given):
        """Which sphere of the case's scene yours is: the one with its centre and radius."""
        if sphere is None:
            return -1
        field = (lambda name: sphere[name]) if isinstance(sphere, dict) else \
            (lambda name: getattr(sphere, name))
        center = cls.result("vector", field("center"), given)
        for index, each in enumerate(given["scene"]["spheres"]):
            if numbers(each["center"]) == tuple(center) and number(each["radius"]) == field("radius"):
                return index
        raise ValueError("not a sphere of the scene")


def load(path, what):
    """Your module (or adapter), loaded from its file; its folder joins the import path.
    Runs in the worker process only."""
    path = Path(path)
    spec = importlib.util.spec_from_file_location(path.stem, path)
    if spec is None or spec.loader is None:
        raise LoadError(f"{what} {path} does not load: not a Python file")
    module = importlib.util.module_from_spec(spec)
    sys.path.insert(0, str(path.resolve().parent))
    try:
        spec.loader.exec_module(module)
    except BaseException as error:  # whatever their file does, one line
        raise LoadError(f"{what} {path} does not load: {one_line(error)}") from None
    return module


def one_line(error):
    """An exception in one line, at the last line of the student's code it went through."""
    frames = [frame for frame in traceback.extract_tb(error.__traceback__)
              if not frame.filename.startswith(str(Path(__file__).resolve().parent))]
    place = f" (at {Path(frames[-1].filename).name}:{frames[-1].lineno})" if frames else ""
    text = str(error).splitlines()[0] if str(error) else ""
    return f"{type(error).__name__}{': ' + text if text else ''}{place}"


def adapted(adapter_module):
    """The default adapter with the functions of the student's adapter in its place."""
    class Adapter(DefaultAdapter):
        pass
    if adapter_module is not None:
        for name in ("vector", "vectors", "point", "color", "booleans", "matrix", "plane",
                     "transform", "triangle", "model", "texture", "tangent_basis", "sphere", "light",
                     "scene", "setup", "result", "index_of"):
            if hasattr(adapter_module, name):
                setattr(Adapter, name, staticmethod(getattr(adapter_module, name)))
    return Adapter


def convert(adapter, kind, value):
    if kind == "number":
        return number(value)
    return getattr(adapter, kind)(value)


def flattened(value):
    """Every number of a case's expected value, lists within lists flattened in order."""
    if value is None:  # none: a function that returns nothing here
        return []
    if isinstance(value, list):
        return [n for each in value for n in flattened(each)]
    return [number(value)]


def pixel_differences(drawn, expected):
    """None when a drawing function put exactly the pixels expected, else which differ."""
    yours = {(x, y): (r, g, b) for x, y, r, g, b in drawn}
    ours = {(x, y): (r, g, b) for x, y, r, g, b in expected}
    lines = []
    for what, pixels in (("missing", [p for p in ours if p not in yours]),
                         ("extra", [p for p in yours if p not in ours]),
                         ("of another colour", [p for p in ours if p in yours and yours[p] != ours[p]])):
        if pixels:
            listed = ", ".join(f"({x}, {y})" + (f" yours {yours[(x, y)]} ours {ours[(x, y)]}"
                                                 if what == "of another colour" else "")
                               for x, y in sorted(pixels)[:8])
            more = f" and {len(pixels) - 8} more" if len(pixels) > 8 else ""
            lines.append(f"{len(pixels)} pixels {what}: {listed}{more}")
    return lines or None


def shown(values):
    """Numbers as the cases write them: 0.75, not 0.75000000000000001; 255, not 255.0."""
    return "[" + ", ".join(f"{value:.10g}" for value in values) + "]"


# The worker: the process your code runs in. It loads your module (and adapter), says which
# of the book functions it is asked about your module has, then runs each case it is sent
# and reports what your function returned (or drew, or raised), never a verdict: it is
# sent a case's inputs only, never what is expected.

def run_case(function, case, parameters, returns, adapter, module):
    """What your function made of one case, for the checker to judge: {"values": [...]},
    {"pixels": [...]} or {"problem": [lines]}."""
    given = decoded(case.get("given", {}))
    canvas = None
    if returns == "pixels":  # what the function draws, through the checker's PutPixel
        canvas = Canvas(given["canvas"]["width"], given["canvas"]["height"])
        given["canvas"]["PutPixel"] = canvas.PutPixel
    try:
        adapter.setup(module, given)
        # One call, or several in turn on one canvas and depth buffer (case["calls"]).
        calls = [[convert(adapter, kind, decoded(call[name])) for name, kind in parameters]
                 for call in case.get("calls", [case.get("args")])]
    except BaseException as error:
        return {"problem": [f"your adapter failed to build the inputs: {one_line(error)}"]}
    try:
        for args in calls:
            value = function(*args)
    except BaseException as error:
        return {"problem": [f"raised {one_line(error)}"]}
    if canvas:
        return {"pixels": canvas.drawn()}
    if value is None and returns == "triangles":  # CullBackFaces changes its object
        value = args[0]
    # The case's globals, and the arguments as your function was given them (after it ran).
    given = dict(decoded(case.get("given", {})), arguments=dict(zip((n for n, _ in parameters), args)))
    try:
        values = [float(each) for each in adapter.result(returns, value, given)]
        return {"values": values}
    except BaseException:
        try:
            shown_value = repr(value)[:200]
        except BaseException:
            shown_value = f"a {type(value).__name__}"
        return {"problem": [f"returned {shown_value}, not a {returns}"]}


def worker(module_path, adapter_path, requests_fd, replies_fd):
    replies = os.fdopen(replies_fd, "w", buffering=1)
    requests = os.fdopen(requests_fd, "r")

    def reply(message):
        replies.write(json.dumps(message) + "\n")
        replies.flush()

    try:
        adapter = adapted(load(adapter_path, "your adapter") if adapter_path else None)
        module = load(module_path, "your module")
    except LoadError as error:
        reply({"load_error": str(error)})
        return
    names = json.loads(requests.readline())["functions"]
    reply({"loaded": [name for name in names if callable(getattr(module, name, None))]})
    for line in requests:
        request = json.loads(line)
        result = run_case(getattr(module, request["function"]), request["case"],
                          request["parameters"], request["returns"], adapter, module)
        result["id"] = request["id"]
        try:
            reply(result)
        except (TypeError, ValueError):
            reply({"id": request["id"], "problem": ["returned something that is not numbers"]})


# The checker's side: a worker process at a time, judged by what it reports.

LOAD_LIMIT = 60  # seconds a module may take to load, apart from its cases' time limit


class Worker:
    """A process running the worker above on your module."""

    def __init__(self, options):
        to_child, self.requests = os.pipe()
        self.replies, from_child = os.pipe()
        command = [sys.executable, "-B", str(Path(__file__).resolve()), "--worker",
                   options.module, options.adapter or "", str(to_child), str(from_child)]
        # What your code prints is not shown: it would break the report's lines.
        self.process = subprocess.Popen(command, pass_fds=(to_child, from_child),
                                        stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                                        stderr=subprocess.DEVNULL)
        os.close(to_child)
        os.close(from_child)
        self.buffer = b""

    def send(self, message):
        os.write(self.requests, (json.dumps(message) + "\n").encode())

    def receive(self, limit):
        """The next message; "timeout" after `limit` seconds; "ended" if the process is
        gone (or said something that is not a message)."""
        deadline = time.monotonic() + limit
        while b"\n" not in self.buffer:
            left = deadline - time.monotonic()
            if left <= 0:
                return "timeout"
            ready, _, _ = select.select([self.replies], [], [], left)
            if not ready:
                return "timeout"
            chunk = os.read(self.replies, 65536)
            if not chunk:
                return "ended"
            self.buffer += chunk
        line, self.buffer = self.buffer.split(b"\n", 1)
        try:
            message = json.loads(line)
        except ValueError:
            return "ended"
        return message if isinstance(message, dict) else "ended"

    def stop(self):
        """Kills the process (nothing it does can keep it alive); its exit status."""
        self.process.kill()
        status = self.process.wait()
        for fd in (self.requests, self.replies):
            os.close(fd)
        return status

    def exit_status(self):
        """How the process ended, once it has: its status, or -signal."""
        try:
            status = self.process.wait(timeout=2)
        except subprocess.TimeoutExpired:
            status = self.stop()
            return status
        for fd in (self.requests, self.replies):
            os.close(fd)
        return status


def start_worker(options, names):
    """A worker with your module loaded, and which of the book functions `names` it has;
    LoadError if it does not load."""
    worker_ = Worker(options)
    try:
        worker_.send({"functions": names})
    except OSError:
        pass  # it ended already: said below
    message = worker_.receive(LOAD_LIMIT)
    if message == "timeout":
        worker_.stop()
        raise LoadError(f"your module {options.module} does not load: still running after {LOAD_LIMIT} s")
    if message == "ended" or "loaded" not in message:
        if isinstance(message, dict) and "load_error" in message:
            worker_.exit_status()
            raise LoadError(str(message["load_error"]))
        status = worker_.exit_status()
        raise LoadError(f"your module {options.module} does not load: it ended the process "
                        f"(exit status {status}) while loading")
    return worker_, set(message["loaded"])


def verdict(reply, case, returns):
    """None when the case passes, else what went wrong, in lines."""
    if "problem" in reply:
        return [str(line) for line in reply["problem"]]
    if returns == "pixels":
        return pixel_differences(reply.get("pixels", []), case["expected"])
    actual = reply.get("values")
    if not isinstance(actual, list) or not all(isinstance(each, (int, float)) for each in actual):
        return ["returned something that is not numbers"]
    expected = flattened(decoded(case["expected"]))
    if case.get("compare") == "truncated":  # as a canvas truncates pixel coordinates
        actual = [math.trunc(each) if math.isfinite(each) else each for each in actual]
    tolerance = case["tolerance"]
    if len(actual) == len(expected) and all(
            a == e if math.isinf(e) else abs(a - e) <= tolerance for a, e in zip(actual, expected)):
        return None
    return [f"returned {shown(actual)}" + (" (truncated)" if case.get("compare") else "") +
            f", expected {shown(expected)}" + (f" (within {tolerance:g})" if tolerance else "")]


# The globals each kind of a case's "given" sets on your module (DefaultAdapter.setup).
GLOBALS_SET = {"canvas": "Cw, Ch", "viewport": "Vw, Vh, d", "scene": "scene, BACKGROUND_COLOR",
               "depth_buffer": "depth_buffer", "camera": "camera"}


def globals_note(failures):
    """The line that says which globals the checker set, when a failed case set any."""
    kinds = [kind for kind in GLOBALS_SET if any(kind in case.get("given", {}) for _, case, _ in failures)]
    if not kinds:
        return None
    names = ", ".join(GLOBALS_SET[kind] for kind in kinds)
    return (f"    note: the checker set {names} on your module before these cases; if your "
            f"module keeps its own, give an adapter (docs/students.md, \"How the book's data "
            f"reach your code\"; --adapter-template prints one to fill in)")


class Session:
    """Runs the cases on a worker at a time, starting a new one after a case that did not
    come back."""

    def __init__(self, options, names):
        self.options, self.names = options, names
        self.worker, self.written = start_worker(options, names)
        self.next_id = 0

    def run(self, entry, case):
        if self.worker is None:
            try:
                self.worker, _ = start_worker(self.options, self.names)
            except LoadError as error:
                return [f"a new process for the next cases could not load your module: {error}"]
        self.next_id += 1
        inputs = {key: case[key] for key in ("given", "args", "calls") if key in case}
        try:
            self.worker.send({"id": self.next_id, "function": entry["function"], "case": inputs,
                              "parameters": entry["parameters"], "returns": entry["returns"]})
            reply = self.worker.receive(self.options.time_limit)
        except OSError:
            reply = "ended"
        if reply == "timeout":
            self.worker.stop()
            self.worker = None
            return [f"did not return within {self.options.time_limit:g} s"]
        if reply == "ended" or reply.get("id") != self.next_id:
            status = self.worker.stop() if reply != "ended" else self.worker.exit_status()
            self.worker = None
            return [f"ended the process it ran in (exit status {status}) instead of returning"
                    if reply == "ended" else "said something else than what it returned"]
        return reply

    def close(self):
        if self.worker is not None:
            self.worker.stop()


def check_function(session, entry, file):
    """Prints the verdict of one book function; whether it failed."""
    name = entry["function"]
    cases = entry["cases"]
    if name not in session.written:
        print(f"  {name:22} not written yet ({len(cases)} cases)")
        return False
    failures = []
    for number_, case in enumerate(cases, 1):
        reply = session.run(entry, case)
        problem = reply if isinstance(reply, list) else verdict(reply, case, entry["returns"])
        if problem:
            failures.append((number_, case, problem))
    if not failures:
        print(f"  {name:22} passed ({len(cases)} cases)")
        return False
    print(f"  {name:22} FAILED {len(failures)} of {len(cases)} cases")
    for number_, case, problem in failures:
        print(f"    case {number_} of {file}: {case['catches']}")
        inputs = dict(case.get("given", {}), **case.get("args", {"calls": case.get("calls")}))
        print(f"      {entry['call']} with {json.dumps(inputs)}")
        for line in problem:
            print(f"      {line}")
    note = globals_note(failures)
    if note:
        print(note)
    return True


ADAPTER_TEMPLATE = """\
# An adapter for check-functions.py (docs/students.md, "How the book's data reach your
# code"): give it with --adapter. Define only what your module needs; each function here
# takes the place of the checker's own of the same name.


def setup(module, given):
    \"\"\"Called before each case, with what the case sets as the book's globals:
        given["canvas"]   {"width": ..., "height": ..., and for drawing functions
                           "PutPixel": the checker's PutPixel(x, y, color)}
        given["viewport"] {"width": ..., "height": ..., "d": ...}
        given["scene"]    {"spheres": [...], "lights": [...], "background_color": [r, g, b]}
    Put them where your module reads them. This one sets the book's names, as the checker
    does; rename them to yours. (Chapter 12's depth_buffer and chapter 5's camera: see
    DefaultAdapter.setup in check-functions.py.)\"\"\"
    if "canvas" in given:
        module.Cw = given["canvas"]["width"]
        module.Ch = given["canvas"]["height"]
        if "PutPixel" in given["canvas"]:
            module.PutPixel = given["canvas"]["PutPixel"]
    if "viewport" in given:
        module.Vw = given["viewport"]["width"]
        module.Vh = given["viewport"]["height"]
        module.d = given["viewport"]["d"]
    if "scene" in given:
        module.scene = given["scene"]  # a dict: "spheres", "lights", "background_color"
        module.BACKGROUND_COLOR = given["scene"].get("background_color", [255, 255, 255])


# Your own types, if your functions take them (each gets the case's JSON value):
# def vector(value):
#     return MyVector(*value)
# def sphere(value):
#     return MySphere(center=value["center"], radius=value["radius"], color=value["color"])
"""


def main(argv):
    if argv == ["--adapter-template"]:
        print(ADAPTER_TEMPLATE, end="")
        return 0
    parser = argparse.ArgumentParser(prog="check-functions.py", description=__doc__.split("\n")[0])
    parser.add_argument("chapter", help="the chapter: its number (02) or folder name")
    parser.add_argument("module", help="your chapter's Python file")
    parser.add_argument("--adapter", help="your adapter's Python file (optional)")
    parser.add_argument("--time-limit", type=float, default=5, metavar="SECONDS",
                        help="how long a case may take (default 5)")
    options = parser.parse_args(argv)
    if not 0 < options.time_limit <= 3600:
        raise Usage(f"--time-limit {options.time_limit:g}: give 0 to 3600 seconds")
    have = ", ".join(path.stem for path in sorted(CASES_DIR.glob("*.json")))
    if not re.fullmatch(r"[0-9]{2}(-[a-z0-9-]+)?", options.chapter):
        raise Usage(f"no chapter '{options.chapter}': give a number such as 02 "
                    f"or a folder name; there are cases for {have}")
    matches = sorted(CASES_DIR.glob(f"{options.chapter}*.json"))
    if len(matches) != 1:
        raise Usage(f"no cases for chapter '{options.chapter}'; there are cases for {have}")
    for path in (options.module, options.adapter):
        if path is not None and not Path(path).is_file():
            raise Usage(f"{path}: no such file")
    cases = json.loads(matches[0].read_text())
    session = Session(options, [entry["function"] for entry in cases["functions"]])
    try:
        print(f"{cases['chapter']}: {Path(options.module).name}, the book's functions one by one")
        failed = [check_function(session, entry, matches[0].name) for entry in cases["functions"]]
    finally:
        session.close()
    return 1 if any(failed) else 0


if __name__ == "__main__":
    if len(sys.argv) == 6 and sys.argv[1] == "--worker":
        worker(sys.argv[2], sys.argv[3], int(sys.argv[4]), int(sys.argv[5]))
        sys.exit(0)
    try:
        sys.exit(main(sys.argv[1:]))
    except Usage as error:
        print(f"check-functions.py: error: {error}", file=sys.stderr)
        sys.exit(2)
    except LoadError as error:
        print(f"check-functions.py: {error}", file=sys.stderr)
        sys.exit(1)
    except BrokenPipeError:  # the output piped into a reader that stopped (| head)
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        sys.exit(1)
