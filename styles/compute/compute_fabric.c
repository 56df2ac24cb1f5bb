/* compute_fabric.c - `compute ID group fabric cutoff tensor ... [type/include
 * itypes jtypes ...]`: fabric tensors of the contact network, as LAMMPS's
 * compute fabric (GRANULAR package; Ouadfel and Rothenburg's expansion):
 * over the pairs of group atoms within the cut-off (`type`: the pair
 * style's type-pair cut-off, `radius`: r_i + r_j), n = (x_i - x_j) / r,
 *   contact            A_c = 15/2 (<n n> - tr/3 I), <.> the mean over the
 *                      nc pairs
 *   branch             15 / (6 tr D) (D - tr D/3 I), D = sum r n n / (nc (1 + n.A_c.n))
 *   force/normal       15 / (6 tr X) (X - tr X/3 I), X = sum f_n n n / (nc (1 + n.A_c.n))
 *   force/tangential   15 / (9 tr X) (Y - tr Y/3 I), Y likewise with |f_t|
 * each as six values xx yy zz xy xz yz, in the order given: a global vector
 * of 6 per tensor (intensive); the global scalar is nc (extensive). The
 * forces are the pair style's single() (f_n = r fpair; |f_t| its 4th extra
 * value: gran/hooke/history, gran/hertz/history), as LAMMPS. type/include
 * keeps only pairs whose types are in the two lists (comma-separated
 * ranges, both ways round). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "compute.h"
#include "error.h"
#include "host_pairs.h"
#include "pair.h"
#include "pair_single_eval.h"

#define WHO "compute fabric"

enum { T_CONTACT, T_BRANCH, T_FNORMAL, T_FTANGENT };

struct fabric {
    int radius;          /* cut-off r_i + r_j (else the type-pair cut-off) */
    int n, t[16];        /* the tensors, in order */
    int need_force, need_ft;
    int ntypes;
    unsigned char *keep; /* type/include: [(ntypes + 1)^2], NULL: every pair */
    double nc;
};

static void fb_destroy(struct compute *c)
{
    struct fabric *fb = c->data;
    if (fb)
        free(fb->keep);
    free(fb);
    c->data = NULL;
}

/* every range of a comma-separated list, into lo[], hi[] (returns the count) */
static int type_list(struct gravel *g, const char *s, int n, int *lo, int *hi, int cap)
{
    char buf[256];
    if (strlen(s) >= sizeof buf)
        gr_error(g, WHO ": type list '%.64s...' is too long", s);
    strcpy(buf, s);
    int m = 0;
    for (char *save = NULL, *tok = strtok_r(buf, ",", &save); tok;
         tok = strtok_r(NULL, ",", &save)) {
        if (m == cap)
            gr_error(g, WHO ": at most %d type ranges in a list", cap);
        arg_type_range(g, tok, n, lo + m, hi + m);
        m++;
    }
    if (m == 0)
        gr_error(g, WHO ": empty type list");
    return m;
}

static void fb_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, WHO " expects a cutoff style (type or radius) and tensors");
    struct fabric *fb = gr_calloc(g, 1, sizeof *fb);
    c->data = fb;
    if (!strcmp(argv[0], "radius"))
        fb->radius = 1;
    else if (strcmp(argv[0], "type"))
        gr_error(g, WHO ": cutoff style must be type or radius, got '%.64s'", argv[0]);
    fb->ntypes = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1;
    for (int i = 1; i < argc; i++) {
        const char *s = argv[i];
        int t = -1;
        if (!strcmp(s, "contact"))
            t = T_CONTACT;
        else if (!strcmp(s, "branch"))
            t = T_BRANCH;
        else if (!strcmp(s, "force/normal"))
            t = T_FNORMAL;
        else if (!strcmp(s, "force/tangential"))
            t = T_FTANGENT;
        if (t >= 0) {
            if (fb->n == 16)
                gr_error(g, WHO ": at most 16 tensors");
            fb->t[fb->n++] = t;
            fb->need_force |= t >= T_FNORMAL;
            fb->need_ft |= t == T_FTANGENT;
            continue;
        }
        if (strcmp(s, "type/include"))
            gr_error(g, WHO ": unknown tensor or keyword '%.64s' (contact, branch, "
                        "force/normal, force/tangential, type/include)", s);
        if (i + 2 >= argc)
            gr_error(g, WHO ": type/include needs two type lists");
        const int n = fb->ntypes, w = n + 1;
        if (!fb->keep)
            fb->keep = gr_calloc(g, (size_t)w * w, 1);
        int ilo[64], ihi[64], jlo[64], jhi[64];
        const int ni = type_list(g, argv[i + 1], n, ilo, ihi, 64);
        const int nj = type_list(g, argv[i + 2], n, jlo, jhi, 64);
        for (int a = 0; a < ni; a++)
            for (int b = 0; b < nj; b++)
                for (int it = ilo[a]; it <= ihi[a]; it++)
                    for (int jt = jlo[b]; jt <= jhi[b]; jt++)
                        fb->keep[it * w + jt] = fb->keep[jt * w + it] = 1;
        i += 2;
    }
    c->vector_flag = 1;
    c->size_vector = 6 * fb->n;
    c->extvector = 0;
    c->scalar_flag = 1;
    c->extscalar = 1;
}

