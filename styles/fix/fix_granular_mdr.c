/* fix_granular_mdr.c - `fix ID group granular/mdr` (today's LAMMPS
 * fix_granular_mdr.cpp): the per-atom bookkeeping of pair granular's mdr
 * normal model, and that model's normal force. pair_coeff ... mdr creates
 * it as `fix MDR all granular/mdr` when no such fix exists (LAMMPS's
 * GranSubModNormalMDR::init does the same).
 *
 * Every step before the forces (pre_force; at a run's setup only new atoms
 * are set up and nothing advances, as LAMMPS's setup_pre_force and its
 * setup force without history update), on the host, in LAMMPS's order:
 *   1. each atom's update from the sums its contacts gathered at the step
 *      before: volumes, free surface ratio psi, apparent radius growth
 *      (styles/pair/gran_mdr.c, mdr_atom_update); the sums are zeroed;
 *   2. the contact penalties of particles seen through a third one (every
 *      three mutually overlapping atoms, Zunker et al. 2025);
 *   3. each atom's mean surface displacement increment (the bulk response);
 *   4. each contact's mdr normal force (mdr_pair_force), which advances its
 *      history, gathers the atoms' sums and leaves the force in the
 *      contact's history row (MH_FN), where the kernel reads it
 *      (kernels/pair_granular.cl) and adds damping mdr, friction, rolling
 *      and twisting;
 *   5. the mdr walls' contacts (fix wall/gran/region granular mdr on plane
 *      regions): their share of step 3 after the pairs', then their force
 *      after the pairs' (the walls' section below).
 * The work is on the host because every step couples each contact to the
 * per-atom sums of all of its atoms' contacts and the penalties to triples
 * of atoms: contacts are visited in ascending (lower tag, higher tag), so
 * each atom's sums run in ascending partner tag and nothing depends on the
 * memory order. The atoms' state is kept by tag (so it follows every
 * re-sort; commands that renumber atoms refuse while the fix exists) and
 * saved in restart files; the new radii go to the device.
 * LAMMPS's neighbor lists do not follow the radius growth; here an atom
 * grown by a quarter of the skin since the last build asks a rebuild with
 * cut-offs for the new radii (nbr_radii_changed), which changes no result.
 * On several MPI ranks every rank gathers every rank's atoms and contacts
 * (fix_granular_mdr_ranks.h) and runs all of the above on the whole set in
 * the same order, so the state by tag is the same on every rank and the
 * results are one process's bits; each rank takes back its own part. */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "atom_custom.h"
#include "device.h"
#include "domain.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "fix_granular_mdr_ranks.h"
#include "fix_wall_gran.h"
#include "gran_mdr.h"
#include "neighbor.h"
#include "pair.h"
#include "pair_granular.h"
#include "par.h"
#include "region.h"
#include "wall.h"

/* the per-atom state a restart file keeps: these doubles of struct
 * mdr_atom, in this order, after the atom's tag */
static const size_t atom_vals[] = {
    offsetof(struct mdr_atom, Ro),      offsetof(struct mdr_atom, Vgeo),
    offsetof(struct mdr_atom, Velas),   offsetof(struct mdr_atom, Acon0),
    offsetof(struct mdr_atom, Acon1),   offsetof(struct mdr_atom, Atot),
    offsetof(struct mdr_atom, psi),     offsetof(struct mdr_atom, ddelta_bar),
    offsetof(struct mdr_atom, dRavg),   offsetof(struct mdr_atom, Vcaps),
    offsetof(struct mdr_atom, eps_bar), offsetof(struct mdr_atom, dRnum),
    offsetof(struct mdr_atom, dRden),   offsetof(struct mdr_atom, Atot_sum)};
#define MDR_ATOM_VALS (sizeof atom_vals / sizeof atom_vals[0])
#define MDR_REC (sizeof(int64_t) + MDR_ATOM_VALS * sizeof(double))

static double *atom_val(struct mdr_atom *a, size_t k)
{
    return (double *)((char *)a + atom_vals[k]);
}

struct mdr_fix {
    struct mdr_mat mat;
    double eta, dtype;          /* damping mdr's eta_n0 and type (the walls must agree) */
    int hoff;                   /* the mdr block in the history row */
    struct mdr_atom *at;        /* by tag */
    int64_t cap;                /* tags 0 .. cap - 1 held */
    unsigned char *restart;     /* the state read_restart gave, applied at the next run */
    size_t restart_len;
    bigint builds;              /* the run's neighbor builds when Rlist was taken (-1: none) */
    int warned;                 /* the plastic-overlap warning was given */
    /* the mdr walls' contact state: MH_N doubles per (tag, wall of the
     * run); zeroed when the run's mdr walls change in number */
    double *wallh;
    int64_t wcap;               /* tags held */
    int wall_n;                 /* walls held */
};

static void destroy(struct fix *f)
{
    struct mdr_fix *d = f->data;
    if (d) {
        free(d->at);
        free(d->wallh);
        free(d->restart);
        free(d);
    }
}

/* LAMMPS's fix property/atom of the mdr state (FixGranularMDR::
 * post_constructor): the same d_ names, for compute property/atom, dump
 * custom and atom-style variables; a copy of the state by tag, written at
 * the end of every pre_force (at a run's setup only for atoms set up then:
 * LAMMPS neither updates nor zeroes the others there). */
