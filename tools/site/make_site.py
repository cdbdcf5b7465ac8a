#!/usr/bin/env python3
"""Writes the static site of scripts/site: every chapter's page, with its figures drawn
live by the chapter's C++ compiled to WebAssembly, its README, its source files and its
diff from the chapter it continues; an index that mirrors the README's chapter table.

Usage: make_site.py REPO WEB_BUILD PYODIDE OUT
  REPO       the project's folder
  WEB_BUILD  where the web preset put <chapter>.js (build-web/web)
  PYODIDE    npm's package pyodide, as scripts/site installs it
             (build-web/npm/node_modules/pyodide): its files go into vendor/pyodide.js
  OUT        the site's folder (out/site): made whole in a fresh folder beside it
             (out/.site-new-*), then put in its place; nothing else is written

The chapters with cases (tests/cases) get a "Your code" panel: an editor (Debian's
libjs-codemirror, copied from /usr/share/javascript/codemirror), the function checker's
core and the JavaScript runner bundled with esbuild (vendor/check.js, vendor/sources.js),
and Pyodide for Python.

The page's globals, each written once and only read elsewhere (the scripts load as
classic scripts or workers, so these names are how they meet):
  CGFS_SOURCES      vendor/sources.js, here: the workers' and runners' source texts;
                    read by code_runner.js and figures_client.js
  CGFS_CASES        vendor/cases.js, here: tests/cases/*.json; read by yourcode.js
  CGFS_DRAWINGS     vendor/cases.js, here: tools/site/drawings.json; read by yourcode.js
  CGFS_PYODIDE      vendor/pyodide.js, here: Pyodide's files; read (once, then
                    dropped) by code_runner.js
  CGFS_FIGURES_OF   <chapter>/figures-source.js, here: the chapter's WebAssembly module;
                    read by chapter.js, index.js and yourcode.js
  CGFS_MODELS       models/<name>.js, here: the models' files; read by models.js
  CGFS_CHECK        vendor/check.js, by check_entry.mjs (the checker's core, bundled
                    by esbuild); read by code_runner.js, editor_marks.js, yourcode.js
  CGFS_MODULE       the figures worker's first line, by figures_client.js; read by
                    figures_worker.js
  CGFS_PYODIDE_LOADER, CGFS_PYODIDE_ASM
                    inside the Python worker, by python_worker.js from CGFS_PYODIDE
                    (PYODIDE_SCRIPTS below); read there

Every page a README links to is made too (the docs, the golden images, the catalogues
of mistakes, ...), so links work inside the site; a link to a file the repository does
not have stops the build with one line. Exit status 0, or 1 with one line on stderr.
"""
import base64
import html
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
from pathlib import Path, PurePosixPath

SITE_FILES = Path(__file__).resolve().parent  # chapter.js, index.js, site.css
CHECKER = SITE_FILES.parent / "check-functions"
CODEMIRROR = Path("/usr/share/javascript/codemirror")
NODE_MODULES = "/usr/share/nodejs"  # Debian's acorn and acorn-globals, which esbuild bundles
# The files the site takes from Debian's CodeMirror 5 and from npm's Pyodide.
CODEMIRROR_FILES = [
    "lib/codemirror.js",
    "lib/codemirror.css",
    "mode/javascript/javascript.js",
    "mode/python/python.js",
]
# Pyodide's two ES modules become scripts (a page opened from a file may start a classic
# worker from a Blob, not a module worker), each under a global name.
PYODIDE_SCRIPTS = {
    "loader": ("pyodide.mjs", "CGFS_PYODIDE_LOADER"),
    "asm": ("pyodide.asm.mjs", "CGFS_PYODIDE_ASM"),
}
PYODIDE_BYTES = {"wasm": "pyodide.asm.wasm", "stdlib": "python_stdlib.zip"}
IMAGE_SUFFIXES = {".png", ".jpg", ".jpeg", ".svg"}
LARGEST_TEXT_FILE = 1 << 20  # a linked text file larger than this is not made a page


# The figure a chapter's page opens at, when not its first: the business card's first
# takes seconds; its one-sample version shows the same scene at once. The index's small
# pictures are these too.
OPENING_FIGURES = {"16-business-card": "business-card-1-sample"}


