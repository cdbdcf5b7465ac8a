"""The process a student's Python chapter runs in, for the function checker
(tools/check-functions/check-functions.js, docs/students.md).

It loads the chapter (and the student's adapter, if any), says what it finds there (the
book's functions, their parameters, the module-level names each one reads), then runs one
case at a time: it builds the case's inputs, puts the case's canvas, viewport and scene
where the chapter reads them, calls the function and answers with what it returned, as
plain data. It is never told what a case expects and decides nothing: the checker
judges every answer in a process of its own.

Messages are JSON lines: requests on file descriptor 3, answers on 4 (the checker's
pipes; nothing of them is in sys.argv). Each case runs in a child process of its own,
forked from this one once the chapter is loaded, so that a case that never returns ends
alone, after its time limit, without loading the chapter again.
"""

import ast
import builtins
import collections
import ctypes
import dis
import errno
import importlib.util
import inspect
import json
import math
import os
import select
import signal
import sys
import tempfile
import textwrap
import time
import traceback
import types
from pathlib import Path

sys.dont_write_bytecode = True  # never a __pycache__ in the student's folder

RUNNER_DIR = str(Path(__file__).resolve().parent)
MAX_ANSWER = 4 << 20  # bytes of one answer
MAX_ITEMS = 200_000  # numbers, strings and lists in one answer
MAX_PIXELS = 100_000  # PutPixel calls one case may make
MAX_PRINTED = 4000  # characters of what one case printed, kept for the report

Point = collections.namedtuple("Point", "x y h", defaults=(1.0,))  # h: chapter 8's intensity
Vector = collections.namedtuple("Vector", "x y z")
Pair = collections.namedtuple("Pair", "x y")  # a canvas point as the demos pass it: (x, y)


class LoadError(Exception):
    """The student's module or adapter does not load."""


class Record(types.SimpleNamespace):
    """One of the book's records (a sphere, a light, a scene...): its fields read as
    attributes or as a dict's keys, sphere.radius or sphere["radius"]; a triangle's v
    also as the demos' indexes or v0, v1 and v2, a plane's D as their distance."""

    ALIASES = {
        "indexes": ("v",),
        "v0": ("v", 0),
        "v1": ("v", 1),
        "v2": ("v", 2),
        "distance": ("D",),
    }
    demos_fields_read = {}  # the aliases the case's code read, for the report's REPL call

    def __getattr__(self, name):  # only for a name the record does not have
        field, *index = Record.ALIASES.get(name, (None,))
        if field in vars(self):
            Record.demos_fields_read[name] = [field, *index]
            value = vars(self)[field]
            return value[index[0]] if index else value
        raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")

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
    """texture[i][j]: the texel in column i, row j (rows from the top), as the book
    indexes a texture, with its width and height."""

    def __init__(self, width, height, texels):
        self.width, self.height = width, height
        self.columns = [[texels[j * width + i] for j in range(height)] for i in range(width)]

    def __getitem__(self, i):
        return self.columns[i]


def number(value):
    """A number of the cases: JSON's (a whole number stays an int, as the book's pixel
    coordinates and indices are), or "inf" / "-inf"."""
    if value == "inf":
        return math.inf
    if value == "-inf":
        return -math.inf
    return value if isinstance(value, int) and not isinstance(value, bool) else float(value)


def numbers(value):
    return tuple(number(each) for each in value)


class DefaultAdapter:
    """How the book's data reach the student's code. An adapter file may define any of
    these as plain functions to build its own types instead (docs/students.md)."""

    @staticmethod
    def vector(value):
        return Vector(*numbers(value))

    @staticmethod
    def point(value):
        return Point(*numbers(value))

    @staticmethod
    def pair(value):
        return Pair(*numbers(value))

    @staticmethod
    def output(value):
        """A list the function appends its results to (the demos' ClipTriangle(triangle,
        plane, triangles, vertices)): empty."""
        return []

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
        return Record(
            vertices=cls.vectors(value["vertices"]),
            triangles=[cls.triangle(each) for each in value["triangles"]],
        )

    @classmethod
    def texture(cls, value):
        return Texture(
            value["width"], value["height"], [cls.color(each) for each in value["texels"]]
        )

    @classmethod
    def transform(cls, value):
        return Record(
            scale=number(value["scale"]),
            rotation=cls.matrix(value["rotation"]),
            translation=cls.vector(value["translation"]),
        )

    @classmethod
    def sphere(cls, value):
        return Record(
            center=cls.vector(value["center"]),
            radius=number(value["radius"]),
            color=cls.color(value["color"]),
            specular=number(value.get("specular", -1)),
            reflective=number(value.get("reflective", 0)),
        )

    @classmethod
    def light(cls, value):
        """A light with its type's fields only: an ambient light has no position or
        direction, a point light a position, a directional light a direction."""
        light = Record(type=value["type"], intensity=number(value["intensity"]))
        for field in ("position", "direction"):
            if field in value:
                setattr(light, field, cls.vector(value[field]))
        return light

    @classmethod
    def spheres(cls, value):
        return [cls.sphere(each) for each in value]

    @classmethod
    def lights(cls, value):
        return [cls.light(each) for each in value]

    @classmethod
    def scene(cls, value):
        return Record(
            spheres=cls.spheres(value.get("spheres", [])),
            lights=cls.lights(value.get("lights", [])),
            background_color=cls.color(value.get("background_color", [255, 255, 255])),
        )

    @classmethod
    def camera(cls, value):
        """Chapter 5's camera: its position, and its rotation, a 3x3 matrix row by row."""
        return Record(
            position=cls.vector(value["position"]),
            rotation=tuple(numbers(row) for row in value["rotation"]),
        )

    @staticmethod
    def rows(value):
        return tuple(numbers(row) for row in value)

    @staticmethod
    def depth_buffer(canvas):
        """Chapter 12's buffer, depth_buffer[x][y] with x and y from 0: 0 is 1/z
        infinitely far."""
        return [[0] * canvas["height"] for _ in range(canvas["width"])]


