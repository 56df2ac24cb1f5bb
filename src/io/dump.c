/* dump.c - the dump registry (styles/styles.def), the `dump`, `dump_modify`
 * and `undump` commands, the LAMMPS schedule, and crash-safe file writing
 * (temporary name + rename; see dump.h for the scheme). */
#include "dump.h"
#include "par.h"

#include <ctype.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "engine.h"
#include "error.h"
#include "outfile.h"

#define PAIR(k, i)
#define FIX(k, i)
#define COMPUTE(k, i)
#define REGION(k, i)
#define DUMP(k, i) extern const struct dump_style dump_style_##i;
#include "styles.def"
#undef DUMP

static const struct dump_style *const dump_styles[] = {
#define DUMP(k, i) &dump_style_##i,
#include "styles.def"
#undef DUMP
    NULL};
#undef PAIR
#undef FIX
#undef COMPUTE
#undef REGION

struct dump *dump_find(struct gravel *g, const char *id)
{
    for (int i = 0; i < g->styles.ndump; i++)
        if (strcmp(g->styles.dump[i]->id, id) == 0)
            return g->styles.dump[i];
    return NULL;
}

/* ---- file names ------------------------------------------------------------- */

/* The file a snapshot at `step` goes to: '*' replaced by the step, zero
 * padded to d->pad digits. malloc'd. */
static char *snapshot_name(struct gravel *g, const struct dump *d, bigint step)
{
    const char *star = strchr(d->file, '*');
    if (!star)
        return gr_strdup(g, d->file);
    char num[40];
    snprintf(num, sizeof num, "%0*lld", d->pad, (long long)step);
    size_t n = strlen(d->file) + strlen(num);
    char *s = gr_malloc(g, n);
    snprintf(s, n, "%.*s%s%s", (int)(star - d->file), d->file, num, star + 1);
    return s;
}

/* ---- lifetime ---------------------------------------------------------------- */

/* Finish the append-mode file: rename its temporary over the target (a
 * target written through is flushed and stays open until `final`, so a
 * FIFO's reader sees one stream across runs). `strict`: errors raise, else
 * warn (destroy path). */
static void publish(struct gravel *g, struct dump *d, int strict, int final)
{
    if (!d->out.fp)
        return;
    char tmp[600];
    snprintf(tmp, sizeof tmp, "%.590s", d->out.tmp ? d->out.tmp : "");
    int e;
    if (of_through(&d->out) && !final) {
        if ((e = of_flush(&d->out)) == 0)
            return;
        of_abort(&d->out);
        if (strict)
            gr_error(g, "dump %s: cannot write '%.250s': %s", d->id, d->file, strerror(e));
        gr_warn(g, "dump %s: cannot write '%.250s': %s", d->id, d->file, strerror(e));
        return;
    }
    int through = of_through(&d->out);
    if ((e = of_commit(&d->out, OF_KEEP)) == 0) {
        d->published = !through;
        return;
    }
    if (through) {
        if (strict)
            gr_error(g, "dump %s: cannot write '%.250s': %s", d->id, d->file, strerror(e));
        gr_warn(g, "dump %s: cannot write '%.250s': %s", d->id, d->file, strerror(e));
        return;
    }
    if (strict)
        gr_error(g, "dump %s: cannot finish file '%.250s': %s (the new data is in %s)", d->id,
                 d->file, strerror(e), tmp);
    gr_warn(g, "dump %s: cannot finish file '%.250s': %s (the new data is in %s)", d->id, d->file,
            strerror(e), tmp);
}

static void dump_delete(struct gravel *g, struct dump *d, int strict)
{
    if (!d)
        return;
    publish(g, d, strict, 1);
    if (d->style && d->style->destroy)
        d->style->destroy(d);
    free(d->file);
    free(d->every_var);
    free(d->idx);
    free(d);
}

void dump_free_all(struct gravel *g)
{
    for (int i = 0; i < g->styles.ndump; i++)
        dump_delete(g, g->styles.dump[i], 0);
    free(g->styles.dump);
    g->styles.dump = NULL;
    g->styles.ndump = g->styles.ndump_cap = 0;
}

