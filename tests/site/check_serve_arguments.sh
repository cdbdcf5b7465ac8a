#!/usr/bin/env bash
# scripts/site --serve's port, before anything is built: not a number, out of range,
# more than one line, too long, or taken by another program, each one line and exit
# status 2, at once: within 10 s, where each takes a fraction of a second quiet (a
# refusal after a build of minutes is what this catches; 60 s cuts a hang). (The deep
# checks' site part serves the built site, 200 requests at once.)
# Usage: check_serve_arguments.sh SOURCE_DIR
set -uo pipefail
source_dir=$1
failed=0
expect_refused() {  # WHAT PORT
  local out status start=$SECONDS
  out=$(timeout 60 "$source_dir/scripts/site" --serve "$2" 2>&1)
  status=$?
  if [ $status -ne 2 ] || [ "$(wc -l <<<"$out")" -ne 1 ] || [ $((SECONDS - start)) -gt 10 ]; then
    echo "FAIL: $1: exit status $status after $((SECONDS - start)) s, said:"
    echo "$out"
    failed=1
  else
    echo "ok: $1: $out"
  fi
}
expect_refused "not a number" abc
expect_refused "out of range" 99999
expect_refused "below 1024" 80
expect_refused "a leading zero" 0800
expect_refused "two lines" $'8000\n1'
expect_refused "too long" 123456789012345678901234567890
# A port another program has.
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -c "import socket, time; s = socket.socket(); s.bind(('127.0.0.1', $port)); s.listen(); time.sleep(30)" &
holder=$!
sleep 0.5
expect_refused "a port another program has" "$port"
kill $holder
[ $failed -eq 0 ] && echo "PASS: scripts/site --serve refuses a port it cannot have, in one line"
exit $failed
