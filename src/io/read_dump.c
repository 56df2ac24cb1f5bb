/* read_dump.c - `read_dump file Nstep field ... [keyword value ...]` as
 * LAMMPS 2021 (read_dump.cpp, reader_native.cpp), native text dumps, one
 * process, orthogonal boxes:
 *   fields   x y z vx vy vz ix iy iz fx fy fz (and id, type; z vz iz fz are
 *            illegal in 2d; q does not exist in atom_style sphere). The last
 *            field may not be id or type (LAMMPS's check).
 *   box yes|no       (yes) take the snapshot's box (z only in 3d)
 *   replace yes|no   (yes) overwrite matching atoms' fields (never the type)
 *   purge yes|no     (no) delete every atom first (needs replace no, trim no)
 *   trim yes|no      (no) delete atoms the snapshot does not hold
 *   add yes|keep|no  (no) create snapshot atoms no atom matches (needs the
 *                    dump's type column): yes gives them new IDs after the
 *                    largest, keep the dump's IDs; radius 0.5, density 1
 *   label field col  read a field from a column with another name
 *   scaled, wrapped  yes|no: how a labelled x/y/z column is stored
 *   format native    the only reader (must be last)
 * Columns: x is read from `x`, else from the first of xs, xu, xsu in the
 * file (scaled: lo + s L of the snapshot box; unwrapped: image flags of the
 * replaced atom are zeroed and recomputed by the remap). ix iy iz set image
 * flags. Afterwards every atom is remapped into the periodic box and
 * shrink-wrapped faces refitted. read_dump resets the timestep to Nstep and
 * prints LAMMPS's summary (atoms before read, in snapshot, purged,
 * replaced, trimmed, added, after read). */
#include "read_dump.h"

#include <errno.h>
#include <math.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "command.h"
#include "domain.h"
#include "error.h"
#include "fileio.h"
#include "fix.h"
#include "log.h"

enum { F_ID, F_TYPE, F_X, F_Y, F_Z, F_VX, F_VY, F_VZ, F_Q, F_IX, F_IY, F_IZ, F_FX, F_FY, F_FZ };
static const char *field_name[] = {"id", "type", "x",  "y",  "z",  "vx", "vy", "vz",
                                   "q",  "ix",   "iy", "iz", "fx", "fy", "fz"};
enum { UNSET, NOSCALE_NOWRAP, NOSCALE_WRAP, SCALE_NOWRAP, SCALE_WRAP };
enum { NOADD, YESADD, KEEPADD };
#define RD_MAXFIELD 32
#define RD_MAXLINE (1 << 20)

struct rdump {
    int nfile, curfile;
    char **files;
    FILE *fp;
    char *line;
    size_t cap;
    int nfield, type[RD_MAXFIELD], index[RD_MAXFIELD];
    char *label[RD_MAXFIELD];
    int boxflag, replace, purge, trim, add, scaleflag, wrapflag;
    int scaled, wrapped;
    bigint nsnap;
    double box[3][2];
    double *fields;
    bigint cnt[6];
};

static int which_field(const char *s)
{
    for (int k = 0; k <= F_FZ; k++)
        if (!strcmp(s, field_name[k]))
            return k;
    return -1;
}

void rd_destroy(struct rdump *rd)
{
    if (!rd)
        return;
    if (rd->fp)
        fclose(rd->fp);
    for (int i = 0; i < rd->nfield; i++)
        free(rd->label[i]);
    free(rd->files);
    free(rd->line);
    free(rd->fields);
    free(rd);
}

