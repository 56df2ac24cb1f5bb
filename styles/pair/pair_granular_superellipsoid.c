/* pair_granular_superellipsoid.c - `pair_style granular/superellipsoid
 * [cutoff] [no_bounding_box] [geometric] [curvature_gaussian]` (LAMMPS 30
 * Mar 2026): granular contacts between superellipsoids (atom_style
 * ellipsoid superellipsoid).
 *
 * pair_coeff I J NORMAL kn gamman [tangential linear_history|classic kt xt
 * mu] [damping mass_velocity|viscoelastic] [limit_damping] [cutoff c]:
 *   normal     hooke: Fn = kn (d_i + d_j); hertz: Fn = kn (d_i + d_j) a,
 *              d_i, d_j the two overlaps along the normal from the contact
 *              point, a = sqrt((d_i + d_j) / (k_i + k_j)) the contact
 *              radius from the surfaces' curvatures k (mean curvature, or
 *              sqrt|Gaussian| with curvature_gaussian);
 *   damping    mass_velocity: Fd = gamman m* vn; viscoelastic (default):
 *              Fd = gamman m* a vn (vn the normal relative velocity of the
 *              contact points, positive approaching);
 *   tangential linear_history: the displacement history s (rotated onto
 *              the tangent plane, its length kept, when it has a normal
 *              part) grows by vt dt, Ft = -kt s - xt gamman m* [a] vt,
 *              capped at mu |Fn + Fd| (s rescaled to the cap); classic: s
 *              grows, then loses its normal part, Ft = -kt [a] s - ...;
 *              none given: no tangential force;
 *   limit_damping: no attraction from the damping (Fn + Fd >= 0).
 * Mixed pairs take geometric means (the models must agree). The contact
 * point, normal and overlaps come from src/contact/superellipsoid_contact.h
 * (the midway point by Newton's method, an oriented-bounding-box test first
 * unless no_bounding_box; a new contact starts from spheres of the
 * volume-equivalent radii morphed to the true shapes in 5 steps, a
 * continuing one from the last contact point); the force acts at the
 * contact point: torque_i = (X0 - x_i) x F, and the contact velocity uses
 * omega = I^-1 L from the angular momentum.
 *
 * History per contact (LAMMPS's 5 + 3 values): the contact point relative
 * to the lower-tag particle and mu^2, the last separating box axis, the
 * tangential displacement; kept by the pair of tags, across runs.
 *
 * First landing: the law runs on the host. After the device clears the
 * forces each step, host_forces() reads the particles back, finds the pairs
 * within the sum of bounding radii (a cell grid, src/contact/host_pairs.h),
 * evaluates them in (lower tag, higher tag) order and writes the forces and
 * torques. The run's neighbor list is not used. Not supported (refused):
 * rolling, twisting and heat models (as LAMMPS), MPI ranks, walls.
 *
 * Restart: the settings are p->coef (the pair section); the models and the
 * contact history go into restart section 14 through state_write/state_read
 * (an explicit byte layout, validated before read_restart applies it); the
 * models' bytes join the force fingerprint of the exact continuation. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "device.h"
#include "error.h"
#include "fix.h"
#include "host_pairs.h"
#include "pair.h"
#include "par.h"
#include "rigid_math.h"
#include "superellipsoid_contact.h"

enum { N_HOOKE, N_HERTZ };
enum { D_MASS_VELOCITY, D_VISCOELASTIC };
enum { T_NONE, T_CLASSIC, T_LINEAR_HISTORY };

struct model {
    int set;                    /* explicit pair_coeff */
    int normal, damping, tangential, limit;
    double kn, gamman, kt, xt, mu, cutoff;
};

/* One contact's history (LAMMPS's values, the tangential displacement last). */
struct hist {
    int64_t ti, tj;             /* tags, ti < tj */
    int touch;                  /* in contact at the last evaluation */
    double x0[4];               /* contact point - x(lower tag), mu^2 */
    double axis;                /* last separating box axis */
    double s[3];                /* tangential displacement */
};

/* The pair_style settings live in p->coef (restart's pair section, the
 * force fingerprint): */
enum { C_CUTOFF, C_BOUNDING_BOX, C_GEOMETRIC, C_GAUSSIAN };

/* p->data: the per-type models and the contact history (pair_coeff and the
 * runs fill it; restart section 14 keeps it; redefining the style keeps it,
 * as LAMMPS keeps the coefficients and the history fix). */
struct sqe_pair {
    int nt;
    struct model *m;            /* nt x nt */
    int bounding_box, gaussian; /* copied from p->coef at init */
    enum sqe_formulation form;
    int nhist;
    struct hist *hist;          /* sorted by (ti, tj) */
};

static void destroy(struct pair *p)
{
    struct sqe_pair *s = p->data;
    if (s) {
        free(s->m);
        free(s->hist);
        free(s);
    }
    p->data = NULL;
}

/* The style's data (created by the first pair_coeff, or restored by
 * read_restart). */
