#!/bin/sh
# run.sh - run every test program and script; count PASS/FAIL lines and end
# with one line "N passed, M failed". A test program that crashes or exits
# non-zero without reporting a FAIL counts as one failure.
cd "$(dirname "$0")/.." || exit 1
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0"
export LSAN_OPTIONS="suppressions=$(pwd)/tests/lsan.supp:print_suppressions=0"
status=0
for t in build/tests/test_* tests/scripts/*.sh tests/scripts/*.py; do
    [ -e "$t" ] || continue
    case "$t" in
        *.sh) cmd="sh $t" ;;
        *.py) cmd="/usr/bin/python3 $t" ;;
        *) cmd="$t" ;;
    esac
    name=$(basename "$t")
    start=$(date +%s)
    $cmd > "$out/$name.log" 2>&1
    rc=$?
    secs=$(( $(date +%s) - start ))
    p=$(grep -c '^PASS ' "$out/$name.log")
    f=$(grep -c '^FAIL ' "$out/$name.log")
    if [ $rc -ne 0 ] && [ "$f" -eq 0 ]; then
        echo "FAIL $name (exit $rc)" >> "$out/$name.log"
    fi
    f=$(grep -c '^FAIL ' "$out/$name.log")
    echo "== $name: $p passed, $f failed (${secs}s)"
    if [ "$f" -ne 0 ]; then
        grep -v '^PASS ' "$out/$name.log" | tail -40
        status=1
    fi
done
passed=$(cat "$out"/*.log 2>/dev/null | grep -c '^PASS ')
failed=$(cat "$out"/*.log 2>/dev/null | grep -c '^FAIL ')
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ] && [ $status -eq 0 ]
