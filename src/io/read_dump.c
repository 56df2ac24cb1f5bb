/* read_dump.c - `read_dump file Nstep field ... [keyword value ...]` as
 * LAMMPS 2021 (read_dump.cpp, reader_native.cpp), native text dumps, one
 * process, orthogonal or triclinic snapshots (a triclinic header holds the
 * bounding box and the tilts, as LAMMPS and gravel's dumps write it):
 *   fields   x y z vx vy vz ix iy iz fx fy fz (and id, type; z vz iz fz are
 *            illegal in 2d; q does not exist in atom_style sphere). The last
 *            field may not be id or type (LAMMPS's check).
 *   box yes|no       (yes) take the snapshot's box and tilts (z, xz, yz only
 *                    in 3d); the simulation box must be of the same kind
 *                    (LAMMPS: the triclinic status must match); no keeps
 *                    the box
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
 * replaced, trimmed, added, after read).
 * Every value is checked as it is read, naming the file, line and step:
 * IDs exact integers in 1..INT64_MAX - 1, once per snapshot; other fields
 * finite, types and image flags integers in range; box bounds finite. */
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
    double box[3][2];           /* the snapshot's lo, hi (triclinic: not the bounding box) */
    int tri_snap;               /* the snapshot's box is triclinic ... */
    double tilt[3];             /* ... with tilts xy, xz, yz (else 0) */
    int xyz_k[3];               /* field index of x, y, z in a row (-1: not read) */
    double *fields;             /* nsnap rows of nfield; column 0 unused (ids) */
    int64_t *ids;               /* the snapshot's atom IDs, parsed as integers */
    long lineno;                /* lines read from the current file */
    long atom_line0;            /* line of the snapshot's first atom */
    bigint step;                /* timestep of the snapshot at the position */
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
    free(rd->ids);
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
    rd->lineno++;
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
    *step = rd->step = parse_count(g, rd, "a timestep");
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
    rd->lineno = 0;
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

static double coord(const struct rdump *rd, int d, const double *fv);

/* The largest atom ID read: LAMMPS's tag_check refuses IDs >= MAXTAGINT,
 * so that a new ID (largest + 1) still fits. */
#define RD_MAXTAG (INT64_MAX - 1)

/* An atom ID word: an integer in 1..RD_MAXTAG, exactly (not through a
 * double, which rounds IDs beyond 2^53). */
static int64_t parse_id(struct gravel *g, struct rdump *rd, const char *word)
{
    const char *fn = rd->files[rd->curfile];
    char *end;
    errno = 0;
    long long v = strtoll(word, &end, 10);
    if (end == word || *end)
        gr_error(g, "dump file '%s' line %ld (step %lld): atom ID '%.32s' is not an integer",
                 fn, rd->lineno, (long long)rd->step, word);
    if (errno == ERANGE || v > RD_MAXTAG)
        gr_error(g, "dump file '%s' line %ld (step %lld): atom ID %.32s is too big (at most "
                    "%lld)",
                 fn, rd->lineno, (long long)rd->step, word, (long long)RD_MAXTAG);
    if (v <= 0)
        gr_error(g, "dump file '%s' line %ld (step %lld): atom ID %.32s is not positive", fn,
                 rd->lineno, (long long)rd->step, word);
    return v;
}

/* A field value of atom `id` on the current line: finite, and a type or
 * image flag an integer in range. */
static void check_value(struct gravel *g, struct rdump *rd, int64_t id, int t, double v,
                        const char *word)
{
    const char *fn = rd->files[rd->curfile];
    if (!isfinite(v))
        gr_error(g, "dump file '%s' line %ld (step %lld): atom ID %lld has a non-finite %s "
                    "('%.32s')",
                 fn, rd->lineno, (long long)rd->step, (long long)id, field_name[t], word);
    int integral = t == F_TYPE || (t >= F_IX && t <= F_IZ);
    double lim = t == F_TYPE ? 1e6 : (double)(1 << 20);
    if (integral && (v != floor(v) || fabs(v) > lim))
        gr_error(g, "dump file '%s' line %ld (step %lld): atom ID %lld has %s '%.32s' (an "
                    "integer within +-%g expected)",
                 fn, rd->lineno, (long long)rd->step, (long long)id, field_name[t], word, lim);
}

static int cmp_id_line(const void *pa, const void *pb)
{
    const int64_t *a = pa, *b = pb;
    if (a[0] != b[0])
        return (a[0] > b[0]) - (a[0] < b[0]);
    return (a[1] > b[1]) - (a[1] < b[1]);
}

