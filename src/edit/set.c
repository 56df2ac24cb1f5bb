/* set.c - `set style ID keyword value ...`: change per-atom properties of the
 * atoms selected by style atom|type|group|region (LAMMPS set).
 *
 * LAMMPS semantics for atom_style sphere: `diameter` changes the radius only
 * (not the mass, as LAMMPS 2021 checked); `density` sets the mass from the
 * current radius, mass = 4/3 pi r^3 rho, or mass = rho for a point particle
 * (radius 0), also in 2d; `density/disc` (2d only) sets mass = pi r^2 rho
 * (an area density); `mass` sets the mass directly. Keywords apply in order.
 * Coordinates set in periodic dimensions are wrapped into the box. Values of
 * type, mass, diameter, density, omega, omegax omegay omegaz (LIGGGHTS's one
 * component), x y z and vx vy vz may be v_name, an
 * atom-style variable evaluated for every atom when the keyword applies.
 *
 * The random keywords draw LAMMPS's numbers (src/core/random.c), so `lmp` on one
 * process picks the same atoms:
 *   type/fraction T f seed  each selected atom's RanPark is reseeded from
 *                           seed and its coordinates; it becomes type T when
 *                           the first draw is <= f (about a fraction f);
 *   type/ratio T f seed     exactly floor(f N) of the N selected atoms,
 *   type/subset T n seed    exactly n of them: RanMars(seed) with LAMMPS's
 *                           select_subset over the selected atoms in storage
 *                           order.
 *
 * atom_style ellipsoid superellipsoid (LAMMPS 30 Mar 2026, AtomVecEllipsoid
 * set_shape / set_block and Set):
 *   shape Dx Dy Dz   the three diameters (semi-axes half of them; all 0
 *                    makes the atom a point particle again); a new shape
 *                    starts aligned with the box (quat 1 0 0 0), blockiness
 *                    2 2;
 *   block n1 n2      blockiness (> 0; an atom without a shape gets semi-axes
 *                    0.5 0.5 0.5);
 *   quat a b c theta rotation by theta degrees about the axis (a, b, c)
 *                    (normalized; in 2d only about z; a b c may be v_name,
 *                    theta is a number);
 *   quat/random seed uniform random orientations (LAMMPS's RanPark draws,
 *                    reseeded per atom from its coordinates);
 *   angmom Lx Ly Lz  the angular momentum.
 * Shape and block recompute the principal moments from the current mass
 * and the bounding radius (radius); mass and density recompute the moments
 * too (density: mass = volume x density), so the moments always belong to
 * the mass; `diameter` is refused (the radius is the bounding radius). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atom_custom.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "log.h"
#include "random.h"
#include "region.h"
#include "superellipsoid.h"
#include "variable.h"

/* Parse a LAMMPS id range "*", "n", "n*", "*n", "m*n" into [lo, hi] within 1..max. */
static void parse_range(struct gravel *g, const char *s, bigint max, bigint *lo, bigint *hi,
                        const char *what)
{
    const char *star = strchr(s, '*');
    if (!star) {
        *lo = *hi = arg_bigint(g, s, what);
        if (*lo < 1 || *lo > max)
            gr_error(g, "%s %s is outside 1..%lld", what, s, (long long)max);
        return;
    }
    char buf[64];
    size_t n = (size_t)(star - s);
    if (n >= sizeof buf || strlen(star + 1) >= sizeof buf)
        gr_error(g, "invalid %s range '%.64s'", what, s);
    memcpy(buf, s, n);
    buf[n] = '\0';
    *lo = n ? arg_bigint(g, buf, what) : 1;
    *hi = star[1] ? arg_bigint(g, star + 1, what) : max;
    if (*lo < 1 || *lo > *hi)
        gr_error(g, "invalid %s range '%.64s'", what, s);
}