def decoded(value):
    """A case's JSON with "inf" and "-inf" made numbers, so that adapters see numbers only."""
    if value in ("inf", "-inf"):
        return number(value)
    if isinstance(value, list):
        return [decoded(each) for each in value]
    if isinstance(value, dict):
        return {key: decoded(each) for key, each in value.items()}
    return value


def at(given, path):
    """given's value at a dotted path ("canvas.width"), or None."""
    for key in path.split("."):
        if not isinstance(given, dict) or key not in given:
            return None
        given = given[key]
    return given


def one_line(error):
    """An exception in one line, at the last line of the student's code it went through
    (for a syntax error, where Python found it)."""
    if isinstance(error, SyntaxError) and error.filename:
        return (
            f"{type(error).__name__}: {error.msg} (at {Path(error.filename).name}:{error.lineno})"
        )
    frames = [
        frame
        for frame in traceback.extract_tb(error.__traceback__)
        if not frame.filename.startswith(RUNNER_DIR) and not frame.filename.startswith("<frozen")
    ]
    place = f" (at {Path(frames[-1].filename).name}:{frames[-1].lineno})" if frames else ""
    text = str(error).splitlines()[0] if str(error) else ""
    return f"{type(error).__name__}{': ' + text if text else ''}{place}"


def load(path, name):
    """The student's module (or adapter), loaded from its file, its folder on the import
    path, run as it would be imported (not as __main__)."""
    path = Path(path)
    spec = importlib.util.spec_from_file_location(path.stem, path)
    if spec is None or spec.loader is None:
        raise LoadError(f"{name} {path} does not load: not a Python file")
    module = importlib.util.module_from_spec(spec)
    sys.path.insert(0, str(path.resolve().parent))
    # In sys.modules before it runs, as an import puts it: a dataclass under
    # `from __future__ import annotations` looks its module up there as it is made.
    previous = sys.modules.get(spec.name)
    sys.modules[spec.name] = module
    try:
        spec.loader.exec_module(module)
    except BaseException as error:  # whatever their file does, one line
        if previous is None:
            sys.modules.pop(spec.name, None)
        else:
            sys.modules[spec.name] = previous
        hint = ""
        if isinstance(error, ModuleNotFoundError) and error.name:
            version = ".".join(map(str, sys.version_info[:3]))
            package = error.name.split(".")[0]
            hint = (
                f": neither your folder nor the Python that ran it, {sys.executable} ({version}), has "
                f"'{package}'; install it for that Python ({sys.executable} -m pip install {package}, or your "
                "system's package), or put the python3 that has it first on your PATH"
            )
        if isinstance(error, OSError) and error.errno in (errno.EROFS, errno.EACCES, errno.EPERM):
            hint = ': it writes a file as it loads, which it may not here; keep that under if __name__ == "__main__":'
        raise LoadError(f"{name} {path} does not load: {one_line(error)}{hint}") from None
    return module


# What the checker is told about the chapter: which book functions it defines, their
# parameters, and the module-level names each reads (through the functions of the
# student's own files it calls), so that a case whose canvas or scene never reaches the
# code is named as such, not as a mistake in it.


def code_reads(code):
    """The global names a code object (and the functions and lambdas inside it) loads."""
    for instruction in dis.get_instructions(code):
        if instruction.opname in ("LOAD_GLOBAL", "LOAD_NAME") and isinstance(
            instruction.argval, str
        ):
            yield instruction.argval
    for constant in code.co_consts:
        if isinstance(constant, types.CodeType):
            yield from code_reads(constant)


def is_students(function, folder):
    return isinstance(function, types.FunctionType) and os.path.abspath(
        function.__code__.co_filename
    ).startswith(folder + os.sep)


def module_label(namespace, main):
    """ "" for the chapter's own module, else the file a namespace belongs to."""
    return "" if namespace is main.__dict__ else Path(namespace.get("__file__") or "?").name


