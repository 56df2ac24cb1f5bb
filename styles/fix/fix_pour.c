/* fix_pour.c - `fix ID group pour N type seed keyword values ...`: insert N
 * granular particles into a block or z-cylinder region in batches, as
 * LAMMPS's fix pour (GRANULAR package, 2021), drawing LAMMPS's random
 * numbers in LAMMPS's order so the inserted atoms (tags, positions, radii,
 * masses, velocities) and the insertion steps are LAMMPS's.
 *
 * Schedule (at creation): a particle falls through the region in
 *   t = (-(v - rate) - sqrt((v - rate)^2 - 2 g dz)) / g     (g = -|gravity|)
 * with v the vertical velocity of `vel` (vz in 3d, vy in 2d), dz the
 * region's height (z in 3d, y in 2d); batches come every nfreq =
 * int(t/dt + 0.5) steps from the next step on, nper = int(vol x V / v1)
 * each (V the region volume, 3d blocks with dy >= 1; v1 the volume of the
 * largest sphere, or the poly-weighted mean; 2d: areas).
 *
 * The generator is RanPark(seed), warmed up with 30 draws at creation.
 * A batch (pre_exchange of its step, before the neighbor rebuild it
 * forces): the atoms within radius + rmax of the region (z/y bounds moved
 * by rate x elapsed time) are the "near" list. For each particle: u -> the
 * height h = hi - u^2 (hi - lo); the radius (range: 1 draw, poly: 1 draw);
 * then up to Ntry x nper attempts over the whole batch, each a random
 * point at h (block: x, y; cylinder: rejection pairs in the unit disc; 2d:
 * x), rejected when it touches a near or already placed particle (minimum
 * image; touching counts). A particle that finds no place ends the batch
 * (warning "Less insertions than requested"). Placed: vx, vy uniform in the
 * vel ranges, vz = -sqrt(vz^2 + 2 g (z - hi)) (its speed after falling from
 * hi), then one density draw (dens lo hi); mass = 4/3 pi r^3 density (also
 * in 2d, as LAMMPS 2021). Tags: max tag + 1, + 2, ... (id max: the current
 * atoms' largest tag each batch; id next: counted on from the largest tag at
 * creation). Mask: all + the fix group. An atom outside the box (except
 * above its top face) is not created, as on LAMMPS's one process.
 *
 * Molecules (`mol T`, LAMMPS's mode MOLECULE): copies of molecule template
 * T instead of single spheres; per molecule one height draw, per attempt a
 * point, the template draw (molfrac: one-molecule templates, so 1.0) and a
 * random rotation about the template's geometric centre; every atom must
 * clear the near list; the template's radius enters v1 and the near list.
 * `rigid ID`: each inserted molecule becomes a body of fix rigid/small ID
 * (same template). `shake` is an error (granular molecules have no bonds).
 *
 * Requires a fix gravity pointing -z (3d) or -y (2d) of unchanged magnitude
 * and an unchanged timestep; reset_timestep is refused while it exists.
 * `ignore` (skip line/triangle particles in the near list) has nothing to
 * skip: gravel's particles are spheres. Full contract: doc/styles/fix_pour.md. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "coeff_check.h"
#include "domain.h"
#include "device.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "par.h"
#include "par_sum.h"
#include "fix_gravity.h"
#include "fix_rigid_small.h"
#include "log.h"
#include "molecule.h"
#include "random.h"
#include "region.h"
#include "rigid_math.h"

#define POUR_EPSILON 0.001 /* gravity direction tolerance (LAMMPS EPSILON) */
#define POUR_SMALL 1.0e-10 /* poly fractions must sum to 1 within this */

enum { DIAM_ONE, DIAM_RANGE, DIAM_POLY };

struct pour {
    int ninsert, ntype, seed;
    int ninserted, nper, nfreq;
    bigint nfirst;
    struct rng_park rng;
    /* region */
    int cyl;                        /* 0 block, 1 z-cylinder */
    double xlo, xhi, ylo, yhi, zlo, zhi;
    double xc, yc, rc;
    /* options */
    int dstyle, npoly;
    double radius_one, radius_lo, radius_hi, radius_max;
    double *radius_poly, *frac_poly;
    double dens_lo, dens_hi;
    double volfrac;
    int maxattempt;
    double rate;
    double vxlo, vxhi, vylo, vyhi, vy, vz;
    int idnext;
    int64_t maxtag;                 /* id next: tags counted from here */
    double grav;                    /* -magnitude of the gravity at creation */
    double dt;                      /* timestep at creation (sets nfreq) */
    double dt_check;                /* the timestep runs must keep */
    int dt_free;                    /* created before any run: LAMMPS 2021 lets the
                                     * timestep change until the first run (nfreq
                                     * stays that of the creation timestep) */
    double lo_cur, hi_cur;          /* vertical bounds of the current batch */
    double *near;                   /* 4 per entry: x y z radius */
    int near_cap;
    /* molecule mode (mol T [rigid F]) */
    struct molecule *mol;
    char rigid_id[GR_NAMELEN];
    struct fix *rigid;              /* the fix rigid/small of rigid_id (init) */
    int64_t maxmol;                 /* id next: molecule IDs counted from here */
    double *coords;                 /* 4 per template atom: x y z radius */
    int *imgs;                      /* 3 per template atom */
};

/* LAMMPS FixPour::outside(): value outside [lo, hi] along dim, periodic
 * images of the interval included. */