/* Select atoms: sel[i] = 1 for chosen atoms. */
static void select_atoms(struct gravel *g, const char *style, const char *id, char *sel)
{
    const struct atoms *a = &g->atoms;
    if (!strcmp(style, "atom")) {
        bigint lo, hi;
        parse_range(g, id, a->maxtag > 0 ? a->maxtag : 1, &lo, &hi, "atom ID");
        for (int i = 0; i < a->n; i++)
            sel[i] = a->tag[i] >= lo && a->tag[i] <= hi;
    } else if (!strcmp(style, "type")) {
        bigint lo, hi;
        parse_range(g, id, a->ntypes, &lo, &hi, "atom type");
        if (hi > a->ntypes)
            gr_error(g, "atom type range '%s' is outside 1..%d", id, a->ntypes);
        for (int i = 0; i < a->n; i++)
            sel[i] = a->type[i] >= lo && a->type[i] <= hi;
    } else if (!strcmp(style, "group")) {
        unsigned bit = group_bit(arg_group(g, id));
        for (int i = 0; i < a->n; i++)
            sel[i] = (a->mask[i] & bit) != 0;
    } else if (!strcmp(style, "region")) {
        struct region *r = region_get(g, id);
        region_prematch(g, r);
        for (int i = 0; i < a->n; i++)
            sel[i] = region_match(r, a->x + 3 * i);
    } else if (!strcmp(style, "mol")) {
        gr_error(g, "style mol is not supported: select by atom, type, group or region");
    } else {
        gr_error(g, "unknown style '%.32s': expected atom, type, group or region", style);
    }
}

/* type/ratio and type/subset: mark exactly nsubset of the selected atoms
 * (LAMMPS Set::setrandom). flag and work are the caller's scratch arrays. */
static long select_exact(struct gravel *g, char *sel, int newtype, int64_t nsubset, int seed,
                         int *flag, int *work)
{
    struct atoms *a = &g->atoms;
    struct rng_mars rm;
    rng_mars_init(&rm, seed); /* seed + rank, rank 0 */
    int count = 0;
    for (int i = 0; i < a->n; i++)
        count += sel[i] != 0;
    rng_mars_select_subset(&rm, nsubset, count, flag, work);
    long changed = 0;
    int k = 0;
    for (int i = 0; i < a->n; i++) {
        if (!sel[i])
            continue;
        if (flag[k++]) {
            a->type[i] = newtype;
            changed++;
        }
    }
    return changed;
}

/* A keyword's value: a number (into *num, NULL returned) or v_name, an
 * atom-style variable evaluated now for every atom into buf (returned; in a
 * dry pass only checked). */
static const double *kw_value(struct gravel *g, const char *s, const char *what, double *num,
                              double *buf, int dry)
{
    if (!strncmp(s, "v_", 2) && s[2]) {
        var_check_atom(g, s + 2, "set");
        if (!dry)
            var_compute_atom(g, s + 2, buf);
        return buf;
    }
    *num = arg_double(g, s, what);
    return NULL;
}

#define VAL(p, num, i) ((p) ? (p)[i] : (num))

/* 1 when atom i is a superellipsoid (has a shape). */
static int has_shape(const struct atoms *a, int i)
{
    const double *sh = a->shape + 3 * i;
    return sh[0] != 0.0 || sh[1] != 0.0 || sh[2] != 0.0;
}

/* Atom i's principal moments (from its mass) and bounding radius after a
 * change of shape, blockiness or mass (superellipsoid.h). */
static void sqe_refresh(struct atoms *a, int i)
{
    if (!has_shape(a, i))
        return;
    sqe_inertia(a->shape + 3 * i, a->rmass[i], a->block + 2 * i, a->inertia + 3 * i);
    a->radius[i] = sqe_bounding_radius(a->shape + 3 * i, a->block + 2 * i);
}

/* Atom i becomes a superellipsoid: aligned with the box, an ellipsoid
 * until `block` (LAMMPS's new bonus record). */
static void sqe_create(struct atoms *a, int i)
{
    double *q = a->quat + 4 * i;
    q[0] = 1.0, q[1] = q[2] = q[3] = 0.0;
    a->block[2 * i] = a->block[2 * i + 1] = 2.0;
}

static void need_ellipsoid(struct gravel *g, const char *kw)
{
    if (!g->atoms.ellipsoid_flag)
        gr_error(g, "keyword '%s' does not apply to atom_style sphere (it needs atom_style "
                    "ellipsoid superellipsoid)", kw);
}

/* The quaternion of atom i, which must have a shape (LAMMPS: "Cannot set
 * quaternion for atom that has none"). */
