#!/bin/sh
# cli.sh - the command line: -in/-i, stdin, -var/-v, -log/-l (header line),
# -echo/-e, -screen/-sc, -device, -precision, -h, -version, bad flags, and
# exit codes (0 ok, 1 error, quit status). One PASS/FAIL line per check.
cd "$(dirname "$0")/../.." || exit 1
bin="$(pwd)/bin/gravel"
t=$(mktemp -d)
trap 'rm -rf "$t"' EXIT
cd "$t" || exit 1
check() { # name, condition (shell expression)
    if eval "$2"; then echo "PASS cli_$1"; else echo "FAIL cli_$1"; fi
}

printf 'variable a equal 6*7\nprint "a=$a T=${T}"\n' > in.ok
"$bin" -in in.ok -var T 300 > out 2> err; rc=$?
check in_file '[ $rc -eq 0 ] && grep -q "^a=42 T=300$" out'
check default_log '[ -f log.gravel ] && head -1 log.gravel | grep -q "^gravel (" && grep -q "^variable a equal 6\*7$" log.gravel'
check header_screen 'head -1 out | grep -q "^gravel ("'

"$bin" -l custom.log -v T 1 2 -i in.ok > out 2>&1; rc=$?
check short_flags '[ $rc -eq 0 ] && [ -f custom.log ] && grep -q "T=1" out'

rm -f log.gravel
"$bin" -log none < in.ok > out 2>&1; rc=$?
check stdin_and_log_none '[ $rc -eq 1 ] && [ ! -f log.gravel ] && grep -q "variable .T. is not defined" out'

"$bin" -in in.ok -var T -5 -log none -echo screen > out 2>&1; rc=$?
check echo_screen_negative_value '[ $rc -eq 0 ] && grep -q "^print \"a=\$a T=\${T}\"$" out && grep -q "T=-5" out'

"$bin" -in in.ok -var T 1 -log none -screen none > out 2>&1; rc=$?
check screen_none '[ $rc -eq 0 ] && [ ! -s out ]'

printf 'print one\nquit 7\nprint two\n' > in.quit
"$bin" -in in.quit -log none > out 2>&1; rc=$?
check quit_status '[ $rc -eq 7 ] && grep -q "^one$" out && ! grep -q "^two$" out'

printf 'print one\n\nbogus_cmd 1\nprint two\n' > in.bad
"$bin" -in in.bad -log bad.log > out 2> err; rc=$?
check error_exit '[ $rc -eq 1 ] && grep -q "^ERROR: bogus_cmd: unknown command .bogus_cmd. (nearest known command: .*) (in.bad:3)$" err && grep -q "^  bogus_cmd 1$" err && grep -q "^ERROR: bogus_cmd" bad.log && ! grep -q "^two$" out'

"$bin" -in missing.in -log none > out 2>&1; rc=$?
check missing_input '[ $rc -eq 1 ] && grep -q "cannot open input script .missing.in." out'

"$bin" -bogus > out 2>&1; rc=$?
check bad_flag '[ $rc -eq 1 ] && grep -q "unknown option .-bogus." out'
"$bin" -in > out 2>&1; rc=$?
check missing_value '[ $rc -eq 1 ] && grep -q "needs a file name" out'
"$bin" -device fast > out 2>&1; rc=$?
check bad_device '[ $rc -eq 1 ] && grep -q "device must be cpu, serial, gpu or a device number" out'
"$bin" -precision half > out 2>&1; rc=$?
check bad_precision '[ $rc -eq 1 ] && grep -q "precision must be single or double" out'
"$bin" -echo loud > out 2>&1; rc=$?
check bad_echo '[ $rc -eq 1 ] && grep -q "echo must be none, screen, log or both" out'
"$bin" -var 'a-b' 1 -log none < /dev/null > out 2>&1; rc=$?
check bad_var_name '[ $rc -eq 1 ] && grep -q "may contain only letters" out'
printf 'print ok\n' > in.p
"$bin" -device gpu -precision single -progress -in in.p -log none > out 2>&1; rc=$?
check device_precision_accepted '[ $rc -eq 0 ] && grep -q "^ok$" out'

"$bin" -h > out 2>&1; rc=$?
check help '[ $rc -eq 0 ] && grep -q "^  variable " out && grep -q "^  print " out && grep -q "styles:" out'
n_cmd=$(grep -c '^CMD(' "$OLDPWD/src/script/commands.def")
n_help=$(sed -n '/^Commands:/,/^$/p' out | grep -c '^  ')
check help_lists_every_command '[ "$n_cmd" -eq "$n_help" ]'
"$bin" -version > out 2>&1; rc=$?
check version '[ $rc -eq 0 ] && grep -q "^gravel [0-9]" out'

# launched as several MPI ranks (the launcher's environment): every rank stops
# before any file is opened, rank 0 says why; one rank runs as usual
rm -f log.gravel
OMPI_COMM_WORLD_SIZE=2 OMPI_COMM_WORLD_RANK=0 "$bin" -in in.ok -var T 1 > out 2>&1; rc=$?
check mpi_ranks_refused '[ $rc -eq 1 ] && [ ! -f log.gravel ] && grep -q "^ERROR: bin/gravel was launched as 2 MPI ranks, but it is the one-process build: run bin/gravel-mpi" out'
PMI_SIZE=4 PMI_RANK=3 "$bin" -in in.ok -var T 1 > out 2>&1; rc=$?
check mpi_other_rank_silent '[ $rc -eq 1 ] && [ ! -s out ] && [ ! -f log.gravel ]'
OMPI_COMM_WORLD_SIZE=1 OMPI_COMM_WORLD_RANK=0 "$bin" -in in.ok -var T 1 > out 2>&1; rc=$?
check mpi_one_rank_runs '[ $rc -eq 0 ] && grep -q "^a=42 T=1$" out'
