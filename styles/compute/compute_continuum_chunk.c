/* compute_continuum_chunk.c - `compute ID group continuum/chunk chunkID
 * cutoff width field ... [boundary/atom G] [boundary/fix]`: coarse-grained
 * continuum fields at the bin centres of a compute chunk/atom (bin/1d,
 * bin/2d, bin/3d), as today's LAMMPS's compute continuum/chunk (GRANULAR
 * package, 2026; Goldhirsch, Granular Matter 12 (2010) 239; boundary
 * corrections of Weinhart et al., Granular Matter 14 (2012) 289).
 *
 * The kernel W is a Gaussian of standard deviation `width` truncated at
 * `cutoff` and shifted to zero there, normalised over the binned dimensions
 * (a line, a plane or space); an atom i contributes to the bins whose
 * centre is within the cut-off of it, the distance taken in the binned
 * dimensions only. Fields (a, b: x y z; `name/ *` (no space) expands to every
 * component, two or four in 2d):
 *   natoms               atoms within the cut-off of the bin centre
 *   density              sum m_i W
 *   volume/fraction      sum V_i W (V the sphere's volume, its area in 2d)
 *   momentum/a           sum m_i v_ia W;  velocity/a  momentum / density
 *   momentum/grad/ab, velocity/grad/ab   centred differences between
 *                        neighbouring bins along a (one-sided at a
 *                        non-periodic end, 0 along an unbinned dimension) of
 *                        component b (LAMMPS's source: a the derivative)
 *   strain/rate/ab       (grad_ab + grad_ba) / 2 of the velocity
 *   stress/ke/ab         -sum m_i u_ia u_ib W, u = v_i - the velocity of the
 *                        bin that holds i
 *   stress/contacts/ab   -1/2 sum_{i,j} f_ij,a r_ij,b int_0^1 W(r - r_i +
 *                        s r_ij) ds over ordered pairs (each contact twice),
 *                        the line integral in closed form (erf)
 *   stress/ab            stress/ke + stress/contacts
 *   fabric/ab            1/2 sum_{i,j} V_i n_a n_b int W ds
 *   temperature          sum m_i |u_i|^2 / 2 W
 *   boundary/force/a     -sum f_ik,a W(contact point) over boundary contacts
 * Fields other than natoms, velocities, gradients and strain rates are
 * divided by the box length of each unbinned dimension. boundary/atom G:
 * atoms of G leave the atom and pair sums and act as a boundary (a contact
 * with one: its stress along the line from the atom to the contact point,
 * its force in boundary/force); boundary/fix: the contacts of every fix
 * wall/gran and wall/gran/region (each needs `contacts`) likewise.
 *
 * Contact forces are the engine's forces of the step (the records of
 * pair_contacts: every pair law, tangential and cohesive parts included),
 * where LAMMPS calls the pair style's single(). Two places differ from
 * LAMMPS's source (2026) on purpose, both following its documented
 * formulas: the partner's half of a contact's stress and fabric is
 * integrated along the line from the partner towards the atom (LAMMPS's
 * source runs it away from the atom), and the partner's fabric term is
 * added (its source line has no effect). Global array: one row per chunk,
 * one column per requested component, intensive. One process only (the
 * contacts are read from the device). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "compute.h"
#include "compute_chunk_atom.h"
#include "domain.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "group.h"
#include "neighbor.h"
#include "pair.h"

#define WHO "compute continuum/chunk"

enum field {
    F_NATOMS, F_DENSITY, F_VOLFRAC, F_MOMENTUM, F_VELOCITY, F_MGRAD, F_VGRAD, F_STRAINRATE,
    F_STRESS, F_STRESSKE, F_STRESSCON, F_IFD, F_FABRIC, F_TEMPERATURE
};

struct cc_value {
    int field, a, b; /* a: a vector's component; a tensor's ab */
    int nonorm;      /* natoms: not divided by unbinned lengths */
};

struct continuum {
    char chunk[GR_NAMELEN];
    double wcut, wsd, scale, offset; /* the kernel: scale exp(-r^2/2 sd^2) - offset */
    struct cc_value *val;
    int nval, nout;                  /* values; the first nout are the output columns */
    int idx_density, idx_mom[3], idx_vel[3], idx_vgrad[3][3];
    int pair, two_loops, bfix;
    unsigned bgroupbit;              /* boundary/atom (0: none) */
    int warned;
};

/* ---- the kernel --------------------------------------------------------- */

