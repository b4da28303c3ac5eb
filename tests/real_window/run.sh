#!/usr/bin/env bash
# Runs a GUI test as a user's desktop would show it: a real X server (Xvfb), the openbox
# window manager, Qt's xcb platform, real key events. Shortcut clashes, focus and window
# sizes that the offscreen platform hides show up here (on a Linux desktop Redo is
# Ctrl+Shift+Z; offscreen it is Ctrl+Y). README.md beside this file says how the tests stay
# independent of the window manager's timing.
#   tests/real_window/run.sh TEST_BINARY [arguments…]
# GRANOTA_SCREEN=WxH picks the screen's size (1280x1024 unless set): a projector's 1024x768
# or 800x600 (tests/test_gui_screen_fit.cpp).
# Xvfb picks a free display itself (-displayfd) and says which, so any number of these can
# run at once (xvfb-run -a guesses a free number, and two started together may guess the same).
set -euo pipefail
export QT_QPA_PLATFORM=xcb QT_SCALE_FACTOR=1
scratch="$(mktemp -d "${TMPDIR:-/tmp}/granota-xvfb.XXXXXX")"
xvfb="" wm=""
cleanup() {
  # Xvfb first: openbox ends with its display, and the supervisor, which starts openbox again
  # only while Xvfb lives, ends after it.
  for pid in $xvfb $wm; do kill "$pid" 2>/dev/null || true; done
  for pid in $xvfb $wm; do wait "$pid" 2>/dev/null || true; done
  rm -rf "$scratch"
}
trap cleanup EXIT
Xvfb -displayfd 3 -screen 0 "${GRANOTA_SCREEN:-1280x1024}x24" -nolisten tcp 3>"$scratch/display" 2>"$scratch/xvfb.log" &
xvfb=$!
for _ in $(seq 300); do
  [ -s "$scratch/display" ] && break
  kill -0 "$xvfb" 2>/dev/null || { echo "error: Xvfb did not start:" >&2; cat "$scratch/xvfb.log" >&2; exit 1; }
  sleep 0.1
done
[ -s "$scratch/display" ] || { echo "error: Xvfb named no display in 30 s" >&2; exit 1; }
export DISPLAY=":$(head -1 "$scratch/display")"
# openbox under a supervisor: should it ever exit (a CI run once saw every window of a suite
# left unframed, as with no window manager at all), it is started again at once, and takes
# over the windows already mapped, as a window manager does when it starts.
(
  while kill -0 "$xvfb" 2>/dev/null; do
    openbox >>"$scratch/openbox.log" 2>&1 || true
    echo "openbox exited; started again" >>"$scratch/openbox.log"
    sleep 0.2
  done
) &
wm=$!
managed=""
for _ in $(seq 600); do
  if xprop -root _NET_SUPPORTING_WM_CHECK 2>/dev/null | grep -q window; then managed=1; break; fi
  sleep 0.1
done
[ -n "$managed" ] || { echo "error: openbox did not start on $DISPLAY in 60 s:" >&2; cat "$scratch/openbox.log" >&2; exit 1; }
# openbox announces itself before it manages new windows: a window mapped in that moment
# may never be exposed (tests/gui_timeouts.h shows it again if so).
sleep 1
status=0
"$@" || status=$?
if [ "$status" -ne 0 ] && [ -s "$scratch/openbox.log" ]; then
  echo "openbox said:" >&2
  tail -20 "$scratch/openbox.log" >&2
fi
exit "$status"
