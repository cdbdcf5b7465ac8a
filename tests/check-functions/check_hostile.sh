#!/usr/bin/env bash
# The function checker against student code that fights it (docs/students.md, "Where your
# code runs"): every way below, from inside the student's process, to pass a case it
# fails, to read or change the case files or the checker, to stop, outlive or flood the
# checker, ends in failed cases and exit status 1, within the time the run may take, with
# no process of the student's left behind and nothing written outside its sandbox. In
# both languages, with the sandbox (bubblewrap); skipped without it. With --deep, also
# the slow ones: a run that hits its bound and says so.
# Usage: check_hostile.sh SOURCE_DIR WORK_DIR [--deep]
set -euo pipefail
source_dir=$1 work=$2 deep=${3:-}
rm -rf "$work"
mkdir -p "$work"
# shellcheck source=tests/check-functions/checks.sh
source "$(dirname "${BASH_SOURCE[0]}")/checks.sh"
checker=$source_dir/tools/check-functions/check-functions.js
reference=$source_dir/tools/check-functions/reference
marker=cgfs-hostile-$$
if ! command -v node >/dev/null || ! bwrap --ro-bind / / --unshare-all true 2>/dev/null; then
  echo "SKIPPED: no node or no bubblewrap sandbox here (CI installs both: scripts/setup)"
  exit 0
fi
# The case files and the checker's code, to see that nothing changed them.
fingerprint() { find "$source_dir/tests/cases" "$source_dir/tools/check-functions" -type f -exec md5sum {} + | sort; }
before=$(fingerprint)
# RUN... a check, timed; its output in out.txt, status in $status, seconds in $took.
run() {
  local start=$SECONDS
  status=0
  node "$checker" "$@" >"$work/out.txt" 2>&1 || status=$?
  took=$((SECONDS - start))
  sed 's/^/    /' "$work/out.txt" | cut -c1-200
}
# Chapter 02's cases, for the bound a run may take (checks.sh's promised).
cases=$(node -e 'const f = require(process.argv[1]); console.log(f.functions.reduce((n, e) => n + e.cases.length, 0))' \
  "$source_dir/tests/cases/02-basic-rays.json")
fails_within() {  # WHAT SECONDS: exit 1, and took at most SECONDS
  check "$1: exit status 1" test $status -eq 1
  check "$1: within $2 s (took $took)" test $took -le "$2"
  check "$1: no traceback of the checker's" bash -c '! grep -qE "^(Traceback|    at |node:internal)" "$1"' _ "$work/out.txt"
}

