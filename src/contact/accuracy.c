/* accuracy.c - collision resolution and wall overlap of the contacts that
 * happen during a run: the records of kernels/accuracy.cl, their reduction
 * and the run's warning and stop (see accuracy.h). */
#include "accuracy.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "device.h"
#include "error.h"
#include "fix.h"
#include "neighbor.h"
#include "wall_layout.h"

/* record widths and offsets: kernels/wall_layout.h (ACC_*); the records are
 * float in both precisions (a diagnostic: 12 bytes per pair contact) */
enum { NCHUNK = 256, PAIR_REC = ACC_PAIR_W, WALL_REC = ACC_WALL_W, FSZ = sizeof(cl_float) };

struct acc {
    cl_mem prec, pstep;     /* pair contacts: float[2], int */
    cl_mem wrec, wstep;     /* particles (walls): float[ACC_WALL_W], int */
    cl_mem out, idx;        /* reduction: float[2 NCHUNK], int[2 NCHUNK] */
    size_t pcap, wcap;
    cl_kernel k_reduce;
    int force, warned;
    struct acc_worst worst;
};

static struct acc *get(struct gravel *g)
{
    struct engine *e = g->eng;
    if (!e->acc)
        e->acc = gr_calloc(g, 1, sizeof *e->acc);
    return e->acc;
}

static void rel(cl_mem *m)
{
    if (*m)
        clReleaseMemObject(*m);
    *m = NULL;
}

/* Records for at least `need` items of `nrec` floats, zeroed (contents not
 * kept); `slack`: room to grow by 1/8 (contacts; particle records follow
 * the engine's capacity exactly). */
static void grow(struct gravel *g, cl_mem *rec, cl_mem *step, size_t *cap, size_t need,
                 int slack, int nrec, const char *what)
{
    if (*rec && need <= *cap)
        return;
    rel(rec);
    rel(step);
    *cap = slack ? need + need / 8 + 64 : need;
    *rec = eng_alloc(g, *cap * (size_t)nrec * FSZ, what);
    *step = eng_alloc(g, *cap * sizeof(cl_int), what);
    eng_fill_zero(g, *rec, *cap * (size_t)nrec * FSZ);
    eng_fill_zero(g, *step, *cap * sizeof(cl_int));
}

static size_t ncontact(struct gravel *g)
{
    return g->eng->k_pair ? (size_t)nbr_list(g)->ncontact : 0;
}

void acc_reserve(struct gravel *g)
{
    struct acc *s = get(g);
    struct engine *e = g->eng;
    grow(g, &s->prec, &s->pstep, &s->pcap, ncontact(g), 1, PAIR_REC,
         "contact accuracy records");
    if (s->wrec) /* the particle records exist once a wall kernel asked for them */
        grow(g, &s->wrec, &s->wstep, &s->wcap, (size_t)e->cap, 0, WALL_REC,
             "particle accuracy records");
    if (!s->out) {
        s->out = eng_alloc(g, 2 * NCHUNK * FSZ, "accuracy reduction");
        if (!s->idx)
            s->idx = eng_alloc(g, 2 * NCHUNK * sizeof(cl_int), "accuracy reduction");
    }
}

void acc_begin(struct gravel *g, int force)
{
    struct acc *s = get(g);
    s->k_reduce = eng_kernel(g, "acc_reduce");
    acc_reserve(g);
    eng_fill_zero(g, s->prec, s->pcap * PAIR_REC * FSZ);
    eng_fill_zero(g, s->pstep, s->pcap * sizeof(cl_int));
    rel(&s->wrec); /* made again, zeroed, by the run's first wall kernel (acc_wall_rec) */
    rel(&s->wstep);
    s->wcap = 0;
    s->force = force;
    s->warned = 0;
    memset(&s->worst, 0, sizeof s->worst);
}

static double read_float(struct gravel *g, cl_mem m, size_t i)
{
    cl_float v;
    eng_read(g, m, i * sizeof v, sizeof v, &v);
    return v;
}

static int read_int(struct gravel *g, cl_mem m, size_t i)
{
    cl_int v;
    eng_read(g, m, i * sizeof v, sizeof v, &v);
    return v;
}

static long long read_tag(struct gravel *g, int i)
{
    cl_long t;
    eng_read(g, eng_atoms(g)->tag, (size_t)i * sizeof t, sizeof t, &t);
    return (long long)t;
}

/* The largest record of n (value at offset 0; ovoff >= 0: also that one):
 * index of the max (lowest on ties, -1 none) and the maxima. */
static int reduce(struct gravel *g, cl_mem rec, int n, int stride, int ovoff, double *q,
                  double *ov)
{
    struct acc *s = get(g);
    *q = *ov = 0;
    if (n <= 0)
        return -1;
    int chunk = (n + NCHUNK - 1) / NCHUNK, nch = (n + chunk - 1) / chunk;
    cl_kernel k = s->k_reduce;
    eng_arg_int(g, k, 0, n);
    eng_arg_int(g, k, 1, chunk);
    eng_arg_int(g, k, 2, stride);
    eng_arg_int(g, k, 3, ovoff);
    eng_arg_mem(g, k, 4, rec);
    eng_arg_mem(g, k, 5, s->out);
    eng_arg_mem(g, k, 6, s->idx);
    eng_launch(g, k, (size_t)nch);
    cl_float v[2 * NCHUNK];
    cl_int ix[2 * NCHUNK];
    eng_read(g, s->out, 0, 2 * (size_t)nch * sizeof *v, v);
    eng_read(g, s->idx, 0, 2 * (size_t)nch * sizeof(cl_int), ix);
    int best = -1;
    for (int c = 0; c < nch; c++) { /* chunks in index order: the first max wins */
        if (v[2 * c] > *q) {
            *q = v[2 * c];
            best = ix[2 * c];
        }
        *ov = fmax(*ov, v[2 * c + 1]);
    }
    return best;
}