#define MDR_PROPS_FIX "MDR_PARTICLE_HISTORY_VARIABLES"
enum { MDR_NPROPS = 18 };
static const char *const prop_names[MDR_NPROPS] = {
    "Ro",   "Vcaps",    "Vgeo",       "Velas", "eps_bar", "dRnumerator",        "dRdenominator",
    "Acon0", "Acon1",   "Atot",       "Atot_sum", "ddelta_bar", "psi", "history_setup_flag",
    "sigmaxx", "sigmayy", "sigmazz", "dRavg"};

static void prop_values(const struct mdr_atom *a, double v[MDR_NPROPS])
{
    const double vals[MDR_NPROPS] = {a->Ro,    a->Vcaps, a->Vgeo,     a->Velas,    a->eps_bar,
                                     a->dRnum, a->dRden, a->Acon0,    a->Acon1,    a->Atot,
                                     a->Atot_sum, a->ddelta_bar, a->psi, a->ready ? 1.0 : 0.0,
                                     a->sigma[0], a->sigma[1], a->sigma[2], a->dRavg};
    memcpy(v, vals, sizeof vals);
}

static void props_write(struct gravel *g, const struct mdr_fix *d, int setup)
{
    struct atoms *A = &g->atoms;
    const int k0 = custom_find(A, prop_names[0]);
    if (k0 < 0)
        return;
    struct custom_ref ref[MDR_NPROPS];
    for (int q = 0; q < MDR_NPROPS; q++)
        ref[q] = (struct custom_ref){custom_find(A, prop_names[q]), 0};
    for (int i = 0; i < A->n; i++) {
        if (A->tag[i] >= d->cap)
            continue;
        const struct mdr_atom *a = &d->at[A->tag[i]];
        if (setup && custom_get(A, ref[13], i) != 0.0)
            continue;
        double v[MDR_NPROPS];
        prop_values(a, v);
        for (int q = 0; q < MDR_NPROPS; q++)
            *custom_at(A, ref[q], i) = v[q];
    }
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    (void)argv;
    if (argc != 0)
        gr_error(g, "fix granular/mdr takes no arguments, got %d", argc);
    f->data = gr_calloc(g, 1, sizeof(struct mdr_fix));
    f->hooks = HOOK_PRE_FORCE;
    struct custom_def defs[MDR_NPROPS];
    for (int q = 0; q < MDR_NPROPS; q++)
        defs[q] = (struct custom_def){prop_names[q], 0, 0, NULL};
    custom_define(g, MDR_PROPS_FIX, MDR_NPROPS, defs);
}

static void unfix(struct gravel *g, struct fix *f)
{
    (void)f;
    custom_remove_fix(g, MDR_PROPS_FIX);
}

static void grow(struct gravel *g, struct mdr_fix *d, int64_t tag)
{
    if (tag < d->cap)
        return;
    int64_t cap = d->cap ? d->cap : 64;
    while (cap <= tag)
        cap *= 2;
    struct mdr_atom *n = realloc(d->at, (size_t)cap * sizeof *n);
    if (!n)
        gr_error(g, "fix granular/mdr: out of memory for %lld atoms' state", (long long)cap);
    memset(n + d->cap, 0, (size_t)(cap - d->cap) * sizeof *n);
    d->at = n;
    d->cap = cap;
}

/* LAMMPS's setup_pre_force checks: pair granular whose every type pair is
 * the one mdr model. */
#define MDR_WALLS_MAX 64 /* mdr walls in one run */

/* The walls' contact state of a restart file (its marker record, then the
 * rows; sizes checked by read_restart) into d->wallh, by tag. */
static void walls_restore(struct gravel *g, struct mdr_fix *d, const unsigned char *p, size_t n)
{
    double head[2];
    memcpy(head, p + sizeof(int64_t), sizeof head);
    const int nw = (int)head[0];
    const size_t row = (size_t)nw * MH_N, wb = sizeof(int64_t) + row * sizeof(double);
    int64_t cap = d->cap;
    for (size_t o = MDR_REC; o + wb <= n; o += wb) {
        int64_t tag;
        memcpy(&tag, p + o, sizeof tag);
        if (tag < 1 || tag > ((int64_t)1 << 40))
            gr_error(g, "fix granular/mdr: the restart file's wall state names atom %lld",
                     (long long)tag);
        if (tag + 1 > cap)
            cap = tag + 1;
    }
    free(d->wallh);
    d->wallh = gr_calloc(g, (size_t)(cap ? cap : 1) * row, sizeof *d->wallh);
    d->wcap = cap;
    d->wall_n = nw;
    for (size_t o = MDR_REC; o + wb <= n; o += wb) {
        int64_t tag;
        memcpy(&tag, p + o, sizeof tag);
        memcpy(d->wallh + (size_t)tag * row, p + o + sizeof tag, row * sizeof(double));
    }
}