static struct sqe_pair *data_of(struct gravel *g, struct pair *p)
{
    if (!p->data)
        p->data = gr_calloc(g, 1, sizeof(struct sqe_pair));
    return p->data;
}

static void settings(struct gravel *g, struct pair *p, int argc, char **argv)
{
    double *c = p->coef;
    c[C_CUTOFF] = -1;
    c[C_BOUNDING_BOX] = 1;
    c[C_GEOMETRIC] = 0;
    c[C_GAUSSIAN] = 0;
    for (int i = 0; i < argc; i++) {
        if (!strcmp(argv[i], "no_bounding_box"))
            c[C_BOUNDING_BOX] = 0;
        else if (!strcmp(argv[i], "geometric"))
            c[C_GEOMETRIC] = 1;
        else if (!strcmp(argv[i], "curvature_gaussian"))
            c[C_GAUSSIAN] = 1;
        else if (i == 0)
            c[C_CUTOFF] = arg_positive(g, argv[i], "pair_style granular/superellipsoid cutoff");
        else
            gr_error(g, "pair_style granular/superellipsoid: unknown keyword '%.64s' "
                        "(no_bounding_box, geometric, curvature_gaussian)", argv[i]);
    }
}

static struct model *model_at(struct sqe_pair *s, int i, int j)
{
    return &s->m[(size_t)(i - 1) * s->nt + (j - 1)];
}

static double nonneg(struct gravel *g, const char *v, const char *what)
{
    return arg_nonneg(g, v, what);
}

static void coeff(struct gravel *g, struct pair *p, int ilo, int ihi, int jlo, int jhi, int argc,
                  char **argv)
{
    struct sqe_pair *s = data_of(g, p);
    int nt = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1;
    if (!s->m || s->nt != nt) {
        free(s->m);
        s->m = gr_calloc(g, (size_t)nt * nt, sizeof *s->m);
        s->nt = nt;
    }
    struct model md = {.set = 1, .damping = D_VISCOELASTIC, .tangential = T_NONE, .cutoff = -1};
    if (argc < 1)
        gr_error(g, "granular/superellipsoid needs a normal model (hooke or hertz)");
    if (!strcmp(argv[0], "hooke") || !strcmp(argv[0], "hertz")) {
        md.normal = argv[0][1] == 'o' ? N_HOOKE : N_HERTZ;
        arg_need(g, argc, 0, 2, argv[0]);
        md.kn = nonneg(g, argv[1], "normal stiffness kn");
        md.gamman = nonneg(g, argv[2], "normal damping gamman");
    } else {
        gr_error(g, "unknown normal model '%.64s' for granular/superellipsoid "
                    "(hooke or hertz)", argv[0]);
    }
    for (int k = 3; k < argc; k++) {
        const char *kw = argv[k];
        if (!strcmp(kw, "tangential")) {
            arg_need(g, argc, k, 4, kw);
            const char *t = argv[k + 1];
            if (!strcmp(t, "linear_history"))
                md.tangential = T_LINEAR_HISTORY;
            else if (!strcmp(t, "classic"))
                md.tangential = T_CLASSIC;
            else
                gr_error(g, "unknown tangential model '%.64s' for "
                            "granular/superellipsoid (linear_history or classic)", t);
            md.kt = nonneg(g, argv[k + 2], "tangential stiffness kt");
            md.xt = nonneg(g, argv[k + 3], "tangential damping xt");
            md.mu = nonneg(g, argv[k + 4], "friction coefficient mu");
            k += 4;
        } else if (!strcmp(kw, "damping")) {
            arg_need(g, argc, k, 1, kw);
            if (!strcmp(argv[k + 1], "mass_velocity"))
                md.damping = D_MASS_VELOCITY;
            else if (!strcmp(argv[k + 1], "viscoelastic"))
                md.damping = D_VISCOELASTIC;
            else
                gr_error(g, "unknown damping model '%.64s' for "
                            "granular/superellipsoid (mass_velocity or viscoelastic)",
                         argv[k + 1]);
            k += 1;
        } else if (!strcmp(kw, "limit_damping")) {
            md.limit = 1;
        } else if (!strcmp(kw, "cutoff")) {
            arg_need(g, argc, k, 1, kw);
            md.cutoff = arg_positive(g, argv[k + 1], "cutoff");
            k += 1;
        } else if (!strcmp(kw, "rolling") || !strcmp(kw, "twisting") || !strcmp(kw, "heat")) {
            gr_error(g, "%s models are not implemented for superellipsoids (nor in "
                        "LAMMPS)", kw);
        } else {
            gr_error(g, "unknown keyword '%.64s' for granular/superellipsoid", kw);
        }
    }
    for (int i = ilo; i <= ihi; i++)
        for (int j = i > jlo ? i : jlo; j <= jhi; j++)
            *model_at(s, i, j) = *model_at(s, j, i) = md;
    p->coeff_set = 1;
}