struct rdump *rd_create(struct gravel *g, int nfile, char **files, int argc, char **argv)
{
    struct rdump *rd = gr_calloc(g, 1, sizeof *rd);
    rd->files = calloc((size_t)nfile, sizeof(char *));
    if (!rd->files) {
        free(rd);
        gr_error(g, "out of memory");
    }
    rd->nfile = nfile;
    for (int i = 0; i < nfile; i++)
        rd->files[i] = files[i];
    rd->curfile = -1;
    jmp_buf jb, *outer = g->err.jmp;
    g->err.jmp = &jb;
    if (setjmp(jb)) {
        g->err.jmp = outer;
        rd_destroy(rd);
        if (outer)
            longjmp(*outer, 1);
        gr_report_error(g);
        exit(1);
    }
    for (int i = 0; i < nfile; i++)
        if (strchr(files[i], '%'))
            gr_error(g, "dump file '%s': multi-process dump files (%%) are not supported",
                     files[i]);
    /* LAMMPS: `add yes|keep` anywhere puts a type field right after the ID */
    int addtype = 0;
    for (int i = 0; i + 1 < argc; i++)
        if (!strcmp(argv[i], "add") && (!strcmp(argv[i + 1], "yes") || !strcmp(argv[i + 1], "keep")))
            addtype = 1;
    rd->type[rd->nfield++] = F_ID;
    if (addtype)
        rd->type[rd->nfield++] = F_TYPE;
    int i = 0;
    for (; i < argc; i++) {
        int t = which_field(argv[i]);
        if (t < 0)
            break;
        if (t == F_Q)
            gr_error(g, "field q: atom_style sphere has no charge");
        if (rd->nfield == RD_MAXFIELD)
            gr_error(g, "too many fields");
        rd->type[rd->nfield++] = t;
    }
    if (rd->type[rd->nfield - 1] == F_ID || rd->type[rd->nfield - 1] == F_TYPE)
        gr_error(g, "needs at least one field after Nstep, and the last field may not be id "
                    "or type (as LAMMPS)");
    for (int k = 0; k < rd->nfield; k++) {
        int t = rd->type[k];
        if (g->dom.dimension == 2 && (t == F_Z || t == F_VZ || t == F_IZ || t == F_FZ))
            gr_error(g, "field %s is illegal in a 2d simulation", field_name[t]);
        for (int j = k + 1; j < rd->nfield; j++)
            if (rd->type[j] == t)
                gr_error(g, "duplicate field %s", field_name[t]);
    }
    rd->boxflag = rd->replace = rd->wrapflag = 1;
    while (i < argc) {
        const char *kw = argv[i];
        arg_need(g, argc, i, 1, kw);
        const char *v = argv[i + 1];
        if (!strcmp(kw, "box")) {
            rd->boxflag = arg_yesno(g, v, kw);
        } else if (!strcmp(kw, "replace")) {
            rd->replace = arg_yesno(g, v, kw);
        } else if (!strcmp(kw, "purge")) {
            rd->purge = arg_yesno(g, v, kw);
        } else if (!strcmp(kw, "trim")) {
            rd->trim = arg_yesno(g, v, kw);
        } else if (!strcmp(kw, "scaled")) {
            rd->scaleflag = arg_yesno(g, v, kw);
        } else if (!strcmp(kw, "wrapped")) {
            rd->wrapflag = arg_yesno(g, v, kw);
        } else if (!strcmp(kw, "add")) {
            if (!strcmp(v, "yes"))
                rd->add = YESADD;
            else if (!strcmp(v, "keep"))
                rd->add = KEEPADD;
            else if (!strcmp(v, "no"))
                rd->add = NOADD;
            else
                gr_error(g, "add must be yes, keep or no, got '%.32s'", v);
        } else if (!strcmp(kw, "label")) {
            arg_need(g, argc, i, 2, kw);
            int t = which_field(v), k = 0;
            while (k < rd->nfield && rd->type[k] != t)
                k++;
            if (t < 0 || k == rd->nfield)
                gr_error(g, "label: '%.32s' is not one of the fields read", v);
            free(rd->label[k]);
            rd->label[k] = strdup(argv[i + 2]);
            if (!rd->label[k])
                gr_error(g, "out of memory");
            i++;
        } else if (!strcmp(kw, "format")) {
            if (strcmp(v, "native"))
                gr_error(g, "format %.32s: only the native dump format is supported", v);
            if (i + 2 < argc)
                gr_error(g, "format native takes no settings, got '%.32s'", argv[i + 2]);
        } else if (!strcmp(kw, "nfile")) {
            gr_error(g, "nfile: the dump file is not a multi-process file");
        } else {
            gr_error(g, "unknown keyword '%.32s' (box, replace, purge, trim, add, label, "
                        "scaled, wrapped, format)",
                     kw);
        }
        i += 2;
    }
    if (rd->purge && (rd->replace || rd->trim))
        gr_error(g, "purge yes cannot be combined with replace or trim (use replace no)");
    g->err.jmp = outer;
    return rd;
}

