/* fix_ave_chunk.c - `fix ID group ave/chunk Nevery Nrepeat Nfreq chunkID
 * value ... keyword args ...`: per-chunk time averages, LAMMPS's
 * fix_ave_chunk.cpp semantics and text file.
 *
 * Values: vx vy vz fx fy fz, density/number, density/mass, mass, c_ID and
 * c_ID[N] (per-atom compute), f_ID and f_ID[N] (a fix's per-atom output),
 * v_name (atom-style variable), and gravel's `solidicity`: the volume of the
 * spheres whose centres are in the chunk over the chunk volume (003 sec.
 * 5.2.9, 6.2: a sphere is counted wholly in the bin of its centre, as the
 * chunk assignment; porosity = 1 - solidicity). Solidicity is normalized
 * like the densities: summed over the samples, divided by Nrepeat and the
 * chunk volume, never by the atom count.
 * Keywords: norm all|sample|none (default all), ave one|running|window M,
 * scale atom|none, adof, cdof (accepted; no temp value), file F, append F,
 * overwrite, format F (a printf format used as given: LAMMPS 2021 adds no
 * separating space), title1/2/3, and gravel's `vtk F`: the
 * grid of a bin/1d-3d chunk compute with Ncount and every value as CELL_DATA
 * field arrays (named as the columns, '/' '[' ']' as '_') in a
 * legacy VTK STRUCTURED_POINTS file at each Nfreq step ('*' in F becomes
 * the step: a series ParaView opens as one).
 *
 * Samples are taken at end_of_step on steps nvalid, nvalid + Nevery, ...
 * (Nrepeat of them ending on a multiple of Nfreq), and at a run's setup
 * when that step is due, as LAMMPS; host arrays are synchronized first.
 * Sums run over the atoms in host order (deterministic). */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "args.h"
#include "atoms.h"
#include "ave_common.h"
#include "compute_chunk_atom.h"
#include "engine.h"
#include "error.h"
#include "expr.h"
#include "fileio.h"
#include "fix.h"
#include "outfile.h"
#include "variable.h"

enum { V_V, V_F, V_DNUM, V_DMASS, V_MASS, V_COMPUTE, V_SOLID, V_FIX, V_VARIABLE };
enum { NORM_ALL, NORM_SAMPLE, NORM_NONE };

#define AVE_MAXVAL 64

struct ave_chunk {
    struct ave_sched s;
    char chunk[GR_NAMELEN];
    int nvalues;
    int which[AVE_MAXVAL], argindex[AVE_MAXVAL];
    char ids[AVE_MAXVAL][GR_NAMELEN];
    char names[AVE_MAXVAL][GR_NAMELEN];
    int normflag, noscale;
    struct ave_window w;
    struct ave_file af;
    char *format;
    char *vtk;                          /* vtk file pattern or NULL */
    int spatial;                        /* LIGGGHTS's fix ave/spatial: its file layout */
    int write_ts;                       /* ave/spatial write_ts: the step line */
    char own_chunk;                     /* ave/spatial: the chunk compute is its own */
    char reduced;                       /* ave/spatial: units reduced */
    /* state */
    int nchunk, maxchunk;
    double *count_one, *count_many, *count_sum, *count_total, *count_list;
    double *values_one, *values_many, *values_sum, *values_total, *values_list;
    const struct chunk_grid *grid;
};

/* the values without an ID */
static const struct { const char *name; int which, index; } plain[] = {
    {"vx", V_V, 0}, {"vy", V_V, 1}, {"vz", V_V, 2}, {"fx", V_F, 0}, {"fy", V_F, 1},
    {"fz", V_F, 2}, {"density/number", V_DNUM, 0}, {"density/mass", V_DMASS, 0},
    {"mass", V_MASS, 0}, {"solidicity", V_SOLID, 0}};

/* s is a value (a plain one, or c_, f_, v_ with a name) */
static int value_word(const char *s)
{
    for (size_t k = 0; k < sizeof plain / sizeof plain[0]; k++)
        if (!strcmp(s, plain[k].name))
            return 1;
    return (!strncmp(s, "c_", 2) || !strncmp(s, "f_", 2) || !strncmp(s, "v_", 2)) && s[2];
}