static int outside(const struct gravel *g, int dim, double value, double lo, double hi)
{
    const struct domain *d = &g->dom;
    double boxlo = d->lo[dim], boxhi = d->hi[dim], prd = boxhi - boxlo;
    int pbc_out = 1, reg_out = value < lo || value > hi;
    if (d->periodic[dim]) {
        if ((lo < boxlo && hi > boxhi) || hi - lo > prd)
            pbc_out = 0;
        else if (lo < boxlo)
            pbc_out = value > hi && value < lo + prd;
        else if (hi > boxhi)
            pbc_out = value < lo && value > hi - prd;
    }
    return pbc_out && reg_out;
}

/* 1 if an atom at x of this radius could touch a particle of the batch
 * (LAMMPS FixPour::overlap). */
static int near_region(const struct gravel *g, const struct pour *p, const double *x,
                       double radius)
{
    double delta = radius + (p->mol ? p->mol->molradius : p->radius_max);
    if (g->dom.dimension == 3) {
        if (!p->cyl) {
            if (outside(g, 0, x[0], p->xlo - delta, p->xhi + delta) ||
                outside(g, 1, x[1], p->ylo - delta, p->yhi + delta))
                return 0;
        } else {
            double del[3] = {x[0] - p->xc, x[1] - p->yc, 0.0};
            domain_minimum_image(g, del);
            double rsq = del[0] * del[0] + del[1] * del[1], r = p->rc + delta;
            if (rsq > r * r)
                return 0;
        }
        return !outside(g, 2, x[2], p->lo_cur - delta, p->hi_cur + delta);
    }
    return !outside(g, 0, x[0], p->xlo - delta, p->xhi + delta) &&
           !outside(g, 1, x[1], p->lo_cur - delta, p->hi_cur + delta);
}

/* p->near = (x, y, z, r) of the nold existing atoms that could touch a new
 * particle, with room for `extra` more (the new ones); returns their count. */
static int near_list(struct gravel *g, struct pour *p, const struct atoms *a, int nold,
                     int extra)
{
    int nnear = 0;
    for (int i = 0; i < nold; i++)
        if (near_region(g, p, a->x + 3 * i, a->radius[i]))
            nnear++;
    int need = nnear + extra;
    if (need > p->near_cap) {
        p->near = gr_realloc(g, p->near, (size_t)(need > 0 ? need : 1) * 4 * sizeof(double));
        p->near_cap = need;
    }
    nnear = 0;
    for (int i = 0; i < nold; i++)
        if (near_region(g, p, a->x + 3 * i, a->radius[i])) {
            double *q = p->near + 4 * nnear++;
            q[0] = a->x[3 * i], q[1] = a->x[3 * i + 1], q[2] = a->x[3 * i + 2];
            q[3] = a->radius[i];
        }
    if (par_on(g)) { /* several ranks: the near atoms of every rank, on every rank */
        double *rows = gr_malloc(g, (size_t)(nnear + 1) * 4 * sizeof(double));
        memcpy(rows, p->near, (size_t)nnear * 4 * sizeof(double));
        nnear = par_gather_rows(g, &rows, nnear, 4);
        if (nnear + extra > p->near_cap) {
            p->near_cap = nnear + extra;
            p->near = gr_realloc(g, p->near, (size_t)(p->near_cap + 1) * 4 * sizeof(double));
        }
        memcpy(p->near, rows, (size_t)nnear * 4 * sizeof(double));
        free(rows);
    }
    return nnear;
}

static void xyz_random(const struct gravel *g, struct pour *p, double h, double c[3])
{
    if (g->dom.dimension == 3) {
        if (!p->cyl) {
            c[0] = p->xlo + rng_park_uniform(&p->rng) * (p->xhi - p->xlo);
            c[1] = p->ylo + rng_park_uniform(&p->rng) * (p->yhi - p->ylo);
        } else {
            double r1, r2;
            for (;;) {
                r1 = rng_park_uniform(&p->rng) - 0.5;
                r2 = rng_park_uniform(&p->rng) - 0.5;
                if (r1 * r1 + r2 * r2 < 0.25)
                    break;
            }
            c[0] = p->xc + 2.0 * r1 * p->rc;
            c[1] = p->yc + 2.0 * r2 * p->rc;
        }
        c[2] = h;
    } else {
        c[0] = p->xlo + rng_park_uniform(&p->rng) * (p->xhi - p->xlo);
        c[1] = h;
        c[2] = 0.0;
    }
}

static double radius_sample(struct pour *p)
{
    if (p->dstyle == DIAM_ONE)
        return p->radius_one;
    if (p->dstyle == DIAM_RANGE)
        return p->radius_lo + rng_park_uniform(&p->rng) * (p->radius_hi - p->radius_lo);
    double value = rng_park_uniform(&p->rng), sum = 0.0;
    int i = 0;
    while (sum < value && i < p->npoly) /* LAMMPS: while (sum < value) */
        sum += p->frac_poly[i++];
    return p->radius_poly[i > 0 ? i - 1 : 0];
}

/* The largest molecule ID of every rank. */
static int64_t max_mol(struct gravel *g)
{
    int64_t m = 0;
    for (int i = 0; g->atoms.molecule_flag && i < g->atoms.n; i++)
        if (g->atoms.mol[i] > m)
            m = g->atoms.mol[i];
    return par_max_tag(g, m);
}

/* The first fix whose style starts with "gravity" (LAMMPS ^gravity). */
static struct fix *find_gravity(struct gravel *g)
{
    for (int i = 0; i < g->styles.nfix; i++)
        if (!strncmp(g->styles.fix[i]->style->name, "gravity", 7))
            return g->styles.fix[i];
    return NULL;
}

