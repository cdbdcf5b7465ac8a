#!/usr/bin/env bash
# The function checker's sandbox bounded as a whole (docs/students.md, "Where your code
# runs"): student code that forks without end at import, fills its /tmp and /dev/shm,
# writes anywhere else, and (with --deep) holds memory in three processes at once, or
# asks for more than a process may have. With a
# cgroup where this machine lets the checker make one, and without (CGFS_NO_CGROUP=1); run
# as root, the code runs as nobody without capabilities. A JavaScript module's
# process.exit() at import is seen within seconds. Skipped without bubblewrap.
# Usage: check_sandbox_bounds.sh SOURCE_DIR WORK_DIR [--deep]
set -euo pipefail
source_dir=$1 work=$2 deep=${3:-}
rm -rf "$work"
mkdir -p "$work"
# shellcheck source=tests/check-functions/checks.sh
source "$(dirname "${BASH_SOURCE[0]}")/checks.sh"
if ! command -v node >/dev/null || ! command -v python3 >/dev/null || ! bwrap --ro-bind / / --unshare-all true 2>/dev/null; then
  echo "SKIPPED: no node, python3 or bubblewrap sandbox here (CI installs them: scripts/setup)"
  exit 0
fi
# A copy of the checker, its case files and the student's files that any user can read,
# in a folder of its own under /tmp (run as root with no cgroup, the checker runs the code
# as nobody, who must read them; the build folder may be in a folder only its owner
# reads), and Debian's python3.
copy=$(mktemp -d /tmp/cgfs-sandbox-bounds.XXXXXX)
trap 'rm -rf "$copy"' EXIT
mkdir -p "$copy/tools" "$copy/tests" "$copy/student"
cp -r "$source_dir/tools/check-functions" "$copy/tools/"
cp -r "$source_dir/tests/cases" "$copy/tests/"
checker=$copy/tools/check-functions/check-functions.js
export PATH=/usr/bin:/bin
ln -s "$copy/student" "$work/student"

# PROBE is printed by CanvasToViewport: what the code could do in its sandbox.
cat >"$work/student/probe.py" <<'EOF'
import os, time

forks = 0
for _ in range(5000):
    try:
        if os.fork() == 0:
            time.sleep(1)
            os._exit(0)
        forks += 1
    except OSError:
        break
while True:  # its children gone, the runner can start its own process for the case
    try:
        os.wait()
    except ChildProcessError:
        break


def filled(folder):
    written = 0
    try:
        with open(os.path.join(folder, "fill"), "wb") as out:
            for _ in range(200):
                out.write(b"x" * (1 << 20))
                out.flush()
                written += 1
    except OSError:
        pass
    os.remove(os.path.join(folder, "fill"))  # the case's printing is kept in /tmp too
    return written


def writable(folder):
    try:
        with open(os.path.join(folder, "probe"), "w") as out:
            out.write("x")
        return "yes"
    except OSError:
        return "no"


def CanvasToViewport(x, y):
    caps = [line.split()[1] for line in open("/proc/self/status") if line.startswith("CapEff")][0]
    print(f"PROBE forks={forks} tmp_mib={filled('/tmp')} shm_mib={filled('/dev/shm')} "
          f"root={writable('/')} dev={writable('/dev')} uid={os.getuid()} caps={caps}")
    return (x, y, 1)
EOF
chmod -R a+rX "$copy"