static void ave_destroy(struct fix *f)
{
    struct ave_chunk *a = f->data;
    if (a) {
        ave_file_close(&a->af);
        free(a->format);
        free(a->vtk);
        free(a->count_one);
        free(a->count_many);
        free(a->count_sum);
        free(a->count_total);
        free(a->count_list);
        free(a->values_one);
        free(a->values_many);
        free(a->values_sum);
        free(a->values_total);
        free(a->values_list);
    }
    free(a);
    f->data = NULL;
}

/* ave/chunk's arguments; spatial: as LIGGGHTS's fix ave/spatial (argv's
 * chunkID its own compute), whose file heads and step lines differ */
static void create_in(struct gravel *g, struct fix *f, int argc, char **argv, int spatial,
                      int write_ts)
{
    if (argc < 5)
        gr_error(g, "fix ave/chunk expects Nevery Nrepeat Nfreq chunkID and at least one value");
    struct ave_chunk *a = gr_calloc(g, 1, sizeof *a);
    f->data = a;
    a->spatial = spatial;
    a->write_ts = write_ts;
    ave_sched_parse(g, &a->s, argv, "fix ave/chunk");
    snprintf(a->chunk, sizeof a->chunk, "%s", argv[3]);
    struct compute *cc = chunk_atom_get(g, a->chunk, "fix ave/chunk");
    int iarg = 4;
    for (; iarg < argc; iarg++) {
        const char *s = argv[iarg];
        int w = -1, idx = 0;
        for (size_t k = 0; k < sizeof plain / sizeof plain[0]; k++)
            if (!strcmp(s, plain[k].name)) {
                w = plain[k].which;
                idx = plain[k].index;
            }
        char id[GR_NAMELEN] = "";
        if (w < 0) {
            if (!strcmp(s, "temp"))
                gr_error(g, "fix ave/chunk: value 'temp' is not supported");
            if (!strncmp(s, "v_", 2)) {
                if (!s[2] || strlen(s + 2) >= GR_NAMELEN || strchr(s, '['))
                    gr_error(g, "fix ave/chunk: '%.64s' must name an atom-style variable", s);
                var_check_atom(g, s + 2, "fix ave/chunk");
                snprintf(id, sizeof id, "%s", s + 2);
                w = V_VARIABLE;
                a->s.reads_vars = 1; /* several ranks: thermo keywords taken first */
            }
            if (!strncmp(s, "f_", 2)) {
                fix_peratom_check(g, s, "fix ave/chunk");
                w = V_FIX;
            }
            if (!strncmp(s, "c_", 2)) {
                if (!compute_parse_ref(s, id, &idx))
                    gr_error(g, "fix ave/chunk: malformed compute reference '%.64s'", s);
                compute_peratom_check(g, id, idx, "fix ave/chunk");
                w = V_COMPUTE;
            }
        }
        if (w < 0)
            break;
        if (a->nvalues == AVE_MAXVAL)
            gr_error(g, "fix ave/chunk: at most %d values", AVE_MAXVAL);
        a->which[a->nvalues] = w;
        a->argindex[a->nvalues] = idx;
        snprintf(a->ids[a->nvalues], GR_NAMELEN, "%s", id);
        snprintf(a->names[a->nvalues], GR_NAMELEN, "%s", s);
        a->nvalues++;
    }
    if (a->nvalues == 0)
        gr_error(g, "fix ave/chunk: no values given (vx, density/mass, c_ID, solidicity, ...)");
    a->normflag = NORM_ALL;
    a->w.kind = AVE_ONE;
    const char *file = NULL, *title[3] = {NULL, NULL, NULL};
    int append = 0;
    for (int i = iarg; i < argc; i++) {
        const char *kw = argv[i];
        if (!strcmp(kw, "norm")) {
            arg_need(g, argc, i, 1, kw);
            const char *v = argv[++i];
            if (!strcmp(v, "all"))
                a->normflag = NORM_ALL;
            else if (!strcmp(v, "sample"))
                a->normflag = NORM_SAMPLE;
            else if (!strcmp(v, "none"))
                a->normflag = NORM_NONE;
            else
                gr_error(g, "fix ave/chunk: norm must be all, sample or none, got '%.32s'", v);
        } else if (!strcmp(kw, "ave")) {
            ave_window_parse(g, &a->w, argc, argv, &i, "fix ave/chunk");
        } else if (!strcmp(kw, "scale")) {
            arg_need(g, argc, i, 1, kw);
            const char *v = argv[++i];
            if (!strcmp(v, "atom"))
                a->noscale = 0;
            else if (!strcmp(v, "none"))
                a->noscale = 1;
            else
                gr_error(g, "fix ave/chunk: scale must be atom or none, got '%.32s'", v);
        } else if (!strcmp(kw, "adof") || !strcmp(kw, "cdof")) {
            arg_need(g, argc, i, 1, kw);
            arg_double(g, argv[++i], kw);
        } else if (!strcmp(kw, "bias")) {
            gr_error(g, "fix ave/chunk: keyword 'bias' is not supported (no temp value)");
        } else if (!strcmp(kw, "file") || !strcmp(kw, "append")) {
            arg_need(g, argc, i, 1, kw);
            file = argv[++i];
            append = !strcmp(kw, "append");
        } else if (!strcmp(kw, "overwrite")) {
            a->af.overwrite = 1;
        } else if (!strcmp(kw, "format")) {
            arg_need(g, argc, i, 1, kw);
            free(a->format);
            a->format = gr_malloc(g, strlen(argv[i + 1]) + 1);
            strcpy(a->format, argv[++i]); /* used as given, no separator (LAMMPS 2021) */
            if (!expr_format_ok(a->format))
                gr_error(g, "fix ave/chunk: format '%.64s' must have exactly one floating "
                            "point conversion", argv[i]);
        } else if (!strcmp(kw, "title1") || !strcmp(kw, "title2") || !strcmp(kw, "title3")) {
            arg_need(g, argc, i, 1, kw);
            title[kw[5] - '1'] = argv[++i];
        } else if (!strcmp(kw, "vtk")) {
            arg_need(g, argc, i, 1, kw);
            free(a->vtk);
            a->vtk = gr_malloc(g, strlen(argv[i + 1]) + 1);
            strcpy(a->vtk, argv[++i]);
        } else {
            gr_error(g, "fix ave/chunk: unknown value or keyword '%.64s'", kw);
        }
    }
    if (a->w.kind != AVE_RUNNING && a->af.overwrite)
        gr_error(g, "fix ave/chunk: overwrite needs ave running");
    if (a->vtk && (chunk_atom_ncoord(cc) == 0 || chunk_atom_radial(cc)))
        gr_error(g, "fix ave/chunk: vtk needs spatial bins on a grid (compute %s is not bin/1d, "
                    "bin/2d or bin/3d)", cc->id);
    if (file && spatial) { /* LIGGGHTS: a title of one character prints nothing */
        ave_file_open(g, &a->af, file, append, "fix ave/spatial");
        FILE *fp = a->af.fp;
        if (!title[0])
            fprintf(fp, "# Spatial-averaged data for fix %s and group %s\n", f->id,
                    g->groups.name[f->igroup]);
        else if (strlen(title[0]) > 1)
            fprintf(fp, "%s\n", title[0]);
        if (!title[1])
            fprintf(fp, "# Timestep Number-of-bins\n");
        else if (strlen(title[1]) > 1)
            fprintf(fp, "%s\n", title[1]);
        if (!title[2]) {
            static const char *head[] = {"", "# Bin Coord Ncount", "# Bin Coord1 Coord2 Ncount",
                                         "# Bin Coord1 Coord2 Coord3 Ncount"};
            fputs(head[chunk_atom_ncoord(cc)], fp);
            for (int k = 0; k < a->nvalues; k++)
                fprintf(fp, " %s", a->names[k]);
            fputc('\n', fp);
        } else if (strlen(title[2]) > 1)
            fprintf(fp, "%s\n", title[2]);
        ave_file_header_done(g, &a->af, "fix ave/spatial");
    } else if (file) {
        ave_file_open(g, &a->af, file, append, "fix ave/chunk");
        FILE *fp = a->af.fp;
        if (title[0])
            fprintf(fp, "%s\n", title[0]);
        else
            fprintf(fp, "# Chunk-averaged data for fix %s and group %s\n", f->id,
                    g->groups.name[f->igroup]);
        fprintf(fp, "%s\n", title[1] ? title[1] : "# Timestep Number-of-chunks Total-count");
        if (title[2])
            fprintf(fp, "%s\n", title[2]);
        else {
            static const char *head[] = {"# Chunk Ncount", "# Chunk Coord1 Ncount",
                                         "# Chunk Coord1 Coord2 Ncount",
                                         "# Chunk Coord1 Coord2 Coord3 Ncount"};
            fputs(head[chunk_atom_ncoord(cc)], fp);
            for (int k = 0; k < a->nvalues; k++)
                fprintf(fp, " %s", a->names[k]);
            fputc('\n', fp);
        }
        ave_file_header_done(g, &a->af, "fix ave/chunk");
    }
    ave_sched_reset(g, &a->s);
    f->hooks = HOOK_END_OF_STEP;
}