static void init(struct gravel *g, struct pair *p)
{
    struct sqe_pair *s = p->data;
    int nt = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1;
    const struct atoms *a = &g->atoms;
    if (!a->ellipsoid_flag)
        gr_error(g, "pair granular/superellipsoid requires atom_style ellipsoid superellipsoid");
    if (par_on(g))
        par_refuse(g, "pair granular/superellipsoid (its contacts are evaluated on the host of "
                      "one process)");
    if (!s || !s->m || s->nt != nt)
        gr_error(g, "pair granular/superellipsoid: pair_coeff must be given for the %d atom "
                    "type(s) of the box", nt);
    s->bounding_box = p->coef[C_BOUNDING_BOX] != 0;
    s->form = p->coef[C_GEOMETRIC] != 0 ? SQE_GEOMETRIC : SQE_ALGEBRAIC;
    s->gaussian = p->coef[C_GAUSSIAN] != 0;
    for (int i = 0; i < a->n; i++) {
        const double *sh = a->shape + 3 * i, *b = a->block + 2 * i;
        if (sh[0] == 0.0 && sh[1] == 0.0 && sh[2] == 0.0)
            gr_error(g, "pair granular/superellipsoid requires all atoms are ellipsoids: atom "
                        "%lld has no shape (set shape)", (long long)a->tag[i]);
        if (b[0] < 2.0 || b[1] < 2.0)
            gr_error(g, "pair granular/superellipsoid requires convex particles: atom %lld has "
                        "blockiness %g %g (both must be >= 2)", (long long)a->tag[i], b[0],
                     b[1]);
    }
    for (int i = 1; i <= nt; i++)
        if (!model_at(s, i, i)->set)
            gr_error(g, "all pair coeffs are not set: no pair_coeff for types %d %d of pair "
                        "style granular/superellipsoid", i, i);
    for (int i = 1; i <= nt; i++)
        for (int j = i + 1; j <= nt; j++) {
            struct model *m = model_at(s, i, j);
            if (m->set)
                continue;
            const struct model *a1 = model_at(s, i, i), *b1 = model_at(s, j, j);
            if (a1->normal != b1->normal || a1->tangential != b1->tangential ||
                a1->damping != b1->damping)
                gr_error(g, "granular/superellipsoid models of types %d and %d differ: cannot "
                            "mix them, give pair_coeff %d %d explicitly", i, j, i, j);
            *m = *a1;
            m->set = 0;
            m->limit = a1->limit > b1->limit ? a1->limit : b1->limit;
            m->kn = sqrt(a1->kn * b1->kn);
            m->gamman = sqrt(a1->gamman * b1->gamman);
            m->kt = sqrt(a1->kt * b1->kt);
            m->xt = sqrt(a1->xt * b1->xt);
            m->mu = sqrt(a1->mu * b1->mu);
            *model_at(s, j, i) = *m;
        }
}

/* ---- the contact law: a pure function of one contact's state ------------- */

struct sqe_contact {
    const struct sqe_body *bi, *bj;
    double X0[3], nij[3];       /* contact point, normal from i to j */
    double vi[3], vj[3], wi[3], wj[3]; /* centre velocities, angular velocities */
    double meff, dt;
    int update;                 /* advance the tangential history (not at set-up) */
    int gaussian;
};

/* The force on i (F), the torques on i and j, from the model md; s is the
 * tangential displacement history (advanced when c->update). */