static double cc_w(const struct continuum *cc, double r)
{
    return r > cc->wcut ? 0.0 : cc->scale * exp(-r * r / (2 * cc->wsd * cc->wsd)) - cc->offset;
}

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* int_0^1 W(|dr - s rij|) ds: dr the atom's position from the bin centre,
 * the line running from the atom along -rij; the part inside the cut-off,
 * in closed form (the Gaussian's erf, less the offset over its length) */
static double cc_w_line(const struct continuum *cc, const double *dr, const double *rij)
{
    const double d2 = dot3(dr, dr), dd = dot3(dr, rij), r2 = dot3(rij, rij);
    const double sd = cc->wsd, c2 = cc->wcut * cc->wcut;
    if (r2 < 1e-8 * sd * sd) /* apart only along an unbinned dimension */
        return cc_w(cc, sqrt(d2));
    double disc = dd * dd - d2 * r2 + r2 * c2;
    if (disc < 0)
        return 0.0;
    disc = sqrt(disc);
    const double s0 = fmax(0.0, (dd - disc) / r2), s1 = fmin(1.0, (dd + disc) / r2);
    if (s0 >= 1.0 || s1 <= 0.0)
        return 0.0;
    const double rl = sqrt(r2), t = M_SQRT2 * rl * sd;
    double in = erf((r2 * s1 - dd) / t) - erf((r2 * s0 - dd) / t);
    in *= exp((dd * dd - d2 * r2) / (t * t)) * sqrt(0.5 * M_PI) * sd / rl;
    return cc->scale * in - cc->offset * (s1 - s0);
}

/* 1 / the integral of the shifted Gaussian over the cut-off ball of the
 * binned dimensions */
static double cc_scale(int nbin, double c, double sd)
{
    const double e = exp(-c * c / (2 * sd * sd)), er = erf(c / (M_SQRT2 * sd));
    if (nbin == 1)
        return 1.0 / (sqrt(2 * M_PI) * sd * er - 2 * c * e);
    if (nbin == 2)
        return 1.0 / (2 * M_PI * (sd * sd * (1 - e) - 0.5 * c * c * e));
    const double ball = sqrt(0.5 * M_PI) * sd * sd * sd * er - c * e * (c * c + 3 * sd * sd) / 3;
    return 1.0 / (4 * M_PI * ball);
}

/* ---- arguments ---------------------------------------------------------- */

static int add_value(struct gravel *g, struct continuum *cc, int field, int a, int b)
{
    cc->val = realloc(cc->val, (size_t)(cc->nval + 1) * sizeof *cc->val);
    if (!cc->val)
        gr_error(g, WHO ": out of memory");
    cc->val[cc->nval] = (struct cc_value){field, a, b, field == F_NATOMS};
    if (field == F_MOMENTUM)
        cc->idx_mom[a] = cc->nval;
    if (field == F_VELOCITY)
        cc->idx_vel[a] = cc->nval;
    if (field == F_VGRAD)
        cc->idx_vgrad[a][b] = cc->nval;
    if (field == F_DENSITY)
        cc->idx_density = cc->nval;
    return cc->nval++;
}

static int axis(char ch) { return ch == 'x' ? 0 : ch == 'y' ? 1 : ch == 'z' ? 2 : -1; }

/* name/a or name/ * (every component of the dimension) */
static void add_vector(struct gravel *g, struct continuum *cc, const char *arg, size_t plen,
                       int field, int dim)
{
    const char *c = arg + plen;
    if (!strcmp(c, "*")) {
        for (int a = 0; a < dim; a++)
            add_value(g, cc, field, a, 0);
        return;
    }
    int a = c[0] && !c[1] ? axis(c[0]) : -1;
    if (a < 0)
        gr_error(g, WHO ": invalid property '%.64s' (a component x, y, z or *)", arg);
    if (a >= dim)
        gr_error(g, WHO ": invalid property '%.64s' in 2d", arg);
    add_value(g, cc, field, a, 0);
}

/* name/ab or name/ * (xx xy [xz] yx yy [yz zx zy zz]) */
static void add_tensor(struct gravel *g, struct continuum *cc, const char *arg, size_t plen,
                       int field, int dim)
{
    const char *c = arg + plen;
    if (!strcmp(c, "*")) {
        for (int a = 0; a < dim; a++)
            for (int b = 0; b < dim; b++)
                add_value(g, cc, field, a, b);
        return;
    }
    int a = c[0] ? axis(c[0]) : -1, b = a >= 0 && c[1] && !c[2] ? axis(c[1]) : -1;
    if (a < 0 || b < 0)
        gr_error(g, WHO ": invalid property '%.64s' (components xx, xy, ... or *)", arg);
    if (a >= dim || b >= dim)
        gr_error(g, WHO ": invalid property '%.64s' in 2d", arg);
    add_value(g, cc, field, a, b);
}

static int prefix(const char *s, const char *p, size_t *len)
{
    *len = strlen(p);
    return !strncmp(s, p, *len);
}

static void cc_destroy(struct compute *c)
{
    struct continuum *cc = c->data;
    if (cc)
        free(cc->val);
    free(cc);
    c->data = NULL;
}

static void cc_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc < 4)
        gr_error(g, WHO " expects chunkID cutoff width field ..., got %d arguments", argc);
    struct continuum *cc = gr_calloc(g, 1, sizeof *cc);
    c->data = cc;
    if (strlen(argv[0]) >= GR_NAMELEN)
        gr_error(g, WHO ": chunk ID '%.64s...' is too long", argv[0]);
    strcpy(cc->chunk, argv[0]);
    struct compute *ca = chunk_atom_get(g, cc->chunk, WHO);
    cc->wcut = arg_double(g, argv[1], WHO " cutoff");
    cc->wsd = arg_double(g, argv[2], WHO " width");
    if (!(cc->wcut > 0))
        gr_error(g, "illegal " WHO " cutoff value: %g", cc->wcut);
    if (!(cc->wsd > 0))
        gr_error(g, "illegal " WHO " width value: %g", cc->wsd);
    const int dim = g->dom.dimension;
    cc->idx_density = -1;
    for (int a = 0; a < 3; a++) {
        cc->idx_mom[a] = cc->idx_vel[a] = -1;
        for (int b = 0; b < 3; b++)
            cc->idx_vgrad[a][b] = -1;
    }
    int need_density = 0, need_mom = 0, need_vel = 0, need_vgrad = 0, ifd = 0, i = 3;
    for (; i < argc; i++) {
        const char *s = argv[i];
        size_t n;
        if (!strcmp(s, "natoms")) {
            add_value(g, cc, F_NATOMS, 0, 0);
        } else if (!strcmp(s, "density")) {
            add_value(g, cc, F_DENSITY, 0, 0);
        } else if (!strcmp(s, "volume/fraction")) {
            add_value(g, cc, F_VOLFRAC, 0, 0);
        } else if (!strcmp(s, "temperature")) {
            add_value(g, cc, F_TEMPERATURE, 0, 0);
            need_density = need_mom = cc->two_loops = 1;
        } else if (prefix(s, "momentum/grad/", &n)) {
            add_tensor(g, cc, s, n, F_MGRAD, dim);
            need_mom = 1;
        } else if (prefix(s, "velocity/grad/", &n)) {
            add_tensor(g, cc, s, n, F_VGRAD, dim);
            need_density = need_mom = need_vel = 1;
        } else if (prefix(s, "momentum/", &n)) {
            add_vector(g, cc, s, n, F_MOMENTUM, dim);
        } else if (prefix(s, "velocity/", &n)) {
            add_vector(g, cc, s, n, F_VELOCITY, dim);
            need_density = need_mom = 1;
        } else if (prefix(s, "strain/rate/", &n)) {
            add_tensor(g, cc, s, n, F_STRAINRATE, dim);
            need_density = need_mom = need_vel = need_vgrad = 1;
        } else if (prefix(s, "stress/ke/", &n)) {
            add_tensor(g, cc, s, n, F_STRESSKE, dim);
            need_density = need_mom = cc->two_loops = 1;
        } else if (prefix(s, "stress/contacts/", &n)) {
            add_tensor(g, cc, s, n, F_STRESSCON, dim);
            cc->pair = 1;
        } else if (prefix(s, "stress/", &n)) {
            add_tensor(g, cc, s, n, F_STRESS, dim);
            cc->pair = need_density = need_mom = cc->two_loops = 1;
        } else if (prefix(s, "boundary/force/", &n)) {
            add_vector(g, cc, s, n, F_IFD, dim);
            cc->pair = ifd = 1;
        } else if (prefix(s, "fabric/", &n)) {
            add_tensor(g, cc, s, n, F_FABRIC, dim);
            cc->pair = 1;
        } else {
            break;
        }
    }
    if (cc->nval == 0)
        gr_error(g, "no values in " WHO " command");
    cc->nout = cc->nval;
    /* what derived values need, after the output columns */
    if (need_density && cc->idx_density < 0)
        add_value(g, cc, F_DENSITY, 0, 0);
    for (int a = 0; need_mom && a < dim; a++)
        if (cc->idx_mom[a] < 0)
            add_value(g, cc, F_MOMENTUM, a, 0);
    for (int a = 0; need_vel && a < dim; a++)
        if (cc->idx_vel[a] < 0)
            add_value(g, cc, F_VELOCITY, a, 0);
    for (int a = 0; need_vgrad && a < dim; a++)
        for (int b = 0; b < dim; b++)
            if (cc->idx_vgrad[a][b] < 0)
                add_value(g, cc, F_VGRAD, a, b);
    for (; i < argc; i++) {
        if (!strcmp(argv[i], "boundary/fix")) {
            cc->bfix = 1;
        } else if (!strcmp(argv[i], "boundary/atom")) {
            if (i + 1 >= argc)
                gr_error(g, WHO ": boundary/atom needs a group ID");
            const int ig = group_find(g, argv[++i]);
            if (ig < 0)
                gr_error(g, WHO ": boundary/atom group '%.64s' does not exist", argv[i]);
            cc->bgroupbit = group_bit(ig);
        } else {
            gr_error(g, "unknown " WHO " keyword '%.64s' (boundary/atom, boundary/fix)",
                     argv[i]);
        }
    }
    if (ifd && !cc->bfix && !cc->bgroupbit)
        gr_error(g, WHO ": boundary/force needs boundary/atom or boundary/fix");
    if (g->dom.triclinic)
        gr_error(g, WHO " does not support triclinic boxes");
    const int nbin = chunk_atom_ncoord(ca);
    if (nbin == 0 || chunk_atom_radial(ca))
        gr_error(g, WHO ": compute %s is not a rectangular spatial binning (bin/1d, bin/2d, "
                    "bin/3d)", ca->id);
    const double e = exp(-cc->wcut * cc->wcut / (2 * cc->wsd * cc->wsd));
    cc->scale = cc_scale(nbin, cc->wcut, cc->wsd);
    cc->offset = cc->scale * e;
    c->array_flag = 1;
    c->size_array_cols = cc->nout;
    c->extarray = 0;
}