/* Errors if an atom ID appears twice in the snapshot: `add keep` would make
 * two atoms of one ID (LAMMPS stops later, at its atom map); replace would
 * apply two lines to one atom. */
static void check_unique_ids(struct gravel *g, struct rdump *rd)
{
    bigint n = rd->nsnap;
    int64_t *p = malloc(((size_t)n + 1) * 2 * sizeof(int64_t));
    if (!p)
        gr_error(g, "out of memory");
    for (bigint i = 0; i < n; i++) {
        p[2 * i] = rd->ids[i];
        p[2 * i + 1] = i;
    }
    qsort(p, (size_t)n, 2 * sizeof(int64_t), cmp_id_line);
    for (bigint i = 1; i < n; i++)
        if (p[2 * i] == p[2 * i - 2]) {
            long first = rd->atom_line0 + (long)p[2 * i - 1];
            long second = rd->atom_line0 + (long)p[2 * i + 1];
            long long id = p[2 * i];
            free(p);
            gr_error(g, "dump file '%s' (step %lld): atom ID %lld appears twice, on lines %ld "
                        "and %ld",
                     rd->files[rd->curfile], (long long)rd->step, id, first, second);
        }
    free(p);
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
    rd->tri_snap = strstr(rd->line, "xy") != NULL;
    /* LAMMPS: "Read_dump triclinic status does not match simulation" */
    if (rd->boxflag && rd->tri_snap != g->dom.triclinic)
        gr_error(g, "dump file '%s' (step %lld) has %s box but the simulation box is %s: box "
                    "yes needs the same kind of box (as LAMMPS); use box no to keep the "
                    "current box",
                 fn, (long long)rd->step, rd->tri_snap ? "a triclinic" : "an orthogonal",
                 g->dom.triclinic ? "triclinic" : "orthogonal");
    for (int d = 0; d < 3; d++) {
        next_line(g, rd, 1);
        char *end, *e2, *e3;
        rd->box[d][0] = strtod(rd->line, &end);
        rd->box[d][1] = strtod(end, &e2);
        rd->tilt[d] = rd->tri_snap ? strtod(e2, &e3) : 0.0;
        if (e2 == end || (rd->tri_snap && e3 == e2))
            gr_error(g, "dump file '%s' is incorrectly formatted: bad box bounds '%.40s'", fn,
                     rd->line);
        if (!isfinite(rd->tilt[d]))
            gr_error(g, "dump file '%s' line %ld (step %lld): the %s tilt %g is not finite", fn,
                     rd->lineno, (long long)rd->step, d == 0 ? "xy" : d == 1 ? "xz" : "yz",
                     rd->tilt[d]);
    }
    if (rd->tri_snap) { /* the lines hold the bounding box (LAMMPS's ReadDump::header) */
        double xy = rd->tilt[0], xz = rd->tilt[1], yz = rd->tilt[2];
        rd->box[0][0] -= fmin(fmin(0.0, xy), fmin(xz, xy + xz));
        rd->box[0][1] -= fmax(fmax(0.0, xy), fmax(xz, xy + xz));
        rd->box[1][0] -= fmin(0.0, yz);
        rd->box[1][1] -= fmax(0.0, yz);
    }
    for (int d = 0; d < 3; d++)
        if (!isfinite(rd->box[d][0]) || !isfinite(rd->box[d][1]) ||
            !(rd->box[d][0] < rd->box[d][1]) ||
            !isfinite(rd->box[d][1] - rd->box[d][0]))
            gr_error(g, "dump file '%s' (step %lld): the %c box bounds %g %g are not finite "
                        "with lo < hi",
                     fn, (long long)rd->step, "xyz"[d], rd->box[d][0], rd->box[d][1]);
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
    for (int d = 0; d < 3; d++)
        rd->xyz_k[d] = -1;
    for (int k = 0; k < rd->nfield; k++)
        if (rd->type[k] >= F_X && rd->type[k] <= F_Z)
            rd->xyz_k[rd->type[k] - F_X] = k;
    if (rd->scaled && rd->tri_snap &&
        (rd->xyz_k[0] < 0 || rd->xyz_k[1] < 0 || (g->dom.dimension == 3 && rd->xyz_k[2] < 0)))
        gr_error(g, "dump file '%s': scaled coordinates of a triclinic snapshot need all of the "
                    "x, y, z fields (as LAMMPS)",
                 fn);
    /* the atoms */
    free(rd->fields);
    free(rd->ids);
    rd->fields = NULL;
    rd->ids = NULL;
    if (rd->nsnap > 200000000)
        gr_error(g, "dump file '%s': snapshot of %lld atoms is too large", fn,
                 (long long)rd->nsnap);
    rd->fields = malloc(((size_t)rd->nsnap + 1) * (size_t)rd->nfield * sizeof(double));
    rd->ids = malloc(((size_t)rd->nsnap + 1) * sizeof(int64_t));
    if (!rd->fields || !rd->ids)
        gr_error(g, "out of memory");
    rd->atom_line0 = rd->lineno + 1;
    for (bigint i = 0; i < rd->nsnap; i++) {
        next_line(g, rd, 1);
        char *w[256];
        int n = 0;
        for (char *t = strtok(rd->line, " \t"); t && n < 256; t = strtok(NULL, " \t"))
            w[n++] = t;
        if (n < nw)
            gr_error(g, "dump file '%s' line %ld: insufficient columns in an atom line (%d of "
                        "%d)",
                     fn, rd->lineno, n, nw);
        rd->ids[i] = parse_id(g, rd, w[rd->index[0]]);
        for (int k = 1; k < rd->nfield; k++) {
            char *end;
            const char *word = w[rd->index[k]];
            double v = strtod(word, &end);
            if (end == word || *end)
                gr_error(g, "dump file '%s' line %ld: bad number '%.32s' in column %s", fn,
                         rd->lineno, word, column(rd, k));
            check_value(g, rd, rd->ids[i], rd->type[k], v, word);
            rd->fields[(size_t)i * rd->nfield + k] = v;
        }
        for (int d = 0; d < 3; d++)
            if (rd->xyz_k[d] >= 0 && !isfinite(coord(rd, d, rd->fields + (size_t)i * rd->nfield)))
                gr_error(g, "dump file '%s' line %ld (step %lld): atom ID %lld: the scaled "
                            "coordinates give a non-finite %c",
                         fn, rd->lineno, (long long)rd->step, (long long)rd->ids[i], "xyz"[d]);
    }
    check_unique_ids(g, rd);
}