static void sqe_force(const struct model *md, const struct sqe_contact *c, double s[3],
                      double F[3], double ti[3], double tj[3])
{
    double nji[3] = {-c->nij[0], -c->nij[1], -c->nij[2]};
    double di = sqe_overlap_distance(c->bi, c->X0, c->nij);
    double dj = sqe_overlap_distance(c->bj, c->X0, nji);
    double ri[3], rj[3], vr[3];
    for (int k = 0; k < 3; k++) {
        ri[k] = c->X0[k] - c->bi->xc[k];
        rj[k] = c->X0[k] - c->bj->xc[k];
    }
    double ci[3] = {c->wi[1] * ri[2] - c->wi[2] * ri[1], c->wi[2] * ri[0] - c->wi[0] * ri[2],
                    c->wi[0] * ri[1] - c->wi[1] * ri[0]};
    double cj[3] = {c->wj[1] * rj[2] - c->wj[2] * rj[1], c->wj[2] * rj[0] - c->wj[0] * rj[2],
                    c->wj[0] * rj[1] - c->wj[1] * rj[0]};
    for (int k = 0; k < 3; k++)
        vr[k] = (c->vi[k] + ci[k]) - (c->vj[k] + cj[k]);
    double vn = vr[0] * c->nij[0] + vr[1] * c->nij[1] + vr[2] * c->nij[2], vt[3];
    for (int k = 0; k < 3; k++)
        vt[k] = vr[k] - vn * c->nij[k];
    int radius_flag = md->normal == N_HERTZ || md->damping == D_VISCOELASTIC;
    double a = 0.0;
    if (radius_flag) {
        /* LAMMPS's contact radius: sqrt of the overlap over the summed
         * curvatures at the two surface points (its capped estimate is
         * overwritten by this plain one) */
        double pi[3], pj[3];
        for (int k = 0; k < 3; k++) {
            pi[k] = c->X0[k] + di * c->nij[k];
            pj[k] = c->X0[k] + dj * nji[k];
        }
        double ki = sqe_curvature(c->bi, pi, c->gaussian);
        double kj = sqe_curvature(c->bj, pj, c->gaussian);
        a = sqrt((di + dj) / (ki + kj));
    }
    double fn = md->normal == N_HOOKE ? md->kn * (di + dj) : md->kn * (di + dj) * a;
    double damp = md->damping == D_MASS_VELOCITY ? md->gamman * c->meff
                                                 : md->gamman * c->meff * a;
    double ftot = fn + damp * vn;
    if (md->limit && ftot < 0.0)
        ftot = 0.0;
    double fscrit = fabs(ftot) * md->mu, dampt = md->xt * damp, fs[3] = {0, 0, 0};
    if (md->tangential == T_LINEAR_HISTORY) {
        if (c->update) {
            double rsht = s[0] * c->nij[0] + s[1] * c->nij[1] + s[2] * c->nij[2];
            if (fabs(rsht) * md->kt > 1e-10 * fscrit) { /* back onto the tangent plane */
                double mag = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
                for (int k = 0; k < 3; k++)
                    s[k] -= rsht * c->nij[k];
                double pm = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
                double sc = pm > 0 ? mag / pm : 0.0;
                for (int k = 0; k < 3; k++)
                    s[k] *= sc;
            }
            for (int k = 0; k < 3; k++)
                s[k] += c->dt * vt[k];
        }
        double fd[3];
        for (int k = 0; k < 3; k++) {
            fd[k] = -dampt * vt[k];
            fs[k] = -md->kt * s[k] + fd[k];
        }
        double mag = sqrt(fs[0] * fs[0] + fs[1] * fs[1] + fs[2] * fs[2]);
        if (mag > fscrit) {
            double smag = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
            if (smag != 0.0) {
                double r = fscrit * (1.0 / mag);
                for (int k = 0; k < 3; k++) {
                    s[k] = -(r * fs[k] - fd[k]) / md->kt;
                    fs[k] *= r;
                }
            } else {
                fs[0] = fs[1] = fs[2] = 0.0;
            }
        }
    } else if (md->tangential == T_CLASSIC) {
        if (c->update)
            for (int k = 0; k < 3; k++)
                s[k] += c->dt * vt[k];
        double smag = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
        if (c->update) {
            double rsht = s[0] * c->nij[0] + s[1] * c->nij[1] + s[2] * c->nij[2];
            for (int k = 0; k < 3; k++)
                s[k] -= rsht * c->nij[k];
        }
        double kt = radius_flag ? md->kt * a : md->kt, fd[3];
        for (int k = 0; k < 3; k++) {
            fd[k] = -dampt * vt[k];
            fs[k] = -kt * s[k] + fd[k];
        }
        double mag = sqrt(fs[0] * fs[0] + fs[1] * fs[1] + fs[2] * fs[2]);
        if (mag > fscrit) {
            if (smag != 0.0) {
                for (int k = 0; k < 3; k++) {
                    fs[k] *= fscrit / mag;
                    s[k] = (fs[k] - fd[k]) * (-1.0 / kt);
                }
            } else {
                fs[0] = fs[1] = fs[2] = 0.0;
            }
        }
    }
    for (int k = 0; k < 3; k++)
        F[k] = ftot * nji[k] + fs[k];
    ti[0] = ri[1] * F[2] - ri[2] * F[1];
    ti[1] = ri[2] * F[0] - ri[0] * F[2];
    ti[2] = ri[0] * F[1] - ri[1] * F[0];
    tj[0] = F[1] * rj[2] - F[2] * rj[1];
    tj[1] = F[2] * rj[0] - F[0] * rj[2];
    tj[2] = F[0] * rj[1] - F[1] * rj[0];
}

/* ---- the host evaluation of one step ------------------------------------ */

/* The device state one step reads (device order). */
struct snap {
    int n;
    int64_t *tag;
    int *type;
    unsigned *mask;
    double *x, *v, *rmass, *radius, *quat, *angmom, *inertia, *shape, *block;
    double L[3];                /* periodic lengths (0: not periodic) */
};

struct cand {
    int i, j;                   /* i the lower tag */
    double del[3], rsq;         /* x_i - x_j, minimum image */
};

struct scan_ctx {
    const struct snap *sn;
    int n, cap;
    struct cand *c;
};

static double minimg(double d, double L)
{
    if (L > 0 && (d > 0.5 * L || d < -0.5 * L))
        d -= L * floor(d / L + 0.5);
    return d;
}