static void init(struct gravel *g, struct fix *f)
{
    struct mdr_fix *d = f->data;
    const struct pair *p = g->styles.pair;
    if (!p || strcmp(p->style->name, "granular"))
        gr_error(g, "fix granular/mdr: Must use pair granular with MDR model");
    double mat[7];
    int off = granular_mdr_model(g, p, mat);
    if (off < 0)
        gr_error(g, "fix granular/mdr: Must specify MDR normal model with pair granular");
    mdr_mat_set(&d->mat, mat[0], mat[1], mat[2], mat[3], mat[4]);
    d->eta = mat[5];
    d->dtype = mat[6];
    d->hoff = off;
    d->builds = -1;
    if (d->restart) { /* read_restart's state (atom_vals; then the walls', checked) */
        size_t o = 0;
        for (; o + MDR_REC <= d->restart_len; o += MDR_REC) {
            int64_t tag;
            memcpy(&tag, d->restart + o, sizeof tag);
            if (tag == -1)
                break;
            if (tag < 1 || tag > ((int64_t)1 << 40))
                gr_error(g, "fix granular/mdr: the restart file's state names atom %lld",
                         (long long)tag);
            grow(g, d, tag);
            struct mdr_atom *a = &d->at[tag];
            for (size_t k = 0; k < MDR_ATOM_VALS; k++)
                memcpy(atom_val(a, k), d->restart + o + sizeof tag + k * sizeof(double),
                       sizeof(double));
            a->ready = 1;
        }
        if (o + MDR_REC <= d->restart_len)
            walls_restore(g, d, d->restart + o, d->restart_len - o);
        free(d->restart);
        d->restart = NULL;
    }
}

/* contacts in ascending (owner tag, partner tag): the owner is the lower tag */
static const int64_t *sort_tag;
static const int *sort_ci, *sort_cj;
static int cmp_contact(const void *pa, const void *pb)
{
    const int a = *(const int *)pa, b = *(const int *)pb;
    const int64_t ai = sort_tag[sort_ci[a]], bi = sort_tag[sort_ci[b]];
    if (ai != bi)
        return ai < bi ? -1 : 1;
    const int64_t aj = sort_tag[sort_cj[a]], bj = sort_tag[sort_cj[b]];
    return aj < bj ? -1 : aj > bj;
}

