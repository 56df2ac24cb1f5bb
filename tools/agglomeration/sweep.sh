#!/bin/sh
# Runs the agglomeration study of source document 000 chapter 6 end to end
# (`make reproduce-agglomeration`): the deck inputs/published/agglomeration/
# agglomeration.in runs each point of the 4 x 4 Stickiness x Stokes grid in a
# gravel process of its own, checkpointing with restart files;
# tools/agglomeration/average.py averages every grid point over the window of
# 000 sec. 6.2.2 (the same fraction of the run as 500-550 s of 600 s),
# tools/agglomeration/plot.py draws fig. 6.8 (mean size and void fraction
# against the Stokes number, one line per Stickiness number) and the time series.
#
# Resumable: run it again after an interruption (a wall-time limit, a stopped
# session) with the same settings and it keeps the finished grid points,
# resumes each interrupted one from its newer restart file (exact
# continuation: the same numbers as an uninterrupted run) and starts the rest.
# Other settings than the run directory's (its file `settings`) start over.
# Where files do not outlive a session, tools/agglomeration/park.sh keeps the
# progress in the repository (runs/agglomeration/<tag>/): a run directory
# that lacks a grid point takes it from there (log, histograms, restart).
#
# Environment (all optional):
#   AGGLO_QUICK=1  shortened sweep: 5 s per grid point (a few minutes in all)
#   AGGLO_N        number of particles     (default 1000; 000 table 6.1: 10000)
#   AGGLO_TEND     simulated s per point   (default 300, quick 5; 000: 600)
#   AGGLO_NOUT     thermo rows per point   (default 240, quick 50)
#   AGGLO_SEED     seed of the initial state (default 12345)
#   AGGLO_SY, AGGLO_ST  the grid (default 000's: "0.1 0.6 1.0 1.5", "0.1 1.0 5.0 10.0")
#   AGGLO_KCSET    k_c in N/m for every point instead of eq. 6.5's (deck -var kcset;
#                  default 0: eq. 6.5, e.g. 117.24 for table 6.2's Sy 1.5 value)
#   AGGLO_CHECKPOINTS  restart files per grid point (default 24; 0: none, no resume)
#   AGGLO_TAG      name of this run in the output names (default full or quick)
#   AGGLO_OUT      run directory (default build/agglomeration/<tag>)
#   AGGLO_DOC      where the PNGs and the Markdown table go (default doc)
#   AGGLO_PLOT=0   no plots (no gnuplot needed)
#   AGGLO_JOBS     grid points run at once (default 1). With J > 1 each gravel
#                  process gets cores / J OpenCL threads (AGGLO_THREADS to set it;
#                  PoCL's POCL_CPU_MAX_CU_COUNT), its screen output goes to
#                  screen_Sy<Sy>_St<St>.txt, and a point that starts afresh (it writes
#                  the shared initial state) runs alone until its grid starts.
#                  Measured here (2 cores): two points on one thread each do 1.18-
#                  1.33x the work of one point on two threads (doc/agglomeration.md).
#   AGGLO_PARKED   where parked sweeps are (default runs/agglomeration; park.sh)
# Outputs: $AGGLO_DOC/agglomeration_<tag>.png (fig. 6.8), _<tag>_series.png,
# _<tag>.md (table); the logs, restart files, table.dat and the initial state
# in the run dir.
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
if [ "${AGGLO_QUICK:-0}" = 1 ]; then
    tag=quick; tend=${AGGLO_TEND:-5}; nout=${AGGLO_NOUT:-50}
else
    tag=full; tend=${AGGLO_TEND:-300}; nout=${AGGLO_NOUT:-240}
fi
n=${AGGLO_N:-1000}
seed=${AGGLO_SEED:-12345}
sys=${AGGLO_SY:-0.1 0.6 1.0 1.5}
sts=${AGGLO_ST:-0.1 1.0 5.0 10.0}
ncp=${AGGLO_CHECKPOINTS:-24}
kcset=${AGGLO_KCSET:-0}
tag=${AGGLO_TAG:-$tag}
out=${AGGLO_OUT:-$root/build/agglomeration/$tag}
doc=${AGGLO_DOC:-$root/doc}
deck=$root/inputs/published/agglomeration/agglomeration.in
mkdir -p "$out" "$doc"
cd "$out"
settings="N $n tend $tend nout $nout seed $seed checkpoints $ncp kcset $kcset deck $(cksum < "$deck")"
# a parked sweep (tools/agglomeration/park.sh: runs/agglomeration/<tag>/ in the
# repository, same settings): the grid points this run directory does not hold
parked=${AGGLO_PARKED:-$root/runs/agglomeration}/$tag
if [ -f "$parked/settings" ] && [ "$(cat "$parked/settings")" = "$settings" ] &&
    { [ ! -f settings ] || [ "$(cat settings)" = "$settings" ]; }; then
    for log in "$parked"/agglo_Sy*_St*.log; do
        [ -f "$log" ] || continue
        p=$(basename "$log" .log)
        [ -f "$p.log" ] && continue
        echo "grid point ${p#agglo_}: from the parked run in $parked"
        cp "$log" .
        for h in "$parked/$p".hist "$parked/$p".from*.hist; do
            if [ -f "$h" ]; then cp "$h" .; fi
        done
        rm -f "$p.restart.b"
        if [ -f "$parked/$p.restart.gz" ]; then gunzip -c "$parked/$p.restart.gz" > "$p.restart.a"; fi
    done
    if [ -f "$parked/binaries.txt" ] && [ ! -f binaries.txt ]; then cp "$parked/binaries.txt" .; fi