/* every fix wall/gran and wall/gran/region (LAMMPS matches the style name) */
static int is_wall_gran(const struct fix *f) { return strstr(f->style->name, "wall/gran") != NULL; }

static void cc_init(struct gravel *g, struct compute *c)
{
    struct continuum *cc = c->data;
    struct compute *ca = chunk_atom_get(g, cc->chunk, WHO);
    const struct chunk_grid *grid = chunk_atom_setup(g, ca);
    if (grid->discard_no)
        gr_error(g, WHO ": the compute chunk/atom discard no option is not supported");
    if (g->dom.triclinic)
        gr_error(g, WHO " does not support triclinic boxes");
    if (cc->bfix) {
        int nwall = 0;
        for (int k = 0; k < g->styles.nfix; k++) {
            const struct fix *f = g->styles.fix[k];
            if (!is_wall_gran(f))
                continue;
            nwall++;
            if (!f->peratom_flag)
                gr_error(g, WHO " %s: boundary/fix needs the contacts keyword in fix %s (%s)",
                         c->id, f->id, f->style->name);
        }
        if (!nwall)
            gr_error(g, WHO " %s: boundary/fix finds no fix wall/gran", c->id);
    }
    if (cc->pair && !g->styles.pair)
        gr_error(g, WHO " %s: stress, fabric and boundary/force need a pair style", c->id);
    if (!cc->warned)
        for (int m = 0; m < grid->ndim; m++) {
            const int d = grid->dim[m];
            const double prd = g->dom.hi[d] - g->dom.lo[d];
            const double nb = grid->reduced ? 1.0 / grid->delta[m] : prd / grid->delta[m];
            if (g->dom.periodic[d] && fabs(nb - round(nb)) > 1e-8) {
                gr_warn(g, "%s %s: bins do not evenly divide the periodic box along %c: "
                           "results on the boundary may be incorrect",
                        WHO, c->id, "xyz"[d]);
                cc->warned = 1;
                break;
            }
        }
}