static void ave_create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    create_in(g, f, argc, argv, 0, 1);
}

/* LIGGGHTS's (LAMMPS 2013's) `fix ID group ave/spatial Nevery Nrepeat Nfreq
 * dim origin delta [dim origin delta ...] value ... keyword ...`: ave/chunk
 * over its own compute chunk/atom bin/Nd (ID_spatial: the fix's group,
 * units, region, discard no: atoms beyond the box in the end bins, as
 * ave/spatial clamps them), with ave/spatial's file: `# Spatial-averaged
 * data ...`, `# Timestep Number-of-bins`, `# Bin Coord ...`, a step line
 * without the total count (write_ts no: none). */
static void spatial_create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    const char *who = "fix ave/spatial";
    if (argc < 7)
        gr_error(g, "%s expects Nevery Nrepeat Nfreq dim origin delta ... and at least one "
                    "value", who);
    int i = 3, ndim = 0;
    while (i + 2 < argc && (!strcmp(argv[i], "x") || !strcmp(argv[i], "y") ||
                            !strcmp(argv[i], "z"))) {
        if (++ndim > 3)
            gr_error(g, "%s: at most three binned dimensions", who);
        i += 3;
    }
    if (!ndim)
        gr_error(g, "%s: expecting a dimension x, y or z after Nfreq, got '%.32s'", who, argv[3]);
    const char *units = "lattice", *region = NULL;
    int write_ts = 1;
    char **rest = gr_calloc(g, (size_t)argc + 1, sizeof *rest);
    int nrest = 0;
    static const char *pass1[] = {"norm", "file", "append", "title1", "title2", "title3"};
    for (int k = i; k < argc; k++) {
        const char *kw = argv[k];
        int known = 0;
        for (size_t q = 0; q < sizeof pass1 / sizeof pass1[0]; q++)
            known |= !strcmp(kw, pass1[q]);
        if (!strcmp(kw, "units") || !strcmp(kw, "region") || !strcmp(kw, "write_ts")) {
            arg_need(g, argc, k, 1, kw);
            if (kw[0] == 'u')
                units = argv[k + 1];
            else if (kw[0] == 'r')
                region = argv[k + 1];
            else
                write_ts = arg_yesno(g, argv[k + 1], "write_ts");
            k++;
        } else if (!strcmp(kw, "std")) {
            gr_error(g, "%s: keyword 'std' is not supported", who);
        } else if (known) {
            arg_need(g, argc, k, 1, kw);
            rest[nrest++] = argv[k];
            rest[nrest++] = argv[++k];
        } else if (!strcmp(kw, "ave")) {
            arg_need(g, argc, k, 1, kw);
            rest[nrest++] = argv[k];
            rest[nrest++] = argv[++k];
            if (!strcmp(argv[k], "window")) {
                arg_need(g, argc, k, 1, "ave window");
                rest[nrest++] = argv[++k];
            }
        } else if (!strcmp(kw, "overwrite")) {
            rest[nrest++] = argv[k];
        } else if (value_word(kw)) {
            rest[nrest++] = argv[k];
        } else {
            gr_error(g, "%s: unknown value or keyword '%.64s'", who, kw);
        }
    }
    /* its own chunk/atom compute: ID_spatial (replacing one of an earlier fix of this ID) */
    static char *const styles[] = {"bin/1d", "bin/2d", "bin/3d"};
    char cid[GR_NAMELEN + 16], *style = styles[ndim - 1];
    snprintf(cid, sizeof cid, "%s_spatial", f->id);
    if (compute_find(g, cid)) {
        char *un[] = {cid};
        cmd_uncompute(g, 1, un);
    }
    char *cargv[24];
    int nc = 0;
    cargv[nc++] = cid;
    cargv[nc++] = g->groups.name[f->igroup];
    cargv[nc++] = "chunk/atom";
    cargv[nc++] = style;
    for (int k = 3; k < 3 + 3 * ndim; k++)
        cargv[nc++] = argv[k];
    cargv[nc++] = "units";
    cargv[nc++] = (char *)units;
    cargv[nc++] = "discard";
    cargv[nc++] = "no";
    if (region) {
        cargv[nc++] = "region";
        cargv[nc++] = (char *)region;
    }
    cmd_compute(g, nc, cargv);
    char **av = gr_calloc(g, (size_t)nrest + 5, sizeof *av);
    int na = 0;
    for (int k = 0; k < 3; k++)
        av[na++] = argv[k];
    av[na++] = cid;
    for (int k = 0; k < nrest; k++)
        av[na++] = rest[k];
    free(rest);
    create_in(g, f, na, av, 1, write_ts);
    free(av);
    ((struct ave_chunk *)f->data)->own_chunk = 1;
    ((struct ave_chunk *)f->data)->reduced = !strcmp(units, "reduced");
}

