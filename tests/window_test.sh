#!/usr/bin/env bash
# The inspector's window on a virtual display (ctest runs this under xvfb-run): it opens with
# the Vulkan validation layer on, takes keys, is resized (the swapchain made again), and
# saves the window through its swapchain on Ctrl+S, T turns the plots' axis to time and back, and
# it closes on Ctrl+Q with status 0 and no word from the validation layer (runWindow exits
# non-zero on what it reports while the device lives, and objects left when the instance goes
# are printed). First, a pin that does not exist, found as the window opens: one line, status 1,
# and every Vulkan object gone as well.
# usage: window_test.sh LLOYDSCOPE MESH
set -uo pipefail
cli=$(realpath "$1")
mesh=$(realpath "$2")
folder=$(mktemp -d)  # where Ctrl+S saves lloydscope.png
log=$folder/log
trap 'rm -rf "$folder"' EXIT
cd "$folder" || exit 1
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
# Ctrl+S saves the whole window (Export PNG's defaults) as lloydscope.png, read back from the
# swapchain: here moved to $1 once saved, within 10 s.
save() {
  rm -f lloydscope.png
  xdotool key ctrl+s
  for _ in $(seq 100); do
    [ -f lloydscope.png ] && break
    sleep 0.1
  done
  mv lloydscope.png "$1" 2>/dev/null || fail "Ctrl+S saved no picture in 10 s (for $1)"
}
# 1280x800, the window's size.
save first.png
size=$(od -An -tu1 -j16 -N8 first.png | tr -s ' ')
[ "$size" = " 0 0 5 0 0 0 3 32" ] || fail "the picture saved is not 1280x800 (its header's size: $size)"
[ "$(stat -c %s first.png)" -gt 20000 ] || fail "the picture saved is nearly empty"

# T plots the convergence against time, and T again against iterations: the window saved after
# each differs, then is as it was. (From the second picture on, each shows the message line's
# "saved lloydscope.png".)
save iterations.png
xdotool key t
sleep 0.5
save time.png
xdotool key t
sleep 0.5
save again.png
cmp -s iterations.png time.png && fail "T changed nothing in the window"
cmp -s iterations.png again.png || fail "T twice did not give back the plots against iterations"

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
echo "window test: opened, took keys, saved a picture, resized, closed on Ctrl+Q"