# The models the pages of the chapters that take --model offer (models.js): each a
# folder, the files of it the model is (its .obj first), and whose it is. The project's
# own test model is always there; two of the models Debian's assimp-testmodels installs
# (scripts/setup --deep) when they are on the machine.
ASSIMP_MODELS = "/usr/share/assimp/models/OBJ"
SITE_MODELS = {
    "house": (
        "tests/models",
        ["house.obj", "house.mtl", "house-bricks.ppm"],
        "this project's test model",
    ),
    "spider": (
        ASSIMP_MODELS,
        [
            "spider.obj",
            "spider.mtl",
            "SpiderTex.jpg",
            "drkwood2.jpg",
            "engineflare1.jpg",
            "wal67ar_small.jpg",
            "wal69ar_small.jpg",
        ],
        "assimp's test models",
    ),
    "WusonOBJ": (ASSIMP_MODELS, ["WusonOBJ.obj"], "assimp's test models"),
}


# The scripts of a chapter page's "Your code" panel, in order.
YOUR_CODE_SCRIPTS = [
    "vendor/codemirror/codemirror.js",
    "vendor/codemirror/javascript.js",
    "vendor/codemirror/python.js",
    "vendor/check.js",
    "vendor/cases.js",
    "code_runner.js",
    "compare_view.js",
    "editor_marks.js",
    "yourcode.js",
]


class SiteError(Exception):
    pass


def bundled(entry, *options):
    """An ES module and what it imports, as one script (esbuild, Debian's): the
    checker's core for the pages, the JavaScript runner's worker with acorn; with
    --bundle=false, one module alone made a script (Pyodide's)."""
    result = subprocess.run(
        ["esbuild", str(entry), "--bundle", "--format=iife", "--log-level=error", *options],
        capture_output=True,
        text=True,
        env={**os.environ, "NODE_PATH": NODE_MODULES},
    )
    if result.returncode != 0:
        raise SiteError(f"esbuild could not bundle {entry}: {result.stderr.strip()}")
    return result.stdout


class SiteFolder:
    """The site, written into a fresh folder beside OUT and put in OUT's place only once
    it is whole: a build that fails leaves the old site as it was. OUT must be a folder
    of its own (not a link), and every file goes inside it."""

    def __init__(self, out):
        self.out = Path(os.path.abspath(out))
        if self.out.is_symlink() or (self.out.exists() and not self.out.is_dir()):
            raise SiteError(
                f"{out} is not a folder of its own (a file, or a link); remove it or choose another"
            )
        self.out.parent.mkdir(parents=True, exist_ok=True)
        self.root = Path(tempfile.mkdtemp(dir=self.out.parent, prefix=f".{self.out.name}-new-"))

    def write(self, relative, data):
        target = Path(os.path.normpath(self.root / relative))
        if os.path.commonpath([self.root, target]) != str(self.root):
            raise SiteError(f"{relative} would be written outside the site")
        if target.exists():
            raise SiteError(f"two pages of the site would be {relative}")
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(data.encode() if isinstance(data, str) else data)

    def publish(self):
        old = None
        if self.out.exists():
            old = tempfile.mkdtemp(dir=self.out.parent, prefix=f".{self.out.name}-old-")
            os.replace(self.out, Path(old) / "site")
        os.chmod(self.root, 0o755)
        os.replace(self.root, self.out)
        if old:
            shutil.rmtree(old)

    def discard(self):
        shutil.rmtree(self.root, ignore_errors=True)


def png_size(path):
    """The width and height of a PNG file, from its header."""
    with open(path, "rb") as file:
        header = file.read(24)
    if len(header) < 24 or header[:8] != b"\x89PNG\r\n\x1a\n":
        raise SiteError(f"{path} is not a PNG file")
    return list(struct.unpack(">II", header[16:24]))


def slug(text):
    """A heading's anchor as GitHub makes it: lower case, punctuation dropped,
    spaces as dashes."""
    text = re.sub(r"<[^>]*>", "", html.unescape(text)).strip().lower()
    return re.sub(r"[^\w\- ]", "", text).replace(" ", "-")


def add_heading_ids(page):
    seen = {}

    def with_id(match):
        base = slug(match.group(2))
        count = seen.get(base, 0)
        seen[base] = count + 1
        anchor = base if count == 0 else f"{base}-{count}"
        return f'<h{match.group(1)} id="{anchor}">{match.group(2)}</h{match.group(1)}>'

    return re.sub(r"<h([1-6])>(.*?)</h\1>", with_id, page)


def relative_link(from_page, to_page):
    """The link from one site page to another (both relative to the site's root)."""
    start = PurePosixPath(from_page).parent
    return os.path.relpath(to_page, start.as_posix() if start.parts else ".")


