#!/usr/bin/env bash
# Checks Exodus results in real ParaView (pvpython under a virtual X server).
# Usage: run_paraview_check.sh GRID POINTS EXPECTED_POINTS OUT.png [EXPECTED_TIMES]
# Installs Debian's paraview, python3-paraview, xvfb and xauth first if pvpython or Xvfb is
# missing (needs root).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

if [ "$#" -lt 4 ]; then
  echo "usage: $0 GRID POINTS EXPECTED_POINTS OUT.png [EXPECTED_TIMES]" >&2
  exit 2
fi

if ! command -v pvpython >/dev/null 2>&1 || ! command -v Xvfb >/dev/null 2>&1; then
  if [ "$(id -u)" != "0" ]; then
    echo "paraview check: pvpython or Xvfb missing and not root;" \
         "install: apt-get install paraview python3-paraview xvfb xauth" >&2
    exit 1
  fi
  echo "paraview check: installing paraview python3-paraview xvfb xauth (apt-get)" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q >&2
  apt-get install -y -q paraview python3-paraview xvfb xauth >&2
fi

# Our own Xvfb with -displayfd: the server itself picks a free display and reports it once it
# is ready. (`xvfb-run -a` races when several checks start at once: they all take :99.)
# Up to three tries: a server that dies at start (seen once, in a full run under load,
# while another check started its own) is started again.
display_file="$(mktemp)"
xvfb_pid=""
trap 'kill "$xvfb_pid" 2>/dev/null || true; wait "$xvfb_pid" 2>/dev/null || true; rm -f "$display_file"' EXIT
display=""
for attempt in 1 2 3; do
  : >"$display_file"
  Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp 3>"$display_file" 2>/dev/null &
  xvfb_pid=$!
  for _ in $(seq 100); do
    [ -s "$display_file" ] && break
    kill -0 "$xvfb_pid" 2>/dev/null || break
    sleep 0.1
  done
  display="$(head -n 1 "$display_file")"
  [ -n "$display" ] && break
  echo "paraview check: Xvfb did not start (try $attempt of 3)" >&2
  kill "$xvfb_pid" 2>/dev/null || true
  wait "$xvfb_pid" 2>/dev/null || true
  sleep 1
done
if [ -z "$display" ]; then
  echo "paraview check FAILED: Xvfb did not start" >&2
  exit 1
fi

DISPLAY=":$display" pvpython "$here/check_exodus.py" "$@"