/* ---- evaluation --------------------------------------------------------- */

/* a stencil: the bin offsets whose centres lie within some distance of a
 * bin's, and their displacements */
struct cc_stencil {
    int n, (*dn)[3];
    double (*dx)[3];
};

struct cc_eval {
    const struct continuum *cc;
    const struct chunk_grid *grid;
    double width[3];      /* bin widths (box units) */
    struct cc_stencil *st;     /* the one in use: atoms', or contacts' */
    struct cc_stencil atoms;   /* an atom's kernel: cut-off + half a bin diagonal */
    struct cc_stencil lines;   /* a contact's line: also its longest line */
    double *acc;          /* [nchunk][nval] */
};

/* the bin m shifted by dn: -1 beyond a non-periodic end */
static int shifted(const struct gravel *g, const struct chunk_grid *gr, int m, const int *dn)
{
    int x[3] = {0, 0, 0}, rem = m;
    for (int q = gr->ndim - 1; q >= 0; q--) {
        x[q] = rem % gr->nlayers[q] + dn[q];
        rem /= gr->nlayers[q];
    }
    int k = 0;
    for (int q = 0; q < gr->ndim; q++) {
        const int n = gr->nlayers[q];
        if (!g->dom.periodic[gr->dim[q]]) {
            if (x[q] < 0 || x[q] >= n)
                return -1;
        } else {
            x[q] = ((x[q] % n) + n) % n;
        }
        k = k * n + x[q];
    }
    return k;
}

/* the bins whose centres may lie within `reach` of a point in bin m: centre
 * distances up to reach + half the bin's diagonal (LAMMPS's stencil has reach
 * = the cut-off, also for a contact's line, whose far end it then drops) */