/* One line into rd->line; 0 at the end of the file. */
static int next_line(struct gravel *g, struct rdump *rd, int need)
{
    ssize_t n = fio_getline(rd->fp, &rd->line, &rd->cap, RD_MAXLINE);
    if (n == FIO_ERR)
        gr_error(g, "cannot read dump file '%s': %s", rd->files[rd->curfile],
                 errno ? strerror(errno) : "line too long");
    if (n == FIO_EOF) {
        if (need)
            gr_error(g, "unexpected end of dump file '%s'", rd->files[rd->curfile]);
        return 0;
    }
    return 1;
}

static int starts(const char *line, const char *item)
{
    while (*line == ' ' || *line == '\t')
        line++;
    return !strncmp(line, item, strlen(item));
}

static bigint parse_count(struct gravel *g, struct rdump *rd, const char *what)
{
    char *end;
    errno = 0;
    long long v = strtoll(rd->line, &end, 10);
    while (*end == ' ' || *end == '\t')
        end++;
    if (errno || end == rd->line || *end || v < 0)
        gr_error(g, "dump file '%s' is incorrectly formatted: expected %s, got '%.40s'",
                 rd->files[rd->curfile], what, rd->line);
    return v;
}

/* ReaderNative::read_time: 1 at the end of the file. */
static int read_time(struct gravel *g, struct rdump *rd, bigint *step)
{
    if (!next_line(g, rd, 0))
        return 1;
    /* optional units and time items before the timestep (LAMMPS skips them) */
    if (starts(rd->line, "ITEM: UNITS")) {
        next_line(g, rd, 1);
        next_line(g, rd, 1);
    }
    if (starts(rd->line, "ITEM: TIME") && !starts(rd->line, "ITEM: TIMESTEP")) {
        next_line(g, rd, 1);
        next_line(g, rd, 1);
    }
    if (!starts(rd->line, "ITEM: TIMESTEP"))
        gr_error(g, "dump file '%s' is incorrectly formatted: expected 'ITEM: TIMESTEP', got "
                    "'%.40s'",
                 rd->files[rd->curfile], rd->line);
    next_line(g, rd, 1);
    *step = parse_count(g, rd, "a timestep");
    return 0;
}

static void skip_snapshot(struct gravel *g, struct rdump *rd)
{
    next_line(g, rd, 1);
    next_line(g, rd, 1);
    bigint n = parse_count(g, rd, "the number of atoms");
    for (int k = 0; k < 5; k++)
        next_line(g, rd, 1);
    for (bigint k = 0; k < n; k++)
        next_line(g, rd, 1);
}

static void open_file(struct gravel *g, struct rdump *rd, int k)
{
    if (rd->fp)
        fclose(rd->fp);
    rd->fp = NULL;
    rd->curfile = k;
    const char *why = NULL;
    rd->fp = fio_open_read(rd->files[k], 0, &why);
    if (!rd->fp)
        gr_error(g, "cannot open dump file '%s': %s", rd->files[k], why ? why : "error");
}

static void close_file(struct rdump *rd)
{
    if (rd->fp)
        fclose(rd->fp);
    rd->fp = NULL;
}