/* the box may change size in a run: a shrink-wrapped face or a fix that
 * changes it (FIX_BOX_CHANGE; LAMMPS's domain->box_change_size) */
static int box_changes_size(const struct gravel *g)
{
    for (int d = 0; d < 3; d++)
        for (int k = 0; k < 2; k++)
            if (g->dom.bnd[d][k] == BND_S || g->dom.bnd[d][k] == BND_M)
                return 1;
    for (int i = 0; i < g->styles.nfix; i++)
        if (g->styles.fix[i]->style->flags & FIX_BOX_CHANGE)
            return 1;
    return 0;
}

/* unfix of an ave/spatial: its chunk compute goes with it */
static void spatial_unfix(struct gravel *g, struct fix *f)
{
    const struct ave_chunk *a = f->data;
    if (a && a->own_chunk && compute_find(g, a->chunk)) {
        char *un[] = {(char *)a->chunk};
        cmd_uncompute(g, 1, un);
    }
}

static void grow(struct gravel *g, struct ave_chunk *a, int nchunk)
{
    a->nchunk = nchunk;
    if (nchunk <= a->maxchunk)
        return;
    size_t nv = (size_t)a->nvalues, n = (size_t)nchunk;
    double **c[] = {&a->count_one, &a->count_many, &a->count_sum, &a->count_total};
    double **v[] = {&a->values_one, &a->values_many, &a->values_sum, &a->values_total};
    for (int k = 0; k < 4; k++) {
        *c[k] = gr_realloc(g, *c[k], n * sizeof(double));
        *v[k] = gr_realloc(g, *v[k], n * nv * sizeof(double));
    }
    /* totals start from zero for new chunks (LAMMPS allocate()) */
    for (size_t m = (size_t)a->maxchunk; m < n; m++) {
        a->count_total[m] = 0;
        for (size_t j = 0; j < nv; j++)
            a->values_total[m * nv + j] = 0;
    }
    if (a->w.kind == AVE_WINDOW) {
        free(a->count_list);
        free(a->values_list);
        a->count_list = gr_calloc(g, (size_t)a->w.nwindow * n, sizeof(double));
        a->values_list = gr_calloc(g, (size_t)a->w.nwindow * n * nv, sizeof(double));
    }
    a->maxchunk = nchunk;
}