void dump_free_pending(struct gravel *g)
{
    for (int i = 0; i < g->styles.ndump; i++)
        publish(g, g->styles.dump[i], 0, 0);
}

void dump_run_end(struct gravel *g)
{
    for (int i = 0; i < g->styles.ndump; i++)
        publish(g, g->styles.dump[i], 1, 0);
}

/* ---- commands ------------------------------------------------------------------ */

static void check_id(struct gravel *g, const char *id)
{
    size_t n = strlen(id);
    if (n == 0 || n >= GR_NAMELEN)
        gr_error(g, "dump ID must have 1 to %d characters", GR_NAMELEN - 1);
    for (size_t k = 0; k < n; k++)
        if (!isalnum((unsigned char)id[k]) && id[k] != '_')
            gr_error(g, "dump ID '%.64s' may contain only letters, digits and underscores", id);
}

void cmd_dump(struct gravel *g, int argc, char **argv)
{
    check_id(g, argv[0]);
    if (dump_find(g, argv[0]))
        gr_error(g, "dump ID '%.64s' already exists; use undump first", argv[0]);
    int igroup = arg_group(g, argv[1]);
    const struct dump_style *st = NULL;
    for (int k = 0; dump_styles[k]; k++)
        if (strcmp(dump_styles[k]->name, argv[2]) == 0)
            st = dump_styles[k];
    if (!st) {
        char known[256] = "";
        for (int k = 0; dump_styles[k]; k++) {
            strncat(known, k ? ", " : "", sizeof known - strlen(known) - 1);
            strncat(known, dump_styles[k]->name, sizeof known - strlen(known) - 1);
        }
        gr_error(g, "unknown dump style '%.64s' (known: %s)", argv[2], known);
    }
    int every = arg_int(g, argv[3], "the dump interval N");
    if (every <= 0)
        gr_error(g, "the dump interval N must be positive, got %d", every);
    const char *file = argv[4];
    if (!*file || strlen(file) > 4000)
        gr_error(g, "invalid dump file name");
    const char *star = strchr(file, '*');
    if (star && strchr(star + 1, '*'))
        gr_error(g, "dump file name '%.200s' has more than one '*'", file);
    if (strchr(file, '%'))
        gr_error(g, "dump file name '%.200s': '%%' (one file per process) is not supported",
                 file);
    for (int k = 0; k < g->styles.ndump; k++)
        if (strcmp(g->styles.dump[k]->file, file) == 0)
            gr_error(g, "file '%.200s' is already written by dump %s", file,
                     g->styles.dump[k]->id);
    size_t fl = strlen(file);
    if (fl > 3 && strcmp(file + fl - 3, ".gz") == 0)
        gr_error(g, "dump file name '%.200s': compressed dumps are not supported", file);

    struct dump *d = gr_calloc(g, 1, sizeof *d);
    snprintf(d->id, sizeof d->id, "%s", argv[0]);
    d->style = st;
    d->igroup = igroup;
    d->groupbit = 1u << igroup;
    d->every = every;
    d->multifile = star != NULL;
    d->last_dump = -1;
    d->file = strdup(file);
    if (!d->file) {
        free(d);
        gr_error(g, "out of memory");
    }

    struct styles *s = &g->styles;
    if (s->ndump == s->ndump_cap) {
        int cap = s->ndump_cap ? 2 * s->ndump_cap : 4;
        struct dump **p = realloc(s->dump, (size_t)cap * sizeof *p);
        if (!p) {
            dump_delete(g, d, 0);
            gr_error(g, "out of memory");
        }
        s->dump = p;
        s->ndump_cap = cap;
    }
    s->dump[s->ndump++] = d;

    jmp_buf jb, *outer = g->err.jmp;
    g->err.jmp = &jb;
    if (setjmp(jb)) {
        g->err.jmp = outer;
        s->ndump--;
        dump_delete(g, d, 0);
        if (outer)
            longjmp(*outer, 1);
        gr_report_error(g);
        exit(1);
    }
    st->create(g, d, argc - 5, argv + 5);
    g->err.jmp = outer;
}

