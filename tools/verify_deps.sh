#!/bin/sh
# verify_deps.sh - `make verify` also needs gnuplot (PNG plots of
# doc/verification.md); `make test` does not, so it is checked here rather
# than in tools/deps.sh. As root it installs what is missing; otherwise it
# prints the exact apt-get line and fails.
PKGS="gnuplot-nox"
missing=""
for p in $PKGS; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
if [ "$(id -u)" = 0 ]; then
    echo "make verify: installing$missing"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq && apt-get install -y -qq $missing >/dev/null || exit 1
else
    echo "make verify: missing packages:$missing"
    echo "run: sudo apt-get install -y$missing"
    exit 1
fi
