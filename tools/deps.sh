#!/bin/sh
# deps.sh - make sure the Debian packages gravel needs are installed: by
# default those it builds, runs and tests with (make deps, test, run, bench);
# `deps.sh PKG...` checks the named ones instead (make verify: gnuplot-nox).
# As root it installs what is missing; otherwise it prints the exact apt-get
# line and fails. `deps.sh --list` prints the default list (for .ci/run).
PKGS="gcc make ocl-icd-opencl-dev opencl-headers pocl-opencl-icd libgsl-dev python3 python3-vtk9 clang lammps lammps-examples liggghts-doc openmpi-bin libopenmpi-dev"
if [ "$1" = "--list" ]; then echo "$PKGS"; exit 0; fi
[ $# -gt 0 ] && PKGS="$*"
missing=""
for p in $PKGS; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
if [ "$(id -u)" = 0 ]; then
    echo "deps: installing$missing"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq && apt-get install -y -qq $missing >/dev/null || exit 1
else
    echo "deps: missing packages:$missing"
    echo "run: sudo apt-get install -y$missing"
    exit 1
fi