static double num(struct gravel *g, int argc, char **argv, int i, const char *what)
{
    if (i >= argc)
        gr_error(g, "fix pour: %s is missing", what);
    return arg_double(g, argv[i], what);
}

static void parse_options(struct gravel *g, struct pour *p, int argc, char **argv,
                          struct region **reg)
{
    int dim = g->dom.dimension;
    for (int i = 0; i < argc;) {
        const char *k = argv[i];
        if (!strcmp(k, "region")) {
            arg_need(g, argc, i, 1, k);
            *reg = region_find(g, argv[i + 1]);
            if (!*reg)
                gr_error(g, "fix pour region ID '%.64s' does not exist", argv[i + 1]);
            i += 2;
        } else if (!strcmp(k, "mol")) {
            arg_need(g, argc, i, 1, k);
            p->mol = molecule_find(g, argv[i + 1]);
            if (!p->mol)
                gr_error(g, "molecule template ID %.64s for fix pour does not exist",
                         argv[i + 1]);
            mol_require_atoms(g, p->mol);
            i += 2;
        } else if (!strcmp(k, "molfrac")) {
            /* one molecule per template here: molfrac 1.0 */
            if (!p->mol)
                gr_error(g, "fix pour: molfrac needs mol first");
            double v = num(g, argc, argv, i + 1, "molfrac");
            if (v < 1.0 - POUR_EPSILON || v > 1.0 + POUR_EPSILON)
                gr_error(g, "fix pour: molfrac of a one-molecule template must be 1.0, got %s",
                         argv[i + 1]);
            i += 2;
        } else if (!strcmp(k, "rigid")) {
            arg_need(g, argc, i, 1, k);
            snprintf(p->rigid_id, sizeof p->rigid_id, "%s", argv[i + 1]);
            i += 2;
        } else if (!strcmp(k, "shake")) {
            gr_error(g, "fix pour: shake is not supported (granular molecules have no bonds)");
        } else if (!strcmp(k, "id")) {
            arg_need(g, argc, i, 1, k);
            if (!strcmp(argv[i + 1], "max"))
                p->idnext = 0;
            else if (!strcmp(argv[i + 1], "next"))
                p->idnext = 1;
            else
                gr_error(g, "fix pour: id must be max or next, got '%.64s'", argv[i + 1]);
            i += 2;
        } else if (!strcmp(k, "ignore")) {
            i += 1; /* no line or triangle particles to skip */
        } else if (!strcmp(k, "diam")) {
            arg_need(g, argc, i, 1, k);
            const char *s = argv[i + 1];
            if (!strcmp(s, "one")) {
                p->dstyle = DIAM_ONE;
                p->radius_one = 0.5 * coeff_check(g, "fix pour", "diam one diameter",
                                                  num(g, argc, argv, i + 2, "diam one diameter"),
                                                  CR_POSITIVE);
                p->radius_max = p->radius_one;
                i += 3;
            } else if (!strcmp(s, "range")) {
                p->dstyle = DIAM_RANGE;
                p->radius_lo = 0.5 * coeff_check(g, "fix pour", "diam range lo",
                                                 num(g, argc, argv, i + 2, "diam range lo"),
                                                 CR_POSITIVE);
                p->radius_hi = 0.5 * num(g, argc, argv, i + 3, "diam range hi");
                if (p->radius_lo > p->radius_hi)
                    gr_error(g, "fix pour: diam range needs lo <= hi, got %s %s", argv[i + 2],
                             argv[i + 3]);
                p->radius_max = p->radius_hi;
                i += 4;
            } else if (!strcmp(s, "poly")) {
                if (i + 2 >= argc)
                    gr_error(g, "fix pour: diam poly needs N and N diameter fraction pairs");
                int np = arg_int(g, argv[i + 2], "diam poly N");
                if (np <= 0 || np > 1000000)
                    gr_error(g, "fix pour: diam poly N must be positive, got %s", argv[i + 2]);
                if (i + 3 + 2 * np > argc)
                    gr_error(g, "fix pour: diam poly %d needs %d diameter fraction pairs", np,
                             np);
                free(p->radius_poly);
                free(p->frac_poly);
                p->radius_poly = NULL;
                p->frac_poly = NULL;
                p->radius_poly = gr_calloc(g, (size_t)np, sizeof(double));
                p->frac_poly = gr_calloc(g, (size_t)np, sizeof(double));
                p->npoly = np;
                p->dstyle = DIAM_POLY;
                p->radius_max = 0.0;
                i += 3;
                for (int q = 0; q < np; q++) {
                    p->radius_poly[q] = 0.5 * arg_double(g, argv[i++], "diam poly diameter");
                    p->frac_poly[q] = arg_double(g, argv[i++], "diam poly fraction");
                    if (p->radius_poly[q] <= 0.0 || p->frac_poly[q] < 0.0)
                        gr_error(g, "fix pour: diam poly needs diameters > 0 and fractions "
                                    ">= 0, got %s %s", argv[i - 2], argv[i - 1]);
                    if (p->radius_poly[q] > p->radius_max)
                        p->radius_max = p->radius_poly[q];
                }
                double sum = 0.0;
                for (int q = 0; q < np; q++)
                    sum += p->frac_poly[q];
                if (fabs(sum - 1.0) > POUR_SMALL)
                    gr_error(g, "fix pour polydisperse fractions do not sum to 1.0 (sum %.12g)",
                             sum);
            } else {
                gr_error(g, "fix pour: diam must be one, range or poly, got '%.64s'", s);
            }
        } else if (!strcmp(k, "dens")) {
            p->dens_lo = coeff_check(g, "fix pour", "dens lo", num(g, argc, argv, i + 1, "dens lo"),
                                     CR_POSITIVE);
            p->dens_hi = num(g, argc, argv, i + 2, "dens hi");
            if (p->dens_lo > p->dens_hi)
                gr_error(g, "fix pour: dens needs lo <= hi, got %s %s", argv[i + 1],
                         argv[i + 2]);
            i += 3;
        } else if (!strcmp(k, "vol")) {
            p->volfrac = coeff_check(g, "fix pour", "vol fraction",
                                     num(g, argc, argv, i + 1, "vol fraction"), CR_POSITIVE);
            if (i + 2 >= argc)
                gr_error(g, "fix pour: vol needs a fraction and a number of attempts");
            p->maxattempt = arg_int(g, argv[i + 2], "vol attempts");
            i += 3;
        } else if (!strcmp(k, "rate")) {
            p->rate = num(g, argc, argv, i + 1, "rate");
            i += 2;
        } else if (!strcmp(k, "vel")) {
            if (dim == 3) {
                p->vxlo = num(g, argc, argv, i + 1, "vel vxlo");
                p->vxhi = num(g, argc, argv, i + 2, "vel vxhi");
                p->vylo = num(g, argc, argv, i + 3, "vel vylo");
                p->vyhi = num(g, argc, argv, i + 4, "vel vyhi");
                if (p->vxlo > p->vxhi || p->vylo > p->vyhi)
                    gr_error(g, "fix pour: vel needs vxlo <= vxhi and vylo <= vyhi");
                p->vz = num(g, argc, argv, i + 5, "vel vz");
                i += 6;
            } else {
                p->vxlo = num(g, argc, argv, i + 1, "vel vxlo");
                p->vxhi = num(g, argc, argv, i + 2, "vel vxhi");
                p->vy = num(g, argc, argv, i + 3, "vel vy");
                p->vz = 0.0;
                if (p->vxlo > p->vxhi)
                    gr_error(g, "fix pour: vel needs vxlo <= vxhi");
                i += 4;
            }
        } else {
            gr_error(g, "fix pour: unknown keyword '%.64s' (expected region, diam, dens, vol, "
                        "rate, vel, id, ignore, mol, molfrac, rigid, shake)", k);
        }
    }
}