static void build_stencil(struct gravel *g, struct cc_eval *ev, double reach,
                          struct cc_stencil *st)
{
    const struct chunk_grid *gr = ev->grid;
    double diag = 0;
    int size[3] = {0, 0, 0};
    for (int q = 0; q < gr->ndim; q++)
        diag += ev->width[q] * ev->width[q];
    const double cut = reach + 0.5 * sqrt(diag);
    long total = 1;
    for (int q = 0; q < gr->ndim; q++) {
        size[q] = (int)ceil(cut / ev->width[q]);
        total *= 2 * size[q] + 1;
    }
    if (total > 1L << 22)
        gr_error(g, WHO ": a reach of %g spans more than 2^22 bins", reach);
    st->dn = gr_malloc(g, (size_t)total * sizeof *st->dn);
    st->dx = gr_malloc(g, (size_t)total * sizeof *st->dx);
    st->n = 0;
    for (int i0 = -size[0]; i0 <= size[0]; i0++)
        for (int i1 = -size[1]; i1 <= size[1]; i1++)
            for (int i2 = -size[2]; i2 <= size[2]; i2++) {
                const int d[3] = {i0, i1, i2};
                double off[3] = {0, 0, 0};
                for (int q = 0; q < gr->ndim; q++)
                    off[gr->dim[q]] = d[q] * ev->width[q];
                if (dot3(off, off) > cut * cut)
                    continue;
                memcpy(st->dn[st->n], d, sizeof d);
                memcpy(st->dx[st->n], off, sizeof off);
                st->n++;
            }
}

static void free_stencil(struct cc_stencil *st)
{
    free(st->dn);
    free(st->dx);
}

/* the centre of bin m, the unbinned coordinates those of x */
static void bin_centre(const struct gravel *g, const struct chunk_grid *gr, int m,
                       const double *x, double *out)
{
    memcpy(out, x, 3 * sizeof *out);
    for (int q = 0; q < gr->ndim; q++) {
        const int d = gr->dim[q];
        const double c = gr->coord[(size_t)m * gr->ndim + q];
        out[d] = gr->reduced ? g->dom.lo[d] + c * (g->dom.hi[d] - g->dom.lo[d]) : c;
    }
}

/* v with its unbinned components zeroed */
static void binned_only(const struct chunk_grid *gr, const double *v, double *out)
{
    out[0] = out[1] = out[2] = 0;
    for (int q = 0; q < gr->ndim; q++)
        out[gr->dim[q]] = v[gr->dim[q]];
}

static double volume_of(const struct gravel *g, double r)
{
    return g->dom.dimension == 3 ? 4.0 / 3.0 * M_PI * r * r * r : M_PI * r * r;
}

/* a boundary contact seen from atom position xa (f the force on the atom,
 * xc the contact point): its stress (STRESS, STRESSCON) and boundary force
 * (IFD) into the bins around bin m, times `half` (1 for a wall, 1/2 for a
 * boundary atom's share of a pair) */
static void add_boundary(const struct gravel *g, struct cc_eval *ev, int m, const double *xa,
                         const double *f, const double *xc, double half, int ifd_sign)
{
    const struct continuum *cc = ev->cc;
    double x0[3], dac[3], dacf[3];
    bin_centre(g, ev->grid, m, xa, x0);
    for (int d = 0; d < 3; d++)
        dac[d] = xa[d] - xc[d];
    binned_only(ev->grid, dac, dacf);
    for (int s = 0; s < ev->st->n; s++) {
        const int mt = shifted(g, ev->grid, m, ev->st->dn[s]);
        if (mt < 0)
            continue;
        double xb[3], dab[3], dbc[3];
        for (int d = 0; d < 3; d++) {
            xb[d] = x0[d] + ev->st->dx[s][d];
            dab[d] = xa[d] - xb[d];
            dbc[d] = 0;
        }
        for (int q = 0; q < ev->grid->ndim; q++) {
            const int d = ev->grid->dim[q];
            dbc[d] = xb[d] - xc[d];
        }
        const double wl = cc_w_line(cc, dab, dacf), wc = cc_w(cc, sqrt(dot3(dbc, dbc)));
        double *row = ev->acc + (size_t)mt * cc->nval;
        for (int k = 0; k < cc->nval; k++) {
            const struct cc_value *v = &cc->val[k];
            if (v->field == F_STRESS || v->field == F_STRESSCON)
                row[k] -= half * f[v->a] * dac[v->b] * wl;
            else if (v->field == F_IFD && ifd_sign)
                row[k] -= f[v->a] * wc;
        }
    }
}

/* one side of a contact between two non-boundary atoms: the atom at xa in
 * bin m, rab = xa - (the other atom) and f the force on it */
static void add_pair_side(const struct gravel *g, struct cc_eval *ev, int m, const double *xa,
                          const double *rab, const double *f, double vol)
{
    const struct continuum *cc = ev->cc;
    double x0[3], rf[3];
    bin_centre(g, ev->grid, m, xa, x0);
    binned_only(ev->grid, rab, rf);
    const double r2 = dot3(rab, rab);
    for (int s = 0; s < ev->st->n; s++) {
        const int mt = shifted(g, ev->grid, m, ev->st->dn[s]);
        if (mt < 0)
            continue;
        double dab[3];
        for (int d = 0; d < 3; d++)
            dab[d] = xa[d] - (x0[d] + ev->st->dx[s][d]);
        const double wl = cc_w_line(cc, dab, rf);
        if (wl == 0.0)
            continue;
        double *row = ev->acc + (size_t)mt * cc->nval;
        for (int k = 0; k < cc->nval; k++) {
            const struct cc_value *v = &cc->val[k];
            if (v->field == F_STRESS || v->field == F_STRESSCON)
                row[k] -= 0.5 * f[v->a] * rab[v->b] * wl;
            else if (v->field == F_FABRIC)
                row[k] += 0.5 * vol * rab[v->a] * rab[v->b] * wl / r2;
        }
    }
}