/* One pass over the dump_modify keywords. With apply 0 the core settings go
 * to a scratch copy and the style hook only checks: a pass that raises no
 * error leaves d as it was. */
static void dump_modify_pass(struct gravel *g, struct dump *d, int argc, char **argv, int apply)
{
    struct dump scratch = *d;
    struct dump *t = apply ? d : &scratch;
    for (int i = 1; i < argc;) {
        const char *kw = argv[i];
        int used = d->style->modify ? d->style->modify(g, d, argc, argv, i, apply) : 0;
        if (used > 0) {
            i += used;
            continue;
        }
        if (strcmp(kw, "every") == 0) {
            arg_need(g, argc, i, 1, kw);
            const char *a = argv[i + 1];
            if (a[0] == 'v' && a[1] == '_') { /* the variable's value: the next step */
                if (!a[2] || strlen(a + 2) >= GR_NAMELEN)
                    gr_error(g, "every v_name needs a variable name, got '%.64s'", a);
                if (apply) {
                    free(d->every_var);
                    d->every_var = gr_strdup(g, a + 2);
                }
            } else {
                int n = arg_int(g, a, "every");
                if (n <= 0)
                    gr_error(g, "every must be positive, got %d", n);
                t->every = n;
                if (apply) {
                    free(d->every_var);
                    d->every_var = NULL;
                }
            }
            i += 2;
        } else if (strcmp(kw, "sort") == 0) {
            arg_need(g, argc, i, 1, kw);
            if (strcmp(argv[i + 1], "id") == 0)
                t->sort = 1;
            else if (strcmp(argv[i + 1], "off") == 0)
                t->sort = 0;
            else
                gr_error(g, "sort must be id or off, got '%.64s' (sorting by a column is not "
                            "supported)", argv[i + 1]);
            i += 2;
        } else if (strcmp(kw, "pad") == 0) {
            arg_need(g, argc, i, 1, kw);
            t->pad = arg_int_range(g, argv[i + 1], 0, 20, "pad");
            i += 2;
        } else if (strcmp(kw, "first") == 0) {
            arg_need(g, argc, i, 1, kw);
            t->first = arg_yesno(g, argv[i + 1], "first");
            i += 2;
        } else if (strcmp(kw, "append") == 0) {
            arg_need(g, argc, i, 1, kw);
            int yes = arg_yesno(g, argv[i + 1], "append");
            if (!d->style->append || d->multifile)
                gr_error(g, "append applies to a dump custom writing one file (dump %s)", d->id);
            if (d->nsnap == 0)
                t->published = yes; /* the first snapshot continues the existing file */
            i += 2;
        } else if (strcmp(kw, "binary") == 0) {
            gr_error(g, "binary applies to dump vtk only (dump %s is %s)", d->id, d->style->name);
        } else if (strcmp(kw, "scale") == 0 || strcmp(kw, "image") == 0) {
            gr_error(g, "%s applies to dump atom only (dump %s is %s)", kw, d->id,
                     d->style->name);
        } else {
            gr_error(g, "unknown keyword '%.64s' for dump %s (%s): known are every, sort, pad, "
                        "first%s", kw, d->id, d->style->name,
                     strcmp(d->style->name, "vtk") == 0 ? ", binary" : ", append, format");
        }
    }
}

void cmd_dump_modify(struct gravel *g, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "expected: dump_modify ID keyword value ...");
    struct dump *d = dump_find(g, argv[0]);
    if (!d)
        gr_error(g, "unknown dump ID '%.64s'", argv[0]);
    if (argc < 2)
        gr_error(g, "expected keyword/value pairs after the dump ID");
    dump_modify_pass(g, d, argc, argv, 0);
    dump_modify_pass(g, d, argc, argv, 1);
}