bigint rd_seek(struct gravel *g, struct rdump *rd, bigint nrequest, int exact)
{
    bigint step = -1;
    for (int f = 0; f < rd->nfile; f++) {
        open_file(g, rd, f);
        step = -1;
        while (!read_time(g, rd, &step)) {
            if (step >= nrequest)
                break;
            skip_snapshot(g, rd);
        }
        if (step >= nrequest)
            break;
        close_file(rd);
    }
    if (step < nrequest || (exact && step != nrequest)) {
        close_file(rd);
        return -1;
    }
    return step;
}

bigint rd_next(struct gravel *g, struct rdump *rd, bigint ncurrent, bigint nlast, int nevery,
               int nskip)
{
    bigint step = -1;
    int iskip = 0, eof = 1;
    for (int f = rd->curfile; f < rd->nfile; f++) {
        if (f != rd->curfile || !rd->fp)
            open_file(g, rd, f);
        step = -1;
        eof = 0;
        for (;;) {
            if (read_time(g, rd, &step)) {
                eof = 1;
                break;
            }
            if (step > nlast)
                break;
            if (step <= ncurrent) {
                skip_snapshot(g, rd);
                continue;
            }
            if (iskip == nskip)
                iskip = 0;
            iskip++;
            if (nevery && step % nevery)
                skip_snapshot(g, rd);
            else if (iskip < nskip)
                skip_snapshot(g, rd);
            else
                break;
        }
        if (!eof)
            break;
        close_file(rd);
    }
    if (eof || step <= ncurrent || step > nlast) {
        close_file(rd);
        return -1;
    }
    return step;
}

/* The name of field k's column for messages: the labels read from the
 * header live in the line buffer, which each atom line overwrites (or moves),
 * so the field's own name or `label` is used. */
static const char *column(const struct rdump *rd, int k)
{
    return rd->label[k] ? rd->label[k] : field_name[rd->type[k]];
}

/* The ID, type and image flag columns become integers: a value that is not
 * an integer, or that no conversion could hold (IDs are exact in a double up
 * to 2^53; types and image flags are ints), is an error naming the column,
 * before any conversion. */
static void check_integer(struct gravel *g, const char *fn, int t, const char *col, double v)
{
    double max = t == F_ID ? 9007199254740992.0 : 2147483647.0;
    if ((t == F_ID || t == F_TYPE || (t >= F_IX && t <= F_IZ)) &&
        (v != floor(v) || !(fabs(v) <= max)))
        gr_error(g, "dump file '%s': %.17g in column %s is not an integer of magnitude at most "
                    "%.17g", fn, v, col, max);
}