static void write_vtk(struct gravel *g, struct fix *f, struct ave_chunk *a);

/* One sample (and the epoch's output when it closes it), on the host atoms. */
static void take(struct gravel *g, struct fix *f)
{
    struct ave_chunk *a = f->data;
    run_sync_host(g);
    struct compute *cc = chunk_atom_get(g, a->chunk, "fix ave/chunk");
    const int nv = a->nvalues;
    if (a->s.irepeat == 0) {
        a->grid = chunk_atom_setup(g, cc);
        if (a->s.nrepeat > 1 && a->w.kind == AVE_ONE) /* LAMMPS: nchunk fixed for the epoch */
            chunk_atom_lock(g, cc, f->id);
        grow(g, a, a->grid->nchunk);
        for (int m = 0; m < a->nchunk; m++) {
            a->count_many[m] = a->count_sum[m] = 0;
            for (int j = 0; j < nv; j++)
                a->values_many[(size_t)m * nv + j] = 0;
        }
    }
    for (int m = 0; m < a->nchunk; m++) {
        a->count_one[m] = 0;
        for (int j = 0; j < nv; j++)
            a->values_one[(size_t)m * nv + j] = 0;
    }
    const struct atoms *at = &g->atoms;
    const int *ichunk = chunk_atom_assign(g, cc);
    const unsigned bit = f->groupbit;
    for (int i = 0; i < at->n; i++)
        if ((at->mask[i] & bit) && ichunk[i] > 0 && ichunk[i] <= a->nchunk)
            a->count_one[ichunk[i] - 1] += 1;
    for (int j = 0; j < nv; j++) {
        const double *src = NULL;
        double *owned = NULL;
        int stride = 1, comp = a->argindex[j];
        switch (a->which[j]) {
        case V_V: src = at->v; stride = 3; break;
        case V_F: src = at->f; stride = 3; break;
        case V_COMPUTE: {
            struct compute *pc = compute_get(g, a->ids[j], "fix ave/chunk");
            src = compute_peratom_ref(g, pc, a->argindex[j], &stride, "fix ave/chunk");
            comp = 0;
            break;
        }
        case V_FIX:
            src = fix_peratom_ref(g, a->names[j], &stride, "fix ave/chunk");
            comp = 0;
            break;
        case V_VARIABLE:
            src = owned = var_atom_values(g, a->ids[j]);
            comp = 0;
            break;
        default: break;
        }
        const int *order = atoms_tag_order(g); /* sums that depend on the atoms only */
        for (int k = 0; k < at->n; k++) {
            const int i = order[k];
            if (!(at->mask[i] & bit) || ichunk[i] <= 0 || ichunk[i] > a->nchunk)
                continue;
            double val;
            switch (a->which[j]) {
            case V_DNUM: val = 1.0; break;
            case V_DMASS: case V_MASS: val = at->rmass[i]; break;
            case V_SOLID: {
                double r = at->radius[i];
                val = g->dom.dimension == 3 ? 4.0 / 3.0 * M_PI * r * r * r : M_PI * r * r;
                break;
            }
            default: val = src[(size_t)stride * i + comp]; break;
            }
            a->values_one[(size_t)(ichunk[i] - 1) * nv + j] += val;
        }
        free(owned);
    }
    /* the sample: accumulate sums (all, none) or per-sample averages (sample) */
    for (int m = 0; m < a->nchunk; m++) {
        double *one = a->values_one + (size_t)m * nv, *many = a->values_many + (size_t)m * nv;
        if (a->normflag != NORM_SAMPLE) {
            a->count_many[m] += a->count_one[m];
            for (int j = 0; j < nv; j++)
                many[j] += one[j];
        } else {
            double cnt = a->count_one[m];
            a->count_many[m] = cnt;
            if (cnt > 0)
                for (int j = 0; j < nv; j++) {
                    int w = a->which[j];
                    if (w == V_DNUM || w == V_DMASS || w == V_SOLID || a->noscale)
                        many[j] += one[j];
                    else
                        many[j] += one[j] / cnt;
                }
            a->count_sum[m] += cnt;
        }
    }
    if (!ave_sched_next(g, &a->s))
        return;
    chunk_atom_unlock(cc, f->id);
    /* the epoch's average */
    double repeat = a->s.nrepeat;
    for (int m = 0; m < a->nchunk; m++) {
        double *sum = a->values_sum + (size_t)m * nv, *many = a->values_many + (size_t)m * nv;
        if (a->normflag == NORM_ALL) {
            a->count_sum[m] = a->count_many[m];
            for (int j = 0; j < nv; j++) {
                sum[j] = many[j];
                if (a->count_sum[m] > 0) {
                    int w = a->which[j];
                    if (w == V_DMASS || w == V_DNUM || w == V_SOLID || a->noscale)
                        sum[j] /= repeat; /* mv2d = 1 in lj, si and cgs */
                    else
                        sum[j] /= a->count_sum[m];
                }
            }
            a->count_sum[m] /= repeat;
        } else {
            if (a->normflag == NORM_NONE)
                a->count_sum[m] = a->count_many[m];
            for (int j = 0; j < nv; j++)
                sum[j] = many[j] / repeat;
            a->count_sum[m] /= repeat;
        }
    }
    const double *vols = a->grid->volumes;
    for (int j = 0; j < nv; j++) {
        int w = a->which[j];
        if (w == V_DNUM || w == V_DMASS || w == V_SOLID)
            for (int m = 0; m < a->nchunk; m++)
                a->values_sum[(size_t)m * nv + j] /= vols ? vols[m] : a->grid->volume;
    }
    ave_window_add(&a->w, a->values_total, a->values_list, a->values_sum,
                   (size_t)a->nchunk * nv);
    ave_window_add(&a->w, a->count_total, a->count_list, a->count_sum, (size_t)a->nchunk);
    ave_window_advance(&a->w);
    FILE *fp = a->af.fp;
    if (fp) {
        ave_file_begin(&a->af);
        double count = 0;
        for (int m = 0; m < a->nchunk; m++)
            count += a->count_total[m];
        if (!a->spatial)
            fprintf(fp, "%lld %d %g\n", (long long)g->step, a->nchunk, count);
        else if (a->write_ts)
            fprintf(fp, "%lld %d\n", (long long)g->step, a->nchunk);
        const char *fmt = a->format ? a->format : " %g";
        const struct chunk_grid *gr = a->grid;
        double nc = a->w.norm;
        for (int m = 0; m < a->nchunk; m++) {
            fprintf(fp, "  %d", m + 1);
            for (int k = 0; k < gr->ncoord; k++)
                fprintf(fp, " %g", gr->coord[(size_t)m * gr->ncoord + k]);
            fprintf(fp, " %g", a->count_total[m] / nc);
            for (int j = 0; j < nv; j++)
                fprintf(fp, fmt, a->values_total[(size_t)m * nv + j] / nc);
            fputc('\n', fp);
        }
        ave_file_end(g, &a->af, "fix ave/chunk", f->id);
    }
    if (a->vtk)
        write_vtk(g, f, a);
}