field() { { grep -ohE "PROBE [^\\]*" "$work/out.txt" "$work/results.json" || true; } | head -1 | { grep -oE "(^| )$1=[^ ]*" || echo "=none"; } | cut -d= -f2; }
# MODE: cgroup (the checker's default), no-cgroup, or as-a-user (run as root: the
# checker itself run as nobody, who can make no cgroup).
probe() {
  local mode=$1 results=$copy/results.json
  case $mode in
    cgroup) node "$checker" 02 "$copy/student/probe.py" --function CanvasToViewport --case 1 --json "$results" ;;
    no-cgroup) CGFS_NO_CGROUP=1 node "$checker" 02 "$copy/student/probe.py" --function CanvasToViewport --case 1 --json "$results" ;;
    as-a-user) setpriv --reuid=65534 --regid=65534 --clear-groups -- env HOME=/tmp node "$checker" 02 \
      "$copy/student/probe.py" --function CanvasToViewport --case 1 --json - ;;
  esac >"$work/out.txt" 2>&1
}
modes="cgroup no-cgroup"
if [ "$(id -u)" = 0 ]; then modes="$modes as-a-user"; fi
for mode in $modes; do
  status=0
  start=$SECONDS
  rm -f "$copy/results.json"
  probe "$mode" || status=$?
  if [ -f "$copy/results.json" ]; then cp "$copy/results.json" "$work/results.json"; else cp "$work/out.txt" "$work/results.json"; fi
  took=$((SECONDS - start))
  sed 's/^/    /' "$work/out.txt" | cut -c1-200 | head -12
  if [ "$mode" = cgroup ] && says "no cgroup can be made here"; then
    echo "    (this machine lets the checker make no cgroup: its per-process limits are checked below)"
    continue
  fi
  check "$mode: the module loaded and its case ran" grep -q "PROBE forks=" "$work/results.json"
  check "$mode: within the checker's promise for one case (took $took of $(promised 1 5) s)" test $took -le "$(promised 1 5)"
  forks=$(field forks)
  bound=$([ "$mode" = cgroup ] && echo 128 || echo 2000)
  check "$mode: forks at import stop at the sandbox's bound ($forks of the 5000 tried, at most $bound)" test "${forks:-99999}" -lt "$bound"
  check "$mode: /tmp holds at most 64 MiB ($(field tmp_mib))" test "$(field tmp_mib)" -le 64 2>/dev/null
  check "$mode: /dev/shm holds at most 16 MiB ($(field shm_mib))" test "$(field shm_mib)" -le 16 2>/dev/null
  check "$mode: / and /dev are read-only" test "$(field root)$(field dev)" = nono
  check "$mode: no capability" test "$(field caps)" = 0000000000000000
  if [ "$(id -u)" = 0 ]; then
    check "$mode: run as root, the code runs as nobody" test "$(field uid)" = 65534
  fi
  if [ "$mode" != cgroup ]; then
    check "$mode: the report says the limits are each process's" says "note: (CGFS_NO_CGROUP=1|no cgroup can be made here): the sandbox's memory and processes are capped for each process"
  fi
  # (this copy's runner: other tests may be running theirs)
  check "$mode: no process of the sandbox is left" bash -c '! pgrep -f "$1" >/dev/null' _ "$copy/tools/check-functions/runners/python_runne[r].py"
done

# Run as root with no cgroup, a folder nobody can read is refused in one line.
if [ "$(id -u)" = 0 ]; then
  mkdir -p "$copy/private" && chmod 700 "$copy/private" && cp "$copy/student/probe.py" "$copy/private/"
  status=0
  CGFS_NO_CGROUP=1 node "$checker" 02 "$copy/private/probe.py" >"$work/out.txt" 2>&1 || status=$?
  sed 's/^/    /' "$work/out.txt" | cut -c1-200
  check "root, no cgroup, a folder nobody can read: exit 2" test $status -eq 2
  check "root, no cgroup, a folder nobody can read: one line naming it" \
    bash -c '[ "$(wc -l <"$1")" = 1 ] && grep -q "nobody cannot read $2: make it readable by others" "$1"' _ "$work/out.txt" "$copy/private"
fi

# A chapter kept in / would have the whole file system for its folder: refused (run as
# root, the only user who can put one there).
if [ "$(id -u)" = 0 ]; then
  at_root=/cgfs-sandbox-bounds-$$.py
  cp "$copy/student/probe.py" "$at_root"
  status=0
  node "$checker" 02 "$at_root" >"$work/out.txt" 2>&1 || status=$?
  rm -f "$at_root"
  sed 's/^/    /' "$work/out.txt"
  check "a chapter in /: exit 2, one line" bash -c '[ "$1" = 2 ] && [ "$(wc -l <"$2")" = 1 ] && grep -q "put your chapter in a folder of its own" "$2"' _ "$status" "$work/out.txt"