def global_reads(function, main, folder, names, wanted=()):
    """{"reads": [[name, file, "data" | "missing"]...], "complete": whether every function
    it calls could be followed}. A name of the checker's table is a read, never followed
    (the checker sets it)."""
    reads, seen, stack, complete, calls = {}, set(), [function], True, set()
    while stack:
        current = stack.pop()
        if current in seen:
            continue
        seen.add(current)
        namespace = current.__globals__
        for name in set(code_reads(current.__code__)):
            if name in names:
                reads[(name, module_label(namespace, main))] = (
                    "data" if name in namespace else "missing"
                )
                continue
            if name in namespace:
                value = namespace[name]
            elif hasattr(builtins, name):
                continue
            else:
                reads[(name, module_label(namespace, main))] = "missing"
                continue
            if isinstance(value, types.FunctionType):
                if is_students(value, folder):
                    stack.append(value)
                    if name in wanted and value is not function:
                        calls.add(name)
                continue
            if isinstance(value, types.ModuleType) and os.path.abspath(
                getattr(value, "__file__", None) or "/"
            ).startswith(folder + os.sep):
                complete = False  # a module of the student's: what is called in it is not followed
                continue
            if isinstance(value, (type, types.ModuleType, types.BuiltinFunctionType)):
                continue
            if callable(value):  # a partial, a bound method: not followed
                complete = False
                continue
            reads[(name, module_label(namespace, main))] = "data"
    return {
        "reads": [[name, file, kind] for (name, file), kind in sorted(reads.items())],
        "complete": complete,
        "calls": sorted(calls),
    }


def bound_defaults(function):
    """The parameters whose default is written with a module-level name (spheres=SPHERES):
    the value is taken once, when the def runs."""
    try:
        tree = ast.parse(textwrap.dedent(inspect.getsource(function)))
    except (OSError, TypeError, SyntaxError):
        return []
    definition = tree.body[0] if tree.body else None
    if not isinstance(definition, (ast.FunctionDef, ast.AsyncFunctionDef)):
        return []
    arguments = definition.args
    positional = arguments.posonlyargs + arguments.args
    pairs = list(zip(positional[len(positional) - len(arguments.defaults) :], arguments.defaults))
    pairs += [
        (arg, default)
        for arg, default in zip(arguments.kwonlyargs, arguments.kw_defaults)
        if default
    ]
    bound = []
    for arg, default in pairs:
        names = [
            node.id
            for node in ast.walk(default)
            if isinstance(node, ast.Name)
            and node.id in function.__globals__
            and not callable(function.__globals__[node.id])
            and not isinstance(function.__globals__[node.id], types.ModuleType)
        ]
        if names:
            bound.append({"parameter": arg.arg, "default": ast.unparse(default), "names": names})
    return bound


def is_empty(definition):
    """Whether a def's body has nothing in it but `pass`, `...` or a docstring, as a
    page's starter leaves it: not written yet."""
    return all(
        isinstance(statement, ast.Pass)
        or (
            isinstance(statement, ast.Expr)
            and isinstance(statement.value, ast.Constant)
            and (isinstance(statement.value.value, str) or statement.value.value is Ellipsis)
        )
        for statement in definition.body
    )


def declared_functions(source):
    """The functions a module's source defines at its top level, read before any of it
    runs: name -> {count, required, more, empty} (core/account.mjs holds the runner's
    account against it)."""
    found = {}
    for node in ast.parse(source).body:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            a = node.args
            positional = len(a.posonlyargs) + len(a.args)
            found[node.name] = {
                "count": positional,
                "required": positional - len(a.defaults),
                "more": a.vararg is not None,
                "empty": is_empty(node),
            }
    return found


def empty_body(function):
    """Whether a function of the chapter is still empty (is_empty on its own source)."""
    try:
        tree = ast.parse(textwrap.dedent(inspect.getsource(function)))
    except (OSError, TypeError, SyntaxError):
        return False
    return (
        bool(tree.body)
        and isinstance(tree.body[0], (ast.FunctionDef, ast.AsyncFunctionDef))
        and is_empty(tree.body[0])
    )


def parameters(function):
    """The names of the positional parameters, and how many have no default."""
    try:
        signature = inspect.signature(function)
    except (TypeError, ValueError):
        return None
    kinds = (inspect.Parameter.POSITIONAL_ONLY, inspect.Parameter.POSITIONAL_OR_KEYWORD)
    listed = [p for p in signature.parameters.values() if p.kind in kinds]
    varargs = any(p.kind == inspect.Parameter.VAR_POSITIONAL for p in signature.parameters.values())
    return {
        "names": [p.name for p in listed],
        "required": sum(p.default is p.empty for p in listed),
        "more": varargs,
    }


def described(value):
    """A module-level value in a few words, for the report and the adapter template."""
    if isinstance(value, bool) or value is None:
        return repr(value)
    if isinstance(value, (int, float)):
        return f"{value:g}" if isinstance(value, float) else str(value)
    if isinstance(value, (list, tuple, dict, set)):
        return f"a {type(value).__name__} of {len(value)}"
    return f"a {type(value).__name__}"


def facts(main, wanted, folder, names):
    functions = {}
    for name in wanted:
        function = getattr(main, name, None)
        if not callable(function):
            continue
        fact = {
            "parameters": parameters(function),
            "reads": None,
            "complete": False,
            "bound": [],
            "calls": [],
        }
        if isinstance(function, types.FunctionType):
            fact.update(global_reads(function, main, folder, names, wanted))
            fact["bound"] = bound_defaults(function)
            fact["empty"] = empty_body(function)
        functions[name] = fact
    data = {
        name: described(value)
        for name, value in vars(main).items()
        if not name.startswith("__")
        and not callable(value)
        and not isinstance(value, (types.ModuleType, type))
    }
    classes = {}
    for name, value in vars(main).items():
        if isinstance(value, type) and value.__module__ == main.__name__:
            made = parameters(value)
            classes[name] = made["names"] if made else []
    return {
        "functions": functions,
        "data": data,
        "defined": sorted(n for n in vars(main) if not n.startswith("__")),
        "reachable": "all",
        "classes": classes,
    }