void cmd_undump(struct gravel *g, int argc, char **argv)
{
    if (argc != 1)
        gr_error(g, "expected: undump ID");
    struct styles *s = &g->styles;
    for (int i = 0; i < s->ndump; i++) {
        struct dump *d = s->dump[i];
        if (strcmp(d->id, argv[0]) != 0)
            continue;
        memmove(s->dump + i, s->dump + i + 1, (size_t)(s->ndump - i - 1) * sizeof *s->dump);
        s->ndump--;
        dump_delete(g, d, 0);
        return;
    }
    gr_error(g, "unknown dump ID '%.64s'", argv[0]);
}

/* `write_dump group style file args... [modify dump_modify args...]`: one
 * snapshot of the current state now, through a temporary dump, as LAMMPS'
 * write_dump. Between runs the host arrays are current. */
static const char *const write_dump_id = "WRITE_DUMP";

/* Create the temporary dump from "group style file args" (m words). */
static void write_dump_create(struct gravel *g, int m, char **argv)
{
    char *dargv[260];
    if (m > 250)
        gr_error(g, "too many arguments");
    dargv[0] = (char *)write_dump_id;
    dargv[1] = argv[0];
    dargv[2] = argv[1];
    dargv[3] = "1";
    for (int k = 2; k < m; k++)
        dargv[k + 2] = argv[k];
    cmd_dump(g, m + 2, dargv);
}

/* Apply the words after "modify" (n of them) to the temporary dump. */
static void write_dump_modify(struct gravel *g, int n, char **words)
{
    char *dargv[260];
    if (n < 1)
        gr_error(g, "modify needs dump_modify keywords after it");
    if (n > 250)
        gr_error(g, "too many arguments");
    dargv[0] = (char *)write_dump_id;
    for (int k = 0; k < n; k++)
        dargv[k + 1] = words[k];
    cmd_dump_modify(g, n + 1, dargv);
}

void cmd_write_dump(struct gravel *g, int argc, char **argv)
{
    const char *tmp_id = write_dump_id;
    if (argc < 3)
        gr_error(g, "expected: write_dump group style file args... [modify keyword value ...]");
    if (!g->dom.box_exists)
        gr_error(g, "write_dump before the simulation box is defined");
    int m = argc;
    for (int k = 3; k < argc && m == argc; k++)
        if (strcmp(argv[k], "modify") == 0)
            m = k;
    write_dump_create(g, m, argv);
    struct dump *d = dump_find(g, tmp_id);

    jmp_buf jb, *outer = g->err.jmp;
    g->err.jmp = &jb;
    if (setjmp(jb)) {
        g->err.jmp = outer;
        char *id[1] = {(char *)tmp_id};
        cmd_undump(g, 1, id);
        if (outer)
            longjmp(*outer, 1);
        gr_report_error(g);
        exit(1);
    }
    if (m < argc)
        write_dump_modify(g, argc - m - 1, argv + m + 1);
    if (d->style->init)
        d->style->init(g, d);
    dump_write(g, d);
    publish(g, d, 1, 1);
    g->err.jmp = outer;
    char *id[1] = {(char *)tmp_id};
    cmd_undump(g, 1, id);
}

/* ---- writing ------------------------------------------------------------------- */

static int cmp_tag(const void *a, const void *b, void *arg)
{
    const int64_t *tag = arg;
    int64_t ta = tag[*(const int *)a], tb = tag[*(const int *)b];
    return (ta > tb) - (ta < tb);
}

/* Host indices of the atoms in the group, sorted by tag when asked. */
static int select_atoms(struct gravel *g, struct dump *d)
{
    const struct atoms *a = &g->atoms;
    if (d->idx_cap < a->n || !d->idx) {
        int cap = a->n > 16 ? a->n : 16;
        d->idx = gr_realloc(g, d->idx, (size_t)cap * sizeof *d->idx);
        d->idx_cap = cap;
    }
    int n = 0;
    for (int i = 0; i < a->n; i++)
        if (a->mask[i] & d->groupbit)
            d->idx[n++] = i;
    if (d->sort)
        qsort_r(d->idx, (size_t)n, sizeof *d->idx, cmp_tag, a->tag);
    return n;
}