fi

# A JavaScript module that ends its process as it loads is seen at once.
printf 'process.exit(0);\nfunction CanvasToViewport(x, y) { return [x, y, 1]; }\n' >"$work/student/exits.js"
status=0
start=$SECONDS
node "$checker" 02 "$work/student/exits.js" >"$work/out.txt" 2>&1 || status=$?
took=$((SECONDS - start))
sed 's/^/    /' "$work/out.txt"
# Seen at once, not at the 60 s load limit: 30 s, the widest bound that tells the two apart.
check "process.exit(0) at import: 'ended the process' within 30 s (took $took; the load limit is 60 s)" \
  bash -c "says() { grep -q \"\$1\" '$work/out.txt'; }; says 'ended the process (exit status 0) while loading' && [ $took -le 30 ]"

if [ "$deep" = --deep ]; then
  # Three processes of 1.5 GiB each, all alive at once: together under the sandbox's 3 GiB.
  cat >"$work/student/hoard.py" <<'EOF'
import os, select, signal, time


def CanvasToViewport(x, y):
    children = {}
    for _ in range(3):
        r, w = os.pipe()
        pid = os.fork()
        if pid == 0:
            block = bytearray(3 << 29)
            for at in range(0, len(block), 4096):
                block[at] = 1
            os.write(w, b"1")
            time.sleep(30)
            os._exit(0)
        os.close(w)
        children[pid] = r
    time.sleep(3)
    held = 0  # children alive now that said they hold their block
    for pid, r in children.items():
        alive = os.waitpid(pid, os.WNOHANG) == (0, 0)
        said = select.select([r], [], [], 0)[0] and os.read(r, 1) == b"1"
        held += bool(alive and said)
    for pid in children:
        try:
            os.kill(pid, signal.SIGKILL)
        except OSError:
            pass
    print(f"HELD {held} of 3 blocks of 1.5 GiB at once")
    return (x, y, 1)
EOF
  # One process asking for 3.5 GiB: without a cgroup each process is capped alone, at
  # 3 GiB (prlimit), so it is refused at once (and nothing is touched: the machine need
  # not have the memory, where holding three blocks of 1.5 GiB would need 4.5 GiB).
  cat >"$work/student/big.py" <<'EOF'
def CanvasToViewport(x, y):
    try:
        block = bytearray(7 << 29)
        print(f"BIG allocated {len(block) >> 20} MiB")
    except MemoryError:
        print("BIG refused")
    return (x, y, 1)
EOF
  chmod a+r "$copy/student/hoard.py" "$copy/student/big.py"
  rm -f "$copy/results.json"
  node "$checker" 02 "$copy/student/hoard.py" --function CanvasToViewport --case 1 --json "$copy/results.json" >"$work/out.txt" 2>&1 || true
  sed 's/^/    /' "$work/out.txt" | cut -c1-200 | head -8
  if says "no cgroup can be made here"; then
    echo "    (this machine lets the checker make no cgroup: the memory of three processes together is not checked)"
  else
    held=$( (grep -oE "HELD [0-9]" "$copy/results.json" || true) | head -1 | cut -d" " -f2)
    check "cgroup: of three processes of 1.5 GiB, at most one holds its block at once (${held:-none})" \
      test "${held:-9}" -le 1
  fi
  rm -f "$copy/results.json"
  CGFS_NO_CGROUP=1 node "$checker" 02 "$copy/student/big.py" --function CanvasToViewport --case 1 --json "$copy/results.json" >"$work/out.txt" 2>&1 || true
  sed 's/^/    /' "$work/out.txt" | cut -c1-200 | head -8
  big=$( (grep -oE "BIG [a-z]+" "$copy/results.json" || true) | head -1 | cut -d" " -f2)
  check "no-cgroup: each process is capped alone: 3.5 GiB in one process refused (${big:-none}), and the note says so" \
    bash -c '[ "$1" = refused ] && grep -q "CGFS_NO_CGROUP=1: the sandbox" "$2"' _ "${big:-none}" "$work/out.txt"
fi
exit "$failed"