python=$(command -v python3 || true)
if [ -n "$python" ]; then
  base=$reference/python/basic_rays.py
  # Its CanvasToViewport is wrong, and it reaches into the process it runs in.
  { cat "$base"; cat <<EOF

import json, os, sys
main = sys.modules.get("__main__")
for name in ("run_case", "encoded", "plain", "run_in_child", "one_line"):
    if hasattr(main, name):
        setattr(main, name, lambda *a, **k: {"returned": [0.5, -0.25, 1], "placed": []})
json.dumps = lambda *a, **k: '{"returned": [0.5, -0.25, 1]}'
sys.modules["json"] = json


def CanvasToViewport(x, y):
    return (9, 9, 9)
EOF
  } >"$work/patches.py"
  # It forges the process's account of itself and a pile of answers at import.
  { cat <<'EOF'
import json, os
os.write(4, (json.dumps({"loaded": {"functions": {}, "data": {}, "defined": [], "reachable": "all"}}) + "\n").encode())
for i in range(1, 40):
    os.write(4, (json.dumps({"id": i, "nonce": "x", "returned": [0, 0, 1], "raised": {"not": "a string"}}) + "\n").encode())
EOF
    cat "$base"; printf '\n\ndef CanvasToViewport(x, y):\n    return (9, 9, 9)\n'; } >"$work/forges.py"
  # It stops itself, stops the process above it, kills it and spins, leaves a grandchild.
  { cat "$base"; cat <<EOF

import os, signal, subprocess


def CanvasToViewport(x, y):
    if x == 300 and y == -150:
        os.kill(os.getpid(), signal.SIGSTOP)
    if x == 0:
        os.kill(os.getppid(), signal.SIGSTOP)
    if x == -300:
        subprocess.Popen(["python3", "-c", "while True: pass", "$marker"], start_new_session=True)
        os.kill(os.getppid(), signal.SIGKILL)
        while True:
            pass
    if y == -200:
        os.kill(1, signal.SIGINT)
        os.kill(os.getppid(), signal.SIGINT)
    return (9, 9, 9)
EOF
  } >"$work/signals.py"
  # It writes into every file it can find: the case files, the checker, terminals, its
  # own folder; and a memory bomb.
  { cat "$base"; cat <<EOF

import glob, os


def CanvasToViewport(x, y):
    for pattern in ("$source_dir/tests/cases/*.json", "$source_dir/tools/check-functions/*/*", "/proc/*/fd/[12]",
                    "/dev/tty", "$work/*", "../*"):
        for path in glob.glob(pattern):
            try:
                with open(path, "a") as out:
                    out.write("FAIL: forged by the student\n")
            except OSError:
                pass
    if x == 0:
        bytearray(10 ** 11)
    return (9, 9, 9)
EOF
  } >"$work/escapes.py"
  # It takes 3 s to load, and every CanvasToViewport case loops for ever.
  { echo "import time; time.sleep(3)"; cat "$base"; printf '\n\ndef CanvasToViewport(x, y):\n    while True:\n        pass\n'; } >"$work/slow.py"

  echo "== Python: routes to a pass, and routes out"
  run 02 "$work/patches.py" --time-limit 1
  fails_within "patching the runner, json and sys.modules" "$(promised "$cases" 1)"
  run 02 "$work/forges.py" --time-limit 1
  fails_within "forging the process's account and answers at import" "$(promised "$cases" 1)"
  check "the functions it hid are named as hidden" says "your file defines CanvasToViewport, but the process it ran in said it does not"
  run 02 "$work/signals.py" --time-limit 1
  fails_within "SIGSTOP to itself and to the process above, SIGKILL and a spin, SIGINT" "$(promised "$cases" 1)"
  check "the case that stopped itself failed on its time limit" says "did not return within 1 s"
  check "the others are still judged" says "^  TraceRay +passed \(9 cases\)"
  run 02 "$work/escapes.py" --time-limit 1
  fails_within "writing to the case files, the checker, terminals; a memory bomb" "$(promised "$cases" 1)"
  check "the memory bomb ended in its case" says "raised MemoryError"
  check "no line of the report is the student's but those marked as what it printed" \
    bash -c '! grep -v "^      | " "$1" | grep -q "forged by the student"' _ "$work/out.txt"
  run 02 "$work/slow.py" --time-limit 0.5
  # Loaded once: 3 s and six cases of 0.5 s (with five cases it took 6 s quiet, 9 s
  # beside four CPU-bound processes; the sixth adds its 0.5 s); loaded again for every
  # case, its sleeps alone would take 21 s whatever the machine. The bound, 16 s, tells
  # the two apart with room on both sides.
  fails_within "a file that loads in 3 s, and a case that never returns: loaded once" 16
  check "(its six cases each on its time limit)" test "$(grep -c "did not return within 0.5 s" "$work/out.txt")" -eq 6
fi