void acc_collect(struct gravel *g)
{
    struct engine *e = g->eng;
    struct acc *s = get(g);
    if (!s->k_reduce || !s->prec)
        return;
    /* the list may have grown since the last force computation (a run that
     * computes none, e.g. run 0 continuing a restart while fix pour rebuilds
     * the list): records that cover it, zero where no kernel wrote */
    acc_reserve(g);
    struct acc_worst *w = &s->worst;
    double q, ov;
    int nc = (int)ncontact(g);
    int c = reduce(g, s->prec, nc, PAIR_REC, -1, &q, &ov);
    if (c >= 0 && q > w->q) {
        const struct nbr_list *l = nbr_list(g);
        w->q = q;
        w->vn = sqrt(read_float(g, s->prec, (size_t)PAIR_REC * c + ACC_PAIR_VN2)); /* stored squared */
        w->step = g->firststep + read_int(g, s->pstep, (size_t)c);
        w->tag_i = read_tag(g, read_int(g, l->ci, (size_t)c));
        w->tag_j = read_tag(g, read_int(g, l->cj, (size_t)c));
        w->wall[0] = 0;
    }
    int n = !s->wrec ? 0 : e->a.n < (int)s->wcap ? e->a.n : (int)s->wcap;
    int i = reduce(g, s->wrec, n, WALL_REC, ACC_WALL_OV, &q, &ov);
    w->wall_ov = fmax(w->wall_ov, ov);
    if (i >= 0 && q > w->q) {
        w->q = q;
        w->vn = read_float(g, s->wrec, (size_t)WALL_REC * i + ACC_WALL_VN);
        int code = (int)read_float(g, s->wrec, (size_t)WALL_REC * i + ACC_WALL_CODE);
        w->step = g->firststep + read_int(g, s->wstep, (size_t)i);
        w->tag_i = read_tag(g, i);
        w->tag_j = 0;
        snprintf(w->wall, sizeof w->wall, "%s",
                 code >= 1 && code <= g->styles.nfix ? g->styles.fix[code - 1]->id : "?");
    }
    eng_fill_zero(g, s->prec, (size_t)nc * PAIR_REC * FSZ);
    if (n > 0)
        eng_fill_zero(g, s->wrec, (size_t)n * WALL_REC * FSZ);
    if (!(w->q > 0))
        return;
    double steps = 1.0 / w->q;
    char who[128];
    if (w->tag_j)
        snprintf(who, sizeof who, "atoms %lld and %lld", w->tag_i, w->tag_j);
    else
        snprintf(who, sizeof who, "atom %lld and wall fix %s", w->tag_i, w->wall);
    if (steps < 2 && !s->force)
        gr_error(g, "step %lld: a collision of %s at normal speed %g is resolved by only %.2f "
                    "time steps (collision time %.4g, time step %g): contacts are not resolved; "
                    "reduce the time step or add 'force yes' to run",
                 (long long)w->step, who, w->vn, steps, g->dt / w->q, g->dt);
    if (steps < 10 && !s->warned) {
        s->warned = 1;
        gr_warn(g, "step %lld: a collision of %s at normal speed %g is resolved by only %.1f "
                   "time steps (at least ~10 are needed for accuracy)",
                (long long)w->step, who, w->vn, steps);
    }
}

const struct acc_worst *acc_worst(struct gravel *g) { return &get(g)->worst; }

cl_mem acc_pair_rec(struct gravel *g) { return get(g)->prec; }
cl_mem acc_pair_step(struct gravel *g) { return get(g)->pstep; }

int acc_step(const struct gravel *g)
{
    bigint d = g->step - g->firststep;
    return d > 0x7fffffff ? 0x7fffffff : (int)d;
}

/* Made on demand: a run without wall, region or mesh contacts holds no
 * particle records. */
cl_mem acc_wall_rec(struct gravel *g)
{
    struct acc *s = get(g);
    grow(g, &s->wrec, &s->wstep, &s->wcap, (size_t)g->eng->cap, 0, WALL_REC,
         "particle accuracy records");
    return s->wrec;
}

cl_mem acc_wall_step(struct gravel *g)
{
    acc_wall_rec(g);
    return get(g)->wstep;
}

int acc_wall_code(const struct gravel *g, const struct fix *f)
{
    int code = 0;
    for (int q = 0; q < g->styles.nfix; q++)
        if (g->styles.fix[q] == f)
            code = q + 1;
    return code;
}

size_t acc_contact_bytes(struct gravel *g)
{
    (void)g;
    return PAIR_REC * FSZ + sizeof(cl_int);
}

size_t acc_held_bytes(struct gravel *g)
{
    const struct acc *s = g->eng->acc;
    if (!s)
        return 0;
    return (s->prec ? s->pcap * (PAIR_REC * FSZ + sizeof(cl_int)) : 0) +
           (s->wrec ? s->wcap * (WALL_REC * FSZ + sizeof(cl_int)) : 0);
}

void acc_free(struct gravel *g)
{
    struct engine *e = g->eng;
    if (!e || !e->acc)
        return;
    struct acc *s = e->acc;
    cl_mem *m[] = {&s->prec, &s->pstep, &s->wrec, &s->wstep, &s->out, &s->idx};
    for (size_t i = 0; i < sizeof m / sizeof *m; i++)
        rel(m[i]);
    free(s);
    e->acc = NULL;
}
