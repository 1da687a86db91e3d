#!/usr/bin/env bash
# The inspector's window on a virtual display (ctest runs this under xvfb-run): it opens with
# the Vulkan validation layer on, takes keys, is resized (the swapchain made again), and
# closes on Ctrl+Q with status 0 and no word from the validation layer (runWindow exits
# non-zero on what it reports while the device lives, and objects left when the instance goes
# are printed). First, a pin that does not exist, found as the window opens: one line, status 1,
# and every Vulkan object gone as well.
# usage: window_test.sh LLOYDSCOPE MESH
set -uo pipefail
cli=$1
mesh=$2
log=$(mktemp)
trap 'rm -f "$log"' EXIT
fail() {
  echo "window test: $*"
  cat "$log"
  [ -n "$pid" ] && kill "$pid" 2>/dev/null
  exit 1
}

pid=""
error=$("$cli" inspect "$mesh" --validation --select-cell 99999 2>&1)
status=$?
expected="lloydscope: $(basename "$mesh"): cell 99999 does not exist (1000 sites, numbered from 0)"
[ "$status" -eq 1 ] && [ "$error" = "$expected" ] ||
  fail "a missing pin gave status $status and: $error"

"$cli" inspect "$mesh" --validation >"$log" 2>&1 &
pid=$!
window=""
for _ in $(seq 300); do  # 30 s to open
  window=$(xdotool search --name '^Lloydscope$' 2>/dev/null | head -1)
  [ -n "$window" ] && break
  kill -0 "$pid" 2>/dev/null || fail "the inspector ended before its window opened"
  sleep 0.1
done
[ -n "$window" ] || fail "no window in 30 s"
xdotool windowfocus --sync "$window" 2>/dev/null

# Keys a lecturer uses: the iterations, playback, presentation mode, the lesson, unpinning.
for key in End Left shift+Left Home space space p p l l Escape; do
  xdotool key "$key"
  sleep 0.2
done
xdotool windowsize --sync "$window" 900 600
sleep 1
kill -0 "$pid" 2>/dev/null || fail "the inspector ended before Ctrl+Q"
xdotool key ctrl+q
for _ in $(seq 200); do  # 20 s to close
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.1
done
kill -0 "$pid" 2>/dev/null && fail "still open 20 s after Ctrl+Q"
wait "$pid"
status=$?
[ "$status" -eq 0 ] || fail "exit status $status"
grep -q "Validation" "$log" && fail "the validation layer reported"
echo "window test: opened, took keys, resized, closed on Ctrl+Q"
