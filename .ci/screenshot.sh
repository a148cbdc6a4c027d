#!/bin/sh
# A screenshot of the workbench running a lesson, taken under a virtual X
# server (xvfb-run) so it works on a machine without a display.
#   .ci/screenshot.sh [BUILD_DIR] [OUT.png] [LESSON] [SECONDS] [BALL]
# Defaults: build, docs/screenshot.png, the first built-in lesson, 3 s, and
# ball 17 selected (so the Inspector shows its numbers; "none" for no ball).
# docs/screenshot.png is made with the defaults: .ci/screenshot.sh BUILD_DIR
# The window starts from fresh settings (a temporary config directory), so
# the picture does not depend on the last session's layout.
set -eu
build=${1:-build}
out=${2:-docs/screenshot.png}
lesson=${3:-}
seconds=${4:-3}
ball=${5:-17}
[ "$ball" = none ] && ball=
if ! command -v xvfb-run >/dev/null 2>&1; then
    echo "screenshot.sh: xvfb-run is missing; install it with: apt-get install xvfb" >&2
    exit 2
fi
config=$(mktemp -d)
trap 'rm -rf "$config"' EXIT
XDG_CONFIG_HOME="$config" xvfb-run -a -s "-screen 0 1400x900x24" \
    "$build/app/forcelab" --screenshot "$out" --after "$seconds" ${ball:+--select "$ball"} ${lesson:+"$lesson"}
echo "wrote $out"