/* Legacy VTK STRUCTURED_POINTS of the grid: unbinned dimensions span the
 * box in one cell; cells ordered x fastest as VTK requires. */
static void write_vtk(struct gravel *g, struct fix *f, struct ave_chunk *a)
{
    const struct chunk_grid *gr = a->grid;
    int n[3];
    double o[3], h[3];
    for (int d = 0; d < 3; d++) {
        double lo = g->dom.lo[d], prd = g->dom.hi[d] - lo;
        n[d] = 1;
        o[d] = lo;
        h[d] = prd > 0 ? prd : 1;
        for (int m = 0; m < gr->ndim; m++)
            if (gr->dim[m] == d) {
                n[d] = gr->nlayers[m];
                o[d] = gr->reduced ? lo + gr->offset[m] * prd : gr->offset[m];
                h[d] = gr->reduced ? gr->delta[m] * prd : gr->delta[m];
            }
    }
    char path[4096];
    const char *star = strchr(a->vtk, '*');
    if (star)
        snprintf(path, sizeof path, "%.*s%lld%s", (int)(star - a->vtk), a->vtk,
                 (long long)g->step, star + 1);
    else
        snprintf(path, sizeof path, "%s", a->vtk);
    int err = 0;
    const char *why = NULL;
    FILE *fp = fio_open_write_checked(path, 0, &err, &why);
    if (!fp)
        gr_error(g, "fix ave/chunk %s: cannot open vtk file %.200s: %s", f->id, path, why);
    size_t ncell = (size_t)n[0] * n[1] * n[2];
    fprintf(fp, "# vtk DataFile Version 3.0\ngravel fix ave/chunk %s step %lld\nASCII\n", f->id,
            (long long)g->step);
    fprintf(fp, "DATASET STRUCTURED_POINTS\nDIMENSIONS %d %d %d\n", n[0] + 1, n[1] + 1, n[2] + 1);
    fprintf(fp, "ORIGIN %.17g %.17g %.17g\nSPACING %.17g %.17g %.17g\n", o[0], o[1], o[2], h[0],
            h[1], h[2]);
    int nv = a->nvalues;
    fprintf(fp, "CELL_DATA %zu\nFIELD FieldData %d\n", ncell, nv + 1);
    double nc = a->w.norm;
    for (int j = -1; j < nv; j++) {
        char name[GR_NAMELEN];
        snprintf(name, sizeof name, "%s", j < 0 ? "Ncount" : a->names[j]);
        for (char *p = name; *p; p++)
            if (*p == '/' || *p == '[' || *p == ']' || *p == ' ')
                *p = '_';
        fprintf(fp, "%s 1 %zu double\n", name, ncell);
        for (int kz = 0; kz < n[2]; kz++)
            for (int ky = 0; ky < n[1]; ky++)
                for (int kx = 0; kx < n[0]; kx++) {
                    int k3[3] = {kx, ky, kz}, id = 0;
                    for (int m = 0; m < gr->ndim; m++)
                        id = id * gr->nlayers[m] + k3[gr->dim[m]];
                    double v = j < 0 ? a->count_total[id] / nc
                                     : a->values_total[(size_t)id * nv + j] / nc;
                    fprintf(fp, "%.9g\n", v);
                }
    }
    int ok = !ferror(fp);
    if (fclose(fp) != 0 || !ok || err)
        gr_error(g, "fix ave/chunk %s: writing %.200s failed: %s", f->id, path,
                 strerror(err ? err : EIO));
}