/* A pair of the cell scan: kept when the bounding spheres overlap. */
static void scan_visit(struct gravel *g, int k, int kk, void *vctx)
{
    struct scan_ctx *c = vctx;
    const struct snap *sn = c->sn;
    int i = k, j = kk;
    if (sn->tag[j] < sn->tag[i])
        i = kk, j = k;
    double del[3], rsq = 0.0;
    for (int q = 0; q < 3; q++) {
        del[q] = minimg(sn->x[3 * i + q] - sn->x[3 * j + q], sn->L[q]);
        rsq += del[q] * del[q];
    }
    double rs = sn->radius[i] + sn->radius[j];
    if (!(rsq < rs * rs))
        return;
    if (c->n == c->cap) {
        c->cap = c->cap ? 2 * c->cap : 64;
        c->c = gr_realloc(g, c->c, (size_t)c->cap * sizeof *c->c);
    }
    struct cand *p = &c->c[c->n++];
    p->i = i, p->j = j, p->rsq = rsq;
    memcpy(p->del, del, sizeof del);
}

static const struct snap *sort_snap;

static int cmp_cand(const void *pa, const void *pb)
{
    const struct cand *a = pa, *b = pb;
    int64_t ai = sort_snap->tag[a->i], bi = sort_snap->tag[b->i];
    if (ai != bi)
        return ai < bi ? -1 : 1;
    int64_t aj = sort_snap->tag[a->j], bj = sort_snap->tag[b->j];
    return aj < bj ? -1 : aj > bj;
}

static const struct hist *find_hist(const struct sqe_pair *s, int64_t ti, int64_t tj)
{
    int lo = 0, hi = s->nhist - 1;
    while (lo <= hi) {
        int mid = (lo + hi) / 2;
        const struct hist *h = &s->hist[mid];
        if (h->ti == ti && h->tj == tj)
            return h;
        if (h->ti < ti || (h->ti == ti && h->tj < tj))
            lo = mid + 1;
        else
            hi = mid - 1;
    }
    return NULL;
}

static void body_of(const struct snap *sn, int i, const double xc[3], struct sqe_body *b)
{
    memcpy(b->xc, xc, 3 * sizeof(double));
    rm_quat_to_mat(sn->quat + 4 * i, b->R);
    memcpy(b->shape, sn->shape + 3 * i, 3 * sizeof(double));
    memcpy(b->block, sn->block + 2 * i, 2 * sizeof(double));
    b->kind = sqe_kind(b->block);
}

/* LAMMPS's check_contact for one pair within its bounding spheres: the box
 * test, then the contact point from the last one (a continuing contact) or
 * from spheres of the volume-equivalent radii morphed to the true shapes in
 * 5 steps (a new one; the first step solved as ellipsoids). Leaves bi, bj
 * with the shapes the force evaluation uses. Returns 1 when touching. */
static int find_contact(struct gravel *g, const struct sqe_pair *s, struct sqe_body *bi,
                        struct sqe_body *bj, const struct hist *old, struct hist *h, int update,
                        double X0[4], double nij[3])
{
    if (s->bounding_box) {
        int axis = sqe_obb_separating_axis(bi, bj, (int)h->axis);
        if (axis >= 0) {
            if (update)
                h->axis = axis;
            return 0;
        }
    }
    int touch = 0;
    if (old && old->touch) {
        for (int q = 0; q < 3; q++)
            X0[q] = old->x0[q] + bi->xc[q];
        X0[3] = old->x0[3];
        int st = sqe_contact_point(bi, bj, X0, nij, s->form);
        if (st == 2)
            gr_warn(g, "superellipsoid contact detection (old contact) failed between "
                       "particle %lld and particle %lld", (long long)h->ti, (long long)h->tj);
        return st == 0;
    }
    const double sh0i[3] = {bi->shape[0], bi->shape[1], bi->shape[2]};
    const double sh0j[3] = {bj->shape[0], bj->shape[1], bj->shape[2]};
    const double b0i[2] = {bi->block[0], bi->block[1]}, b0j[2] = {bj->block[0], bj->block[1]};
    const enum sqe_kind ki = bi->kind, kj = bj->kind;
    double reqi = cbrt(sh0i[0] * sh0i[1] * sh0i[2]), reqj = cbrt(sh0j[0] * sh0j[1] * sh0j[2]);
    double rinv = 1.0 / (reqi + reqj);
    for (int q = 0; q < 3; q++)
        X0[q] = reqj * rinv * bi->xc[q] + reqi * rinv * bj->xc[q];
    X0[3] = reqj / reqi; /* mu^2 */
    enum { MORPH_STEPS = 5 };
    for (int it = 1; it <= MORPH_STEPS; it++) {
        double frac = it / (double)MORPH_STEPS;
        for (int q = 0; q < 3; q++) {
            bi->shape[q] = (1.0 - frac) * reqi + frac * sh0i[q];
            bj->shape[q] = (1.0 - frac) * reqj + frac * sh0j[q];
        }
        for (int q = 0; q < 2; q++) {
            bi->block[q] = 2.0 + frac * (b0i[q] - 2.0);
            bj->block[q] = 2.0 + frac * (b0j[q] - 2.0);
        }
        bi->kind = it == 1 ? SQE_ELLIPSOID : ki;
        bj->kind = it == 1 ? SQE_ELLIPSOID : kj;
        int st = sqe_contact_point(bi, bj, X0, nij, s->form);
        if (st == 0)
            touch = 1;
        else if (st == 1)
            touch = 0;
        else if (it == MORPH_STEPS)
            gr_warn(g, "superellipsoid contact detection (new contact) failed between "
                       "particle %lld and particle %lld", (long long)h->ti, (long long)h->tj);
    }
    return touch;
}

