#!/usr/bin/env python3
"""Draws a figure with a Python chapter in this machine's CPython, as the chapter page's
Python (Pyodide, in a Web Worker) draws it: the checker's runner
(tools/check-functions/runners/python_runner.py) loads the chapter and draws the
figure's recipe (tools/site/drawings.json). Prints the seconds the draw took, for
tests/site/python_speed.mjs to set beside the page's.

Usage: cpython_draw.py REPO CHAPTER FIGURE CHAPTER_FILE"""

import json
import os
import shutil
import sys
import tempfile
import time


def main():
    repo, chapter, figure, source = sys.argv[1:5]
    sys.path.insert(0, os.path.join(repo, "tools", "check-functions", "runners"))
    import python_runner as runner

    cases = json.load(open(os.path.join(repo, "tests", "cases", f"{chapter}.json")))
    kinds = {entry["function"]: entry["parameters"] for entry in cases["functions"]}
    names = json.loads(sys.stdin.read())  # the checker's NAMES (core/names.mjs)
    recipe = json.load(open(os.path.join(repo, "tools", "site", "drawings.json")))
    recipe = recipe["figures"][chapter][figure]
    folder = tempfile.mkdtemp(prefix="cgfs-cpython-draw-")
    try:
        path = os.path.join(folder, os.path.basename(source))
        shutil.copy(source, path)
        os.chdir(folder)
        sys.argv = [os.path.basename(path)]
        module = runner.load(path, "your code")
        loaded = runner.Chapter(module, folder, runner.adapted(None, module), names, list(kinds))
        start = time.perf_counter()
        runner.draw_figure(recipe, loaded, kinds, preview=lambda pixels: None)
        print(f"{time.perf_counter() - start:.3f}")
    finally:
        shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    main()
