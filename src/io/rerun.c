/* rerun.c - `rerun file ... [first N] [last N] [every N] [skip N] [start N]
 * [stop N] dump field ... [read_dump keywords]` as LAMMPS 2021 (rerun.cpp):
 * a run that integrates nothing. The files are scanned in order for the
 * first snapshot at step >= first; each snapshot taken (step <= last, a
 * multiple of `every` when > 0, every `skip`-th of those) is read as
 * read_dump reads it (the fields and keywords after `dump`, box yes by
 * default), the step is set to its timestep, and the forces, the fixes'
 * setup and end_of_step work and the output due at that step are computed
 * on it (the first snapshot prints the thermo header and row; the last
 * snapshot's row is always printed). Pair styles with contact history see
 * no history update (LAMMPS's setup_minimal). start / stop give the run's
 * bounds as time-dependent styles see them (default: first / last); a
 * snapshot after `stop` is an error, and so is a time-dependent fix (fix
 * pour), as LAMMPS. The footer counts snapshots as steps. */
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "command.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "read_dump.h"
#include "run.h"

struct rerun_ctx {
    struct rdump *rd;
    bigint last, stop;
    int nevery, nskip, stopflag;
};

static bigint load_next(struct gravel *g, void *p)
{
    struct rerun_ctx *c = p;
    bigint step = rd_next(g, c->rd, g->step, c->last, c->nevery, c->nskip);
    if (c->stopflag && step > c->stop)
        gr_error(g, "dump snapshot at step %lld is after the rerun stop step %lld",
                 (long long)step, (long long)c->stop);
    if (step < 0)
        return -1;
    g->step = step;
    rd_atoms(g, c->rd);
    return step;
}

static int is_keyword(const char *s)
{
    static const char *kw[] = {"first", "last", "every", "skip", "start", "stop", "dump"};
    for (size_t k = 0; k < sizeof kw / sizeof kw[0]; k++)
        if (!strcmp(s, kw[k]))
            return 1;
    return 0;
}

void cmd_rerun(struct gravel *g, int argc, char **argv)
{
    domain_require_box(g);
    int nfile = 0;
    while (nfile < argc && !is_keyword(argv[nfile]))
        nfile++;
    if (nfile == 0)
        gr_error(g, "needs at least one dump file before the keywords");
    if (nfile == argc)
        gr_error(g, "needs the dump keyword and its fields (rerun file dump x y z)");
    bigint first = 0, last = ((bigint)1 << 62) - 1, start = -1, stop = -1;
    int nevery = 0, nskip = 1, startflag = 0, stopflag = 0, i = nfile;
    while (i < argc && strcmp(argv[i], "dump")) {
        const char *kw = argv[i];
        if (!is_keyword(kw))
            gr_error(g, "unknown keyword '%.32s' (first, last, every, skip, start, stop, dump)",
                     kw);
        arg_need(g, argc, i, 1, kw);
        const char *v = argv[i + 1];
        if (!strcmp(kw, "first") || !strcmp(kw, "last") || !strcmp(kw, "start") ||
            !strcmp(kw, "stop")) {
            bigint n = arg_bigint(g, v, kw);
            if (n < 0)
                gr_error(g, "%s must be >= 0, got %s", kw, v);
            if (kw[0] == 'f')
                first = n;
            else if (kw[0] == 'l')
                last = n;
            else if (!strcmp(kw, "start"))
                start = n, startflag = 1;
            else
                stop = n, stopflag = 1;
        } else {
            int n = arg_int(g, v, kw);
            if (!strcmp(kw, "every")) {
                if (n < 0)
                    gr_error(g, "every must be >= 0, got %s", v);
                nevery = n;
            } else {
                if (n <= 0)
                    gr_error(g, "skip must be > 0, got %s", v);
                nskip = n;
            }
        }
        i += 2;
    }
    if (i >= argc - 1)
        gr_error(g, "dump needs the fields to read (rerun file dump x y z)");
    if (first > last)
        gr_error(g, "first %lld is after last %lld", (long long)first, (long long)last);
    if (startflag && stopflag && start > stop)
        gr_error(g, "start %lld is after stop %lld", (long long)start, (long long)stop);

    struct rerun_ctx c = {.last = last, .stop = stop, .nevery = nevery, .nskip = nskip,
                          .stopflag = stopflag};
    c.rd = rd_create(g, nfile, argv, argc - i - 1, argv + i + 1);
    jmp_buf jb, *outer = g->err.jmp;
    g->err.jmp = &jb;
    if (setjmp(jb)) {
        g->err.jmp = outer;
        rd_destroy(c.rd);
        if (outer)
            longjmp(*outer, 1);
        gr_report_error(g);
        exit(1);
    }
    fix_check_time_reset(g); /* LAMMPS: each snapshot resets the timestep */
    bigint step = rd_seek(g, c.rd, first, 0);
    if (step < 0)
        gr_error(g, "the dump file(s) hold no snapshot at step %lld or later", (long long)first);
    if (stopflag && step > stop)
        gr_error(g, "dump snapshot at step %lld is after the rerun stop step %lld",
                 (long long)step, (long long)stop);
    g->step = step;
    rd_atoms(g, c.rd);
    run_rerun(g, load_next, &c, startflag ? start : first, stopflag ? stop : last);
    g->err.jmp = outer;
    rd_destroy(c.rd);
}