/* tag order of contacts (lower tag first) */
struct cc_contact {
    long long ti, tj;
    int i, j;
    double f[3];
};

static int by_tags(const void *pa, const void *pb)
{
    const struct cc_contact *a = pa, *b = pb;
    if (a->ti != b->ti)
        return a->ti < b->ti ? -1 : 1;
    return (a->tj > b->tj) - (a->tj < b->tj);
}

/* the contacts that act, with the force on the lower tag, in tag order:
 * returns their count (*out malloc'd) */
static int read_contacts(struct gravel *g, struct compute *c, struct cc_contact **out)
{
    const struct atoms *at = &g->atoms;
    int *ci, *cj;
    double *f;
    const int nc = nbr_contact_forces(g, &ci, &cj, &f, NULL);
    if (nc < 0)
        gr_error(g, WHO " %s: stress, fabric and boundary/force read the contacts of a run: "
                    "evaluate it during or after a run with these atoms",
                 c->id);
    struct cc_contact *ct = gr_malloc(g, ((size_t)nc + 1) * sizeof *ct);
    int m = 0;
    for (int k = 0; k < nc; k++) {
        const double *fk = f + 3 * (size_t)k;
        if (fk[0] == 0.0 && fk[1] == 0.0 && fk[2] == 0.0)
            continue;
        int i = ci[k], j = cj[k], s = at->tag[i] < at->tag[j] ? 1 : -1;
        if (s < 0) {
            int t = i;
            i = j;
            j = t;
        }
        ct[m] = (struct cc_contact){at->tag[i], at->tag[j], i, j,
                                    {s * fk[0], s * fk[1], s * fk[2]}};
        m++;
    }
    free(ci);
    free(cj);
    free(f);
    qsort(ct, (size_t)m, sizeof *ct, by_tags);
    *out = ct;
    return m;
}

/* the longest line a contact's stress runs along (binned dimensions): a
 * pair's separation, or an atom's radius (to a contact point) */
static double longest_line(struct gravel *g, const struct chunk_grid *gr,
                           const struct cc_contact *ct, int m)
{
    const struct atoms *at = &g->atoms;
    double best = 0;
    for (int i = 0; i < at->n; i++)
        best = fmax(best, at->radius[i]);
    for (int k = 0; k < m; k++) {
        const double *xi = at->x + 3 * (size_t)ct[k].i, *xj = at->x + 3 * (size_t)ct[k].j;
        double dx[3] = {xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2]}, bf[3];
        domain_minimum_image(g, dx);
        binned_only(gr, dx, bf);
        best = fmax(best, sqrt(dot3(bf, bf)));
    }
    return best;
}

static void add_contacts(struct gravel *g, struct compute *c, struct cc_eval *ev,
                         const int *ichunk, const struct cc_contact *ct, int m)
{
    const struct continuum *cc = ev->cc;
    const struct atoms *at = &g->atoms;
    for (int k = 0; k < m; k++) {
        const int i = ct[k].i, j = ct[k].j;
        if (!(at->mask[i] & c->groupbit) || !(at->mask[j] & c->groupbit))
            continue;
        const int mi = ichunk[i] - 1, mj = ichunk[j] - 1;
        if (mi < 0 || mj < 0)
            continue;
        const double *xi = at->x + 3 * (size_t)i, *xj = at->x + 3 * (size_t)j;
        double dx[3] = {xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2]};
        domain_minimum_image(g, dx);
        const double r = sqrt(dot3(dx, dx)), ri = at->radius[i], rj = at->radius[j];
        if (!(r > 0))
            continue;
        /* the contact point, as seen from i and from j (periodic images) */
        double xci[3], xcj[3], fj[3], rji[3];
        for (int d = 0; d < 3; d++) {
            xci[d] = 0.5 * (2 * xi[d] - dx[d] + (rj - ri) / r * dx[d]);
            xcj[d] = xci[d] + (xj[d] - (xi[d] - dx[d]));
            fj[d] = -ct[k].f[d];
            rji[d] = -dx[d];
        }
        const int bi = cc->bgroupbit && (at->mask[i] & cc->bgroupbit);
        const int bj = cc->bgroupbit && (at->mask[j] & cc->bgroupbit);
        if (bj)
            add_boundary(g, ev, mi, xi, ct[k].f, xci, 0.5, 1);
        else
            add_pair_side(g, ev, mi, xi, dx, ct[k].f, volume_of(g, ri));
        if (bi)
            add_boundary(g, ev, mj, xj, fj, xcj, 0.5, 1);
        else
            add_pair_side(g, ev, mj, xj, rji, fj, volume_of(g, rj));
    }
}