static double *quat_of(struct gravel *g, int i)
{
    if (!has_shape(&g->atoms, i))
        gr_error(g, "cannot set the quaternion of atom %lld: it has no shape (set shape "
                    "first)", (long long)g->atoms.tag[i]);
    return g->atoms.quat + 4 * i;
}

/* A per-atom heat value (temperature, heat source) of the selected atoms
 * from s: what names it in messages, nonneg refuses values below 0 (else
 * only non-finite ones). Returns the atoms set (0 in a dry pass). */
static long set_heat_value(struct gravel *g, double *dst, const char *s, const char *what,
                           int nonneg, const char *sel, int n, double *buf, int dry)
{
    if (!(g->atoms.heat_flag & ATOM_HEAT_T))
        gr_error(g, "cannot set %s without the atoms' temperature (fix property/atom "
                    "temperature first, or fix heat/gran)", what);
    double num = 0;
    const double *p = kw_value(g, s, what, &num, buf, dry);
    long count = 0;
    for (int i = 0; i < n; i++)
        if (sel[i]) {
            double val = VAL(p, num, i);
            if (nonneg ? !(val >= 0) : !isfinite(val))
                gr_error(g, "invalid %s %g in set command", what, val);
            dst[i] = val;
            count++;
        }
    return count;
}

/* Apply the keywords in order; with dry set, only validate them (so a bad
 * keyword late in the line changes nothing). Values given as v_name are
 * checked per atom in the second pass. buf: 3 x atoms.n scratch doubles. */
