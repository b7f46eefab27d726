#!/usr/bin/env bash
# with_x_display.sh XVFB COMMAND...: runs COMMAND with DISPLAY set to a private Xvfb server, which it
# starts and ends. ParaView's renderer in Debian (5.11) draws through GLX only, so pvpython needs an X
# display even offscreen (--force-offscreen-rendering without one crashes). Xvfb picks a free display
# number and writes it when it accepts connections (-displayfd), so the command never races its start;
# -noreset keeps it up between clients (pvpython connects more than once: one connecting while the
# server resets after the last one left gets "bad X server connection").
set -uo pipefail
if [ $# -lt 2 ] || [ ! -x "$1" ]; then
  echo "with_x_display.sh: '${1:-}' is not Xvfb (Debian's xvfb: scripts/install-deps.sh --report)" >&2
  exit 2
fi
xvfb=$1
shift
if ! command -v "$1" >/dev/null; then
  echo "with_x_display.sh: '$1' is not a program (pvpython: Debian's paraview and python3-paraview)" >&2
  exit 2
fi
dir=$(mktemp -d)
"$xvfb" -displayfd 3 -screen 0 1024x768x24 -nolisten tcp -noreset 3>"$dir/display" 2>"$dir/log" &
server=$!
trap 'kill "$server" 2>/dev/null; wait "$server" 2>/dev/null; rm -rf "$dir"' EXIT
for _ in $(seq 100); do
  [ -s "$dir/display" ] && break
  kill -0 "$server" 2>/dev/null || break
  sleep 0.1
done
if [ ! -s "$dir/display" ]; then
  echo "with_x_display.sh: Xvfb did not start within 10 s:" >&2
  cat "$dir/log" >&2
  exit 2
fi
DISPLAY=":$(head -n1 "$dir/display")" "$@"