/* the contacts of the walls (boundary/fix) of atom i in bin m */
static void add_walls(struct gravel *g, struct cc_eval *ev, int i, int m)
{
    const double *xi = g->atoms.x + 3 * (size_t)i;
    for (int k = 0; k < g->styles.nfix; k++) {
        struct fix *f = g->styles.fix[k];
        if (!is_wall_gran(f) || !f->peratom_flag)
            continue;
        const double *arr = f->style->peratom_values(g, f);
        const int w = f->size_peratom_cols;
        if (!arr || w < 7)
            continue;
        const double *row = arr + (size_t)i * w;
        if (row[0] < 0.5)
            continue;
        struct cc_stencil *keep = ev->st;
        ev->st = &ev->lines;
        add_boundary(g, ev, m, xi, row + 1, row + 4, 1.0, 1);
        ev->st = keep;
    }
}

/* an atom in the atom sums: in the group, in a chunk (m >= 0), not a boundary atom */
static int counted(const struct continuum *cc, const struct compute *c, const struct atoms *at,
                   int i, int m)
{
    return (at->mask[i] & c->groupbit) && m >= 0 &&
           !(cc->bgroupbit && (at->mask[i] & cc->bgroupbit));
}

/* a bin an atom reaches: its index, the kernel at the atom, the squared distance */
struct cc_bin {
    int m;
    double w, r2;
};

/* the bins of the atoms' stencil around bin m, seen from an atom at x: into
 * out (room for the stencil), returns how many */
static int atom_bins(const struct gravel *g, const struct cc_eval *ev, int m, const double *x,
                     struct cc_bin *out)
{
    double x0[3];
    bin_centre(g, ev->grid, m, x, x0);
    int nb = 0;
    for (int s = 0; s < ev->atoms.n; s++) {
        const int mt = shifted(g, ev->grid, m, ev->atoms.dn[s]);
        if (mt < 0)
            continue;
        double d[3];
        for (int k = 0; k < 3; k++)
            d[k] = x[k] - (x0[k] + ev->atoms.dx[s][k]);
        const double r2 = dot3(d, d);
        out[nb++] = (struct cc_bin){mt, cc_w(ev->cc, sqrt(r2)), r2};
    }
    return nb;
}