/* The rest of the header (atoms, box, columns) and the field columns. */
static void read_header(struct gravel *g, struct rdump *rd)
{
    const char *fn = rd->files[rd->curfile];
    next_line(g, rd, 1);
    next_line(g, rd, 1);
    rd->nsnap = parse_count(g, rd, "the number of atoms");
    next_line(g, rd, 1);
    if (!starts(rd->line, "ITEM: BOX BOUNDS"))
        gr_error(g, "dump file '%s' is incorrectly formatted: expected 'ITEM: BOX BOUNDS', got "
                    "'%.40s'",
                 fn, rd->line);
    if (strstr(rd->line, "xy"))
        gr_error(g, "dump file '%s' has a triclinic box; gravel boxes are orthogonal", fn);
    for (int d = 0; d < 3; d++) {
        next_line(g, rd, 1);
        char *end;
        rd->box[d][0] = strtod(rd->line, &end);
        char *e2;
        rd->box[d][1] = strtod(end, &e2);
        if (e2 == end)
            gr_error(g, "dump file '%s' is incorrectly formatted: bad box bounds '%.40s'", fn,
                     rd->line);
    }
    next_line(g, rd, 1);
    if (!starts(rd->line, "ITEM: ATOMS"))
        gr_error(g, "dump file '%s' is incorrectly formatted: expected 'ITEM: ATOMS', got "
                    "'%.40s'",
                 fn, rd->line);
    /* column labels */
    char *cols = strstr(rd->line, "ITEM: ATOMS") + 11;
    char *lab[256];
    int nw = 0;
    for (char *t = strtok(cols, " \t"); t && nw < 256; t = strtok(NULL, " \t"))
        lab[nw++] = t;
    int flag[3] = {UNSET, UNSET, UNSET};
    for (int k = 0; k < rd->nfield; k++) {
        int t = rd->type[k], idx = -1;
        const char *want = rd->label[k] ? rd->label[k] : field_name[t];
        for (int w = 0; w < nw; w++)
            if (!strcmp(lab[w], want)) {
                idx = w;
                break;
            }
        if (t == F_X || t == F_Y || t == F_Z) {
            int d = t - F_X;
            if (rd->label[k]) {
                flag[d] = 2 * rd->scaleflag + rd->wrapflag + 1;
            } else {
                flag[d] = NOSCALE_WRAP;
                if (idx < 0) { /* the first of xs, xu, xsu in the file */
                    static const char *suf[] = {"s", "u", "su"};
                    static const int fl[] = {SCALE_WRAP, NOSCALE_NOWRAP, SCALE_NOWRAP};
                    int best = nw;
                    for (int s = 0; s < 3; s++) {
                        char nm[8];
                        snprintf(nm, sizeof nm, "%c%s", 'x' + d, suf[s]);
                        for (int w = 0; w < nw; w++)
                            if (!strcmp(lab[w], nm) && w < best) {
                                best = w;
                                flag[d] = fl[s];
                            }
                    }
                    idx = best < nw ? best : -1;
                }
            }
        }
        if (idx < 0)
            gr_error(g, "field %s (column '%s') not found in dump file '%s'", field_name[t],
                     want, fn);
        rd->index[k] = idx;
    }
    int value = UNSET;
    for (int d = 0; d < 3; d++)
        value = flag[d] > value ? flag[d] : value;
    for (int d = 0; d < 3; d++)
        if (flag[d] != UNSET && flag[d] != value)
            gr_error(g, "the x, y, z columns of dump file '%s' do not have consistent "
                        "scaling/wrapping",
                     fn);
    rd->scaled = value == SCALE_NOWRAP || value == SCALE_WRAP;
    rd->wrapped = value == NOSCALE_WRAP || value == SCALE_WRAP;
    /* the atoms */
    free(rd->fields);
    rd->fields = NULL;
    if (rd->nsnap > 200000000)
        gr_error(g, "dump file '%s': snapshot of %lld atoms is too large", fn,
                 (long long)rd->nsnap);
    rd->fields = malloc(((size_t)rd->nsnap + 1) * (size_t)rd->nfield * sizeof(double));
    if (!rd->fields)
        gr_error(g, "out of memory");
    for (bigint i = 0; i < rd->nsnap; i++) {
        next_line(g, rd, 1);
        char *w[256];
        int n = 0;
        for (char *t = strtok(rd->line, " \t"); t && n < 256; t = strtok(NULL, " \t"))
            w[n++] = t;
        if (n < nw)
            gr_error(g, "dump file '%s': insufficient columns in an atom line (%d of %d)", fn, n,
                     nw);
        for (int k = 0; k < rd->nfield; k++) {
            char *end;
            double v = strtod(w[rd->index[k]], &end);
            if (end == w[rd->index[k]] || *end)
                gr_error(g, "dump file '%s': bad number '%.32s' in column %s", fn,
                         w[rd->index[k]], column(rd, k));
            check_integer(g, fn, rd->type[k], column(rd, k), v);
            rd->fields[(size_t)i * rd->nfield + k] = v;
        }
    }
}

static double coord(const struct rdump *rd, int d, double v)
{
    return rd->scaled ? v * (rd->box[d][1] - rd->box[d][0]) + rd->box[d][0] : v;
}

static int by_tag(const void *pa, const void *pb)
{
    const int64_t *a = pa, *b = pb;
    return (a[0] > b[0]) - (a[0] < b[0]);
}