fi
if [ -f settings ] && [ "$(cat settings)" != "$settings" ]; then
    echo "settings differ from the earlier run in $out: starting over"
    rm -f agglo_Sy*_St*.log agglo_Sy*_St*.hist agglo_Sy*_St*.restart.[ab] agglo_init.* screen.txt \
        screen_Sy*_St*.txt sweep_Sy*_St*.log
fi
printf '%s\n' "$settings" > settings
echo "agglomeration sweep ($tag): N = $n particles, $tend s per grid point, in $out"
start=$(date +%s)
jobs=${AGGLO_JOBS:-1}
case $jobs in '' | *[!0-9]* | 0) echo "AGGLO_JOBS must be a positive integer (got '$jobs')"; exit 1 ;; esac
if [ "$jobs" -gt 1 ]; then
    cores=$(nproc 2>/dev/null || echo 1)
    threads=${AGGLO_THREADS:-$(( cores / jobs > 0 ? cores / jobs : 1 ))}
    export POCL_CPU_MAX_CU_COUNT=$threads POCL_MAX_PTHREAD_COUNT=$threads
    echo "$jobs grid points at once, $threads OpenCL thread(s) each"
fi
running="" # "pid:point" of the grid points running in the background (AGGLO_JOBS > 1)
failed=0

# gravel on grid point ($sy, $st), with the extra arguments given (resume, log)
run_point() {
    "$root/bin/gravel" -in "$deck" -var Sy "$sy" -var St "$st" -var N "$n" -var tend "$tend" \
        -var nout "$nout" -var seed "$seed" -var checkpoints "$ncp" -var kcset "$kcset" \
        -var prefix agglo "$@"
}

# Waits until fewer than $1 background points run; reports those that ended.
reap() {
    while :; do
        left=""
        for job in $running; do
            if kill -0 "${job%%:*}" 2>/dev/null; then
                left="$left $job"
            elif wait "${job%%:*}"; then
                echo "grid point ${job#*:}: done"
            else
                echo "gravel failed on ${job#*:}; see $out/screen_${job#*:agglo_}.txt"
                tail -5 "screen_${job#*:agglo_}.txt"
                failed=1
            fi
        done
        running=$left
        [ "$(echo $running | wc -w)" -lt "$1" ] && return 0
        sleep 5
    done
}

for sy in $sys; do
    for st in $sts; do
        p=agglo_Sy${sy}_St${st}
        if grep -q '^agglomeration grid point done' "$p.log" 2>/dev/null; then
            echo "grid point Sy $sy St $st: finished earlier, kept"
            continue
        fi
        # the newer of the two restart files (written in turn, each atomically)
        rfile=$(/usr/bin/python3 -c 'import os, sys
f = [a for a in sys.argv[1:] if os.path.isfile(a)]
print(max(f, key=lambda a: os.stat(a).st_mtime_ns) if f else "")' "$p.restart.a" "$p.restart.b")
        if [ -n "$rfile" ]; then
            set -- -var resume 1 -var rfile "$rfile"
        else
            rm -f "$p.log" "$p".*hist
            set --
        fi
        if [ "$jobs" -gt 1 ]; then
            reap "$jobs"
            [ $failed = 0 ] || break 2
            : > "screen_${p#agglo_}.txt" # emptied now: the wait below must not read a stale one
            run_point "$@" -log "sweep_${p#agglo_}.log" > "screen_${p#agglo_}.txt" 2>&1 &
            pid=$!
            running="$running $pid:$p"
            echo "grid point Sy $sy St $st: started (pid $pid, output in screen_${p#agglo_}.txt)"
            # a fresh point writes the initial state every point reads: alone until it is read
            while kill -0 $pid 2>/dev/null && ! grep -q '^grid point .* starts at step' "screen_${p#agglo_}.txt"; do
                sleep 2
            done
            grep -E '^(grid point .* starts at step|check:)' "screen_${p#agglo_}.txt" || true
            continue
        fi
        # The deck's own `print` lines show the progress; the full screen output stays in
        # screen.txt (followed from its size now: lines written before tail starts count).
        touch screen.txt
        off=$(( $(wc -c < screen.txt) + 1 ))
        run_point "$@" -log sweep.log >> screen.txt 2>&1 &
        pid=$!
        tail -c +$off -f screen.txt --pid=$pid 2>/dev/null |
            grep --line-buffered -E '^(agglomeration grid point|grid point|check:|ERROR)' || true
        wait $pid || { echo "gravel failed; see $out/screen.txt"; tail -5 screen.txt; exit 1; }
    done
done
reap 1
[ $failed = 0 ] || { echo "a grid point failed: no table"; exit 1; }
echo "sweep took $(( $(date +%s) - start )) s (this invocation)"
/usr/bin/python3 "$root/tools/agglomeration/average.py" . --prefix agglo --out table.dat \
    --markdown "$doc/agglomeration_$tag.md"
cat table.dat
[ "${AGGLO_PLOT:-1}" = 0 ] && exit 0
title="gravel, 000 fig. 6.8 setup: N = $n, $tend s per point, window 5/6-11/12 of the run"
/usr/bin/python3 "$root/tools/agglomeration/plot.py" table.dat "$doc/agglomeration_$tag.png" \
    --title "$title" --series . agglo "$doc/agglomeration_${tag}_series.png"
echo "wrote $doc/agglomeration_$tag.png, $doc/agglomeration_${tag}_series.png, $doc/agglomeration_$tag.md"