# Placing a case's canvas, viewport and scene where the chapter reads them.


class Drawing:
    """The checker's PutPixel: records every call as it is made (x, y and the colour,
    unrounded); the checker keeps them as a canvas would."""

    def __init__(self):
        self.calls = []

    def PutPixel(self, x, y, color):
        if len(self.calls) >= MAX_PIXELS:
            raise RuntimeError(f"more than {MAX_PIXELS} PutPixel calls")
        self.calls.append([x, y, color])


class Chapter:
    """The student's chapter as loaded: its module, the other modules of their folder it
    brought in, their adapter, what the checker was told about it, and the checker's
    table of names (book's and demos') through which a case's data reach it."""

    def __init__(self, main, folder, adapter, names, wanted):
        self.main, self.folder, self.adapter, self.names = main, folder, adapter, names
        self.facts = facts(main, wanted, folder, names)
        self.modules = {"": main}
        for module in list(sys.modules.values()):
            file = getattr(module, "__file__", None)
            if module is not main and file and os.path.abspath(file).startswith(folder + os.sep):
                self.modules[Path(file).name] = module
        self.read = {}  # file label -> the names its functions read
        for fact in self.facts["functions"].values():
            for name, label, _ in fact["reads"] or []:
                self.read.setdefault(label, set()).add(name)

    def targets(self, name, dialect):
        """The modules a name of the table is set on: the chapter's module for the
        book's names, and every module of the student's that defines or reads it."""
        return [
            module
            for label, module in self.modules.items()
            if (label == "" and dialect == "book")
            or name in vars(module)
            or name in self.read.get(label, ())
        ]

    def place(self, given):
        """Sets every name of the table that the case gives; the names set."""
        placed = set()
        for name, spec in self.names.items():
            value = at(given, spec["path"])
            if (
                value is None
                and "empty" in spec
                and at(given, spec["path"].rsplit(".", 1)[0]) is not None
            ):
                value = spec["empty"]
            targets = self.targets(name, spec["dialect"]) if value is not None else []
            for module in targets:
                if spec.get("kind") == "canvas":  # the demos' canvas: its size, set in place
                    set_size(module, name, value)
                elif spec.get("kind") == "scene" and isinstance(
                    getattr(module, name, None), (list, tuple)
                ):
                    # a scene kept as the list of its spheres: the case's spheres
                    setattr(module, name, self.built("spheres", value.get("spheres", []), given))
                else:
                    setattr(module, name, self.built(spec.get("kind", "number"), value, given))
            if targets:
                placed.add(name)
        return placed

    def built(self, kind, value, given):
        if kind == "number":
            return number(value)
        if kind == "depth_buffer":
            return self.adapter.depth_buffer(given["canvas"])
        if kind == "PutPixel":
            return value  # the Drawing's own
        return getattr(self.adapter, kind)(value)

    def fingerprints(self, function):
        """What the names a function reads hold now, to see which an adapter set."""
        fact = self.facts["functions"].get(function, {})
        found = {}
        for name, label, _ in fact.get("reads") or []:
            module = self.modules.get(label)
            if module is not None:
                found[name] = fingerprint(getattr(module, name, None))
        return found

    def set_up(self, function, given):
        """The case's data put in place: the checker's names, then the adapter's setup,
        if it has one, for names of the student's own; the names set (those of the
        adapter's that the function reads)."""
        placed = self.place(given)
        if not hasattr(self.adapter, "own_setup"):
            return placed
        marked = self.mark(function)
        before = self.fingerprints(function)
        setup = self.adapter.own_setup
        try:
            takes_adapter = len(inspect.signature(setup).parameters) >= 3
        except (TypeError, ValueError):
            takes_adapter = False
        try:
            setup(self.main, given, self.adapter) if takes_adapter else setup(self.main, given)
        finally:
            set_again = self.unmark(marked)
        after = self.fingerprints(function)
        return placed | set_again | {name for name in after if after[name] != before.get(name)}

    def mark(self, function):
        """The numbers and strings a function reads, each replaced while the adapter's
        setup runs by an equal value of its own (a subclass), so that setting one again to
        the same value (600 for 600) is seen as set: {(module, name): (mark, value)}."""
        marked = {}
        for name, label, _ in self.facts["functions"].get(function, {}).get("reads") or []:
            module = self.modules.get(label)
            value = getattr(module, name, None) if module is not None else None
            kind = MARKS.get(type(value))
            if kind is not None:
                mark = kind(value)
                setattr(module, name, mark)
                marked[(module, name)] = (mark, value)
        return marked

    @staticmethod
    def unmark(marked):
        """The names the setup set; the others given back their own values."""
        set_again = set()
        for (module, name), (mark, value) in marked.items():
            if getattr(module, name, None) is mark:
                setattr(module, name, value)
            else:
                set_again.add(name)
        return set_again


class MarkedInt(int):
    pass


class MarkedFloat(float):
    pass


class MarkedStr(str):
    pass


MARKS = {int: MarkedInt, float: MarkedFloat, str: MarkedStr}