/* Index of tag among the first n atoms (sorted (tag, index) pairs), or -1. */
static int find_tag(const int64_t *map, int n, int64_t tag)
{
    int lo = 0, hi = n - 1;
    while (lo <= hi) {
        int mid = (lo + hi) / 2;
        if (map[2 * mid] == tag)
            return (int)map[2 * mid + 1];
        if (map[2 * mid] < tag)
            lo = mid + 1;
        else
            hi = mid - 1;
    }
    return -1;
}

static void process_atoms(struct gravel *g, struct rdump *rd, int64_t *map, char *upd,
                          char *isnew)
{
    struct atoms *a = &g->atoms;
    int nlocal = a->n, nf = rd->nfield;
    for (int i = 0; i < nlocal; i++) {
        map[2 * i] = a->tag[i];
        map[2 * i + 1] = i;
    }
    qsort(map, (size_t)nlocal, 2 * sizeof(int64_t), by_tag);
    for (bigint i = 0; i < rd->nsnap; i++) {
        const double *fv = rd->fields + (size_t)i * nf;
        isnew[i] = 1;
        int m = find_tag(map, nlocal, (int64_t)fv[0]);
        if (m < 0)
            continue;
        upd[m] = 1;
        isnew[i] = 0;
        if (!rd->replace)
            continue;
        rd->cnt[3]++;
        int *im = a->image + 3 * m;
        for (int k = 1; k < nf; k++) {
            int t = rd->type[k];
            double v = fv[k];
            if (t >= F_X && t <= F_Z)
                a->x[3 * m + t - F_X] = coord(rd, t - F_X, v);
            else if (t >= F_VX && t <= F_VZ)
                a->v[3 * m + t - F_VX] = v;
            else if (t >= F_IX && t <= F_IZ)
                im[t - F_IX] = (int)v;
            else if (t >= F_FX && t <= F_FZ)
                a->f[3 * m + t - F_FX] = v;
        }
        if (!rd->wrapped)
            im[0] = im[1] = im[2] = 0;
    }
    if (rd->trim) {
        for (int i = 0; i < a->n;) {
            if (!upd[i]) {
                upd[i] = upd[a->n - 1];
                atoms_remove(g, i);
                rd->cnt[4]++;
            } else {
                i++;
            }
        }
    }
    if (rd->add == NOADD)
        return;
    int64_t maxtag = 0;
    for (int i = 0; i < a->n; i++)
        maxtag = a->tag[i] > maxtag ? a->tag[i] : maxtag;
    for (bigint i = 0; i < rd->nsnap; i++) {
        if (!isnew[i])
            continue;
        const double *fv = rd->fields + (size_t)i * nf;
        int type = 0;
        double x[3] = {0, 0, 0};
        for (int k = 1; k < nf; k++) {
            int t = rd->type[k];
            if (t == F_TYPE)
                type = (int)fv[k];
            else if (t >= F_X && t <= F_Z)
                x[t - F_X] = coord(rd, t - F_X, fv[k]);
        }
        if (type < 1 || type > a->ntypes)
            gr_error(g, "dump atom %lld has type %d outside 1..%d", (long long)fv[0], type,
                     a->ntypes);
        int64_t tag = rd->add == KEEPADD ? (int64_t)fv[0] : ++maxtag;
        if (tag <= 0)
            gr_error(g, "dump atom ID %lld is not positive", (long long)fv[0]);
        int m = atoms_add(g, tag, type, x, 0.5, 4.0 * M_PI / 3.0 * 0.125);
        rd->cnt[5]++;
        for (int k = 1; k < nf; k++) {
            int t = rd->type[k];
            if (t >= F_VX && t <= F_VZ)
                a->v[3 * m + t - F_VX] = fv[k];
            else if (t >= F_IX && t <= F_IZ)
                a->image[3 * m + t - F_IX] = (int)fv[k];
        }
    }
    if (rd->add == KEEPADD)
        for (int i = 0; i < a->n; i++)
            maxtag = a->tag[i] > maxtag ? a->tag[i] : maxtag;
    a->maxtag = maxtag;
}