echo "== JavaScript: routes to a pass, and routes out"
base=$reference/js/basic-rays.js
with() {  # NAME CODE: the reference, its CanvasToViewport beginning with CODE
  sed "s|^function CanvasToViewport(x, y) {|function CanvasToViewport(x, y) {\n$2|" "$base" >"$work/$1.js"
}
with blocks "  if (x === 300) require(\"child_process\").execSync(\"sleep 30\");\n  if (x === 0) Atomics.wait(new Int32Array(new SharedArrayBuffer(4)), 0, 0);\n  if (x === -300) { require(\"child_process\").spawn(\"node\", [\"-e\", \"for(;;){}\", \"$marker\"], { detached: true, stdio: \"ignore\" }).unref(); process.kill(process.ppid, \"SIGSTOP\"); for (;;) {} }\n  if (x === 150) { const a = []; for (;;) a.push(new Array(1e6).fill(1.5)); }\n  return [9, 9, 9];"
with forges "  require(\"fs\").writeSync(4, JSON.stringify({ id: 2, nonce: \"x\", returned: [0, 0, 1] }) + \"\\\\n\");\n  try { require(\"fs\").appendFileSync(\"$source_dir/tests/cases/02-basic-rays.json\", \"{}\"); } catch {}\n  return [9, 9, 9];"
{ printf 'require("fs").writeSync(4, JSON.stringify({ loaded: { functions: {}, data: {}, defined: [], reachable: "all" } }) + "\\n");\n'
  cat "$work/forges.js"; } >"$work/forges-account.js"
# Its account says its functions are still empty (not written yet: no case would run).
{ printf 'const told = (names) => ({ parameters: { names, required: names.length, more: false }, empty: true, reads: [], complete: true, bound: [], calls: [] });\n'
  printf 'require("fs").writeSync(4, JSON.stringify({ loaded: { functions: { CanvasToViewport: told(["x", "y"]), IntersectRaySphere: told(["O", "D", "sphere"]), TraceRay: told(["O", "D", "t_min", "t_max"]) }, data: {}, defined: [], reachable: "all" } }) + "\\n");\n'
  cat "$work/forges.js"; } >"$work/forges-empty.js"
with tampers "  Math.abs = () => 0; JSON.stringify = () => '{\"returned\": [0.5, -0.25, 1]}'; return [9, 9, 9];"
run 02 "$work/blocks.js" --time-limit 1
fails_within "a blocking child process, Atomics.wait, a grandchild and SIGSTOP above, a memory bomb" "$(promised "$cases" 1)"
check "each of those cases failed" says "^  CanvasToViewport +FAILED 6 of 6 cases"
run 02 "$work/forges.js" --time-limit 1
fails_within "answers forged into the answer pipe, a case file appended to" "$(promised "$cases" 1)"
run 02 "$work/forges-account.js" --time-limit 1
fails_within "the process's account of itself forged" "$(promised "$cases" 1)"
check "the functions it hid are named as hidden" says "your file defines CanvasToViewport, but the process it ran in said it does not"
run 02 "$work/forges-empty.js" --time-limit 1
fails_within "the process's account forged to say every function is still empty" "$(promised "$cases" 1)"
check "its written functions are not taken for unwritten ones" bash -c '! grep -q "not written yet" "$1"' _ "$work/out.txt"
check "(they run their cases, and CanvasToViewport fails them)" says "^  CanvasToViewport +FAILED"
run 02 "$work/tampers.js" --time-limit 1
fails_within "JSON.stringify and Math replaced" "$(promised "$cases" 1)"

if [ "$deep" = --deep ]; then
  echo "== a run bounded by its cases and the time to load, and said so"
  # 10 s to load, and each case blocks in a child process: every case ends its process,
  # which is loaded again; the run stops at 20 cases x 0.2 s + 60 s.
  { echo 'require("child_process").execSync("sleep 10");'
    sed 's|^function CanvasToViewport(x, y) {|function CanvasToViewport(x, y) {\n  require("child_process").execSync("sleep 30");|' "$base"; } >"$work/bounded.js"
  run 02 "$work/bounded.js" --time-limit 0.2
  fails_within "a run that would take longer than its bound" "$(promised "$cases" 0.2)"
  check "it says it stopped, and why" says "^stopped after [0-9]+ s, the most this check may take \(20 cases × 0.2 s \+ 60 s to load\)"
fi

sleep 1
check "no process of the student's is left" test -z "$(pgrep -f "$marker" || true)"
check "the case files and the checker are as they were" test "$before" = "$(fingerprint)"
[ $failed -eq 0 ] && echo "PASS: student code cannot pass a case, change the checker or outlive it"
exit $failed