/* LAMMPS's refusals of the insertion region: it must bound its points
 * (side out does not: "Fix pour region does not support a bounding box")
 * and keep still (insertion heights come from its extent at creation). */
static void check_region(struct gravel *g, const struct region *reg)
{
    if (!reg->interior)
        gr_error(g, "fix pour region %s has side out: an insertion region must bound its "
                    "points (LAMMPS: Fix pour region does not support a bounding box)",
                 reg->id);
    if (region_dynamic(reg))
        gr_error(g, "fix pour region %s moves or rotates: an insertion region cannot be "
                    "dynamic (as LAMMPS)", reg->id);
}

/* The template's atoms become particles: a finite extent (molradius, which
 * sizes the batches) and per atom a finite radius >= 0 and a mass > 0 (the
 * Masses section, or 4/3 pi r^3 of a unit density as inserted). */
static void check_template(struct gravel *g, const struct molecule *m)
{
    if (!(isfinite(m->molradius) && m->molradius > 0))
        gr_error(g, "fix pour: molecule template %s has no finite positive extent (radius %g)",
                 m->id, m->molradius);
    for (int i = 0; i < m->natoms; i++) {
        double r = m->radius ? m->radius[i] : 0.5;
        double mass = m->rmass ? m->rmass[i] : 4.0 * M_PI / 3.0 * r * r * r;
        if (!(isfinite(r) && r >= 0 && isfinite(mass) && mass > 0))
            gr_error(g, "fix pour: atom %d of molecule template %s would be inserted with "
                        "radius %g and mass %g (a particle needs a mass > 0)",
                     i + 1, m->id, r, mass);
    }
}

/* The lightest and heaviest particle the diameters and densities allow
 * must have a finite mass > 0 (4/3 pi r^3 density, as inserted). */