/* Raise the failure of of_open for dump d. */
static _Noreturn void open_error(struct gravel *g, struct dump *d, const struct ofile *o, int e)
{
    if (o->copying)
        gr_error(g, "dump %s: cannot copy '%.250s' to continue it: %s", d->id, o->failed,
                 strerror(e));
    gr_error(g, "dump %s: cannot open '%.250s': %s", d->id, o->failed, strerror(e));
}

void dump_write(struct gravel *g, struct dump *d)
{
    int n = select_atoms(g, d);
    int append = d->style->append && !d->multifile;
    struct ofile snap, *o = append ? &d->out : &snap;
    char *name = NULL;
    if (!append || !d->out.fp) {
        name = append ? NULL : snapshot_name(g, d, g->step);
        int e = of_open(o, append ? d->file : name, ".tmp",
                        append && d->published ? OF_CONTINUE : OF_TRUNC);
        free(name);
        if (e)
            open_error(g, d, o, e);
    }

    /* the style may raise an error (e.g. a compute column): clean up first */
    jmp_buf jb, *outer = g->err.jmp;
    g->err.jmp = &jb;
    if (setjmp(jb)) {
        g->err.jmp = outer;
        of_abort(o);
        if (outer)
            longjmp(*outer, 1);
        gr_report_error(g);
        exit(1);
    }
    d->style->write(g, d, o->fp, d->idx, n);
    g->err.jmp = outer;

    char shown[300];
    snprintf(shown, sizeof shown, "%.250s", o->tmp && append ? o->tmp : o->final);
    int e = append ? of_flush(o) : of_commit(o, 0);
    if (e) {
        of_abort(o);
        gr_error(g, "dump %s: cannot write '%s': %s", d->id, shown, strerror(e));
    }
    d->last_dump = g->step;
    d->nsnap++;
}

/* ---- schedule ------------------------------------------------------------------ */

static bigint next_multiple(bigint step, int every)
{
    return (step / every) * every + every;
}

/* The step of d's next snapshot after `step`: the next multiple of N, or
 * with every v_name -1: output.c evaluates the variable (dump_every_var). */
static bigint next_dump_step(const struct dump *d, bigint step)
{
    return d->every_var ? -1 : next_multiple(step, d->every);
}

/* d writes at `step`: a multiple of N, or with every v_name the step its
 * variable gave */
static int dump_at(const struct dump *d, bigint step)
{
    return d->every_var ? step == d->next_dump : step % d->every == 0;
}

/* Dumps that run on several ranks: the atoms' own fields and the local
 * computes' rows, gathered (par.h); the meshes' geometry, the same on every
 * rank, and their stress and wear (summed over every rank's atoms in tag
 * order, fix mesh/surface/stress). Rank 0 writes. */
static const char *const across_ranks[] = {"atom",     "custom",   "vtk",
                                           "custom/vtk", "local",  "mesh/stl",
                                           "mesh/vtk", "mesh/gran/VTK", NULL};

void dump_setup_all(struct gravel *g)
{
    int synced = 0;
    for (int i = 0; i < g->styles.ndump && par_on(g); i++) {
        struct dump *d = g->styles.dump[i];
        int ok = 0;
        for (int k = 0; across_ranks[k]; k++)
            ok = ok || strcmp(across_ranks[k], d->style->name) == 0;
        if (!ok) {
            char why[160];
            snprintf(why, sizeof why, "dump %s (%.60s)", d->id, d->style->name);
            par_refuse(g, why);
        }
    }
    for (int i = 0; i < g->styles.ndump; i++) {
        struct dump *d = g->styles.dump[i];
        if (d->style->init)
            d->style->init(g, d);
    }
    for (int i = 0; i < g->styles.ndump; i++) {
        struct dump *d = g->styles.dump[i];
        /* the run's first step: a multiple of N, or (every v_name too) `first yes` */
        int due = (!d->every_var && g->step % d->every == 0) || (d->first && d->last_dump < 0);
        if (due && d->last_dump != g->step) {
            if (!synced) {
                run_sync_host(g);
                par_gather_begin(g); /* several ranks: every atom, rank 0 writes */
                synced = 1;
            }
            dump_write(g, d);
        }
        d->next_dump = next_dump_step(d, g->step);
    }
    par_gather_end(g);
}