static void ave_init(struct gravel *g, struct fix *f)
{
    struct ave_chunk *a = f->data;
    chunk_atom_get(g, a->chunk, "fix ave/chunk");
    if (a->spatial && a->w.kind != AVE_ONE && !a->reduced && box_changes_size(g))
        gr_error(g, "Fix ave/spatial settings invalid with changing box size (ave running or "
                    "window needs units reduced: the bin count may change)");
    for (int j = 0; j < a->nvalues; j++) {
        if (a->which[j] == V_COMPUTE)
            compute_peratom_check(g, a->ids[j], a->argindex[j], "fix ave/chunk");
        else if (a->which[j] == V_FIX)
            fix_peratom_check(g, a->names[j], "fix ave/chunk");
        else if (a->which[j] == V_VARIABLE)
            var_check_atom(g, a->ids[j], "fix ave/chunk");
    }
    if (a->s.nvalid < g->step)
        ave_sched_reset(g, &a->s);
}


static void sample(struct gravel *g, struct fix *f)
{
    struct ave_chunk *a = f->data;
    ave_sample(g, f, &a->s, "fix ave/chunk", take);
}

const struct fix_style fix_style_ave_spatial = {
    .name = "ave/spatial",
    .flags = FIX_OUTPUT,
    .create = spatial_create,
    .init = ave_init,
    .setup = sample,
    .end_of_step = sample,
    .unfix = spatial_unfix,
    .destroy = ave_destroy,
};

const struct fix_style fix_style_ave_chunk = {
    .name = "ave/chunk",
    .flags = FIX_OUTPUT,
    .create = ave_create,
    .init = ave_init,
    .setup = sample, /* LAMMPS's setup(): a sample when the run's first step is due */
    .end_of_step = sample,
    .destroy = ave_destroy,
};