static void check_masses(struct gravel *g, const struct pour *p)
{
    double rlo = p->radius_one, rhi = p->radius_max;
    if (p->dstyle == DIAM_RANGE)
        rlo = p->radius_lo;
    for (int q = 0; p->dstyle == DIAM_POLY && q < p->npoly; q++)
        rlo = q == 0 || p->radius_poly[q] < rlo ? p->radius_poly[q] : rlo;
    double mlo = 4.0 * M_PI / 3.0 * rlo * rlo * rlo * p->dens_lo;
    double mhi = 4.0 * M_PI / 3.0 * rhi * rhi * rhi * p->dens_hi;
    if (!(mlo > 0) || !isfinite(mhi))
        gr_error(g, "fix pour: particles of diameter %g to %g and density %g to %g would have "
                    "masses %g to %g (each needs a finite mass > 0)",
                 2 * rlo, 2 * rhi, p->dens_lo, p->dens_hi, mlo, mhi);
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 3)
        gr_error(g, "fix pour expects N type seed keyword values ...");
    if (g->dom.triclinic)
        gr_error(g, "cannot use fix pour with triclinic box (as LAMMPS)");
    struct pour *p = gr_calloc(g, 1, sizeof *p);
    f->data = p;
    p->ninsert = arg_int(g, argv[0], "number of particles");
    p->ntype = arg_int(g, argv[1], "atom type");
    p->seed = arg_int(g, argv[2], "seed");
    if (p->ninsert < 0)
        gr_error(g, "fix pour: number of particles must be >= 0, got %s", argv[0]);
    if (p->seed <= 0)
        gr_error(g, "fix pour: seed must be a positive integer, got %s", argv[2]);
    /* LAMMPS's defaults */
    p->dstyle = DIAM_ONE;
    p->radius_one = p->radius_max = 0.5;
    p->dens_lo = p->dens_hi = 1.0;
    p->volfrac = 0.25;
    p->maxattempt = 50;
    struct region *reg = NULL;
    parse_options(g, p, argc - 3, argv + 3, &reg);
    if (p->mol) {
        long long top = (long long)p->ntype + p->mol->ntypes; /* no int overflow */
        if (top <= 0 || top > g->atoms.ntypes)
            gr_error(g, "invalid atom type in fix pour mol command (type offset %d + template "
                        "types up to %d, box has %d)", p->ntype, p->mol->ntypes,
                     g->atoms.ntypes);
        mol_compute_center(p->mol); /* inserted about the geometric centre */
        check_template(g, p->mol);
        p->coords = gr_calloc(g, 4 * (size_t)p->mol->natoms, sizeof(double));
        p->imgs = gr_calloc(g, 3 * (size_t)p->mol->natoms, sizeof(int));
    } else if (p->rigid_id[0]) {
        gr_error(g, "cannot use fix pour rigid without mol (a molecule template)");
    } else if (p->ntype <= 0 || p->ntype > g->atoms.ntypes) {
        gr_error(g, "invalid atom type %d in fix pour command (1..%d)", p->ntype,
                 g->atoms.ntypes);
    }
    if (!reg)
        gr_error(g, "must specify a region in fix pour");
    check_region(g, reg);
    if (!p->mol)
        check_masses(g, p);
    const struct domain *d = &g->dom;
    int dim = d->dimension;
    if (!strcmp(reg->style->name, "block")) {
        p->xlo = reg->p[0], p->xhi = reg->p[1];
        p->ylo = reg->p[2], p->yhi = reg->p[3];
        p->zlo = reg->p[4], p->zhi = reg->p[5];
        if (p->xlo < d->lo[0] || p->xhi > d->hi[0] || p->ylo < d->lo[1] || p->yhi > d->hi[1] ||
            p->zlo < d->lo[2] || p->zhi > d->hi[2])
            gr_error(g, "fix pour: insertion region %s extends outside the simulation box",
                     reg->id);
    } else if (!strcmp(reg->style->name, "cylinder")) {
        if (dim == 2)
            gr_error(g, "must use a block region with fix pour for 2d simulations");
        if (reg->dim != 2)
            gr_error(g, "must use a z-axis cylinder region with fix pour (region %s is along "
                        "%c)", reg->id, "xyz"[reg->dim]);
        p->cyl = 1;
        p->xc = reg->p[0], p->yc = reg->p[1], p->rc = reg->p[2];
        p->zlo = reg->p[3], p->zhi = reg->p[4];
        if (p->xc - p->rc < d->lo[0] || p->xc + p->rc > d->hi[0] ||
            p->yc - p->rc < d->lo[1] || p->yc + p->rc > d->hi[1] || p->zlo < d->lo[2] ||
            p->zhi > d->hi[2])
            gr_error(g, "fix pour: insertion region %s extends outside the simulation box",
                     reg->id);
    } else {
        gr_error(g, "must use a block or cylinder region with fix pour (region %s is %s)",
                 reg->id, reg->style->name);
    }
    if (p->idnext) {
        p->maxtag = par_max_atom_tag(g);
        p->maxmol = max_mol(g);
    }
    rng_park_init(&p->rng, p->seed);
    /* LAMMPS 2021 warms the generator up with 30 draws (measured: the first
     * particle's height is draw 31 for every seed) */
    for (int i = 0; i < 30; i++)
        (void)rng_park_uniform(&p->rng);
    struct fix *fg = find_gravity(g);
    double mag, dir[3];
    if (!fg || !fix_gravity_field(fg, &mag, dir))
        gr_error(g, "no fix gravity defined for fix pour");
    p->grav = -mag; /* force->ftm2v = 1 in lj, si and cgs */
    p->dt = p->dt_check = g->dt;
    p->dt_free = g->eng == NULL;

    /* insertion period: the fall time through the region */
    double v_rel, delta;
    if (dim == 3) {
        v_rel = p->vz - p->rate;
        delta = p->zhi - p->zlo;
    } else {
        v_rel = p->vy - p->rate;
        delta = p->yhi - p->ylo;
    }
    double t = (-v_rel - sqrt(v_rel * v_rel - 2.0 * p->grav * delta)) / p->grav;
    double nf = t / g->dt + 0.5;
    if (!(nf >= 0 && nf < 2147483647.0))
        gr_error(g, "fix pour: the fall time %g through the region is not a usable number of "
                    "steps of %g (gravity %g)", t, g->dt, mag);
    p->nfreq = (int)nf;
    f->time_depend = 1;
    f->force_reneighbor = 1;
    f->next_reneighbor = g->step + 1;
    p->nfirst = f->next_reneighbor;

    /* particles per batch from the volume fraction */
    double volume, volume_one = 1.0;
    if (dim == 3) {
        if (!p->cyl) {
            double dy = p->yhi - p->ylo;
            if (dy < 1.0)
                dy = 1.0;
            volume = (p->xhi - p->xlo) * dy * (p->zhi - p->zlo);
        } else {
            volume = M_PI * p->rc * p->rc * (p->zhi - p->zlo);
        }
        if (p->mol) {
            double mr = p->mol->molradius;
            volume_one = 4.0 / 3.0 * M_PI * mr * mr * mr;
        } else if (p->dstyle != DIAM_POLY) {
            volume_one = 4.0 / 3.0 * M_PI * p->radius_max * p->radius_max * p->radius_max;
        } else {
            volume_one = 0.0;
            for (int i = 0; i < p->npoly; i++)
                volume_one += (4.0 / 3.0 * M_PI * p->radius_poly[i] * p->radius_poly[i] *
                               p->radius_poly[i]) * p->frac_poly[i];
        }
    } else {
        volume = (p->xhi - p->xlo) * (p->yhi - p->ylo);
        if (p->mol) {
            volume_one = M_PI * p->mol->molradius * p->mol->molradius;
        } else if (p->dstyle != DIAM_POLY) {
            volume_one = M_PI * p->radius_max * p->radius_max;
        } else {
            volume_one = 0.0;
            for (int i = 0; i < p->npoly; i++)
                volume_one += (M_PI * p->radius_poly[i] * p->radius_poly[i]) * p->frac_poly[i];
        }
    }
    double np = p->volfrac * volume / volume_one;
    if (!(np < 2147483647.0))
        gr_error(g, "fix pour: %g particles per insertion is too many", np);
    p->nper = (int)np;
    if (p->nper <= 0)
        gr_error(g, "fix pour insertion count per timestep is 0 (vol %g of a region of "
                    "volume %g, particle volume %g)", p->volfrac, volume, volume_one);
    bigint nfinal = g->step + 1 + (bigint)((p->ninsert - 1) / p->nper) * p->nfreq;
    gr_print(g, "Particle insertion: %d every %d steps, %d by step %lld\n", p->nper, p->nfreq,
             p->ninsert, (long long)nfinal);
    f->hooks = HOOK_PRE_EXCHANGE;
}