static void cc_array(struct gravel *g, struct compute *c)
{
    struct continuum *cc = c->data;
    const struct atoms *at = &g->atoms;
    struct compute *ca = chunk_atom_get(g, cc->chunk, WHO);
    struct cc_eval ev = {.cc = cc};
    ev.grid = chunk_atom_setup(g, ca);
    const int *ichunk = chunk_atom_assign(g, ca);
    const int nchunk = ev.grid->nchunk, nval = cc->nval, dim = g->dom.dimension;
    for (int q = 0; q < ev.grid->ndim; q++) {
        const int d = ev.grid->dim[q];
        ev.width[q] = ev.grid->delta[q] * (ev.grid->reduced ? g->dom.hi[d] - g->dom.lo[d] : 1.0);
    }
    struct cc_contact *ct = NULL;
    const int ncontact = cc->pair ? read_contacts(g, c, &ct) : 0;
    build_stencil(g, &ev, cc->wcut, &ev.atoms);
    if (cc->pair || cc->bfix)
        build_stencil(g, &ev, cc->wcut + longest_line(g, ev.grid, ct, ncontact), &ev.lines);
    ev.st = &ev.atoms;
    ev.acc = gr_calloc(g, (size_t)nchunk * nval + 1, sizeof *ev.acc);
    const int *order = atoms_tag_order(g);
    const double wc2 = cc->wcut * cc->wcut;
    /* the atoms' own sums, in tag order */
    struct cc_bin *bins = gr_malloc(g, ((size_t)ev.atoms.n + 1) * sizeof *bins);
    for (int q = 0; q < at->n; q++) {
        const int i = order[q], m = ichunk[i] - 1;
        if (!counted(cc, c, at, i, m))
            continue;
        const double *vi = at->v + 3 * (size_t)i;
        const double mi = at->rmass[i], vol = volume_of(g, at->radius[i]);
        const int nb = atom_bins(g, &ev, m, at->x + 3 * (size_t)i, bins);
        for (int s = 0; s < nb; s++) {
            const double w = bins[s].w;
            double *row = ev.acc + (size_t)bins[s].m * nval;
            for (int k = 0; k < nval; k++) {
                const struct cc_value *v = &cc->val[k];
                switch (v->field) {
                case F_NATOMS: row[k] += bins[s].r2 < wc2; break;
                case F_DENSITY: row[k] += mi * w; break;
                case F_VOLFRAC: row[k] += vol * w; break;
                case F_MOMENTUM: row[k] += mi * vi[v->a] * w; break;
                default: break;
                }
            }
        }
        if (cc->bfix)
            add_walls(g, &ev, i, m);
    }
    if (cc->pair) {
        ev.st = &ev.lines;
        add_contacts(g, c, &ev, ichunk, ct, ncontact);
        ev.st = &ev.atoms;
    }
    free(ct);
    /* kinetic stress and temperature: velocities about their bin's */
    if (cc->two_loops) {
        double *vbin = gr_calloc(g, 3 * (size_t)nchunk + 1, sizeof *vbin);
        for (int m = 0; m < nchunk; m++) {
            const double rho = ev.acc[(size_t)m * nval + cc->idx_density];
            for (int a = 0; a < dim; a++) {
                const double p = ev.acc[(size_t)m * nval + cc->idx_mom[a]];
                vbin[3 * m + a] = rho != 0.0 ? p / rho : p;
            }
        }
        for (int q = 0; q < at->n; q++) {
            const int i = order[q], m = ichunk[i] - 1;
            if (!counted(cc, c, at, i, m))
                continue;
            const double *vi = at->v + 3 * (size_t)i;
            const double mi = at->rmass[i];
            double u[3];
            for (int a = 0; a < 3; a++)
                u[a] = vbin[3 * m + a] - vi[a];
            const int nb = atom_bins(g, &ev, m, at->x + 3 * (size_t)i, bins);
            for (int s = 0; s < nb; s++) {
                const double w = bins[s].w;
                double *row = ev.acc + (size_t)bins[s].m * nval;
                for (int k = 0; k < nval; k++) {
                    const struct cc_value *v = &cc->val[k];
                    if (v->field == F_TEMPERATURE)
                        row[k] += 0.5 * mi * dot3(u, u) * w;
                    else if (v->field == F_STRESS || v->field == F_STRESSKE)
                        row[k] -= mi * u[v->a] * u[v->b] * w;
                }
            }
        }
        free(vbin);
    }
    free(bins);
    /* divided by the lengths of the unbinned dimensions */
    int binned[3] = {0, 0, 0};
    for (int q = 0; q < ev.grid->ndim; q++)
        binned[ev.grid->dim[q]] = 1;
    for (int d = 0; d < dim; d++) {
        if (binned[d])
            continue;
        const double len = g->dom.hi[d] - g->dom.lo[d];
        for (int m = 0; m < nchunk; m++)
            for (int k = 0; k < nval; k++)
                if (!cc->val[k].nonorm)
                    ev.acc[(size_t)m * nval + k] /= len;
    }
    /* the derived values: velocities, gradients, strain rates */
    for (int m = 0; m < nchunk; m++) {
        double *row = ev.acc + (size_t)m * nval;
        for (int k = 0; k < nval; k++)
            if (cc->val[k].field == F_VELOCITY && row[cc->idx_density] != 0.0)
                row[k] = row[cc->idx_mom[cc->val[k].a]] / row[cc->idx_density];
    }
    for (int m = 0; m < nchunk; m++)
        for (int k = 0; k < nval; k++) {
            const struct cc_value *v = &cc->val[k];
            if (v->field != F_MGRAD && v->field != F_VGRAD)
                continue;
            const int src = v->field == F_MGRAD ? cc->idx_mom[v->b] : cc->idx_vel[v->b];
            int q = -1;
            for (int p = 0; p < ev.grid->ndim; p++)
                if (ev.grid->dim[p] == v->a)
                    q = p;
            double *out = ev.acc + (size_t)m * nval + k;
            if (q < 0) {
                *out = 0.0;
                continue;
            }
            int sh[3] = {0, 0, 0};
            sh[q] = 1;
            const int mp = shifted(g, ev.grid, m, sh);
            sh[q] = -1;
            const int mm = shifted(g, ev.grid, m, sh);
            const double h = ev.width[q];
#define AT(mb) ev.acc[(size_t)(mb) * nval + src]
            if (mp < 0 && mm < 0)
                *out = 0.0;
            else if (mp < 0)
                *out = (AT(m) - AT(mm)) / h;
            else if (mm < 0)
                *out = (AT(mp) - AT(m)) / h;
            else
                *out = (AT(mp) - AT(mm)) / (2 * h);
#undef AT
        }
    for (int m = 0; m < nchunk; m++) {
        double *row = ev.acc + (size_t)m * nval;
        for (int k = 0; k < nval; k++) {
            const struct cc_value *v = &cc->val[k];
            if (v->field == F_STRAINRATE)
                row[k] = 0.5 * (row[cc->idx_vgrad[v->a][v->b]] + row[cc->idx_vgrad[v->b][v->a]]);
        }
    }
    double *out = compute_array_rows(g, c, nchunk);
    for (int m = 0; m < nchunk; m++)
        memcpy(out + (size_t)m * cc->nout, ev.acc + (size_t)m * nval,
               (size_t)cc->nout * sizeof *out);
    free(ev.acc);
    free_stencil(&ev.atoms);
    free_stencil(&ev.lines);
}

const struct compute_style compute_style_continuum_chunk = {
    .name = "continuum/chunk",
    .ranks = COMPUTE_RANKS_NO,
    .create = cc_create,
    .init = cc_init,
    .array = cc_array,
    .destroy = cc_destroy,
};
