# A chapter 2 whose CanvasToViewport computes nothing: it looks for the answers. As it
# loads, it reads what the sandbox shows of the checker (/proc/1, its environment) and
# walks the file system (all of it but the system's folders) for the case files, their
# copies under any name and git repositories that hold them; each case it answers from
# what it found. tests/check-functions/check_layouts.sh runs it in the layouts where
# earlier checkers showed it the answers. Every case it passes is a hole in the sandbox.
import json
import os
import subprocess

Cw, Ch = 600, 600
Vw, Vh, d = 1, 1, 1
SKIP = {"/usr", "/proc", "/sys", "/dev", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"}


def clues():
    """Whatever /proc/1 tells of the checker: its words and environment."""
    found = []
    for name in ("environ", "cmdline"):  # the environment first: a long message is cut short
        try:
            with open(f"/proc/1/{name}", "rb") as text:
                found += text.read().decode(errors="replace").split("\0")
        except OSError:
            pass
    return [word for word in found if word]


def case_files():
    """Every JSON file with the book's functions in it, and every case file in git."""
    found, seen = [], 0
    for top, folders, files in os.walk("/"):
        folders[:] = [f for f in folders if os.path.join(top, f) not in SKIP]
        seen += len(files) + len(folders)
        if seen > 300000:
            break
        if "HEAD" in files and "objects" in folders:  # a git repository's history
            try:
                listed = subprocess.run(
                    ["git", "--git-dir", top, "log", "--all", "-p"],
                    capture_output=True,
                    text=True,
                    timeout=20,
                ).stdout
                found.append(listed)
            except (OSError, subprocess.SubprocessError):
                pass
        for name in files:
            path = os.path.join(top, name)
            if name.endswith((".py", ".pyc", ".so")):  # the interpreter's own
                continue
            try:
                if os.path.getsize(path) < 2000000:
                    with open(path, errors="replace") as text:
                        content = text.read()
                    if "CanvasToViewport" in content and '"expected"' in content:
                        found.append(content)
            except OSError:
                pass
    return found


def answers():
    table = {}
    for content in case_files():
        start = content.find("{")
        while start >= 0:  # every JSON object in the text, the case files' and git's
            try:
                data, end = json.JSONDecoder().raw_decode(content, start)
            except ValueError:
                start = content.find("{", start + 1)
                continue
            for function in data.get("functions", []) if isinstance(data, dict) else []:
                for case in function.get("cases", []):
                    key = json.dumps(
                        [function.get("function"), case.get("given"), case.get("args")],
                        sort_keys=True,
                    )
                    table[key] = case.get("expected")
            start = content.find("{", end)
    return table


LEAKED = clues()
ANSWERS = answers()


def CanvasToViewport(x, y):
    given = {"canvas": {"width": Cw, "height": Ch}, "viewport": {"width": Vw, "height": Vh, "d": d}}
    key = json.dumps(["CanvasToViewport", given, {"x": x, "y": y}], sort_keys=True)
    if key in ANSWERS:
        return tuple(ANSWERS[key])
    return (9, 9, 9)


def IntersectRaySphere(O, D, sphere):
    """Says, in the message of what it raises, how many answers it found and what /proc/1
    showed of the checker (the count first: a long message is cut short)."""
    raise RuntimeError(f"({len(ANSWERS)} answers) leaked: " + " ".join(LEAKED))