static void init(struct gravel *g, struct fix *f)
{
    struct pour *p = f->data;
    if (g->dom.triclinic)
        gr_error(g, "cannot use fix pour with triclinic box (as LAMMPS)");
    struct fix *fg = find_gravity(g);
    double mag, dir[3];
    if (!fg || !fix_gravity_field(fg, &mag, dir))
        gr_error(g, "no fix gravity defined for fix pour %s", f->id);
    if (g->dom.dimension == 3) {
        if (fabs(dir[0]) > POUR_EPSILON || fabs(dir[1]) > POUR_EPSILON ||
            fabs(dir[2] + 1.0) > POUR_EPSILON)
            gr_error(g, "gravity must point in -z to use with fix pour in 3d (fix %s points "
                        "along %g %g %g)", fg->id, dir[0], dir[1], dir[2]);
    } else {
        if (fabs(dir[0]) > POUR_EPSILON || fabs(dir[1] + 1.0) > POUR_EPSILON ||
            fabs(dir[2]) > POUR_EPSILON)
            gr_error(g, "gravity must point in -y to use with fix pour in 2d (fix %s points "
                        "along %g %g %g)", fg->id, dir[0], dir[1], dir[2]);
    }
    if (-mag != p->grav)
        gr_error(g, "gravity changed since fix pour %s was created (%g, was %g)", f->id, mag,
                 -p->grav);
    if (p->dt_free) {
        p->dt_check = g->dt;
        p->dt_free = 0;
    }
    if (g->dt != p->dt_check)
        gr_error(g, "cannot change timestep with fix pour (%s ran with %g, now %g)", f->id,
                 p->dt_check, g->dt);
    p->rigid = NULL;
    if (p->rigid_id[0]) {
        p->rigid = fix_find(g, p->rigid_id);
        if (!p->rigid)
            gr_error(g, "fix pour rigid fix %s does not exist", p->rigid_id);
        if (rigid_small_template(p->rigid) != p->mol)
            gr_error(g, "fix pour and fix rigid/small not using same molecule template ID");
    }
    if (p->mol && !g->atoms.molecule_flag && p->rigid)
        gr_error(g, "fix pour mol rigid needs molecule IDs (fix property/atom mol)");
}

/* Upper bound of the atoms inserted in (step, step + nsteps]. */
static int reserve(struct gravel *g, struct fix *f, bigint nsteps, double *rmax)
{
    struct pour *p = f->data;
    *rmax = p->radius_max;
    int per = 1;
    if (p->mol) {
        per = p->mol->natoms;
        *rmax = 0.5;
        if (p->mol->radius) {
            *rmax = 0;
            for (int i = 0; i < per; i++)
                *rmax = p->mol->radius[i] > *rmax ? p->mol->radius[i] : *rmax;
        }
    }
    bigint next = f->next_reneighbor, last = g->step + nsteps;
    if (next <= g->step || next > last || p->ninserted >= p->ninsert)
        return 0;
    bigint batches = p->nfreq > 0 ? (last - next) / p->nfreq + 1 : 1;
    bigint left = p->ninsert - p->ninserted;
    bigint most = batches * p->nper;
    return (int)((most < left ? most : left) * per);
}