static void read_snap(struct gravel *g, struct snap *sn)
{
    struct dev_atoms *a = eng_atoms(g);
    int n = sn->n = a->n;
    size_t m = (size_t)(n > 0 ? n : 1);
    sn->tag = gr_malloc(g, m * sizeof *sn->tag);
    sn->type = gr_malloc(g, m * sizeof *sn->type);
    sn->mask = gr_malloc(g, m * sizeof *sn->mask);
    double *buf = gr_malloc(g, m * 26 * sizeof(double));
    sn->x = buf, sn->v = buf + 3 * m, sn->rmass = buf + 6 * m, sn->radius = buf + 7 * m;
    sn->quat = buf + 8 * m, sn->angmom = buf + 12 * m, sn->inertia = buf + 15 * m;
    sn->shape = buf + 18 * m, sn->block = buf + 21 * m;
    eng_read(g, a->tag, 0, (size_t)n * sizeof(int64_t), sn->tag);
    eng_read(g, a->type, 0, (size_t)n * sizeof(int), sn->type);
    eng_read(g, a->mask, 0, (size_t)n * sizeof(unsigned), sn->mask);
    eng_read_positions(g, a, n, sn->x);
    eng_read_reals(g, a->v, 3 * (size_t)n, sn->v);
    eng_read_reals(g, a->rmass, (size_t)n, sn->rmass);
    eng_read_reals(g, a->radius, (size_t)n, sn->radius);
    eng_read_reals(g, a->quat, 4 * (size_t)n, sn->quat);
    eng_read_reals(g, a->angmom, 3 * (size_t)n, sn->angmom);
    eng_read_reals(g, a->inertia, 3 * (size_t)n, sn->inertia);
    eng_read_reals(g, a->shape, 3 * (size_t)n, sn->shape);
    eng_read_reals(g, a->block, 2 * (size_t)n, sn->block);
    for (int q = 0; q < 3; q++)
        sn->L[q] = g->dom.periodic[q] ? g->dom.hi[q] - g->dom.lo[q] : 0.0;
}

static void free_snap(struct snap *sn)
{
    free(sn->tag);
    free(sn->type);
    free(sn->mask);
    free(sn->x);
}

/* One step's forces and torques (the device's were just cleared). */
static void host_forces(struct gravel *g, const struct pair *p)
{
    struct sqe_pair *s = p->data;
    struct snap sn;
    read_snap(g, &sn);
    int n = sn.n, update = !eng_in_setup(g);
    double rmax = 0.0;
    int *idx = gr_malloc(g, (size_t)(n > 0 ? n : 1) * sizeof *idx);
    for (int i = 0; i < n; i++) {
        idx[i] = i;
        rmax = fmax(rmax, sn.radius[i]);
    }
    struct scan_ctx sc = {.sn = &sn};
    if (rmax > 0)
        host_pairs_scan_x(g, sn.x, idx, n, 2.0 * rmax, scan_visit, &sc);
    sort_snap = &sn;
    if (sc.n > 1)
        qsort(sc.c, (size_t)sc.n, sizeof *sc.c, cmp_cand);
    double *ft = gr_calloc(g, 6 * (size_t)(n > 0 ? n : 1), sizeof(double)), *tq = ft + 3 * n;
    struct hist *nh = gr_malloc(g, (size_t)(sc.n > 0 ? sc.n : 1) * sizeof *nh);
    int nn = 0;
    unsigned frozen = fix_frozen_groupbit(g);
    for (int k = 0; k < sc.n; k++) {
        const struct cand *c = &sc.c[k];
        int i = c->i, j = c->j;
        const struct hist *old = find_hist(s, sn.tag[i], sn.tag[j]);
        struct hist h = {.ti = sn.tag[i], .tj = sn.tag[j]};
        if (old)
            h = *old;
        struct sqe_body bi, bj;
        double xj[3] = {sn.x[3 * i] - c->del[0], sn.x[3 * i + 1] - c->del[1],
                        sn.x[3 * i + 2] - c->del[2]};
        body_of(&sn, i, sn.x + 3 * i, &bi);
        body_of(&sn, j, xj, &bj);
        double X0[4], nij[3];
        if (!find_contact(g, s, &bi, &bj, old, &h, update, X0, nij)) {
            h.touch = 0; /* LAMMPS clears all but the cached box axis */
            memset(h.x0, 0, sizeof h.x0);
            memset(h.s, 0, sizeof h.s);
            if (h.axis != 0.0)
                nh[nn++] = h;
            continue;
        }
        h.touch = 1;
        if (update) {
            for (int q = 0; q < 3; q++)
                h.x0[q] = X0[q] - bi.xc[q]; /* relative to the lower tag's centre */
            h.x0[3] = X0[3];
        }
        double mi = sn.rmass[i], mj = sn.rmass[j];
        double meff = mi * mj / (mi + mj);
        if (sn.mask[i] & frozen)
            meff = mj;
        if (sn.mask[j] & frozen)
            meff = mi;
        struct sqe_contact ct = {.bi = &bi, .bj = &bj, .meff = meff, .dt = g->dt,
                                 .update = update, .gaussian = s->gaussian};
        memcpy(ct.X0, X0, sizeof ct.X0);
        memcpy(ct.nij, nij, sizeof ct.nij);
        memcpy(ct.vi, sn.v + 3 * i, sizeof ct.vi);
        memcpy(ct.vj, sn.v + 3 * j, sizeof ct.vj);
        double ex[3], ey[3], ez[3];
        rm_q_to_exyz(sn.quat + 4 * i, ex, ey, ez);
        rm_angmom_to_omega(sn.angmom + 3 * i, ex, ey, ez, sn.inertia + 3 * i, ct.wi);
        rm_q_to_exyz(sn.quat + 4 * j, ex, ey, ez);
        rm_angmom_to_omega(sn.angmom + 3 * j, ex, ey, ez, sn.inertia + 3 * j, ct.wj);
        const struct model *md = model_at(s, sn.type[i], sn.type[j]);
        double F[3], ti[3], tj[3];
        sqe_force(md, &ct, h.s, F, ti, tj);
        for (int q = 0; q < 3; q++) {
            ft[3 * i + q] += F[q];
            ft[3 * j + q] -= F[q];
            tq[3 * i + q] += ti[q];
            tq[3 * j + q] += tj[q];
        }
        nh[nn++] = h;
    }
    free(s->hist);
    s->hist = nh;
    s->nhist = nn;
    struct dev_atoms *a = eng_atoms(g);
    eng_write_reals(g, a->f, 3 * (size_t)n, ft);
    eng_write_reals(g, a->torque, 3 * (size_t)n, tq);
    free(ft);
    free(sc.c);
    free(idx);
    free_snap(&sn);
}