/* Coordinate d of the row fv, in box units: scaled coordinates are mapped
 * through the snapshot's box, with its tilts when triclinic (LAMMPS's
 * xfield, yfield, zfield, their operation order). */
static double coord(const struct rdump *rd, int d, const double *fv)
{
    double v = fv[rd->xyz_k[d]], lo = rd->box[d][0], len = rd->box[d][1] - lo;
    if (!rd->scaled)
        return v;
    if (!rd->tri_snap)
        return v * len + lo;
    int has_z = rd->xyz_k[2] >= 0;
    if (d == 0) {
        double x = len * v + rd->tilt[0] * fv[rd->xyz_k[1]];
        return has_z ? x + rd->tilt[1] * fv[rd->xyz_k[2]] + lo : x + lo;
    }
    if (d == 1)
        return has_z ? len * v + rd->tilt[2] * fv[rd->xyz_k[2]] + lo : len * v + lo;
    return v * len + lo;
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
        int m = find_tag(map, nlocal, rd->ids[i]);
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
                a->x[3 * m + t - F_X] = coord(rd, t - F_X, fv);
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
                x[t - F_X] = coord(rd, t - F_X, fv);
        }
        if (type < 1 || type > a->ntypes)
            gr_error(g, "dump file '%s' line %ld (step %lld): atom ID %lld has type %d outside "
                        "1..%d",
                     rd->files[rd->curfile], rd->atom_line0 + (long)i, (long long)rd->step,
                     (long long)rd->ids[i], type, a->ntypes);
        if (rd->add == YESADD && maxtag >= RD_MAXTAG)
            gr_error(g, "add yes: a new atom ID after %lld would be too big (at most %lld)",
                     (long long)maxtag, (long long)RD_MAXTAG);
        int64_t tag = rd->add == KEEPADD ? rd->ids[i] : ++maxtag;
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
        if (rd->tri_snap) { /* the kinds match (read_header) */
            dm->xy = rd->tilt[0];
            if (dm->dimension == 3) {
                dm->xz = rd->tilt[1];
                dm->yz = rd->tilt[2];
            }
            domain_check_tilt(g);
            domain_check_skew(g);
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
    domain_print_box(g, "  ");
    static const char *what[] = {"before read", "in snapshot", "purged",
                                 "replaced",    "trimmed",     "added"};
    for (int k = 0; k < 6; k++)
        gr_print(g, "  %lld atoms %s\n", (long long)c[k], what[k]);
    gr_print(g, "  %d atoms after read\n", g->atoms.n);
}