static void apply(struct gravel *g, int argc, char **argv, char *sel, int *scratch, double *buf,
                  int dry)
{
    struct atoms *a = &g->atoms;
    int n = dry ? 0 : a->n;
    size_t nb = (size_t)(a->n ? a->n : 1);
    for (int k = 2; k < argc; k++) {
        const char *kw = argv[k];
        long count = 0;
        int nv = 1, shift = 0;
        struct custom_ref cref;
        char ligkw[GR_CUSTOMLEN + 4];
        if (!strcmp(kw, "property/atom")) { /* LIGGGHTS: property/atom NAME value */
            arg_need(g, argc, k, 2, kw);
            const char *nm = argv[k + 1];
            const int ck = custom_find(a, nm);
            if (ck >= 0 && !a->cus.p[ck].isint && !a->cus.p[ck].cols) {
                /* a scalar of LIGGGHTS's fix property/atom: its d_ property */
                snprintf(ligkw, sizeof ligkw, "d_%s", nm);
                kw = ligkw;
            } else if (strcmp(nm, "Temp") && strcmp(nm, "heatSource")) {
                gr_error(g, "set property/atom: unknown property '%.64s' (gravel supports Temp "
                            "and heatSource, of fix heat/gran, and the scalars of fix "
                            "property/atom NAME scalar ...)", nm);
            } else {
                kw = strcmp(nm, "Temp") ? "heatSource" : "temperature";
            }
            shift = 1;
        }
        if (!strcmp(kw, "omega") || !strcmp(kw, "image") || !strcmp(kw, "shape") ||
            !strcmp(kw, "angmom"))
            nv = 3;
        else if (!strcmp(kw, "quat"))
            nv = 4;
        else if (!strcmp(kw, "block"))
            nv = 2;
        else if (!strcmp(kw, "type/fraction") || !strcmp(kw, "type/ratio") ||
                 !strcmp(kw, "type/subset"))
            nv = 3;
        arg_need(g, argc, k + shift, nv, kw);
        char **v = argv + k + 1 + shift;
        if (!strcmp(kw, "type")) {
            double tv = 0;
            const double *p = kw_value(g, v[0], "atom type", &tv, buf, dry);
            if (!p)
                tv = arg_int_range(g, v[0], 1, a->ntypes, "atom type");
            for (int i = 0; i < n; i++)
                if (sel[i]) {
                    double t = VAL(p, tv, i);
                    if (!(t >= 1 && t <= a->ntypes))
                        gr_error(g, "type %g from %s for atom %lld is outside 1..%d", t, v[0],
                                 (long long)a->tag[i], a->ntypes);
                    a->type[i] = (int)t, count++;
                }
        } else if (!strcmp(kw, "type/fraction") || !strcmp(kw, "type/ratio")) {
            int t = arg_int_range(g, v[0], 1, a->ntypes, "atom type");
            double f = arg_double(g, v[1], "fraction");
            if (!(f >= 0 && f <= 1))
                gr_error(g, "fraction must be between 0 and 1, got %s", v[1]);
            int seed = arg_int(g, v[2], "seed");
            if (seed <= 0)
                gr_error(g, "seed must be a positive integer, got %s", v[2]);
            if (kw[5] == 'r' && seed > 900000000)
                gr_error(g, "seed must be at most 900000000 (Marsaglia generator), got %s",
                         v[2]);
            if (kw[5] == 'f') {
                struct rng_park rp;
                rng_park_init(&rp, 1);
                for (int i = 0; i < n; i++) {
                    if (!sel[i])
                        continue;
                    rng_park_reset_coord(&rp, seed, a->x + 3 * i);
                    if (rng_park_uniform(&rp) > f)
                        continue;
                    a->type[i] = t;
                    count++;
                }
            } else if (!dry) {
                long eligible = 0;
                for (int i = 0; i < n; i++)
                    eligible += sel[i] != 0;
                int64_t nsub = (int64_t)(f * (double)eligible);
                count = select_exact(g, sel, t, nsub, seed, scratch, scratch + a->n);
            }
        } else if (!strcmp(kw, "type/subset")) {
            int t = arg_int_range(g, v[0], 1, a->ntypes, "atom type");
            bigint nsub = arg_bigint(g, v[1], "subset size");
            if (nsub < 0)
                gr_error(g, "subset size must be >= 0, got %s", v[1]);
            int seed = arg_int(g, v[2], "seed");
            if (seed <= 0 || seed > 900000000)
                gr_error(g, "seed must be between 1 and 900000000, got %s", v[2]);
            if (!dry) {
                long eligible = 0;
                for (int i = 0; i < n; i++)
                    eligible += sel[i] != 0;
                if (nsub > eligible)
                    gr_error(g, "type/subset %s exceeds the %ld selected atoms", v[1],
                             eligible);
                count = select_exact(g, sel, t, nsub, seed, scratch, scratch + a->n);
            }
        } else if (!strcmp(kw, "mass")) {
            double m = 0;
            const double *p = kw_value(g, v[0], "mass", &m, buf, dry);
            if (!p)
                m = arg_positive(g, v[0], "mass");
            for (int i = 0; i < n; i++)
                if (sel[i]) {
                    if (!(VAL(p, m, i) > 0))
                        gr_error(g, "mass %g from %s for atom %lld must be positive",
                                 VAL(p, m, i), v[0], (long long)a->tag[i]);
                    a->rmass[i] = VAL(p, m, i), count++;
                    if (a->ellipsoid_flag)
                        sqe_refresh(a, i);
                }
        } else if (!strcmp(kw, "diameter")) {
            if (a->ellipsoid_flag)
                gr_error(g, "keyword 'diameter' does not apply to atom_style ellipsoid "
                            "superellipsoid: the radius is the bounding radius of the shape "
                            "(set shape, set block)");
            double d = 0;
            const double *p = kw_value(g, v[0], "diameter", &d, buf, dry);
            if (!p)
                d = arg_nonneg(g, v[0], "diameter");
            for (int i = 0; i < n; i++)
                if (sel[i]) {
                    if (!(VAL(p, d, i) >= 0))
                        gr_error(g, "diameter %g from %s for atom %lld must not be negative",
                                 VAL(p, d, i), v[0], (long long)a->tag[i]);
                    a->radius[i] = 0.5 * VAL(p, d, i), count++;
                }
        } else if (!strcmp(kw, "density") || !strcmp(kw, "density/disc")) {
            int disc = kw[7] == '/';
            if (disc && g->dom.dimension != 2)
                gr_error(g, "density/disc requires a 2d simulation (dimension 2)");
            double rv = 0;
            const double *p = kw_value(g, v[0], "density", &rv, buf, dry);
            if (!p)
                rv = arg_positive(g, v[0], "density");
            for (int i = 0; i < n; i++)
                if (sel[i]) {
                    double r = a->radius[i], rho = VAL(p, rv, i);
                    if (!(rho > 0))
                        gr_error(g, "density %g from %s for atom %lld must be positive", rho,
                                 v[0], (long long)a->tag[i]);
                    if (a->ellipsoid_flag) {
                        /* a superellipsoid's volume; rho itself for a point */
                        a->rmass[i] = has_shape(a, i)
                                          ? sqe_volume(a->shape + 3 * i, a->block + 2 * i) * rho
                                          : rho;
                        sqe_refresh(a, i);
                        count++;
                        continue;
                    }
                    a->rmass[i] = r <= 0 ? rho
                                  : disc ? M_PI * r * r * rho
                                         : 4.0 * M_PI / 3.0 * r * r * r * rho;
                    count++;
                }
        } else if (!strcmp(kw, "omega")) {
            double w[3];
            const double *p[3];
            for (int d = 0; d < 3; d++)
                p[d] = kw_value(g, v[d], "omega", &w[d], buf + (size_t)d * nb, dry);
            for (int i = 0; i < n; i++)
                if (sel[i]) {
                    for (int d = 0; d < 3; d++)
                        a->omega[3 * i + d] = VAL(p[d], w[d], i);
                    count++;
                }
        } else if (!strcmp(kw, "image")) {
            int im[3];
            for (int d = 0; d < 3; d++) {
                im[d] = arg_int(g, v[d], "image flag");
                if (im[d] != 0 && !g->dom.periodic[d])
                    gr_error(g, "cannot set a non-zero image flag in non-periodic %c",
                             "xyz"[d]);
            }
            for (int i = 0; i < n; i++)
                if (sel[i]) {
                    for (int d = 0; d < 3; d++)
                        a->image[3 * i + d] = im[d];
                    count++;
                }
        } else if ((kw[0] == 'x' || kw[0] == 'y' || kw[0] == 'z') && kw[1] == '\0') {
            /* in a periodic dimension the atom is wrapped into the box at
             * once (image flag updated), as LAMMPS' pbc() does at setup */
            int d = kw[0] - 'x';
            double cv = 0;
            const double *p = kw_value(g, v[0], kw, &cv, buf, dry);
            double len = g->dom.hi[d] - g->dom.lo[d];
            for (int i = 0; i < n; i++)
                if (sel[i]) {
                    double val = VAL(p, cv, i);
                    if (g->dom.periodic[d] && !(fabs(val - g->dom.lo[d]) <= 1e9 * len))
                        gr_error(g, "%s = %g is too far outside the periodic box to wrap", kw,
                                 val);
                    a->x[3 * i + d] = val;
                    domain_remap(g, a->x + 3 * i, a->image + 3 * i);
                    count++;
                }
        } else if ((kw[0] == 'v' && kw[1] >= 'x' && kw[1] <= 'z' && kw[2] == '\0') ||
                   (!strncmp(kw, "omega", 5) && kw[5] >= 'x' && kw[5] <= 'z' && kw[6] == '\0')) {
            /* one component: vx vy vz, LIGGGHTS's omegax omegay omegaz */
            const size_t len = strlen(kw);
            double *arr = kw[0] == 'v' ? a->v : a->omega;
            int d = kw[len - 1] - 'x';
            double val = 0;
            const double *p = kw_value(g, v[0], kw, &val, buf, dry);
            for (int i = 0; i < n; i++)
                if (sel[i])
                    arr[3 * i + d] = VAL(p, val, i), count++;
        } else if (!strcmp(kw, "mol")) {
            if (!g->atoms.molecule_flag)
                gr_error(g, "cannot set attribute mol for atom style (fix property/atom mol "
                            "first)");
            double mv = 0;
            const double *p = kw_value(g, v[0], "molecule ID", &mv, buf, dry);
            for (int i = 0; i < n; i++)
                if (sel[i]) {
                    double val = VAL(p, mv, i);
                    if (!(val >= 0 && val < 9.2e18) || val != floor(val))
                        gr_error(g, "invalid molecule ID %g in set command", val);
                    a->mol[i] = (int64_t)val;
                    count++;
                }
        } else if (!strcmp(kw, "temperature")) { /* LAMMPS 2023 Set::process_temperature */
            count = set_heat_value(g, a->temperature, v[0], "temperature", 1, sel, n, buf, dry);
        } else if (!strcmp(kw, "heatSource")) { /* LIGGGHTS: property/atom heatSource Q */
            count = set_heat_value(g, a->heatsource, v[0], "heat source", 0, sel, n, buf, dry);
        } else if (!strcmp(kw, "heatflow")) {
            gr_error(g, "keyword 'heatflow' is not settable: the heat flow is recomputed every "
                        "step from the contacts (LAMMPS's set has no heatflow keyword either)");
        } else if (custom_ref_parse(g, kw, "set", &cref, NULL)) {
            /* LAMMPS: i_name takes an integer (a variable's value is truncated to
             * one), d_name any number; i2_name[k] d2_name[k] set column k */
            const struct custom_prop *cp = &a->cus.p[cref.idx];
            double cv = 0;
            const double *p = kw_value(g, v[0], kw, &cv, buf, dry);
            if (!p)
                custom_check_value(g, a, cref.idx, cv, "set");
            for (int i = 0; i < n; i++)
                if (sel[i]) {
                    double val = VAL(p, cv, i);
                    if (p && cp->isint && isfinite(val))
                        val = trunc(val);
                    *custom_at(a, cref, i) = custom_check_value(g, a, cref.idx, val, "set");
                    count++;
                }
        } else if (!strcmp(kw, "shape")) {
            need_ellipsoid(g, kw);
            double d[3];
            const double *p[3];
            for (int q = 0; q < 3; q++)
                p[q] = kw_value(g, v[q], "shape", &d[q], buf + (size_t)q * nb, dry);
            for (int i = 0; i < n; i++)
                if (sel[i]) {
                    double x = VAL(p[0], d[0], i), y = VAL(p[1], d[1], i), z = VAL(p[2], d[2], i);
                    int zero = x == 0.0 && y == 0.0 && z == 0.0;
                    if (!(x >= 0 && y >= 0 && z >= 0) || !isfinite(x + y + z) ||
                        (!zero && (x == 0.0 || y == 0.0 || z == 0.0)))
                        gr_error(g, "invalid shape %g %g %g for atom %lld: three positive "
                                    "diameters, or 0 0 0 for a point particle",
                                 x, y, z, (long long)a->tag[i]);
                    if (zero) { /* back to a point particle */
                        memset(a->shape + 3 * i, 0, 3 * sizeof(double));
                        memset(a->block + 2 * i, 0, 2 * sizeof(double));
                        memset(a->quat + 4 * i, 0, 4 * sizeof(double));
                        memset(a->inertia + 3 * i, 0, 3 * sizeof(double));
                        a->radius[i] = 0.0;
                        count++;
                        continue;
                    }
                    if (!has_shape(a, i))
                        sqe_create(a, i);
                    a->shape[3 * i] = 0.5 * x;
                    a->shape[3 * i + 1] = 0.5 * y;
                    a->shape[3 * i + 2] = 0.5 * z;
                    sqe_refresh(a, i);
                    count++;
                }
        } else if (!strcmp(kw, "block")) {
            need_ellipsoid(g, kw);
            double b[2];
            const double *p[2];
            for (int q = 0; q < 2; q++)
                p[q] = kw_value(g, v[q], "blockiness", &b[q], buf + (size_t)q * nb, dry);
            for (int i = 0; i < n; i++)
                if (sel[i]) {
                    double n1 = VAL(p[0], b[0], i), n2 = VAL(p[1], b[1], i);
                    if (!(n1 > 0 && n2 > 0) || !isfinite(n1 + n2))
                        gr_error(g, "invalid blockiness %g %g for atom %lld: both must be "
                                    "positive", n1, n2, (long long)a->tag[i]);
                    if (!has_shape(a, i)) { /* LAMMPS: a unit-diameter body */
                        sqe_create(a, i);
                        for (int q = 0; q < 3; q++)
                            a->shape[3 * i + q] = 0.5;
                    }
                    a->block[2 * i] = n1;
                    a->block[2 * i + 1] = n2;
                    sqe_refresh(a, i);
                    count++;
                }
        } else if (!strcmp(kw, "quat")) {
            need_ellipsoid(g, kw);
            double w[4];
            const double *p[3];
            for (int q = 0; q < 3; q++)
                p[q] = kw_value(g, v[q], "quat", &w[q], buf + (size_t)q * nb, dry);
            w[3] = arg_double(g, v[3], "quat angle (degrees; a number)");
            for (int i = 0; i < n; i++)
                if (sel[i]) {
                    double *qt = quat_of(g, i);
                    double ax = VAL(p[0], w[0], i), ay = VAL(p[1], w[1], i),
                           az = VAL(p[2], w[2], i);
                    if (g->dom.dimension == 2 && (ax != 0.0 || ay != 0.0))
                        gr_error(g, "cannot set a quaternion with x or y axis components in 2d");
                    double h = M_PI_2 * w[3] / 180.0, sh = sin(h);
                    qt[0] = cos(h), qt[1] = ax * sh, qt[2] = ay * sh, qt[3] = az * sh;
                    double len = sqrt(qt[0] * qt[0] + qt[1] * qt[1] + qt[2] * qt[2] +
                                      qt[3] * qt[3]);
                    if (!(len > 0) || !isfinite(len))
                        gr_error(g, "quat %g %g %g %g is not a rotation", ax, ay, az, w[3]);
                    for (int q = 0; q < 4; q++)
                        qt[q] /= len;
                    count++;
                }
        } else if (!strcmp(kw, "quat/random")) {
            need_ellipsoid(g, kw);
            int seed = arg_int(g, v[0], "seed");
            if (seed <= 0)
                gr_error(g, "seed must be a positive integer, got %s", v[0]);
            struct rng_park rp;
            rng_park_init(&rp, 1);
            for (int i = 0; i < n; i++)
                if (sel[i]) {
                    double *qt = quat_of(g, i);
                    rng_park_reset_coord(&rp, seed, a->x + 3 * i);
                    if (g->dom.dimension == 3) {
                        double s = rng_park_uniform(&rp), t1 = sqrt(1.0 - s), t2 = sqrt(s);
                        double th1 = 2.0 * M_PI * rng_park_uniform(&rp);
                        double th2 = 2.0 * M_PI * rng_park_uniform(&rp);
                        qt[0] = cos(th2) * t2, qt[1] = sin(th1) * t1;
                        qt[2] = cos(th1) * t1, qt[3] = sin(th2) * t2;
                    } else {
                        double th2 = M_PI * rng_park_uniform(&rp);
                        qt[0] = cos(th2), qt[1] = qt[2] = 0.0, qt[3] = sin(th2);
                    }
                    count++;
                }
        } else if (!strcmp(kw, "angmom")) {
            need_ellipsoid(g, kw);
            double l[3];
            const double *p[3];
            for (int q = 0; q < 3; q++)
                p[q] = kw_value(g, v[q], "angmom", &l[q], buf + (size_t)q * nb, dry);
            for (int i = 0; i < n; i++)
                if (sel[i]) {
                    for (int q = 0; q < 3; q++)
                        a->angmom[3 * i + q] = VAL(p[q], l[q], i);
                    count++;
                }
        } else if (!strcmp(kw, "charge")) {
            gr_error(g, "keyword '%s' does not apply to atom_style sphere", kw);
        } else {
            gr_error(g, "unknown keyword '%.32s'", kw);
        }
        if (!dry)
            gr_print(g, "  %ld settings made for %s\n", count, kw);
        k += nv + shift;
    }
}

void cmd_set(struct gravel *g, int argc, char **argv)
{
    if (argc < 4)
        gr_error(g, "expected: set style ID keyword value ...");
    char *sel = gr_calloc(g, (size_t)(g->atoms.n ? g->atoms.n : 1), 1);
    int *scratch = gr_malloc(g, 2 * (size_t)(g->atoms.n ? g->atoms.n : 1) * sizeof(int));
    double *buf = malloc(3 * (size_t)(g->atoms.n ? g->atoms.n : 1) * sizeof(double));
    jmp_buf *outer = g->err.jmp, here;
    g->err.jmp = &here;
    if (setjmp(here)) {
        g->err.jmp = outer;
        free(sel);
        free(scratch);
        free(buf);
        if (outer)
            longjmp(*outer, 1);
        gr_report_error(g);
        exit(1);
    }
    select_atoms(g, argv[0], argv[1], sel);
    gr_print(g, "Setting atom values ...\n");
    if (!buf)
        gr_error(g, "out of memory");
    apply(g, argc, argv, sel, scratch, buf, 1);
    apply(g, argc, argv, sel, scratch, buf, 0);
    g->err.jmp = outer;
    free(sel);
    free(scratch);
    free(buf);
}