/* ---- restart state (section 14): explicit little records, no padding ------- */

enum { MODEL_INTS = 5, MODEL_REALS = 6, MODEL_BYTES = MODEL_INTS * 4 + MODEL_REALS * 8 };
enum { HIST_BYTES = 2 * 8 + 4 + 8 * 8 };

struct out {
    unsigned char *p;           /* NULL: count only */
    size_t n, cap;
};

static void out_put(struct out *o, const void *v, size_t len)
{
    if (o->p && o->n + len <= o->cap)
        memcpy(o->p + o->n, v, len);
    o->n += len;
}

static void out_i32(struct out *o, int v)
{
    int32_t x = v;
    out_put(o, &x, 4);
}

static void out_f64(struct out *o, double v)
{
    out_put(o, &v, 8);
}

static size_t state_write(const struct pair *p, int part, unsigned char *buf, size_t cap)
{
    const struct sqe_pair *s = p->data;
    struct out o = {buf, 0, cap};
    if (!s)
        return 0;
    if (part == PAIR_STATE_COEFF) {
        out_i32(&o, s->m ? s->nt : 0);
        for (int k = 0; s->m && k < s->nt * s->nt; k++) {
            const struct model *m = &s->m[k];
            int iv[MODEL_INTS] = {m->set, m->normal, m->damping, m->tangential, m->limit};
            double dv[MODEL_REALS] = {m->kn, m->gamman, m->kt, m->xt, m->mu, m->cutoff};
            for (int q = 0; q < MODEL_INTS; q++)
                out_i32(&o, iv[q]);
            for (int q = 0; q < MODEL_REALS; q++)
                out_f64(&o, dv[q]);
        }
    } else {
        out_i32(&o, s->nhist);
        for (int k = 0; k < s->nhist; k++) {
            const struct hist *h = &s->hist[k];
            out_put(&o, &h->ti, 8);
            out_put(&o, &h->tj, 8);
            out_i32(&o, h->touch);
            for (int q = 0; q < 4; q++)
                out_f64(&o, h->x0[q]);
            out_f64(&o, h->axis);
            for (int q = 0; q < 3; q++)
                out_f64(&o, h->s[q]);
        }
    }
    return o.n;
}

struct in {
    const unsigned char *p;
    size_t n, off;
};

/* len bytes into v (left as they are past the end; the offset still
 * advances, so the caller sees the overrun in r->off), as out_put writes */
static void in_get(struct in *r, void *v, size_t len)
{
    if (r->off + len <= r->n)
        memcpy(v, r->p + r->off, len);
    r->off += len;
}

static int in_i32(struct in *r)
{
    int32_t x = 0;
    in_get(r, &x, 4);
    return x;
}

static double in_f64(struct in *r)
{
    double x = 0;
    in_get(r, &x, 8);
    return x;
}

static int64_t in_i64(struct in *r)
{
    int64_t x = 0;
    in_get(r, &x, 8);
    return x;
}