int dump_due(struct gravel *g, bigint step)
{
    for (int i = 0; i < g->styles.ndump; i++) {
        struct dump *d = g->styles.dump[i];
        if (dump_at(d, step) && d->last_dump != step)
            return 1;
    }
    return 0;
}

int dump_step_all(struct gravel *g)
{
    if (!dump_due(g, g->step))
        return 0;
    run_sync_host(g);
    par_gather_begin(g); /* several ranks: every atom, rank 0 writes */
    for (int i = 0; i < g->styles.ndump; i++) {
        struct dump *d = g->styles.dump[i];
        const int at = dump_at(d, g->step);
        if (at && d->last_dump != g->step)
            dump_write(g, d);
        if (at || !d->every_var)
            d->next_dump = next_dump_step(d, g->step);
    }
    par_gather_end(g);
    return 1;
}

/* ---- legacy VTK and binary helpers --------------------------------------------- */

void dump_vtk_check_name(struct gravel *g, const struct dump *d)
{
    const char *dot = strrchr(d->file, '.');
    if (dot && !strcmp(dot, ".vtk"))
        return;
    if (dot && (!strcmp(dot, ".vtu") || !strcmp(dot, ".vtp") || !strcmp(dot, ".pvtu") ||
                !strcmp(dot, ".pvtp")))
        gr_error(g, "dump %s: %s files (VTK XML) are not written here: use a .vtk file name "
                    "(legacy VTK)", d->style->name, dot);
    gr_error(g, "dump %s: file name '%.200s' needs the extension .vtk", d->style->name, d->file);
}

void dump_vtk_polydata_head(struct gravel *g, const struct dump *d, FILE *fp, const char *title)
{
    const int bin = d->binary;
    fprintf(fp, "# vtk DataFile Version 3.0\n%s\n%s\nDATASET POLYDATA\n", title,
            bin ? "BINARY" : "ASCII");
    fprintf(fp, "FIELD FieldData 2\nTIME 1 1 double\n");
    const int32_t cyc = g->step > INT32_MAX ? INT32_MAX : (int32_t)g->step;
    if (bin) {
        dump_write_be_doubles(fp, &g->time, 1);
        fprintf(fp, "\nCYCLE 1 1 int\n");
        dump_write_be_int32(fp, &cyc, 1);
        fputc('\n', fp);
    } else {
        fprintf(fp, "%.17g\nCYCLE 1 1 int\n%d\n", g->time, (int)cyc);
    }
}

int dump_vtk_binary(struct gravel *g, struct dump *d, int argc, char **argv, int i, int apply)
{
    if (strcmp(argv[i], "binary"))
        return 0;
    arg_need(g, argc, i, 1, "binary");
    int yes = arg_yesno(g, argv[i + 1], "binary");
    if (apply)
        d->binary = yes;
    return 2;
}


void dump_write_be_doubles(FILE *fp, const double *v, size_t n)
{
    unsigned char buf[8 * 512];
    size_t k = 0;
    for (size_t i = 0; i < n; i++) {
        uint64_t u;
        memcpy(&u, &v[i], 8);
        for (int b = 7; b >= 0; b--)
            buf[k++] = (unsigned char)(u >> (8 * b));
        if (k == sizeof buf) {
            fwrite(buf, 1, k, fp);
            k = 0;
        }
    }
    if (k)
        fwrite(buf, 1, k, fp);
}

void dump_write_be_int32(FILE *fp, const int32_t *v, size_t n)
{
    unsigned char buf[4 * 1024];
    size_t k = 0;
    for (size_t i = 0; i < n; i++) {
        uint32_t u = (uint32_t)v[i];
        for (int b = 3; b >= 0; b--)
            buf[k++] = (unsigned char)(u >> (8 * b));
        if (k == sizeof buf) {
            fwrite(buf, 1, k, fp);
            k = 0;
        }
    }
    if (k)
        fwrite(buf, 1, k, fp);
}
