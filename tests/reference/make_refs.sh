#!/bin/sh
# make_refs.sh - regenerate the LAMMPS reference dumps: runs every deck here in
# LAMMPS (`lmp`, 2021 build) in a temporary directory and stores its dump as
# <deck>.dump beside it (pair_gran, pair_granular, wall_gran, wall_gran_region,
# rigid; pour/*.in: the fix pour decks of tests/scripts/fix_pour.py). Only needed when a deck changes; the tests read the stored dumps.
cd "$(dirname "$0")" || exit 1
command -v lmp >/dev/null || { echo "lmp (Debian package lammps) is not installed"; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for deck in pair_gran/*.in pair_granular/*.in wall_gran/*.in wall_gran_region/*.in rigid/*.in \
            pour/*.in; do
    name=${deck%.in}
    rm -f "$tmp/out.dump"
    (cd "$tmp" && lmp -in "$OLDPWD/$deck" -log none -screen none) || { echo "lmp failed on $deck"; exit 1; }
    cp "$tmp/out.dump" "$name.dump"
    echo "$name.dump"
done