void rd_atoms(struct gravel *g, struct rdump *rd)
{
    struct atoms *a = &g->atoms;
    memset(rd->cnt, 0, sizeof rd->cnt);
    rd->cnt[0] = a->n;
    read_header(g, rd);
    rd->cnt[1] = rd->nsnap;
    if (rd->purge) {
        rd->cnt[2] = a->n;
        a->n = 0;
    }
    size_t n = (size_t)a->n + 1, ns = (size_t)rd->nsnap + 1;
    int64_t *map = gr_malloc(g, 2 * n * sizeof(int64_t));
    char *upd = calloc(n, 1), *isnew = calloc(ns, 1);
    if (!upd || !isnew) {
        free(map);
        free(upd);
        free(isnew);
        gr_error(g, "out of memory");
    }
    jmp_buf jb, *outer = g->err.jmp;
    g->err.jmp = &jb;
    if (setjmp(jb)) {
        g->err.jmp = outer;
        free(map);
        free(upd);
        free(isnew);
        if (outer)
            longjmp(*outer, 1);
        gr_report_error(g);
        exit(1);
    }
    process_atoms(g, rd, map, upd, isnew);
    g->err.jmp = outer;
    free(map);
    free(upd);
    free(isnew);
    struct domain *dm = &g->dom;
    if (rd->boxflag) {
        for (int d = 0; d < (dm->dimension == 3 ? 3 : 2); d++) {
            dm->lo[d] = rd->box[d][0];
            dm->hi[d] = rd->box[d][1];
        }
        domain_set_initial_box(g);
    }
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < a->n; i++) {
        domain_remap(g, a->x + 3 * i, a->image + 3 * i);
        for (int q = 0; q < 3; q++) {
            lo[q] = fmin(lo[q], a->x[3 * i + q]);
            hi[q] = fmax(hi[q], a->x[3 * i + q]);
        }
    }
    domain_shrink_wrap(g, lo, hi);
}

void rd_counts(const struct rdump *rd, bigint out[6])
{
    memcpy(out, rd->cnt, sizeof rd->cnt);
}

void cmd_read_dump(struct gravel *g, int argc, char **argv)
{
    domain_require_box(g);
    bigint nstep = arg_bigint(g, argv[1], "Nstep");
    struct rdump *rd = rd_create(g, 1, argv, argc - 2, argv + 2);
    jmp_buf jb, *outer = g->err.jmp;
    g->err.jmp = &jb;
    if (setjmp(jb)) {
        g->err.jmp = outer;
        rd_destroy(rd);
        if (outer)
            longjmp(*outer, 1);
        gr_report_error(g);
        exit(1);
    }
    gr_print(g, "Scanning dump file ...\n");
    if (rd_seek(g, rd, nstep, 1) < 0)
        gr_error(g, "dump file '%s' does not contain the requested snapshot (step %lld)", argv[0],
                 (long long)nstep);
    fix_check_time_reset(g);
    g->step = nstep;
    g->laststep_reset = nstep;
    gr_print(g, "Reading snapshot from dump file ...\n");
    rd_atoms(g, rd);
    g->err.jmp = outer;
    bigint c[6];
    rd_counts(rd, c);
    rd_destroy(rd);
    const struct domain *dm = &g->dom;
    gr_print(g, "  orthogonal box = (%.8g %.8g %.8g) to (%.8g %.8g %.8g)\n", dm->lo[0], dm->lo[1],
             dm->lo[2], dm->hi[0], dm->hi[1], dm->hi[2]);
    static const char *what[] = {"before read", "in snapshot", "purged",
                                 "replaced",    "trimmed",     "added"};
    for (int k = 0; k < 6; k++)
        gr_print(g, "  %lld atoms %s\n", (long long)c[k], what[k]);
    gr_print(g, "  %d atoms after read\n", g->atoms.n);
}