/* the pair style's answers; errors as LAMMPS's init */
static void fb_caps(struct gravel *g, struct compute *c, struct pair_caps *caps)
{
    const struct fabric *fb = c->data;
    const struct pair *p = g->styles.pair;
    if (!p)
        gr_error(g, "no pair style is defined for " WHO " %s", c->id);
    pair_describe(p, caps);
    if (fb->need_force && !caps->single)
        gr_error(g, WHO " %s: pair style %s does not support compute fabric normal or "
                    "tangential force (it has no single-pair evaluation here)",
                 c->id, p->style->name);
    if (fb->need_ft && caps->single_extra < 4)
        gr_error(g, WHO " %s: pair style %s does not calculate tangential forces for compute "
                    "fabric here (gran/hooke/history and gran/hertz/history do)",
                 c->id, p->style->name);
    if (caps->beyond)
        gr_error(g, WHO " %s does not support pair styles that extend beyond contact", c->id);
}

static void fb_init(struct gravel *g, struct compute *c)
{
    struct pair_caps caps;
    fb_caps(g, c, &caps);
}

/* the pairs counted: within the cut-off, type/include's types */
static int fb_pairs(struct gravel *g, struct compute *c, struct host_pair **out)
{
    const struct fabric *fb = c->data;
    struct host_pair *p;
    int np = host_pairs_local(g, c->groupbit, fb->radius, &p, WHO);
    if (fb->keep) {
        const int w = fb->ntypes + 1;
        int m = 0;
        for (int k = 0; k < np; k++)
            if (fb->keep[g->atoms.type[p[k].i] * w + g->atoms.type[p[k].j]])
                p[m++] = p[k];
        np = m;
    }
    *out = p;
    return np;
}

static double fb_scalar(struct gravel *g, struct compute *c)
{
    struct fabric *fb = c->data;
    struct host_pair *p;
    const int np = fb_pairs(g, c, &p);
    free(p);
    return fb->nc = np;
}

/* 15 / (k tr) (T - tr/3 I) into out, T symmetric as xx yy zz xy xz yz; tr
 * the trace of `norm` (T itself, or X for the tangential tensor) */
static void deviator(const double *t, double trace_norm, double k, double *out)
{
    const double tr = (t[0] + t[1] + t[2]) / 3.0, s = 15.0 / (k * trace_norm);
    for (int q = 0; q < 6; q++)
        out[q] = s * (q < 3 ? t[q] - tr : t[q]);
}

static void fb_vector(struct gravel *g, struct compute *c)
{
    struct fabric *fb = c->data;
    struct pair_caps caps;
    fb_caps(g, c, &caps);
    struct host_pair *p;
    const int np = fb_pairs(g, c, &p);
    fb->nc = np;
    memset(c->vector, 0, (size_t)c->size_vector * sizeof *c->vector);
    if (np == 0) {
        free(p);
        return;
    }
    double *fpair = NULL, *sv = NULL;
    if (fb->need_force) {
        fpair = gr_calloc(g, (size_t)np, sizeof *fpair);
        sv = fb->need_ft ? gr_calloc(g, (size_t)np * PAIR_SINGLE_SV, sizeof *sv) : NULL;
        pair_single_eval(g, &caps, p, np, NULL, fpair, sv);
    }
    const double ncinv = 1.0 / np;
    double phi[6] = {0}, ac[6], d[6] = {0}, xn[6] = {0}, xt[6] = {0};
    for (int k = 0; k < np; k++) {
        const double r = sqrt(p[k].rsq), n[3] = {p[k].del[0] / r, p[k].del[1] / r,
                                                 p[k].del[2] / r};
        const double nn[6] = {n[0] * n[0], n[1] * n[1], n[2] * n[2],
                              n[0] * n[1], n[0] * n[2], n[1] * n[2]};
        for (int q = 0; q < 6; q++)
            phi[q] += nn[q];
    }
    for (int q = 0; q < 6; q++)
        phi[q] *= ncinv;
    const double trp = (phi[0] + phi[1] + phi[2]) / 3.0;
    for (int q = 0; q < 6; q++)
        ac[q] = 7.5 * (q < 3 ? phi[q] - trp : phi[q]);
    for (int k = 0; k < np; k++) {
        const double r = sqrt(p[k].rsq), n[3] = {p[k].del[0] / r, p[k].del[1] / r,
                                                 p[k].del[2] / r};
        const double nn[6] = {n[0] * n[0], n[1] * n[1], n[2] * n[2],
                              n[0] * n[1], n[0] * n[2], n[1] * n[2]};
        double den = 1 + ac[0] * nn[0] + ac[1] * nn[1] + ac[2] * nn[2];
        den += 2 * ac[3] * nn[3] + 2 * ac[4] * nn[4] + 2 * ac[5] * nn[5];
        const double pre = ncinv / den;
        for (int q = 0; q < 6; q++) {
            d[q] += pre * nn[q] * r;
            if (fpair)
                xn[q] += pre * nn[q] * (r * fpair[k]);
            if (sv)
                xt[q] += pre * nn[q] * sv[(size_t)k * PAIR_SINGLE_SV + 3];
        }
    }
    const double trxn = xn[0] + xn[1] + xn[2];
    for (int i = 0; i < fb->n; i++) {
        double *out = c->vector + 6 * i;
        switch (fb->t[i]) {
        case T_CONTACT: memcpy(out, ac, sizeof ac); break;
        case T_BRANCH: deviator(d, (d[0] + d[1] + d[2]) / 3.0, 6.0, out); break;
        case T_FNORMAL: deviator(xn, trxn / 3.0, 6.0, out); break;
        case T_FTANGENT: deviator(xt, trxn / 3.0, 9.0, out); break;
        }
    }
    free(p);
    free(fpair);
    free(sv);
}

const struct compute_style compute_style_fabric = {
    .name = "fabric",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = fb_create,
    .init = fb_init,
    .scalar = fb_scalar,
    .vector = fb_vector,
    .destroy = fb_destroy,
};