/* A batch of molecules (LAMMPS FixPour::pre_exchange, mode MOLECULE): per
 * molecule the height draw; per attempt a point, the template draw (one
 * template: always the first), the rotation (3d: a random axis, 3 draws; 2d:
 * z) and its angle; the template atoms rotated about the geometric centre
 * and wrapped into the periodic box must all be clear of the near list.
 * Placed: vx (vy) draws; every atom gets the velocity, the template's type
 * (+ the type offset), radius (0.5 without Diameters) and mass (4/3 pi r^3
 * without Masses), tags maxtag + 1 ..., molecule ID maxmol + 1; fix
 * rigid/small turns it into a body. */
static void pre_exchange_mol(struct gravel *g, struct fix *f)
{
    struct pour *p = f->data;
    struct molecule *mol = p->mol;
    struct atoms *a = &g->atoms;
    const struct domain *d = &g->dom;
    int dim = d->dimension, nold = a->n, natom = mol->natoms;
    int64_t maxtag = p->idnext ? p->maxtag : par_max_atom_tag(g);
    int64_t maxmol = p->idnext ? p->maxmol : max_mol(g);
    int nnew = p->nper;
    if (p->ninserted + nnew > p->ninsert)
        nnew = p->ninsert - p->ninserted;
    double shift = (double)(g->step - p->nfirst) * g->dt * p->rate;
    p->lo_cur = (dim == 3 ? p->zlo : p->ylo) + shift;
    p->hi_cur = (dim == 3 ? p->zhi : p->yhi) + shift;
    int nnear = near_list(g, p, a, nold, nnew * natom);
    int nprevious = nnear;
    int nsuccess = 0;
    long attempt = 0, maxiter = (long)nnew * p->maxattempt;
    while (nsuccess < nnew) {
        double rn = rng_park_uniform(&p->rng);
        double h = p->hi_cur - rn * rn * (p->hi_cur - p->lo_cur);
        double c[3], quat[4];
        int success = 0;
        while (attempt < maxiter) {
            attempt++;
            xyz_random(g, p, h, c);
            (void)rng_park_uniform(&p->rng); /* the template draw (molfrac) */
            double rot[3][3];
            mol_random_quat(dim, rng_park_draw, &p->rng, quat);
            rm_quat_to_mat(quat, rot);
            for (int m = 0; m < natom; m++) {
                double *q = p->coords + 4 * m;
                mol_place_atom(mol, rot, c, m, q);
                q[3] = mol->radius ? mol->radius[m] : 0.5;
                int *im = p->imgs + 3 * m;
                im[0] = im[1] = im[2] = 0;
                domain_remap(g, q, im);
            }
            int m;
            for (m = 0; m < natom; m++) {
                const double *q = p->coords + 4 * m;
                int i;
                for (i = 0; i < nnear; i++) {
                    const double *o = p->near + 4 * i;
                    double del[3] = {q[0] - o[0], q[1] - o[1], q[2] - o[2]};
                    domain_minimum_image(g, del);
                    double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
                    double radsum = q[3] + o[3];
                    if (rsq <= radsum * radsum)
                        break;
                }
                if (i < nnear)
                    break;
            }
            if (m == natom) {
                success = 1;
                break;
            }
        }
        if (!success)
            break;
        nsuccess++;
        int first = a->n;
        for (int m = 0; m < natom; m++)
            memcpy(p->near + 4 * nnear++, p->coords + 4 * m, 4 * sizeof(double));
        double vnew[3];
        vnew[0] = p->vxlo + rng_park_uniform(&p->rng) * (p->vxhi - p->vxlo);
        if (dim == 3) {
            vnew[1] = p->vylo + rng_park_uniform(&p->rng) * (p->vyhi - p->vylo);
            vnew[2] = -sqrt(p->vz * p->vz + 2.0 * p->grav * (c[2] - p->hi_cur));
        } else {
            vnew[1] = -sqrt(p->vy * p->vy + 2.0 * p->grav * (c[1] - p->hi_cur));
            vnew[2] = 0.0;
        }
        int top = dim == 3 ? 2 : 1, placed = 0;
        for (int m = 0; m < natom; m++) {
            const double *q = p->coords + 4 * m;
            int inbox = 1, above = q[top] >= d->hi[top];
            for (int k = 0; k < 3; k++) {
                int in = q[k] >= d->lo[k] && q[k] < d->hi[k];
                inbox = inbox && in;
                if (k != top)
                    above = above && in;
            }
            placed += inbox || above;
            if (!(inbox || above) || !par_owns(g, q)) /* several ranks: the brick's owner */
                continue;
            double rad = q[3];
            double mass = mol->rmass ? mol->rmass[m] : 4.0 * M_PI / 3.0 * rad * rad * rad;
            int n = atoms_add(g, maxtag + m + 1, p->ntype + mol->type[m], q, rad, mass);
            a->mask[n] = 1u | f->groupbit;
            if (a->molecule_flag)
                a->mol[n] = maxmol + (mol->molecule ? mol->molecule[m] : 1);
            for (int k = 0; k < 3; k++) {
                a->v[3 * n + k] = vnew[k];
                a->image[3 * n + k] = p->imgs[3 * m + k];
            }
        }
        if (p->rigid) { /* every rank adds the body (its members on their owners) */
            if (placed != natom)
                gr_error(g, "fix pour %s: a rigid molecule was inserted partly outside the box "
                            "(step %lld)", f->id, (long long)g->step);
            rigid_small_add_body(g, p->rigid, p->mol, first, maxtag, p->coords, 4,
                                 1u | f->groupbit, c, vnew, quat);
        }
        maxtag += natom;
        if (a->molecule_flag)
            maxmol += mol->molecule ? mol->nmolecules : 1;
    }
    int ninserted_atoms = nnear - nprevious, now = ninserted_atoms / natom;
    p->ninserted += now;
    if (now < nnew)
        gr_warn(g, "Less insertions than requested (fix pour %s at step %lld: %d of %d)", f->id,
                (long long)g->step, now, nnew);
    if (p->idnext) {
        p->maxtag = maxtag;
        p->maxmol = maxmol;
    }
    eng_append(g, nold);
    if (p->ninserted < p->ninsert)
        f->next_reneighbor += p->nfreq;
    else
        f->next_reneighbor = 0;
}