def set_size(module, name, canvas):
    """A canvas's width and height, and in a drawing case the checker's PutPixel (the
    book's canvas.PutPixel(x, y, color)), set on the object a module holds (attributes
    or keys), or a record of them where it holds none."""
    held = getattr(module, name, None)
    size = {key: canvas[key] for key in ("width", "height", "PutPixel") if key in canvas}
    if isinstance(held, dict):
        held.update(size)
    elif held is not None and hasattr(held, "__dict__"):
        for key, value in size.items():
            setattr(held, key, value)
    else:
        setattr(module, name, Record(**size))


def fingerprint(value):
    """The object a name holds and, one level down, what it holds: a list filled in
    place (SPHERES[:] = ...) counts as set."""
    if isinstance(value, (list, tuple)):
        inside = tuple(map(id, value))
    elif isinstance(value, dict):
        inside = tuple((key, id(each)) for key, each in value.items())
    elif hasattr(value, "__dict__"):
        inside = tuple((key, id(each)) for key, each in vars(value).items())
    else:
        inside = ()
    return (id(value), inside)


def run_case(request, chapter):
    """What the function made of one case: {"returned": ..., "arguments": ...,
    "pixels": [...], "placed": [...]}, or {"raised": ...} / {"adapter_failed": ...}."""
    given = decoded(request.get("given", {}))
    drawing = None
    if request.get("drawing"):
        drawing = Drawing()
        given.setdefault("canvas", {})["PutPixel"] = drawing.PutPixel
    adapter = chapter.adapter
    try:
        placed = chapter.set_up(request["function"], given)
        calls = [
            [argument(adapter, spec, decoded(call)) for spec in request["parameters"]]
            for call in request["calls"]
        ]
    except BaseException as error:
        return {"adapter_failed": one_line(error)}
    function = getattr(chapter.main, request["function"])
    value, args = None, []
    Record.demos_fields_read.clear()  # what the function reads, not the adapter's setup
    try:
        for args in calls:
            value = function(*args)
    except BaseException as error:
        return {"raised": one_line(error), "placed": sorted(placed), **demos_fields()}
    answer = {"placed": sorted(placed), "returned": value, **demos_fields()}
    if drawing:
        answer["pixels"] = drawing.calls
    if hasattr(adapter, "own_result"):
        try:
            answer["returned"] = adapter.own_result(request["returns"], value, given)
        except BaseException as error:
            return {"adapter_failed": f"your adapter's result: {one_line(error)}"}
    if request.get("arguments"):
        answer["arguments"] = args
    return answer


def demos_fields():
    """The demos' names the case's code read from the checker's records, if any, each
    with the book's field (and index) it reads: {"distance": ["D"], "v0": ["v", 0]}."""
    read = dict(sorted(Record.demos_fields_read.items()))
    return {"demos_fields": read} if read else {}


def argument(adapter, spec, call):
    """One argument of a call, built from the case's value(s) by its kind."""
    name, kind = spec[0], spec[1]
    # (an output list has no value in the case: None)
    value = [call[each] for each in spec[2]] if len(spec) > 2 else call.get(name)
    return number(value) if kind == "number" else getattr(adapter, kind)(value)


# Answers as plain data: numbers, strings, lists and records, nothing of the student's
# types; infinities and NaN as the strings JSON lacks them for.


def plain(value, budget, depth=0):
    budget[0] -= 1
    if budget[0] < 0 or depth > 12:
        raise ValueError("too large")
    if value is None or isinstance(value, (bool, str)):
        return value[:200] if isinstance(value, str) else value
    if isinstance(value, (int, float)):
        value = float(value) if not isinstance(value, int) or abs(value) > 2**53 else value
        if isinstance(value, float) and not math.isfinite(value):
            return "nan" if math.isnan(value) else ("inf" if value > 0 else "-inf")
        return value
    if hasattr(value, "tolist") and callable(value.tolist):  # numpy
        return plain(value.tolist(), budget, depth + 1)
    if isinstance(value, dict) or isinstance(value, Record):
        return {
            str(k): plain(v, budget, depth + 1)
            for k, v in list(value.items())[:1000]
            if not callable(v)
        }
    if isinstance(value, Texture):
        return {"width": value.width, "height": value.height}
    if isinstance(value, (list, tuple, range)) or (
        hasattr(value, "__iter__") and hasattr(value, "__len__")
    ):
        if len(value) > MAX_ITEMS:
            raise ValueError("too large")
        return [plain(each, budget, depth + 1) for each in value]
    fields = {}
    for name in (
        "x",
        "y",
        "z",
        "w",
        "h",
        "r",
        "g",
        "b",
        "center",
        "radius",
        "v",
        "triangles",
        "vertices",
    ):
        if hasattr(value, name) and not callable(getattr(value, name)):
            fields[name] = plain(getattr(value, name), budget, depth + 1)
    if not fields and hasattr(value, "__dict__"):
        fields = {
            k: plain(v, budget, depth + 1)
            for k, v in list(vars(value).items())[:1000]
            if not k.startswith("_") and not callable(v)
        }
    if fields:
        return fields
    return f"a {type(value).__name__}"


def encoded(answer):
    try:
        text = json.dumps(plain(answer, [MAX_ITEMS]), allow_nan=False)
    except (ValueError, TypeError, RecursionError):
        return json.dumps({"unreadable": "returned something too large or too deep to send"})
    if len(text) > MAX_ANSWER:
        return json.dumps({"unreadable": "returned something too large to send"})
    return text