static void destroy(struct pair *p);

#define SBAD(...)                                                                             \
    do {                                                                                      \
        snprintf(err, errlen, __VA_ARGS__);                                                   \
        struct pair tmp_ = {.data = s};                                                       \
        destroy(&tmp_);                                                                       \
        return NULL;                                                                          \
    } while (0)

static void *state_read(const unsigned char *coeff, size_t ncoeff, const unsigned char *hist,
                        size_t nhist, char *err, size_t errlen)
{
    struct sqe_pair *s = calloc(1, sizeof *s);
    if (!s) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    struct in r = {coeff, ncoeff, 0};
    int nt = in_i32(&r);
    if (ncoeff < 4 || nt < 0 || nt > 4096 ||
        ncoeff != 4 + (size_t)nt * (size_t)nt * MODEL_BYTES)
        SBAD("granular/superellipsoid coefficients of %zu bytes for %d types", ncoeff, nt);
    s->nt = nt;
    s->m = nt ? calloc((size_t)nt * nt, sizeof *s->m) : NULL;
    if (nt && !s->m)
        SBAD("out of memory");
    for (int k = 0; k < nt * nt; k++) {
        struct model *m = &s->m[k];
        m->set = in_i32(&r);
        m->normal = in_i32(&r);
        m->damping = in_i32(&r);
        m->tangential = in_i32(&r);
        m->limit = in_i32(&r);
        double *dv[MODEL_REALS] = {&m->kn, &m->gamman, &m->kt, &m->xt, &m->mu, &m->cutoff};
        for (int q = 0; q < MODEL_REALS; q++)
            *dv[q] = in_f64(&r);
        if ((m->set != 0 && m->set != 1) || (m->normal != N_HOOKE && m->normal != N_HERTZ) ||
            (m->damping != D_MASS_VELOCITY && m->damping != D_VISCOELASTIC) ||
            m->tangential < T_NONE || m->tangential > T_LINEAR_HISTORY ||
            (m->limit != 0 && m->limit != 1))
            SBAD("invalid granular/superellipsoid model of types %d %d", k / nt + 1,
                 k % nt + 1);
        for (int q = 0; q < MODEL_REALS; q++) /* as pair_coeff takes them */
            if (!isfinite(*dv[q]) || (q < MODEL_REALS - 1 ? *dv[q] < 0 :
                                      !(*dv[q] > 0 || *dv[q] == -1)))
                SBAD("invalid granular/superellipsoid coefficient %d of types %d %d", q + 1,
                     k / nt + 1, k % nt + 1);
    }
    struct in h = {hist, nhist, 0};
    int nh = in_i32(&h);
    if (nhist < 4 || nh < 0 || nhist != 4 + (size_t)nh * HIST_BYTES)
        SBAD("granular/superellipsoid contact history of %zu bytes for %d contacts", nhist,
             nh);
    s->nhist = nh;
    s->hist = calloc((size_t)nh + 1, sizeof *s->hist);
    if (!s->hist)
        SBAD("out of memory");
    for (int k = 0; k < nh; k++) {
        struct hist *c = &s->hist[k];
        c->ti = in_i64(&h);
        c->tj = in_i64(&h);
        c->touch = in_i32(&h);
        for (int q = 0; q < 4; q++)
            c->x0[q] = in_f64(&h);
        c->axis = in_f64(&h);
        for (int q = 0; q < 3; q++)
            c->s[q] = in_f64(&h);
        const struct hist *b = k ? c - 1 : NULL;
        if (c->ti < 1 || c->tj <= c->ti || (c->touch != 0 && c->touch != 1) ||
            (b && (b->ti > c->ti || (b->ti == c->ti && b->tj >= c->tj))))
            SBAD("granular/superellipsoid contact %d (tags %lld %lld) invalid or out of order",
                 k + 1, (long long)c->ti, (long long)c->tj);
        int fin = isfinite(c->axis);
        for (int q = 0; q < 4; q++)
            fin &= isfinite(c->x0[q]) && (q == 3 || isfinite(c->s[q]));
        if (!fin || c->axis < 0 || c->axis > 14 || c->axis != floor(c->axis))
            SBAD("granular/superellipsoid contact %d (tags %lld %lld) has non-finite or "
                 "invalid values", k + 1, (long long)c->ti, (long long)c->tj);
    }
    return s;
}
#undef SBAD

static void describe(const struct pair *p, struct pair_caps *c)
{
    (void)p;
    c->rotation = 1;
    c->host_forces = host_forces;
}

static void pack(const struct pair *p, int itype, int jtype, double *param)
{
    (void)p, (void)itype, (void)jtype, (void)param; /* no device parameters */
}

const struct pair_style pair_style_granular_superellipsoid = {
    .name = "granular/superellipsoid",
    .nparam = 0,
    .settings = settings,
    .coeff = coeff,
    .init = init,
    .describe = describe,
    .pack = pack,
    .destroy = destroy,
    .state_write = state_write,
    .state_read = state_read,
};
