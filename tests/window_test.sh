#!/usr/bin/env bash
# The inspector's window on a virtual display (ctest runs this under xvfb-run): it opens with
# the Vulkan validation layer on, takes keys, is resized (the swapchain made again), and
# saves the window through its swapchain on Ctrl+S, T turns the plots' axis to time and back, and
# it closes on Ctrl+Q with status 0 and no word from the validation layer (runWindow exits
# non-zero on what it reports while the device lives, and objects left when the instance goes
# are printed). First, a pin that does not exist, found as the window opens: one line, status 1,
# and every Vulkan object gone as well.
# A message goes over the views' foot, in presentation mode too, and leaves the controls where
# they were; the window is no smaller than the layout reads in; a click on the lesson's load
# stage, which draws no cells, pins none.
# usage: window_test.sh LLOYDSCOPE MESH PNG_SAME_REGION GRAB_WINDOW
set -uo pipefail
cli=$(realpath "$1")
mesh=$(realpath "$2")
same=$(realpath "$3")  # png_same_region A B X0 Y0 X1 Y1
grab=$(realpath "$4")  # grab_window WINDOW OUT.png: the screen's pixels
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
# At 640x400 the plots' titles and the legends were cut off: the window manager is told not
# to go under 960x600.
xprop -id "$window" WM_NORMAL_HINTS | grep -q "minimum size: 960 by 600" ||
  fail "the window asks for no minimum size of 960x600: $(xprop -id "$window" WM_NORMAL_HINTS)"

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
# each differs, then is as it was. (The pictures leave out the message "saved lloydscope.png".)
save iterations.png
xdotool key t
sleep 0.5
save time.png
xdotool key t
sleep 0.5
save again.png
cmp -s iterations.png time.png && fail "T changed nothing in the window"
cmp -s iterations.png again.png || fail "T twice did not give back the plots against iterations"

# The window's pixels in $1 once two grabs 0.3 s apart agree (a frame under way drawn).
grabSettled() {
  "$grab" "$window" "$1" || fail "cannot read the window's pixels"
  for _ in $(seq 30); do
    sleep 0.3
    "$grab" "$window" settling.png
    cmp -s "$1" settling.png && return 0
    mv settling.png "$1"
  done
  fail "the window kept changing ($1)"
}
# Waits, up to 10 s, for the window to differ from the pixels in $1 (a key's effect drawn).
awaitChange() {
  for _ in $(seq 50); do
    "$grab" "$window" changed.png
    cmp -s "$1" changed.png || return 0
    sleep 0.2
  done
  fail "the window did not change in 10 s (from $1)"
}

# The last picture's "saved lloydscope.png" goes over the views' foot, where presentation mode
# shows it too, and goes after a while (6 s and a little per letter); the controls pane (x < 294
# at 1280x800) stays as it was. Under the controls, it scrolled them (the next click landed on
# another control), and presentation mode hid it. The screen's own pixels: a picture the
# inspector saves leaves the message out.
grabSettled told.png
xdotool key p
awaitChange told.png
grabSettled told_presenting.png
sleep 9
grabSettled quiet_presenting.png
xdotool key p
awaitChange quiet_presenting.png
grabSettled quiet.png
cmp -s told.png quiet.png && fail "no message on the screen after Ctrl+S"
"$same" told.png quiet.png 0 0 290 800 || fail "the message after Ctrl+S moved the controls"
cmp -s told_presenting.png quiet_presenting.png && fail "presentation mode shows no message after Ctrl+S"

# The lesson's load stage (L, paused, Home) draws no cells: a click on its 2D pane pins none,
# which the controls' Selection would list.
xdotool key l space Home
awaitChange quiet.png
grabSettled load.png
xdotool mousemove --window "$window" 1033 330 click 1
sleep 1
grabSettled clicked.png
"$same" load.png clicked.png 0 0 290 800 || fail "a click on the load stage's empty 2D pane pinned a cell"
xdotool key l
sleep 0.2

xdotool windowsize --sync "$window" 1100 700
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