/* One batch of insertions (LAMMPS FixPour::pre_exchange). */
static void pre_exchange(struct gravel *g, struct fix *f)
{
    struct pour *p = f->data;
    if (f->next_reneighbor != g->step)
        return;
    if (p->mol) {
        run_sync_host(g);
        pre_exchange_mol(g, f);
        return;
    }
    run_sync_host(g); /* the host arrays = the device's atoms, in device order */
    struct atoms *a = &g->atoms;
    const struct domain *d = &g->dom;
    int dim = d->dimension, nold = a->n;
    int64_t maxtag = p->idnext ? p->maxtag : par_max_atom_tag(g);
    int nnew = p->nper;
    if (p->ninserted + nnew > p->ninsert)
        nnew = p->ninsert - p->ninserted;
    double shift = (double)(g->step - p->nfirst) * g->dt * p->rate;
    p->lo_cur = (dim == 3 ? p->zlo : p->ylo) + shift;
    p->hi_cur = (dim == 3 ? p->zhi : p->yhi) + shift;

    /* the near list: atoms that could touch a new particle, then the new ones */
    int nnear = near_list(g, p, a, nold, nnew);
    int nprevious = nnear;

    int nsuccess = 0;
    long attempt = 0, maxiter = (long)nnew * p->maxattempt;
    while (nsuccess < nnew) {
        double rn = rng_park_uniform(&p->rng);
        double h = p->hi_cur - rn * rn * (p->hi_cur - p->lo_cur);
        double radtmp = radius_sample(p);
        double c[3];
        int success = 0;
        while (attempt < maxiter) {
            attempt++;
            xyz_random(g, p, h, c);
            int i;
            for (i = 0; i < nnear; i++) {
                const double *q = p->near + 4 * i;
                double del[3] = {c[0] - q[0], c[1] - q[1], c[2] - q[2]};
                domain_minimum_image(g, del);
                double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
                double radsum = radtmp + q[3];
                if (rsq <= radsum * radsum)
                    break;
            }
            if (i == nnear) {
                success = 1;
                break;
            }
        }
        if (!success)
            break;
        nsuccess++;
        double *q = p->near + 4 * nnear++;
        q[0] = c[0], q[1] = c[1], q[2] = c[2], q[3] = radtmp;
        /* velocity: the speed after falling from the top of the region */
        double vnew[3];
        vnew[0] = p->vxlo + rng_park_uniform(&p->rng) * (p->vxhi - p->vxlo);
        if (dim == 3) {
            vnew[1] = p->vylo + rng_park_uniform(&p->rng) * (p->vyhi - p->vylo);
            vnew[2] = -sqrt(p->vz * p->vz + 2.0 * p->grav * (c[2] - p->hi_cur));
        } else {
            vnew[1] = -sqrt(p->vy * p->vy + 2.0 * p->grav * (c[1] - p->hi_cur));
            vnew[2] = 0.0;
        }
        double denstmp = p->dens_lo + rng_park_uniform(&p->rng) * (p->dens_hi - p->dens_lo);
        /* on LAMMPS's one process: inside the box, or above its top face */
        int top = dim == 3 ? 2 : 1, inbox = 1, above = c[top] >= d->hi[top];
        for (int k = 0; k < 3; k++) {
            int in = c[k] >= d->lo[k] && c[k] < d->hi[k];
            inbox = inbox && in;
            if (k < top)
                above = above && in;
        }
        if ((inbox || above) && par_owns(g, c)) { /* several ranks: the brick's owner */
            int n = atoms_add(g, maxtag + 1, p->ntype, c, radtmp,
                              4.0 * M_PI / 3.0 * radtmp * radtmp * radtmp * denstmp);
            a->mask[n] = 1u | f->groupbit;
            for (int k = 0; k < 3; k++)
                a->v[3 * n + k] = vnew[k];
        }
        maxtag += 1;
    }
    int ninserted_now = nnear - nprevious;
    p->ninserted += ninserted_now;
    if (ninserted_now < nnew)
        gr_warn(g, "Less insertions than requested (fix pour %s at step %lld: %d of %d)", f->id,
                (long long)g->step, ninserted_now, nnew);
    if (p->idnext)
        p->maxtag = maxtag;
    eng_append(g, nold);
    if (p->ninserted < p->ninsert)
        f->next_reneighbor += p->nfreq;
    else
        f->next_reneighbor = 0;
}

static void destroy(struct fix *f)
{
    struct pour *p = f->data;
    if (p) {
        free(p->radius_poly);
        free(p->frac_poly);
        free(p->near);
        free(p->coords);
        free(p->imgs);
    }
    free(p);
}

const struct fix_style fix_style_pour = {
    .name = "pour",
    .create = create,
    .init = init,
    .pre_exchange = pre_exchange,
    .reserve = reserve,
    .destroy = destroy,
};