def made_by(make, values, check):
    """What the chapter's own type `make` makes of values (as many as it takes), or None
    unless it holds them (check)."""
    try:
        takes = [
            p
            for p in inspect.signature(make).parameters.values()
            if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)
        ]
        made = make(*values[: len(takes)])
    except Exception:  # not a type this can make: the book's records instead
        return None
    return made if check(made) else None


def field(value, name):
    return getattr(value, name) if hasattr(value, name) else value[name]


def own_maker(make, book, fields):
    """The book's values (x, y, z) or (r, g, b) made by the chapter's own class, where
    what it makes holds them (as fields of those names, or by index); else the book's."""

    def holds(made, values):
        try:
            return all(field(made, name) == value for name, value in zip(fields, values))
        except Exception:
            try:
                return list(made)[:3] == list(values)
            except Exception:
                return False

    def maker(value):
        values = numbers(value)
        return made_by(make, list(values), lambda made: holds(made, values)) or book(value)

    return maker


def in_chapter_style(adapter, main):
    """The adapter's vectors and colours as numpy arrays where the chapter uses numpy, or
    made by the chapter's own class (Vec, Vec3, Vector, Vector3, Vertex; Color) where it
    has one that takes (x, y, z) or (r, g, b) and keeps them; its spheres made by the
    chapter's own Sphere where it has one that takes (center, radius, color, specular,
    reflective) and keeps them."""
    numpy = next(
        (
            v
            for v in vars(main).values()
            if isinstance(v, types.ModuleType) and v.__name__ == "numpy"
        ),
        None,
    )
    if numpy is not None:
        adapter.vector = staticmethod(lambda value: numpy.array(numbers(value), dtype=float))
        adapter.color = staticmethod(lambda value: numpy.array(numbers(value), dtype=float))
    for kind, names, fields in (
        ("vector", ("Vec", "Vec3", "Vector", "Vector3", "Vertex"), "xyz"),
        ("color", ("Color", "Colour", "RGB"), "rgb"),
    ):
        make = next(
            (getattr(main, name) for name in names if isinstance(getattr(main, name, None), type)),
            None,
        )
        if make is not None and numpy is None:
            setattr(adapter, kind, staticmethod(own_maker(make, getattr(adapter, kind), fields)))
    own = getattr(main, "Sphere", None)
    if isinstance(own, type):
        book = adapter.sphere

        def sphere(value):
            default = book(value)
            values = [
                default.center,
                default.radius,
                default.color,
                default.specular,
                default.reflective,
            ]

            def keeps(made):
                try:
                    return field(made, "radius") == default.radius and list(
                        field(made, "center")
                    ) == list(default.center)
                except Exception:
                    return False

            return made_by(own, values, keeps) or default

        adapter.sphere = staticmethod(sphere)
    return adapter


def adapted(adapter_module, main):
    """The default adapter, in the chapter's style, with the functions of the student's
    adapter in its place; their setup and result, when they give them, as own_setup and
    own_result."""

    class Adapter(DefaultAdapter):
        pass

    in_chapter_style(Adapter, main)
    if adapter_module is not None:
        for name in (
            "vector",
            "vectors",
            "point",
            "pair",
            "color",
            "booleans",
            "matrix",
            "plane",
            "transform",
            "triangle",
            "model",
            "texture",
            "tangent_basis",
            "sphere",
            "light",
            "spheres",
            "lights",
            "scene",
            "camera",
            "rows",
            "depth_buffer",
        ):
            if callable(getattr(adapter_module, name, None)):
                setattr(Adapter, name, staticmethod(getattr(adapter_module, name)))
        if callable(getattr(adapter_module, "setup", None)):
            Adapter.own_setup = staticmethod(adapter_module.setup)
        if callable(getattr(adapter_module, "result", None)):
            Adapter.own_result = staticmethod(adapter_module.result)
    return Adapter


# A figure drawn with the chapter's own functions (a chapter page's Draw).


def channel(value):
    """A colour channel as a canvas keeps it: clamped to 0..255, rounded half up."""
    if not value > 0:
        return 0
    return 255 if value >= 255 else math.floor(value + 0.5)


notes = []  # what the last figure drawn has to say of the reader's points (fraction_note)
BY_PIXEL = [["x", "number"], ["y", "number"]]  # the book's CanvasToViewport(x, y)


