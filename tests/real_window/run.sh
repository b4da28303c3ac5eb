#!/usr/bin/env bash
# Runs a GUI test as a user's desktop would show it: a real X server (Xvfb), the openbox
# window manager, Qt's xcb platform, real key events. Shortcut clashes, focus and window
# sizes that the offscreen platform hides show up here (on a Linux desktop Redo is
# Ctrl+Shift+Z; offscreen it is Ctrl+Y).
#   tests/real_window/run.sh TEST_BINARY [test functions…]
set -euo pipefail
export QT_QPA_PLATFORM=xcb QT_SCALE_FACTOR=1
exec xvfb-run -a -s "-screen 0 1280x1024x24" bash -c '
  openbox >/dev/null 2>&1 &
  wm=$!
  for _ in $(seq 50); do xprop -root _NET_SUPPORTING_WM_CHECK 2>/dev/null | grep -q window && break; sleep 0.1; done
  # openbox announces itself before it manages new windows: a window mapped in that moment
  # may never be exposed (tests/gui_timeouts.h shows it again if so).
  sleep 1
  "$@"
  rc=$?
  kill "$wm" 2>/dev/null || true
  exit $rc' run.sh "$@"
