#!/bin/sh
# Runs the agglomeration study of source document 000 chapter 6 end to end
# (`make reproduce-agglomeration`): the deck inputs/published/agglomeration/
# agglomeration.in sweeps the 4 x 4 Stickiness x Stokes grid in one gravel
# process, tools/agglomeration/average.py averages every grid point over the
# window of 000 sec. 6.2.2 (the same fraction of the run as 500-550 s of 600 s),
# tools/agglomeration/plot.py draws fig. 6.8 (mean size and void fraction against
# the Stokes number, one line per Stickiness number) and the time series.
#
# Environment (all optional):
#   AGGLO_QUICK=1  shortened sweep: 5 s per grid point (a few minutes in all)
#   AGGLO_N        number of particles     (default 1000; 000 table 6.1: 10000)
#   AGGLO_TEND     simulated s per point   (default 300, quick 5; 000: 600)
#   AGGLO_NOUT     thermo rows per point   (default 240, quick 50)
#   AGGLO_TAG      name of this run in the output names (default full or quick)
#   AGGLO_OUT      run directory (default build/agglomeration/<tag>)
#   AGGLO_DOC      where the PNGs and the Markdown table go (default doc)
# Outputs: $AGGLO_DOC/agglomeration_<tag>.png (fig. 6.8), _<tag>_series.png,
# _<tag>.md (table); the logs, table.dat and the initial state in the run dir.
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
if [ "${AGGLO_QUICK:-0}" = 1 ]; then
    tag=quick; tend=${AGGLO_TEND:-5}; nout=${AGGLO_NOUT:-50}
else
    tag=full; tend=${AGGLO_TEND:-300}; nout=${AGGLO_NOUT:-240}
fi
n=${AGGLO_N:-1000}
tag=${AGGLO_TAG:-$tag}
out=${AGGLO_OUT:-$root/build/agglomeration/$tag}
doc=${AGGLO_DOC:-$root/doc}
mkdir -p "$out" "$doc"
rm -f "$out"/agglo_Sy*_St*.log
echo "agglomeration sweep ($tag): N = $n particles, $tend s per grid point, 16 grid points, in $out"
start=$(date +%s)
cd "$out"
# The deck's own `print` lines show the progress; the full screen output stays in screen.txt.
"$root/bin/gravel" -in "$root/inputs/published/agglomeration/agglomeration.in" \
    -var N "$n" -var tend "$tend" -var nout "$nout" -var prefix agglo \
    -log sweep.log > screen.txt 2>&1 &
pid=$!
tail -f screen.txt --pid=$pid 2>/dev/null | grep --line-buffered -E '^(agglomeration grid point|check:|ERROR)' || true
wait $pid || { echo "gravel failed; see $out/screen.txt"; tail -5 screen.txt; exit 1; }
echo "sweep took $(( $(date +%s) - start )) s"
/usr/bin/python3 "$root/tools/agglomeration/average.py" . --prefix agglo --out table.dat \
    --markdown "$doc/agglomeration_$tag.md"
cat table.dat
title="gravel, 000 fig. 6.8 setup: N = $n, $tend s per point, window 5/6-11/12 of the run"
/usr/bin/python3 "$root/tools/agglomeration/plot.py" table.dat "$doc/agglomeration_$tag.png" \
    --title "$title" --series . agglo "$doc/agglomeration_${tag}_series.png"
echo "wrote $doc/agglomeration_$tag.png, $doc/agglomeration_${tag}_series.png, $doc/agglomeration_$tag.md"