class Site:
    def __init__(self, repo, web_build, pyodide, out):
        self.repo = Path(repo).resolve()
        self.web_build = Path(web_build)
        self.pyodide = Path(pyodide)
        self.cases = {
            p.stem: json.loads(p.read_text())
            for p in sorted((self.repo / "tests" / "cases").glob("*.json"))
        }
        self.controls = json.loads((SITE_FILES / "controls.json").read_text())["chapters"]
        # The chapters whose figures a reader's functions draw (yourcode.js's draw).
        self.drawn_by_readers = json.loads((SITE_FILES / "drawings.json").read_text())["figures"]
        self.folder = SiteFolder(out)
        self.chapters = sorted(
            p.name
            for p in (self.repo / "chapters").iterdir()
            if re.match(r"\d\d-", p.name) and p.is_dir()
        )
        self.pending = []  # repository paths linked to and not made yet
        self.made = {f"chapters/{chapter}/README.md" for chapter in self.chapters}  # or to be made
        # The site's models: those whose files are all on this machine.
        self.models = {
            name: about
            for name, (folder, files, about) in SITE_MODELS.items()
            if all((self.repo / folder / file).is_file() for file in files)
        }

    # Where a file of the repository is in the site.
    def site_path(self, repo_path):
        parts = PurePosixPath(repo_path).parts
        if repo_path == "README.md":
            return "readme.html"
        if len(parts) == 3 and parts[0] == "chapters" and parts[2] == "README.md":
            return f"{parts[1]}/index.html"
        if len(parts) == 3 and parts[0] == "chapters":
            return f"{parts[1]}/source/{parts[2]}.html"
        if (self.repo / repo_path).is_dir():
            return f"{repo_path}/index.html"
        suffix = PurePosixPath(repo_path).suffix
        if suffix in IMAGE_SUFFIXES:
            return repo_path
        if suffix == ".md":
            return repo_path[:-3] + ".html"
        return repo_path + ".html"

    def link(self, from_page, repo_path):
        """The site's link to a repository file from a page; the file is made later."""
        if repo_path not in self.made:
            self.made.add(repo_path)
            self.pending.append(repo_path)
        return relative_link(from_page, self.site_path(repo_path))

    def rewrite_links(self, page, markdown_path, site_page):
        """Points a rendered Markdown file's relative links and images into the site."""
        folder = PurePosixPath(markdown_path).parent

        def rewrite(match):
            attribute, target = match.group(1), html.unescape(match.group(2))
            if re.match(r"[a-z]+:", target) or target.startswith("#"):
                return match.group(0)
            path, _, anchor = target.partition("#")
            resolved = os.path.normpath((folder / path).as_posix())
            if resolved.startswith("..") or not (self.repo / resolved).exists():
                raise SiteError(
                    f"{markdown_path} links to {target}, which the repository does not have"
                )
            new = self.link(site_page, resolved) + (f"#{anchor}" if anchor else "")
            return f'{attribute}="{html.escape(new)}"'

        return re.sub(r'(href|src)="([^"]*)"', rewrite, page)

    def markdown(self, repo_path, site_page):
        text = (self.repo / repo_path).read_text()
        rendered = subprocess.run(
            ["cmark-gfm", "-e", "table", "-e", "autolink", "-e", "strikethrough"],
            input=text,
            capture_output=True,
            text=True,
            check=True,
        ).stdout
        return self.rewrite_links(add_heading_ids(rendered), repo_path, site_page)

    def page(self, site_page, title, body, scripts=(), styles=()):
        css = relative_link(site_page, "site.css")
        more_css = "".join(
            f'<link rel="stylesheet" href="{relative_link(site_page, s)}">\n' for s in styles
        )
        home = relative_link(site_page, "index.html")
        tags = "".join(f'<script src="{relative_link(site_page, s)}"></script>\n' for s in scripts)
        self.folder.write(
            site_page,
            f"""<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{html.escape(title)}</title>
<link rel="stylesheet" href="{css}">
{more_css}<link rel="icon" href="data:,">
</head>
<body>
<header><a href="{home}">Computer Graphics from Scratch — a C++ companion</a></header>
{body}
{tags}</body>
</html>
""",
        )

    # The pages.
    def chapter_page(self, chapter):
        readme = f"chapters/{chapter}/README.md"
        site_page = f"{chapter}/index.html"
        article = self.markdown(readme, site_page)
        title = re.search(r"<h1[^>]*>(.*?)</h1>", article)
        title = re.sub(r"<[^>]*>", "", title.group(1)) if title else chapter
        sizes = self.figure_sizes(chapter)
        index = self.chapters.index(chapter)
        around = []
        if index > 0:
            around.append(
                f'<a href="../{self.chapters[index - 1]}/index.html">← {self.chapters[index - 1]}</a>'
            )
        if index + 1 < len(self.chapters):
            around.append(
                f'<a href="../{self.chapters[index + 1]}/index.html">{self.chapters[index + 1]} →</a>'
            )
        base = self.diff_base(chapter)
        code = [f'<a href="source/index.html">its source files</a>']
        code.append(
            f'<a href="diff.html">its diff from {base}</a>'
            if base
            else "no diff: it starts afresh, every file is new"
        )
        opening = OPENING_FIGURES.get(chapter, "")
        body = f"""<nav>{" · ".join(around)} · {" · ".join(code)}</nav>
<main class="chapter">
<section id="live" data-chapter="{chapter}" data-module="Chapter{chapter[:2]}" data-sizes='{json.dumps(sizes)}' data-opening="{opening}">
<p id="figures-count" hidden></p>
<div id="figure-lists">
<div id="figures" role="radiogroup" aria-label="figures"></div>
<div id="cost-views-group" hidden><span>where the work goes:</span>
<div id="cost-views" role="radiogroup" aria-label="where the work goes"></div></div>
</div>
<p id="caption"></p>
<p id="status">Loading the chapter's code…</p>
<p id="problem" hidden></p>
<canvas id="canvas" width="600" height="600"></canvas>
<p><button id="cost" type="button" hidden title="where the work goes, pixel by pixel"></button></p>
{self.controls_box(chapter)}
{self.model_picker(chapter)}
<div id="camera" hidden>
<p>The view: <code id="view"></code> · <a id="view-link" href="">a link to this view</a>
· <button id="reset" type="button">back to the chapter's view (R)</button></p>
<div id="camera-pad" aria-label="move the camera">
<button type="button" data-key="6" title="turn left (Q)">⟲</button><button type="button" data-key="0" title="forward (↑)">▲</button><button type="button" data-key="7" title="turn right (E)">⟳</button><button type="button" data-key="8" title="look up (Home)">⤒</button><button type="button" data-key="4" title="up (PgUp)">⇞</button>
<button type="button" data-key="3" title="left (A)">◀</button><button type="button" data-key="1" title="back (↓)">▼</button><button type="button" data-key="2" title="right (D)">▶</button><button type="button" data-key="9" title="look down (End)">⤓</button><button type="button" data-key="5" title="down (PgDn)">⇟</button>
<button type="button" id="camera-reset" title="back to the chapter's view (R)">R</button>
</div>
<p class="keys"><kbd>↑</kbd> <kbd>↓</kbd> forward, back · <kbd>A</kbd> <kbd>D</kbd> left, right ·
<kbd>PgUp</kbd> <kbd>PgDn</kbd> up, down · <kbd>Q</kbd> <kbd>E</kbd> turn · <kbd>Home</kbd> <kbd>End</kbd>
look up, down · drag the picture to turn and look · <kbd>←</kbd> <kbd>→</kbd> figures.
While the camera moves, frames are drawn at half size; the full one follows when it stops.
<code>--view</code> with the view above draws this frame natively; rarely, one byte of it
differs by one, since this build's C library and Linux's round the last bit of sin and
cos apart for a few angles in a hundred.</p>
</div>
<p class="note">Drawn in your browser by this chapter's C++, compiled to WebAssembly,
on one thread beside the page's: the native programs of chapters 5, 16 and 17 use every
core, here their <code>all</code> optimisations use one worker. Every figure is the same,
byte for byte, as the native program's golden image.</p>
</section>
<div id="side">
<div id="tabs" role="tablist">
<button type="button" role="tab" id="tab-readme" aria-selected="true" aria-controls="readme">The chapter</button>
<button type="button" role="tab" id="tab-code" aria-selected="false" aria-controls="your-code">Your code</button>
</div>
<article class="readme" id="readme" role="tabpanel">
{article}
</article>
{self.your_code_panel(chapter, title)}
</div>
</main>"""
        self.folder.write(
            f"{chapter}/figures-source.js",
            "var CGFS_FIGURES_OF = self.CGFS_FIGURES_OF || {};\n"
            f"CGFS_FIGURES_OF[{json.dumps(chapter)}] = {json.dumps((self.web_build / f'{chapter}.js').read_text())};\n",
        )
        has_code = chapter in self.cases
        self.page(
            site_page,
            f"{chapter} — {title}",
            body,
            [
                f"{chapter}/figures-source.js",
                "vendor/sources.js",
                "figures_client.js",
                *(["models.js"] if self.takes_models(chapter) else []),
                "chapter.js",
                *(YOUR_CODE_SCRIPTS if has_code else []),
            ],
            ["vendor/codemirror/codemirror.css"] if has_code else [],
        )

    def controls_box(self, chapter):
        """The chapter's parameters as controls (controls.json; chapter.js's Controls), each
        value one of its figures; with a box to draw the reader's own beside ours, where
        the "Your code" panel draws that chapter's figures."""
        if chapter not in self.controls:
            return ""
        mine = (
            (
                '<p class="note"><label><input type="checkbox" id="controls-mine"> draw it with my code too '
                '(the Your code tab\'s functions)</label></p>\n<div id="controls-yours" hidden><canvas></canvas>'
                "<p></p></div>"
            )
            if chapter in self.drawn_by_readers
            else ""
        )
        return f"""<div id="controls" data-controls='{html.escape(json.dumps(self.controls[chapter]), quote=True)}'>
<p class="controls-title">The chapter's idea, by hand: each value is one of its figures.</p>
{mine}
</div>"""

    def takes_models(self, chapter):
        """Whether the chapter's program takes --model (its options.cpp declares it, with
        program/arguments.h's AddModelOption)."""
        options = self.repo / "chapters" / chapter / "options.cpp"
        return options.is_file() and "cgfs::AddModelOption(" in options.read_text()

    def model_picker(self, chapter):
        """The picker of models.js, on the page of a chapter that takes --model."""
        if not self.takes_models(chapter):
            return ""
        choices = "".join(
            f'<option value="{html.escape(name)}">{html.escape(name)} ({html.escape(about)})</option>'
            for name, about in self.models.items()
        )
        return f"""<div id="model">
<p><label>A model: <select id="model-choice"><option value="">none: the chapter's figures</option>{choices}</select></label>
· <label>your own: <input type="file" id="model-files" multiple accept=".obj,.mtl,.png,.jpg,.jpeg,.ppm"></label></p>
<pre id="model-said" hidden></pre>
<p class="note">A Wavefront OBJ file, chosen with its .mtl and texture files at once (they are
put in one folder), is read as <code>--model FILE.obj</code> reads it, by the same reader
compiled with the chapter's code, and drawn by the chapter's code; what the program would
print (a warning, or the one line that says why not) is shown above. PNG and JPEG textures
are decoded by the browser, the rest as the program does.</p>
</div>"""

    def model_scripts(self):
        """Each site model's files as a script (models/NAME.js; models.js loads it)."""
        for name in self.models:
            folder, files, _ = SITE_MODELS[name]
            encoded = {
                file: base64.b64encode((self.repo / folder / file).read_bytes()).decode()
                for file in files
            }
            self.folder.write(
                f"models/{name}.js",
                "var CGFS_MODELS = self.CGFS_MODELS || {};\n"
                f"CGFS_MODELS[{json.dumps(name)}] = {json.dumps({'open': files[0], 'files': encoded})};\n",
            )

    def your_code_panel(self, chapter, title):
        """The "Your code" tab (yourcode.js), for a chapter with cases."""
        if chapter not in self.cases:
            return ""
        return f"""<section id="your-code" role="tabpanel" hidden data-title="{html.escape(title)}">
<div id="code-panel">
<p class="code-intro">Write this chapter's functions yourself, in JavaScript or Python, under the book's names.
<b>Check</b> (<kbd>Ctrl</kbd>+<kbd>Enter</kbd>) runs the chapter's cases on them, with the messages of the command line's checker
(<a href="{self.link(f"{chapter}/index.html", "docs/students.md")}#3-on-the-chapters-page">docs/students.md</a>);
<b>Draw</b> draws a figure with them beside ours. Your code runs in this browser, in a worker of its own, and is
kept here, for this chapter and language: nothing is sent anywhere.</p>
<div class="code-bar">
<select id="code-language" aria-label="the language you write in"><option value="javascript">JavaScript</option><option value="python">Python</option></select>
<button type="button" id="code-check" title="every case of the chapter (Ctrl+Enter)">Check</button>
<button type="button" id="code-check-one" disabled>Check one function</button>
<span id="code-draw-group"><select id="code-figure" aria-label="the figure to draw"></select> <button type="button" id="code-draw">Draw</button></span>
<button type="button" id="code-stop" hidden>Stop</button>
<label id="code-auto-label" title="JavaScript: a check a second after you stop typing"><input type="checkbox" id="code-auto"> check as I type</label>
</div>
<div class="code-bar code-file-bar"><code id="code-file"></code>
<button type="button" id="code-download">Download</button>
<button type="button" id="code-link-button" title="a link that carries your code in itself">Link</button>
<button type="button" id="code-open-button">Open…</button><input type="file" id="code-open" accept=".js,.mjs,.cjs,.py" hidden>
<button type="button" id="code-start-over">Start over</button>
<input type="text" id="code-link" readonly hidden aria-label="a link with your code"></div>
<p id="code-no-drawing" class="note" hidden>No figure of this chapter is drawn by its checked functions alone:
its figures take the whole pipeline (RenderScene and the rest), which the cases do not cover.</p>
<textarea id="code-editor" aria-label="your code"></textarea>
<p id="code-status" role="status"></p>
<progress id="code-python-start" max="1" value="0" hidden aria-label="Python starting"></progress>
<canvas id="code-preview" hidden title="your figure at a quarter of its resolution, while the full one is drawn"></canvas>
<pre id="code-report"></pre>
<div id="code-drawing" hidden>
<p id="code-teach"></p>
<div class="code-bar" role="radiogroup" aria-label="how to compare">
<label><input type="radio" name="code-view" value="three" checked> ours, yours and the difference</label>
<label><input type="radio" name="code-view" value="one"> one picture, a slider between them</label>
</div>
<div class="code-pictures" id="code-three">
<figure><canvas id="code-ours"></canvas><figcaption>ours</figcaption></figure>
<figure><canvas id="code-yours"></canvas><figcaption>yours</figcaption></figure>
<figure><canvas id="code-difference"></canvas><figcaption>the difference</figcaption></figure>
</div>
<div id="code-one" hidden>
<canvas id="code-overlay"></canvas>
<p class="code-bar"><label>yours <input type="range" id="code-wipe" min="0" max="100" value="50"
aria-label="where yours ends and ours begins"> ours</label>
<label><input type="checkbox" id="code-blink"> blink</label> <span id="code-one-says"></span></p>
</div>
<ul id="code-legend" aria-label="the difference's colours"></ul>
<div id="code-zoom">
<p id="code-zoom-where"></p>
<div class="code-zoom-pictures">
<figure><canvas id="code-zoom-ours"></canvas><figcaption>ours</figcaption></figure>
<figure><canvas id="code-zoom-yours"></canvas><figcaption>yours</figcaption></figure>
<figure><canvas id="code-zoom-difference"></canvas><figcaption>the difference</figcaption></figure>
</div>
</div>
<pre id="code-comparison"></pre>
</div>
</div>
</section>"""

    def figure_sizes(self, chapter):
        """Each figure's size: its golden image's, which the native program draws at."""
        golden = self.repo / "tests" / "golden" / chapter
        return {p.stem: png_size(p) for p in sorted(golden.glob("*.png"))}

    def diff_base(self, chapter):
        """The chapter this one continues, as its README's `diff -ruN` line says."""
        text = (self.repo / "chapters" / chapter / "README.md").read_text()
        found = re.search(rf"diff -ruN chapters/(\S+) chapters/{re.escape(chapter)}\b", text)
        return found.group(1) if found else None

    def diff_page(self, chapter, base):
        result = subprocess.run(
            ["diff", "-ruN", f"chapters/{base}", f"chapters/{chapter}"],
            cwd=self.repo,
            capture_output=True,
            text=True,
        )
        if result.returncode not in (0, 1):
            raise SiteError(f"diff of {base} and {chapter} failed: {result.stderr.strip()}")
        lines = []
        for line in result.stdout.splitlines():
            if line.startswith(("--- ", "+++ ")):
                line = line.split("\t")[0]  # without the files' times, which say nothing here
            kind = (
                "file"
                if line.startswith(("diff ", "--- ", "+++ "))
                else "hunk"
                if line.startswith("@@")
                else "added"
                if line.startswith("+")
                else "removed"
                if line.startswith("-")
                else "same"
            )
            lines.append(f'<span class="{kind}">{html.escape(line)}</span>')
        added = sum(
            1 for l in result.stdout.splitlines() if l.startswith("+") and not l.startswith("+++")
        )
        removed = sum(
            1 for l in result.stdout.splitlines() if l.startswith("-") and not l.startswith("---")
        )
        body = f"""<nav><a href="index.html">{chapter}</a>, this chapter · <a href="../{base}/index.html">{base}</a>,
the chapter it continues · <a href="source/index.html">its source files</a></nav>
<main class="text">
<h1>From {base} to {chapter}</h1>
<p>What the chapter changes: <code>diff -ruN chapters/{base} chapters/{chapter}</code>,
{added} lines added and {removed} removed.</p>
<pre class="diff">{"".join(lines)}</pre>
</main>"""
        self.page(f"{chapter}/diff.html", f"{chapter}: its diff from {base}", body)

    def sources_page(self, chapter):
        files = sorted(
            p.name
            for p in (self.repo / "chapters" / chapter).iterdir()
            if p.is_file() and p.name != "README.md"
        )
        rows = []
        for name in files:
            link = self.link(f"{chapter}/source/index.html", f"chapters/{chapter}/{name}")
            count = len((self.repo / "chapters" / chapter / name).read_text().splitlines())
            rows.append(
                f'<tr><td><a href="{link}"><code>{name}</code></a></td><td>{count}</td></tr>'
            )
        body = f"""<nav><a href="../index.html">{chapter}</a></nav>
<main class="text">
<h1>{chapter}: its files</h1>
<table><thead><tr><th>file</th><th>lines</th></tr></thead><tbody>
{chr(10).join(rows)}
</tbody></table>
</main>"""
        self.page(f"{chapter}/source/index.html", f"{chapter}: its files", body)

    def text_page(self, repo_path):
        site_page = self.site_path(repo_path)
        data = (self.repo / repo_path).read_bytes()
        if len(data) > LARGEST_TEXT_FILE:
            raise SiteError(f"{repo_path} is linked to and larger than {LARGEST_TEXT_FILE} bytes")
        try:
            text = data.decode()
        except UnicodeDecodeError:
            raise SiteError(f"{repo_path} is linked to and is not text") from None
        numbered = "".join(
            f'<span id="L{n}">{html.escape(line)}</span>'
            for n, line in enumerate(text.splitlines(), 1)
        )
        parts = PurePosixPath(repo_path).parts
        nav = (
            f'<nav><a href="../index.html">{parts[1]}</a> · <a href="index.html">its files</a></nav>\n'
            if parts[0] == "chapters"
            else ""
        )
        body = f"""{nav}<main class="text">
<h1><code>{html.escape(repo_path)}</code></h1>
<pre class="source">{numbered}</pre>
</main>"""
        self.page(site_page, repo_path, body)

    def folder_page(self, repo_path):
        site_page = self.site_path(repo_path)
        items = []
        for entry in sorted((self.repo / repo_path).iterdir()):
            if entry.is_file() and entry.stat().st_size <= LARGEST_TEXT_FILE:
                link = self.link(site_page, f"{repo_path}/{entry.name}")
                items.append(f'<li><a href="{link}"><code>{entry.name}</code></a></li>')
        body = f"""<main class="text">
<h1><code>{html.escape(repo_path)}/</code></h1>
<ul>{"".join(items)}</ul>
</main>"""
        self.page(site_page, repo_path, body)

    def linked_file(self, repo_path):
        site_page = self.site_path(repo_path)
        if (self.repo / repo_path).is_dir():
            self.folder_page(repo_path)
        elif PurePosixPath(repo_path).suffix in IMAGE_SUFFIXES:
            self.folder.write(site_page, (self.repo / repo_path).read_bytes())
        elif repo_path.endswith(".md"):
            article = self.markdown(repo_path, site_page)
            self.page(site_page, repo_path, f'<main class="text readme">\n{article}\n</main>')
        else:
            self.text_page(repo_path)

    def index_page(self, speed_table):
        readme = (self.repo / "README.md").read_text()
        table = re.search(r"^\| chapter \| book \|.*?\n(?=\n)", readme, re.S | re.M)
        if not table:
            raise SiteError("README.md has no chapter table (a row starting '| chapter | book |')")
        rows = table.group(0).splitlines()
        rows[0] = "| live | " + rows[0][2:]
        rows[1] = "|---|" + rows[1][1:]
        for i in range(2, len(rows)):
            name = re.search(r"\[`(\d\d-[a-z-]+)`\]", rows[i]).group(1)
            rows[i] = f"| `thumbnail:{name}` | " + rows[i][2:]
        self.link("index.html", "README.md")
        rendered = subprocess.run(
            ["cmark-gfm", "-e", "table"],
            input="\n".join(rows) + "\n",
            capture_output=True,
            text=True,
            check=True,
        ).stdout
        rendered = self.rewrite_links(rendered, "README.md", "index.html")
        rendered = re.sub(
            r"<code>thumbnail:((\d\d)-[a-z-]+)</code>",
            lambda m: f'<a href="{m.group(1)}/index.html"><canvas class="thumbnail" '
            f'data-chapter="{m.group(1)}" data-module="Chapter{m.group(2)}" '
            f"data-sizes='{json.dumps(self.figure_sizes(m.group(1)))}' "
            f'data-opening="{OPENING_FIGURES.get(m.group(1), "")}" '
            f'width="150" height="150"></canvas></a>',
            rendered,
        )
        speed = self.markdown_text(speed_table, "index.html") if speed_table else ""
        body = f"""<main class="text index">
<h1>The chapters, live</h1>
<p>Every chapter of the companion as its own page: its figures drawn in your browser by
the chapter's C++ compiled to WebAssembly (the small pictures below are drawn that way
as this page loads), its README, its source files and its diff from the chapter it
continues. The project's own <a href="readme.html">README</a> says how to build the
programs, run the tests and compare your own images with these.</p>
<div class="chapters">
{rendered}
</div>
{speed}
</main>"""
        self.page(
            "index.html",
            "Computer Graphics from Scratch — a C++ companion",
            body,
            [f"{c}/figures-source.js" for c in self.chapters]
            + ["vendor/sources.js", "figures_client.js", "index.js"],
        )

    def markdown_text(self, path, site_page):
        return self.markdown(os.path.relpath(path, self.repo), site_page)

    def vendor_sources(self):
        """vendor/sources.js: the text of every worker's own code, for the pages to make
        their workers from (a page opened from a file may start a worker from a Blob,
        not from a file): the figures', and the reader's code's in JavaScript (bundled
        with acorn) and Python (with the checker's runner)."""
        sources = {
            "figuresWorker": (SITE_FILES / "figures_worker.js").read_text(),
            "jsWorker": bundled(CHECKER / "runners" / "js_worker.mjs"),
            "pythonWorker": (SITE_FILES / "python_worker.js").read_text(),
            "pythonRunner": (CHECKER / "runners" / "python_runner.py").read_text(),
        }
        self.folder.write("vendor/sources.js", f"var CGFS_SOURCES = {json.dumps(sources)};\n")

    def vendor_your_code(self):
        """What the "Your code" panels share: the checker's core (vendor/check.js), the
        cases and the figures drawn with a reader's functions (vendor/cases.js),
        CodeMirror, and Pyodide's files (vendor/pyodide.js, loaded when Python is)."""
        self.folder.write("vendor/check.js", bundled(SITE_FILES / "check_entry.mjs"))
        drawings = json.loads((SITE_FILES / "drawings.json").read_text())["figures"]
        self.folder.write(
            "vendor/cases.js",
            f"var CGFS_CASES = {json.dumps(self.cases)};\n"
            f"var CGFS_DRAWINGS = {json.dumps(drawings)};\n",
        )
        for name in CODEMIRROR_FILES:
            source = CODEMIRROR / name
            if not source.is_file():
                raise SiteError(
                    f"no {source}: install the Debian package libjs-codemirror (scripts/setup --site)"
                )
            self.folder.write(f"vendor/codemirror/{Path(name).name}", source.read_bytes())
        if not (self.pyodide / "package.json").is_file():
            raise SiteError(
                f"no {self.pyodide}/package.json: npm's pyodide is not installed there (scripts/site installs it)"
            )
        assets = {"lock": (self.pyodide / "pyodide-lock.json").read_text()}
        for key, (name, global_name) in PYODIDE_SCRIPTS.items():
            assets[key] = bundled(
                self.pyodide / name,
                "--bundle=false",
                f"--global-name={global_name}",
                f'--define:import.meta.url="https://pyodide.invalid/{name}"',
            )
        for key, name in PYODIDE_BYTES.items():
            assets[key] = base64.b64encode((self.pyodide / name).read_bytes()).decode()
        self.folder.write("vendor/pyodide.js", f"var CGFS_PYODIDE = {json.dumps(assets)};\n")

    def build(self):
        own_scripts = [name for name in YOUR_CODE_SCRIPTS if not name.startswith("vendor/")]
        for name in (
            "chapter.js",
            "index.js",
            "figures_client.js",
            "models.js",
            "site.css",
            *own_scripts,
        ):
            self.folder.write(name, (SITE_FILES / name).read_bytes())
        self.model_scripts()
        self.vendor_sources()
        self.vendor_your_code()
        for chapter in self.chapters:
            if not (self.web_build / f"{chapter}.js").is_file():
                raise SiteError(f"no {self.web_build}/{chapter}.js: build the web preset first")
            self.chapter_page(chapter)
            self.sources_page(chapter)
            base = self.diff_base(chapter)
            if base:
                self.diff_page(chapter, base)
        self.index_page(SITE_FILES / "speed.md" if (SITE_FILES / "speed.md").exists() else None)
        while self.pending:
            self.linked_file(self.pending.pop())
        return len(self.chapters)


def main():
    if len(sys.argv) != 5:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        return 2
    site = None
    try:
        site = Site(*sys.argv[1:])
        count = site.build()
        site.folder.publish()
    except (SiteError, OSError, subprocess.CalledProcessError) as error:
        print(f"make_site: {error}", file=sys.stderr)
        if site:
            site.folder.discard()
        return 1
    print(f"wrote {count} chapter pages and their files to {sys.argv[4]}/index.html")
    return 0


if __name__ == "__main__":
    sys.exit(main())