/* x_j - x_i (minimum image) and its length */
static double sep(const struct gravel *g, const struct mdr_atoms *v, int i, int j, double d[3])
{
    const double *x = v->x;
    for (int q = 0; q < 3; q++)
        d[q] = x[3 * j + q] - x[3 * i + q];
    domain_minimum_image(g, d);
    return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

/* the contacts (atoms: indices in v) and their history rows */
struct mdr_scene {
    const struct mdr_atoms *v;
    int nc, hw, *ci, *cj, *ord;
    double *hist;
};

/* The contact of atoms i and j in the sorted order, or -1 */
static int find_contact(const struct mdr_scene *s, int i, int j)
{
    const int64_t *tag = s->v->tag;
    int64_t lo = tag[i] < tag[j] ? tag[i] : tag[j], hi = tag[i] < tag[j] ? tag[j] : tag[i];
    int a = 0, b = s->nc - 1;
    while (a <= b) {
        int m = (a + b) / 2, c = s->ord[m];
        int64_t ti = tag[s->ci[c]], tj = tag[s->cj[c]];
        if (ti == lo && tj == hi)
            return c;
        if (ti < lo || (ti == lo && tj < hi))
            a = m + 1;
        else
            b = m - 1;
    }
    return -1;
}

/* The penalty of every contact: zero, then for every three atoms whose
 * three pairs overlap (r <= r_i + r_j), the pair across the longest side
 * gets the increment of the angle at the third atom (LAMMPS's
 * calculate_contact_penalty; each triple once, lowest tag first). */
static void penalties(struct gravel *g, struct mdr_fix *d, struct mdr_scene *s)
{
    const struct mdr_atoms *v = s->v;
    const double *rad = v->radius;
    const int64_t *tag = v->tag;
    for (int c = 0; c < s->nc; c++)
        s->hist[(size_t)c * s->hw + d->hoff + MH_PENALTY] = 0.0;
    int *part = gr_malloc(g, (size_t)(s->nc + 1) * sizeof *part);
    for (int m = 0; m < s->nc;) { /* one owner's contacts: ord[m .. e) */
        const int i = s->ci[s->ord[m]];
        int e = m;
        while (e < s->nc && s->ci[s->ord[e]] == i)
            e++;
        int np = 0;
        for (int k = m; k < e; k++) {
            double dd[3];
            const int j = s->cj[s->ord[k]];
            if (rad[i] + rad[j] - sep(g, v, i, j, dd) >= 0.0)
                part[np++] = s->ord[k];
        }
        for (int u = 0; u < np; u++)
            for (int w = u + 1; w < np; w++) {
                const int j = s->cj[part[u]], k = s->cj[part[w]];
                double dij[3], dik[3], djk[3];
                const double rij = sep(g, v, i, j, dij), rik = sep(g, v, i, k, dik);
                const double rjk = sep(g, v, j, k, djk);
                if (rad[j] + rad[k] - rjk < 0.0)
                    continue;
                const int cjk = find_contact(s, j, k);
                if (cjk < 0)
                    gr_error(g, "fix granular/mdr: Contact between a pair of particles was "
                                "detected by the MDR model, however it is not reflected in the "
                                "neighbor lists (atoms %lld and %lld). To solve this issue "
                                "either build the neighbor lists more frequently or increase "
                                "their size (e.g. increase the skin distance).",
                             (long long)tag[j], (long long)tag[k]);
                const double rmax = fmax(rij, fmax(rik, rjk));
                double c0;
                int hit;
                if (rij == rmax) { /* k in the middle: i-j screened */
                    c0 = (-dik[0] / rik) * (-djk[0] / rjk) + (-dik[1] / rik) * (-djk[1] / rjk) +
                         (-dik[2] / rik) * (-djk[2] / rjk);
                    hit = part[u];
                } else if (rik == rmax) { /* j in the middle: i-k screened */
                    c0 = (-dij[0] / rij) * (djk[0] / rjk) + (-dij[1] / rij) * (djk[1] / rjk) +
                         (-dij[2] / rij) * (djk[2] / rjk);
                    hit = part[w];
                } else { /* i in the middle: j-k screened */
                    c0 = (dij[0] / rij) * (dik[0] / rik) + (dij[1] / rij) * (dik[1] / rik) +
                         (dij[2] / rij) * (dik[2] / rik);
                    hit = cjk;
                }
                s->hist[(size_t)hit * s->hw + d->hoff + MH_PENALTY] += mdr_penalty(acos(c0));
            }
        m = e;
    }
    free(part);
}

static void yield_warn(struct gravel *g, struct mdr_fix *d, int yield_new)
{
    if (yield_new && !d->warned) { /* LAMMPS's words, once */
        gr_warn(g, "fix granular/mdr: The newly inserted particles have pre-existing overlaps "
                   "that have caused immediate plastic deformation. This could lead to "
                   "non-physical results in the MDR model, as it handles some aspects related "
                   "to plastic deformation incrementally.");
        d->warned = 1;
    }
}


/* ---- the mdr walls (fix wall/gran/region granular mdr ...) ----
 * LAMMPS's FixGranularMDR::update_fix_gran_wall and the walls' calls of
 * calculate_forces (fix wall/gran/region's post_force), both done here on
 * the host: each wall contact's mdr force goes to the mdr block of its
 * history slot (the wall's per-atom state, fix_wall_gran.h), where the
 * wall kernel (kernels/fix_wall_gran.cl) reads it and adds damping mdr,
 * friction and rolling as for the pairs. Between this pre_force and the
 * wall's post_force neither the atoms nor the region move, so the
 * contacts found here are the kernel's. Any region a wall/gran/region
 * takes (LAMMPS's mdr walls take any): a plane's one contact is found here
 * (plane_contact), every other region's contacts by the device's own
 * Region::surface (kernels/wall_region.cl region_probe), read back with the
 * wall's state. As LAMMPS, the mdr force of a region contact is the flat
 * one of the particle's apparent radius at the overlap radius - r: the
 * surface's curvature (region contact radius) enters only the other
 * sub-models (the rolling torque's effective radius), in the kernel. */
struct mdr_wall {
    struct fix *f;
    int k;                      /* its index among the run's mdr walls */
    int plane;                  /* a plane region: contacts found on the host */
    int soff;                   /* its first contact slot among all walls' (d->wallh) */
    struct wall_mdr w;
    struct mdr_mat mat;
    size_t sstride;             /* the wall's per-atom state REAL (device) */
    size_t stride;              /* per atom in own / buf: the state, then (not a plane)
                                 * region_probe's record */
    double *own;                /* this process's atoms, host copy */
    double *buf;                /* ... of the atoms the host part reads (own on one process) */
};

/* The walls of this run, in fix order, their state read from the device
 * (own); the checks of LAMMPS's setup_pre_force. Returns their count;
 * *nslot the contact slots of all. */
static int walls_begin(struct gravel *g, struct mdr_fix *d, struct mdr_wall *mw, int cap,
                       int *nslot)
{
    int nw = 0, ns = 0;
    for (int k = 0; k < g->styles.nfix; k++) {
        struct fix *wf = g->styles.fix[k];
        struct wall_mdr w;
        if (!wall_gran_mdr(wf, &w))
            continue;
        if (nw == cap)
            gr_error(g, "fix granular/mdr: more than %d mdr walls", cap);
        static const char *const what[] = {"Young's modulus", "Poisson's ratio",
                                           "Yield stress", NULL, "Bulk response trigger",
                                           "Damping coefficient", "Damping type"};
        const double own[7] = {d->mat.E, d->mat.nu, d->mat.Y, d->mat.gamma, d->mat.psi_b,
                               d->eta, d->dtype};
        for (int q = 0; q < 7; q++) /* the surface energy may differ (the wall's own) */
            if (what[q] && own[q] != w.par[q])
                gr_error(g, "fix granular/mdr: %s in pair style, %g, does not agree with value "
                            "%g in fix %s (wall/gran/region)", what[q], own[q], w.par[q], wf->id);
        const struct region *r = w.region;
        if (!r)
            gr_error(g, "internal error: fix %s (wall/gran/region) has no region", wf->id);
        struct mdr_wall *m = &mw[nw];
        m->k = nw++;
        m->f = wf;
        m->w = w;
        m->plane = !strcmp(r->style->name, "plane");
        m->soff = ns;
        ns += w.slots;
        mdr_mat_set(&m->mat, w.par[0], w.par[1], w.par[2], w.par[3], w.par[4]);
        m->sstride = (size_t)(1 + (1 + w.hw) * w.slots);
        m->stride = m->sstride + (m->plane ? 0 : (size_t)RG_PROBE_W);
        m->own = m->buf = NULL;
        if (!wf->peratom)
            continue;
        const size_t n = g->atoms.n ? (size_t)g->atoms.n : 1;
        m->own = gr_malloc(g, n * m->stride * sizeof(double));
        m->buf = m->own;
        if (region_dynamic(r))
            region_prematch(g, (struct region *)r);
        if (m->plane) {
            eng_read_reals(g, wf->peratom, (size_t)g->atoms.n * m->stride, m->own);
            continue;
        }
        /* the state, then the probe's record, per atom */
        double *st = gr_malloc(g, n * m->sstride * sizeof(double));
        double *pr = gr_malloc(g, n * RG_PROBE_W * sizeof(double));
        eng_read_reals(g, wf->peratom, (size_t)g->atoms.n * m->sstride, st);
        cl_mem out = eng_alloc(g, n * RG_PROBE_W * eng_get(g)->rsz, "mdr wall contacts");
        wall_gran_mdr_probe(g, wf, out);
        eng_read_reals(g, out, (size_t)g->atoms.n * RG_PROBE_W, pr);
        clReleaseMemObject(out);
        for (size_t i = 0; i < (size_t)g->atoms.n; i++) {
            memcpy(m->own + i * m->stride, st + i * m->sstride, m->sstride * sizeof(double));
            memcpy(m->own + i * m->stride + m->sstride, pr + i * RG_PROBE_W,
                   RG_PROBE_W * sizeof(double));
        }
        free(st);
        free(pr);
    }
    *nslot = ns;
    return nw;
}

/* The walls' contact state by (tag, slot of all walls) for tags below
 * d->cap: zeroed when the run's mdr walls' slots change in number. */
static void walls_state(struct gravel *g, struct mdr_fix *d, int nw)
{
    if (nw != d->wall_n || d->wcap < d->cap) {
        const size_t row = (size_t)nw * MH_N;
        double *n = gr_calloc(g, (size_t)(d->cap ? d->cap : 1) * (row ? row : 1), sizeof *n);
        if (nw == d->wall_n && d->wallh)
            memcpy(n, d->wallh, (size_t)d->wcap * row * sizeof *n);
        free(d->wallh);
        d->wallh = n;
        d->wcap = d->cap;
        d->wall_n = nw;
    }
}

/* A plane region's contact with atom x of reach cutoff (LAMMPS's
 * RegPlane::surface_interior / surface_exterior in the region's static
 * frame): 1 and the distance *r and the vector from the plane to the atom
 * del, or 0. */
static int plane_contact(const struct region *r, const double x[3], double cutoff, double *rr,
                         double del[3])
{
    double y[3] = {x[0], x[1], x[2]};
    if (r->moveflag)
        for (int q = 0; q < 3; q++)
            y[q] -= r->d[q];
    if (r->rotateflag)
        region_rotate(r, y, -sin(r->theta), cos(r->theta));
    const double *p = r->p;
    double dot = (y[0] - p[0]) * p[3] + (y[1] - p[1]) * p[4] + (y[2] - p[2]) * p[5];
    const double sgn = r->interior ? 1.0 : -1.0;
    dot = sgn * dot;
    if (!(dot < cutoff && dot >= 0))
        return 0;
    *rr = dot;
    for (int q = 0; q < 3; q++)
        del[q] = sgn * dot * p[3 + q];
    return 1;
}

/* one contact of an atom with a wall: the distance, the vector from the
 * surface to the atom, its mdr state (d->wallh) and the kernel's part of
 * its history slot */
struct mdr_wc {
    double r, del[3];
    double *h, *hk;
};

/* Atom i's contacts with wall m (at most RG_MAXC) into c; returns their
 * count. The slots of the wall's per-atom state are kept as the kernel
 * keeps them (kernels/wall_region.cl region_slots, LAMMPS's
 * update_contacts, its c2r included), and the mdr state rows with them:
 * a slot of a wall id no longer touched takes the last slot's state, a new
 * one starts from zero. An atom out of the group or not matched: none, its
 * state kept; matched without contact: none, its count reset. */
static int wall_contacts(const struct mdr_atoms *A, const struct mdr_fix *d,
                         const struct mdr_wall *m, int i, struct mdr_wc *c)
{
    if (!(A->mask[i] & m->f->groupbit) || !m->buf)
        return 0;
    const double *x = A->x + 3 * i;
    if (!region_match(m->w.region, x))
        return 0;
    double *hist = m->buf + (size_t)i * m->stride;
    int nc, iw[RG_MAXC];
    if (m->plane) {
        nc = plane_contact(m->w.region, x, A->radius[i], &c[0].r, c[0].del);
        iw[0] = 0;
    } else {
        const double *pr = hist + m->sstride;
        nc = (int)pr[0];
        for (int k = 0; k < nc; k++) {
            const double *q = pr + 1 + RG_PROBE_C * k;
            c[k].r = q[0];
            c[k].del[0] = q[1];
            c[k].del[1] = q[2];
            c[k].del[2] = q[3];
            iw[k] = (int)q[4];
        }
    }
    if (nc == 0) {
        hist[0] = 0;
        return 0;
    }
    const int slots = m->w.slots, hw = m->w.hw;
    double *walls = hist + 1, *sh = hist + 1 + slots;
    double *hb = d->wallh + ((size_t)A->tag[i] * d->wall_n + m->soff) * MH_N;
    int ncont = (int)hist[0], c2r[RG_MAXC];
    for (int k = 0; k < RG_MAXC; k++)
        c2r[k] = k;
    if (nc == 1 && ncont == 0) { /* a new contact: zero history */
        ncont = 1;
        walls[0] = iw[0];
        for (int q = 0; q < hw; q++)
            sh[q] = 0;
        for (int q = 0; q < MH_N; q++)
            hb[q] = 0;
    } else if (!(nc == 1 && ncont == 1 && (int)walls[0] == iw[0])) {
        int iold = 0;
        while (iold < ncont) {
            int k = 0;
            while (k < nc && iw[k] != (int)walls[iold])
                k++;
            if (k >= nc) { /* gone: the last slot moves here */
                const int last = ncont - 1;
                memmove(sh + (size_t)hw * iold, sh + (size_t)hw * last, hw * sizeof *sh);
                memmove(hb + (size_t)MH_N * iold, hb + (size_t)MH_N * last, MH_N * sizeof *hb);
                walls[iold] = walls[last];
                ncont--;
            } else
                iold++;
        }
        const int nold = ncont;
        for (int inew = 0; inew < nc; inew++) {
            int k = 0;
            while (k < nold && (int)walls[k] != iw[inew])
                k++;
            if (k < nold)
                c2r[k] = inew;
            else {
                c2r[ncont] = inew;
                memset(sh + (size_t)hw * ncont, 0, hw * sizeof *sh);
                memset(hb + (size_t)MH_N * ncont, 0, MH_N * sizeof *hb);
                walls[ncont] = iw[inew];
                ncont++;
            }
        }
    }
    hist[0] = ncont;
    for (int k = 0; k < nc; k++) {
        c[k].h = hb + (size_t)MH_N * c2r[k];
        c[k].hk = sh + (size_t)hw * c2r[k] + m->w.hoff;
    }
    return nc;
}

/* update_fix_gran_wall: each wall contact's share of its atom's mean
 * surface displacement increment */
static void walls_mean_disp(const struct mdr_atoms *A, struct mdr_fix *d, struct mdr_wall *mw,
                            int nw)
{
    for (int k = 0; k < nw; k++)
        for (int i = 0; i < A->n; i++) {
            struct mdr_wc c[RG_MAXC];
            const int nc = wall_contacts(A, d, &mw[k], i, c);
            struct mdr_atom *a = &d->at[A->tag[i]];
            for (int ic = 0; ic < nc; ic++)
                if (a->Acon0 != 0.0)
                    a->ddelta_bar += 1.0 * c[ic].h[MH_AC_0] / a->Acon0 *
                                     (A->radius[i] - c[ic].r - c[ic].h[MH_DELTA_0]);
        }
}

/* the walls' forces (fix wall/gran/region's post_force), after the pairs' */
static void walls_force(const struct mdr_atoms *A, struct mdr_fix *d, struct mdr_wall *mw,
                        int nw, int update, int *yield_new)
{
    for (int k = 0; k < nw; k++) {
        for (int i = 0; i < A->n; i++) {
            struct mdr_wc c[RG_MAXC];
            const int nc = wall_contacts(A, d, &mw[k], i, c);
            for (int ic = 0; ic < nc; ic++) {
                /* GranularModel's contact of a region wall: r from the contact vector */
                const double *del = c[ic].del;
                const double r = sqrt(del[0] * del[0] + del[1] * del[1] + del[2] * del[2]);
                const double rinv = 1.0 / r;
                const double nrm[3] = {del[0] * rinv, del[1] * rinv, del[2] * rinv};
                double *h = c[ic].h;
                mdr_wall_force(&mw[k].mat, h, A->radius[i] - r, &d->at[A->tag[i]],
                               A->radius[i], nrm, A->rmass[i], update, yield_new);
                c[ic].hk[MHW_FN] = h[MH_FN]; /* the kernel's part (kernels/fix_wall_gran.cl) */
                c[ic].hk[MHW_DAMP_SCALE] = h[MH_DAMP_SCALE];
            }
        }
    }
}

/* The walls' state of this process's atoms back to the device (on several
 * ranks taken from the gathered set first; the probe's records dropped). */
static void walls_end(struct gravel *g, struct mdr_wall *mw, int nw, const struct mdr_ranks *r)
{
    for (int k = 0; k < nw; k++) {
        if (mw[k].own) {
            if (r)
                mdr_ranks_wall_back(r, k, mw[k].own);
            if (mw[k].stride != mw[k].sstride)
                for (size_t i = 0; i < (size_t)g->atoms.n; i++)
                    memmove(mw[k].own + i * mw[k].sstride, mw[k].own + i * mw[k].stride,
                            mw[k].sstride * sizeof(double));
            eng_write_reals(g, mw[k].f->peratom, (size_t)g->atoms.n * mw[k].sstride,
                            mw[k].own);
        }
        free(mw[k].own);
        mw[k].own = mw[k].buf = NULL;
    }
}

/* Several ranks: every rank's inputs gathered, the whole host part
 * evaluated on each (fix_granular_mdr_ranks.h); one process: its own. */
static void pre_force(struct gravel *g, struct fix *f)
{
    struct mdr_fix *d = f->data;
    const int setup = eng_in_setup(g);
    run_sync_host(g); /* host order = device order */
    struct atoms *A = &g->atoms;
    const int ranks = par_on(g);
    struct mdr_ranks rk = {0};
    struct mdr_wall mw[MDR_WALLS_MAX];
    int nslot = 0;
    const int nw = walls_begin(g, d, mw, MDR_WALLS_MAX, &nslot);
    struct mdr_atoms V = {A->n, A->tag, A->x, A->radius, A->rmass, A->mask};
    if (ranks) {
        size_t stride[MDR_WALLS_MAX];
        double *own[MDR_WALLS_MAX];
        for (int k = 0; k < nw; k++) {
            stride[k] = mw[k].stride;
            own[k] = mw[k].own;
        }
        mdr_ranks_atoms(g, &rk, nw, stride, own, &V);
        for (int k = 0; k < nw; k++)
            mw[k].buf = rk.wall[k];
    }
    const int n = V.n;
    int64_t tmax = 0;
    for (int i = 0; i < n; i++)
        tmax = V.tag[i] > tmax ? V.tag[i] : tmax;
    grow(g, d, tmax);
    walls_state(g, d, nslot);
    /* 1. the atoms (new ones set up, also at setup) */
    int moved = 0;
    for (int i = 0; i < n; i++) {
        struct mdr_atom *a = &d->at[V.tag[i]];
        const int fresh = !a->ready;
        if (fresh)
            mdr_atom_init(a, V.radius[i]);
        if (setup && !fresh)
            continue;
        const double r0 = V.radius[i];
        mdr_atom_update(&d->mat, a, &V.radius[i]);
        moved |= V.radius[i] != r0;
    }
    for (int i = 0; i < n; i++) {
        struct mdr_atom *a = &d->at[V.tag[i]];
        a->ddelta_bar = 0.0;
        if (!setup)
            mdr_atom_zero_sums(a);
    }
    if (ranks && moved)
        mdr_ranks_radius_back(&rk, A->radius);
    struct dev_atoms *da = eng_atoms(g);
    if (moved && !da->shared)
        eng_write_reals(g, da->radius, (size_t)A->n, A->radius);
    if (ranks && moved) /* the ghosts' new radii for this step's contacts */
        par_forward_radii(g);
    /* the radii the list was built for; a rebuild once one grew by skin / 4 */
    const bigint builds = g->eng->st.nbuilds;
    int regrow = 0;
    for (int i = 0; i < n; i++) {
        struct mdr_atom *a = &d->at[V.tag[i]];
        if (builds != d->builds)
            a->Rlist = V.radius[i];
        regrow |= V.radius[i] - a->Rlist > 0.25 * g->neigh.skin;
    }
    d->builds = builds;
    if (regrow)
        nbr_radii_changed(g);

    /* the contacts and their history rows */
    int yield_new = 0;
    const struct nbr_list *l = nbr_list(g);
    const int nloc = l->ncontact, hw = g->eng->hist_n;
    double *hloc = NULL;
    int *cloc = NULL;
    struct mdr_scene s = {.v = &V, .hw = hw};
    if (nloc > 0) {
        cloc = gr_malloc(g, 2 * (size_t)nloc * sizeof(int));
        hloc = gr_malloc(g, (size_t)nloc * hw * sizeof(double));
        eng_read(g, l->ci, 0, (size_t)nloc * sizeof(int), cloc);
        eng_read(g, l->cj, 0, (size_t)nloc * sizeof(int), cloc + nloc);
        eng_read_reals(g, l->shear, (size_t)nloc * hw, hloc);
    }
    if (ranks) {
        mdr_ranks_contacts(g, &rk, nloc, cloc, cloc + nloc, hloc, hw);
        s.nc = rk.nc;
        s.ci = rk.ci;
        s.cj = rk.cj;
        s.hist = rk.hist;
    } else {
        s.nc = nloc;
        s.ci = cloc;
        s.cj = cloc + nloc;
        s.hist = hloc;
    }
    s.ord = gr_malloc(g, ((size_t)s.nc + 1) * sizeof(int));
    for (int c = 0; c < s.nc; c++)
        s.ord[c] = c;
    sort_tag = V.tag;
    sort_ci = s.ci;
    sort_cj = s.cj;
    if (s.nc > 1)
        qsort(s.ord, (size_t)s.nc, sizeof(int), cmp_contact);

    /* 2. penalties, 3. mean surface displacements (not at setup) */
    if (!setup && s.nc > 0) {
        penalties(g, d, &s);
        for (int m = 0; m < s.nc; m++) {
            const int c = s.ord[m], i = s.ci[c], j = s.cj[c];
            double *h = s.hist + (size_t)c * s.hw, dd[3];
            const double r = sep(g, &V, i, j, dd), radsum = V.radius[i] + V.radius[j];
            if (!(r * r < radsum * radsum))
                continue; /* step 4 forgets its history */
            const double delta = radsum - r;
            const double *hm = h + d->hoff;
            const double dmax = fmax(hm[MH_DELTA_MAX], delta);
            double ds[2]; /* side 0: the partner j (higher tag), side 1: the owner i */
            mdr_side_deltas(dmax, hm[MH_DELTAP_0], hm[MH_DELTAP_1], delta, V.radius[j],
                            V.radius[i], 0, ds);
            struct mdr_atom *a0 = &d->at[V.tag[j]], *a1 = &d->at[V.tag[i]];
            if (a0->Acon0 != 0.0)
                a0->ddelta_bar += hm[MH_AC_0] / a0->Acon0 * (ds[0] - hm[MH_DELTA_0]);
            if (a1->Acon0 != 0.0)
                a1->ddelta_bar += hm[MH_AC_1] / a1->Acon0 * (ds[1] - hm[MH_DELTA_1]);
        }
    }
    if (!setup)
        walls_mean_disp(&V, d, mw, nw);

    /* 4. the forces */
    const unsigned frozen = fix_frozen_groupbit(g);
    for (int m = 0; m < s.nc; m++) {
        const int c = s.ord[m], i = s.ci[c], j = s.cj[c];
        double *h = s.hist + (size_t)c * s.hw, dd[3];
        const double r = sep(g, &V, i, j, dd), radsum = V.radius[i] + V.radius[j];
        if (!(r * r < radsum * radsum)) { /* apart: LAMMPS's history is zero */
            for (int k = 0; k < s.hw - g->eng->hist_owner; k++)
                h[k] = 0.0;
            continue;
        }
        const double nrm[3] = {-dd[0] / r, -dd[1] / r, -dd[2] / r};
        double meff = V.rmass[i] * V.rmass[j] / (V.rmass[i] + V.rmass[j]);
        if (V.mask[i] & frozen)
            meff = V.rmass[j];
        if (V.mask[j] & frozen)
            meff = V.rmass[i];
        struct mdr_atom *a2[2] = {&d->at[V.tag[j]], &d->at[V.tag[i]]};
        const double R2[2] = {V.radius[j], V.radius[i]};
        mdr_pair_force(&d->mat, h + d->hoff, radsum - r, a2, R2, nrm, meff, !setup,
                       &yield_new);
    }
    walls_force(&V, d, mw, nw, !setup, &yield_new);
    yield_warn(g, d, yield_new);
    walls_end(g, mw, nw, ranks ? &rk : NULL);
    if (ranks && nloc > 0)
        mdr_ranks_contacts_back(&rk, hloc);
    if (nloc > 0)
        eng_write_reals(g, l->shear, (size_t)nloc * hw, hloc);
    free(cloc);
    free(hloc);
    free(s.ord);
    mdr_ranks_free(&rk);
    props_write(g, d, setup);
}

/* restart: every atom's state by tag (tags with state only); then, when the
 * runs had mdr walls, a marker record (tag -1, then the walls' count and the
 * number of rows as doubles, the rest zero) and the rows: a tag and its
 * walls' contact state (wall_n x MH_N doubles, d->wallh), for each tag whose
 * state is not all zero. */
static size_t wall_row_bytes(const struct mdr_fix *d)
{
    return sizeof(int64_t) + (size_t)d->wall_n * MH_N * sizeof(double);
}

static int wall_row_used(const struct mdr_fix *d, int64_t t)
{
    const double *h = d->wallh + (size_t)t * d->wall_n * MH_N;
    for (size_t q = 0; q < (size_t)d->wall_n * MH_N; q++)
        if (h[q] != 0)
            return 1;
    return 0;
}

static size_t write_restart(struct gravel *g, struct fix *f, unsigned char *buf, size_t cap)
{
    (void)g;
    struct mdr_fix *d = f->data;
    size_t len = 0;
    for (int64_t t = 0; t < d->cap; t++) {
        struct mdr_atom *a = &d->at[t];
        if (!a->ready)
            continue;
        if (buf && len + MDR_REC <= cap) {
            memcpy(buf + len, &t, sizeof t);
            for (size_t k = 0; k < MDR_ATOM_VALS; k++)
                memcpy(buf + len + sizeof t + k * sizeof(double), atom_val(a, k),
                       sizeof(double));
        }
        len += MDR_REC;
    }
    if (!d->wallh || d->wall_n == 0)
        return len;
    int64_t rows = 0;
    for (int64_t t = 0; t < d->wcap; t++)
        rows += wall_row_used(d, t);
    if (buf && len + MDR_REC <= cap) {
        unsigned char mark[MDR_REC] = {0};
        const int64_t m = -1;
        const double head[2] = {(double)d->wall_n, (double)rows};
        memcpy(mark, &m, sizeof m);
        memcpy(mark + sizeof m, head, sizeof head);
        memcpy(buf + len, mark, MDR_REC);
    }
    len += MDR_REC;
    const size_t wb = wall_row_bytes(d);
    for (int64_t t = 0; t < d->wcap; t++) {
        if (!wall_row_used(d, t))
            continue;
        if (buf && len + wb <= cap) {
            memcpy(buf + len, &t, sizeof t);
            memcpy(buf + len + sizeof t, d->wallh + (size_t)t * d->wall_n * MH_N,
                   wb - sizeof t);
        }
        len += wb;
    }
    return len;
}

static void read_restart(struct gravel *g, struct fix *f, const unsigned char *buf, size_t len)
{
    struct mdr_fix *d = f->data;
    size_t atoms = 0; /* the atom records' bytes (before the walls' marker) */
    while (atoms + MDR_REC <= len) {
        int64_t tag;
        memcpy(&tag, buf + atoms, sizeof tag);
        if (tag == -1)
            break;
        atoms += MDR_REC;
    }
    if (atoms + MDR_REC <= len) { /* the walls' part: its size is checked here */
        double head[2];
        memcpy(head, buf + atoms + sizeof(int64_t), sizeof head);
        const size_t wb = sizeof(int64_t) + (size_t)head[0] * MH_N * sizeof(double);
        if (!(head[0] >= 1 && head[0] <= MDR_WALLS_MAX * RG_MAXC && head[1] >= 0 &&
              len == atoms + MDR_REC + (size_t)head[1] * wb))
            gr_error(g, "fix granular/mdr: the restart file's wall state (%g walls, %g rows) "
                        "does not fill its %zu bytes", head[0], head[1], len - atoms);
    } else if (atoms != len) {
        gr_error(g, "fix granular/mdr: the restart file's state has %zu bytes, not a multiple "
                    "of %zu", len, (size_t)MDR_REC);
    }
    free(d->restart);
    d->restart = gr_malloc(g, len ? len : 1);
    memcpy(d->restart, buf, len);
    d->restart_len = len;
    init(g, f);
}

const struct fix_style fix_style_granular_mdr = {
    .name = "granular/mdr",
    .flags = FIX_STORES_IDS, /* its state is by atom ID: no renumbering */
    .create = create,
    .init = init,
    .pre_force = pre_force,
    .unfix = unfix,
    .write_restart = write_restart,
    .read_restart = read_restart,
    .destroy = destroy,
};
