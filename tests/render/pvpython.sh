#!/usr/bin/env bash
# Runs ParaView's pvpython from the folder scripts/setup.sh unpacked it into
# (SEDEM_PARAVIEW_DIR, default .paraview/ at the repository's root), with a private X server
# of its own (Xvfb): Debian's ParaView renders through X only.
#   tests/render/pvpython.sh SCRIPT.py [ARGS...]
set -euo pipefail
root=${SEDEM_PARAVIEW_DIR:-$(cd "$(dirname "$0")/../.." && pwd)/.paraview}
if [[ ! -x "$root/usr/bin/pvpython" ]]; then
  echo "pvpython.sh: no ParaView in $root; run scripts/setup.sh" >&2
  exit 2
fi
command -v Xvfb >/dev/null || { echo "pvpython.sh: no Xvfb; run scripts/setup.sh" >&2; exit 2; }
export LD_LIBRARY_PATH="$root/usr/lib/x86_64-linux-gnu${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export PYTHONPATH="$root/usr/lib/python3/dist-packages${PYTHONPATH:+:$PYTHONPATH}"

# Xvfb picks a free display and writes its number once it accepts connections.
tmp=$(mktemp -d)
Xvfb -displayfd 3 -screen 0 1600x1200x24 -nolisten tcp 3>"$tmp/display" 2>"$tmp/xvfb.log" &
xvfb=$!
trap 'kill "$xvfb" 2>/dev/null || true; wait "$xvfb" 2>/dev/null || true; rm -rf "$tmp"' EXIT
for _ in $(seq 100); do
  [[ -s "$tmp/display" ]] && break
  kill -0 "$xvfb" 2>/dev/null || { cat "$tmp/xvfb.log" >&2; exit 2; }
  sleep 0.1
done
[[ -s "$tmp/display" ]] || { echo "pvpython.sh: Xvfb did not start" >&2; exit 2; }
export DISPLAY=":$(tr -d '[:space:]' <"$tmp/display")"
# On some machines Xvfb resets a connection opened right after another one closed, and VTK
# aborts with "bad X server connection" when that happens to its window: run again then.
for attempt in 1 2 3 4 5 6 7 8; do
  status=0
  "$root/usr/bin/pvpython" "$@" >"$tmp/out" 2>&1 || status=$?
  if ((status == 0)) || ! grep -q "bad X server connection" "$tmp/out"; then break; fi
  echo "pvpython.sh: X connection reset (attempt $attempt), running again" >&2
  sleep 1
done
cat "$tmp/out"
exit "$status"