def draw_figure(recipe, chapter, kinds, progress=lambda fraction: None, preview=None):
    """Draws a figure (tools/site/drawings.json) with the chapter's functions: its
    canvas, viewport and scene put where the chapter reads them, as a case's are, then a
    ray per pixel through the chapter's TraceRay, or calls to its drawing functions, each
    argument built as the cases build it (kinds: a function's parameters and their
    kinds) or the value a call of the chapter's returned. RGBA bytes, white where
    nothing was put. preview(bytes): given, a ray-traced figure is first traced at a
    quarter of its resolution (a ray for each block of 4 x 4 pixels, the block given its
    colour) and shown so, before the full picture (a sixteenth more rays)."""
    width, height = recipe["given"]["canvas"]["width"], recipe["given"]["canvas"]["height"]
    pixels = bytearray(b"\xff" * (width * height * 4))

    def put(x, y, color, side=1):
        """The pixel (x, y) in the book's canvas coordinates given a colour, or the block
        of side x side pixels whose bottom-left corner it is."""
        column, row = width // 2 + math.trunc(x), height // 2 - math.trunc(y) - 1
        if 0 <= column < width and 0 <= row < height:
            rgb = plain(color, [16])
            rgb = [rgb[k] for k in "rgb"] if isinstance(rgb, dict) else rgb
            pixel = bytes(channel(number(each)) for each in rgb[:3]) + b"\xff"
            if side == 1:
                at = (row * width + column) * 4
                pixels[at : at + 4] = pixel
                return
            run = min(side, width - column)
            for line in range(max(0, row - side + 1), row + 1):
                at = (line * width + column) * 4
                pixels[at : at + 4 * run] = pixel * run

    given = decoded(recipe["given"])
    given["canvas"]["PutPixel"] = put
    chapter.place(given)
    notes.clear()

    def theirs(name):
        function = getattr(chapter.main, name, None)
        if not callable(function):
            raise NameError(f"{name} is not written yet")
        return function

    if "rays" in recipe:
        rays = recipe["rays"]
        trace, through = theirs("TraceRay"), theirs(rays["direction"])
        origin = chapter.adapter.vector(rays["origin"])
        depth = rays.get("recursion_depth")

        # The book's (x, y) straight through; another signature's (the demos' p2d) built
        # as its cases are, from x and y.
        pixel = kinds.get(rays["direction"], BY_PIXEL)
        if pixel != BY_PIXEL:
            own = through

            def through(x, y):
                return own(*[argument(chapter.adapter, spec, {"x": x, "y": y}) for spec in pixel])

        def ray(x, y):
            D = through(x, y)
            return (
                trace(origin, D, rays["t_min"], math.inf)
                if depth is None
                else trace(origin, D, rays["t_min"], math.inf, depth)
            )

        if preview is not None:
            for x in range(-width // 2, width // 2, 4):
                for y in range(-height // 2, height // 2, 4):
                    put(x, y, ray(x, y), 4)
            preview(bytes(pixels))
        for x in range(-width // 2, width // 2):
            for y in range(-height // 2, height // 2):
                put(x, y, ray(x, y))
            if x % 20 == 0:
                progress((x + width / 2) / width)
    else:

        def call(name, args):
            values = []
            for parameter, kind, *_ in kinds.get(name, []):
                value = args[parameter]
                if isinstance(value, dict) and "call" in value:
                    made = call(value["call"], value["args"])
                    if kind == "point" and not notes:
                        notes.extend(fraction_note(value["call"], made))
                    values.append(made)
                else:
                    values.append(
                        number(value)
                        if kind == "number"
                        else getattr(chapter.adapter, kind)(decoded(value))
                    )
            return theirs(name)(*values)

        for name, args in recipe["calls"]:
            call(name, args)
    return bytes(pixels)


def fraction_note(name, point):
    """The line that says a function of the reader's made a canvas point that is not a
    whole pixel: its drawing functions then draw from other end points than ours."""
    try:
        xy = plain(point, [16])
    except ValueError:
        return []
    if isinstance(xy, dict):
        x, y = xy.get("x"), xy.get("y")
    elif isinstance(xy, list) and len(xy) >= 2:
        x, y = xy[:2]
    else:
        return []
    if all(isinstance(v, (int, float)) and float(v).is_integer() for v in (x, y)):
        return []
    return [
        f"your {name} returned the canvas point ({x}, {y}): ours are whole pixels, truncated toward zero "
        '(docs/conventions.md, "Rounding in the rasterizer"), and your drawing functions draw from other end points'
    ]


# The chapter pages' runner (tools/site/python_worker.js runs this module in Pyodide, in a
# Web Worker): no processes there, so a case runs in this one, and the page ends the
# worker when one runs too long.
page_chapter = None


def page_declare(code):
    """The functions the reader's code defines, read before any of it runs (the page
    holds page_load's account against it), as JSON; none when it is not Python (page_load
    says the syntax error)."""
    try:
        return json.dumps(declared_functions(code))
    except (SyntaxError, ValueError):
        return "{}"


def page_load(code, file, functions, names):
    """Loads the reader's code (text) as the module FILE; the chapter's account of
    itself, or why it does not load, as JSON."""
    global page_chapter
    folder = "/home/pyodide/chapter"
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, os.path.basename(file))
    with open(path, "w") as out:
        out.write(code)
    os.chdir(folder)
    sys.argv = [os.path.basename(file)]
    try:
        main_module = load(path, "your code")
    except LoadError as error:
        return json.dumps({"load_error": str(error).replace(f"your code {path}", "your code")})
    sys.modules.setdefault(main_module.__name__, main_module)
    page_chapter = Chapter(
        main_module, folder, adapted(None, main_module), json.loads(names), json.loads(functions)
    )
    return json.dumps({"loaded": page_chapter.facts})


def page_case(request):
    """One case's answer, as JSON (never what it expects: the page judges)."""
    try:
        return encoded(run_case(json.loads(request), page_chapter))
    except BaseException as error:  # the reader's code made this one fail: said, one line
        return json.dumps({"raised": one_line(error)})


def page_draw_notes():
    """What the last figure drawn has to say of the reader's points, as JSON."""
    return json.dumps(notes)


def page_draw(recipe, kinds, progress, preview):
    """The figure's RGBA bytes, or why it could not be drawn: one line; preview(bytes)
    hears a ray-traced figure at a quarter of its resolution first."""
    try:
        return draw_figure(json.loads(recipe), page_chapter, json.loads(kinds), progress, preview)
    except BaseException as error:  # the reader's code: said, one line
        return one_line(error)


# The loop: a case at a time, each in a child process forked from this one.


def in_child(request, chapter, write_end):
    """Runs in the forked child: the case, its answer written to the parent's pipe."""
    os.setpgid(0, 0)  # the child and what it starts: ended together after the case
    try:  # and ended with the parent, should the parent be ended first
        ctypes.CDLL(None).prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG
    except (AttributeError, OSError):
        pass
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    printed = capture_printing()
    try:
        answer = run_case(request, chapter)
    except BaseException as error:  # the student's code made our own fail: say so
        answer = {"raised": one_line(error)}
    try:
        text = encoded(answer)
    except BaseException as error:
        text = json.dumps({"raised": one_line(error)})
    text = json.dumps({**json.loads(text), **printed_text(printed)})
    data = text.encode()
    while data:
        try:
            data = data[os.write(write_end, data) :]
        except OSError:
            break
    os._exit(0)


def capture_printing():
    """What the case prints (print, sys.stderr, a C library's output), kept in a
    temporary file (the sandbox's /tmp, a tmpfs of a stated size) in place of the standard
    output and error; its descriptor."""
    for stream in (
        sys.stdout,
        sys.stderr,
    ):  # what the module printed as it loaded is not this case's
        try:
            stream.flush()
        except Exception:
            pass
    try:
        kept, name = tempfile.mkstemp(prefix="printed-")
        os.unlink(name)
    except OSError:
        return None
    for fd in (1, 2):
        os.dup2(kept, fd)
    return kept


def printed_text(kept):
    """{"printed": the first MAX_PRINTED characters the case printed, "printed_cut"}."""
    if kept is None:
        return {}
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except Exception:
            pass
    try:
        os.lseek(kept, 0, os.SEEK_SET)
        data = os.read(kept, MAX_PRINTED + 1)
    except OSError:
        return {}
    text = data[:MAX_PRINTED].decode("utf-8", errors="replace")
    return {"printed": text, "printed_cut": len(data) > MAX_PRINTED} if text else {}


def run_in_child(request, chapter, limit):
    read_end, write_end = os.pipe()
    pid = os.fork()
    if pid == 0:
        os.close(read_end)
        for fd in (3, 4):
            os.close(fd)
        in_child(request, chapter, write_end)
    os.close(write_end)
    chunks, size, deadline = [], 0, time.monotonic() + limit
    timed_out = False
    while True:
        left = deadline - time.monotonic()
        if left <= 0:
            timed_out = True
            break
        ready, _, _ = select.select([read_end], [], [], left)
        if not ready:
            timed_out = True
            break
        chunk = os.read(read_end, 65536)
        if not chunk:
            break
        size += len(chunk)
        if size > MAX_ANSWER + 1024:
            break
        chunks.append(chunk)
    os.close(read_end)
    for target in (-pid, pid):  # the child, and anything it started
        try:
            os.kill(target, signal.SIGKILL)
        except OSError:
            pass
    _, status = os.waitpid(pid, 0)
    if timed_out:
        return {"timeout": True}
    try:
        answer = json.loads(b"".join(chunks))
    except ValueError:
        return {"ended": exit_text(status)}
    return answer if isinstance(answer, dict) else {"ended": exit_text(status)}


def exit_text(status):
    if os.WIFSIGNALED(status):
        return f"signal {os.WTERMSIG(status)}"
    return f"status {os.WEXITSTATUS(status) if os.WIFEXITED(status) else status}"


def main():
    if sys.argv[1:2] == [
        "--declared"
    ]:  # the file's own account, for the checker: nothing of it runs
        with open(sys.argv[2], encoding="utf-8", errors="replace") as source:
            print(json.dumps(declared_functions(source.read())))
        return
    requests = os.fdopen(3, "rb")
    answers = os.fdopen(4, "wb")

    def answer(message):
        answers.write((json.dumps(message) + "\n").encode())
        answers.flush()

    first = json.loads(requests.readline())["load"]
    module_path = os.path.abspath(first["module"])
    folder = os.path.dirname(module_path)
    sys.argv = [first["module"]]  # as if run alone: nothing of the checker's
    try:
        main_module = load(module_path, "your module")
        # The adapter's `import raytracer` is the chapter as loaded here, not a second copy.
        sys.modules.setdefault(main_module.__name__, main_module)
        own_adapter = load(first["adapter"], "your adapter") if first.get("adapter") else None
        adapter = adapted(own_adapter, main_module)
    except LoadError as error:
        answer({"load_error": str(error)})
        return
    chapter = Chapter(main_module, folder, adapter, first["names"], first["functions"])
    answer({"loaded": chapter.facts})
    for line in requests:
        request = json.loads(line)
        result = run_in_child(request, chapter, request["limit"])
        result["id"], result["nonce"] = request["id"], request["nonce"]
        answer(result)


if __name__ == "__main__":
    main()
