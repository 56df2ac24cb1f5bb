/* displace_atoms.c - `displace_atoms group style args [units box|lattice]`
 * as LAMMPS 2021 (displace_atoms.cpp), atom_style sphere:
 *   move dx dy dz            add a displacement; each of dx dy dz may be
 *                            v_name of an equal-style variable (one value)
 *                            or an atom-style one (a value per atom)
 *   ramp ddim dlo dhi dim clo chi
 *                            add to coordinate ddim dlo + f (dhi - dlo),
 *                            f = (x_dim - clo) / (chi - clo) clamped to [0, 1]
 *   random dx dy dz seed     add dx (2u - 1), dy (2u - 1), dz (2u - 1) with
 *                            u drawn from RanPark reset by the seed and the
 *                            atom's coordinates (LAMMPS's per-atom reset:
 *                            the result depends on the atom alone)
 *   rotate Px Py Pz Rx Ry Rz theta
 *                            right-hand rotation by theta degrees about the
 *                            axis R through P, of the unwrapped position
 *                            (image flags reset; in 2d z is kept)
 * units lattice (the default) multiplies lengths (not the axis) by the
 * lattice spacings. Afterwards every atom is remapped into the periodic box
 * (image flags updated) and shrink-wrapped faces are refitted; an atom left
 * outside a fixed face stays (LAMMPS on one process keeps it; the next run
 * reports it). Prints "Displacing atoms ...". A displacement that puts an
 * atom at a non-finite position (a variable of 1e309, an overflow) is an
 * error naming the atom, and no atom moves. */
#include <math.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "command.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "log.h"
#include "random.h"
#include "rigid_math.h"
#include "variable.h"

static int parse_dim(struct gravel *g, const char *s, const char *what)
{
    if (!strcmp(s, "x") || !strcmp(s, "y") || !strcmp(s, "z"))
        return s[0] - 'x';
    gr_error(g, "%s must be x, y or z, got '%.32s'", what, s);
}

/* Displace dimension d of the group by a number or v_name, times scale. */
static void move_dim(struct gravel *g, unsigned bit, int d, const char *arg, double scale)
{
    struct atoms *a = &g->atoms;
    if (strncmp(arg, "v_", 2)) {
        double delta = scale * arg_double(g, arg, "displacement");
        for (int i = 0; i < a->n; i++)
            if (a->mask[i] & bit)
                a->x[3 * i + d] += delta;
        return;
    }
    const char *name = arg + 2;
    if (!var_exists(g, name))
        gr_error(g, "variable '%.32s' for displace_atoms does not exist", name);
    if (var_is_atom(g, name)) {
        double *v = var_atom_values(g, name);
        for (int i = 0; i < a->n; i++)
            if (a->mask[i] & bit)
                a->x[3 * i + d] += scale * v[i];
        free(v);
    } else {
        double delta = scale * var_compute_equal(g, name);
        for (int i = 0; i < a->n; i++)
            if (a->mask[i] & bit)
                a->x[3 * i + d] += delta;
    }
}

static void do_ramp(struct gravel *g, unsigned bit, char **argv, const double sc[3])
{
    struct atoms *a = &g->atoms;
    int dd = parse_dim(g, argv[0], "ramp displacement dimension");
    double dlo = sc[dd] * arg_double(g, argv[1], "ramp dlo");
    double dhi = sc[dd] * arg_double(g, argv[2], "ramp dhi");
    int cd = parse_dim(g, argv[3], "ramp coordinate dimension");
    double clo = sc[cd] * arg_double(g, argv[4], "ramp clo");
    double chi = sc[cd] * arg_double(g, argv[5], "ramp chi");
    for (int i = 0; i < a->n; i++) {
        if (!(a->mask[i] & bit))
            continue;
        double f = (a->x[3 * i + cd] - clo) / (chi - clo);
        f = f > 0.0 ? f : 0.0;
        f = f < 1.0 ? f : 1.0;
        a->x[3 * i + dd] += dlo + f * (dhi - dlo);
    }
}

static void do_random(struct gravel *g, unsigned bit, char **argv, const double sc[3])
{
    struct atoms *a = &g->atoms;
    double del[3];
    for (int d = 0; d < 3; d++)
        del[d] = sc[d] * arg_double(g, argv[d], "random displacement");
    int seed = arg_int(g, argv[3], "random seed");
    if (seed <= 0)
        gr_error(g, "random seed must be positive, got %s", argv[3]);
    struct rng_park r;
    rng_park_init(&r, seed);
    for (int i = 0; i < a->n; i++) {
        if (!(a->mask[i] & bit))
            continue;
        double *x = a->x + 3 * i;
        rng_park_reset_coord(&r, seed, x);
        for (int d = 0; d < 3; d++)
            x[d] += del[d] * 2.0 * (rng_park_uniform(&r) - 0.5);
    }
}

static void do_rotate(struct gravel *g, unsigned bit, char **argv, const double sc[3])
{
    struct atoms *a = &g->atoms;
    double p[3], axis[3];
    for (int d = 0; d < 3; d++) {
        p[d] = sc[d] * arg_double(g, argv[d], "rotation point");
        axis[d] = arg_double(g, argv[3 + d], "rotation axis");
    }
    double theta = arg_double(g, argv[6], "rotation angle");
    int dim = g->dom.dimension;
    if (dim == 2 && (axis[0] != 0.0 || axis[1] != 0.0))
        gr_error(g, "rotate: in 2d the axis must be along z, got %s %s %s", argv[3], argv[4],
                 argv[5]);
    double u[3];
    if (rm_unit_axis(axis, u))
        gr_error(g, "rotate: zero-length rotation axis");
    double ang = M_PI * theta / 180.0, c = cos(ang), s = sin(ang);
    for (int i = 0; i < a->n; i++) {
        if (!(a->mask[i] & bit))
            continue;
        double *x = a->x + 3 * i, xu[3];
        domain_unmap(g, x, a->image + 3 * i, xu);
        for (int d = 0; d < 3; d++)
            a->image[3 * i + d] = 0;
        /* X = P + C + A cos + (R x A) sin, C the projection on the axis */
        double dv[3] = {xu[0] - p[0], xu[1] - p[1], xu[2] - p[2]};
        double dr = dv[0] * u[0] + dv[1] * u[1] + dv[2] * u[2];
        double cp[3] = {dr * u[0], dr * u[1], dr * u[2]};
        double av[3] = {dv[0] - cp[0], dv[1] - cp[1], dv[2] - cp[2]};
        double bv[3] = {u[1] * av[2] - u[2] * av[1], u[2] * av[0] - u[0] * av[2],
                        u[0] * av[1] - u[1] * av[0]};
        for (int d = 0; d < 3; d++)
            xu[d] = p[d] + cp[d] + (av[d] * c + bv[d] * s);
        x[0] = xu[0];
        x[1] = xu[1];
        if (dim == 3)
            x[2] = xu[2];
    }
}

/* The style's displacement, then a check that every moved atom is at a
 * finite position (a displacement of 1e309 or an overflow errors). */
static void displace(struct gravel *g, unsigned bit, const char *style, char **sa,
                     const double sc[3])
{
    if (!strcmp(style, "move"))
        for (int d = 0; d < 3; d++)
            move_dim(g, bit, d, sa[d], sc[d]);
    else if (!strcmp(style, "ramp"))
        do_ramp(g, bit, sa, sc);
    else if (!strcmp(style, "random"))
        do_random(g, bit, sa, sc);
    else
        do_rotate(g, bit, sa, sc);
    const struct atoms *a = &g->atoms;
    for (int i = 0; i < a->n; i++) {
        const double *x = a->x + 3 * i;
        if ((a->mask[i] & bit) && !(isfinite(x[0]) && isfinite(x[1]) && isfinite(x[2])))
            gr_error(g, "%s would put atom %lld at a non-finite position (%g %g %g); no atom "
                        "was moved",
                     style, (long long)a->tag[i], x[0], x[1], x[2]);
    }
}

void cmd_displace_atoms(struct gravel *g, int argc, char **argv)
{
    domain_require_box(g);
    int ig = arg_group(g, argv[0]);
    const char *style = argv[1];
    int nargs;
    if (!strcmp(style, "move") || !strcmp(style, "random"))
        nargs = !strcmp(style, "move") ? 3 : 4;
    else if (!strcmp(style, "ramp"))
        nargs = 6;
    else if (!strcmp(style, "rotate"))
        nargs = 7;
    else
        gr_error(g, "unknown style '%.32s': expected move, ramp, random or rotate", style);
    if (argc < 2 + nargs)
        gr_error(g, "style %s needs %d arguments, got %d", style, nargs, argc - 2);
    int lattice = 1;
    for (int i = 2 + nargs; i < argc; i += 2) {
        if (strcmp(argv[i], "units"))
            gr_error(g, "unknown keyword '%.32s' (units)", argv[i]);
        arg_need(g, argc, i, 1, argv[i]);
        lattice = domain_parse_units_kw(g, argv[i + 1]);
    }
    double sc[3];
    domain_unit_scale(g, lattice, sc);
    gr_print(g, "Displacing atoms ...\n");
    unsigned bit = group_bit(ig);
    struct atoms *a = &g->atoms;
    /* the positions before, restored when an argument or a result is bad */
    size_t nb = (size_t)a->n * 3 + 1;
    double *x0 = gr_malloc(g, nb * sizeof(double));
    int *im0 = malloc(nb * sizeof(int));
    if (!im0) {
        free(x0);
        gr_error(g, "out of memory");
    }
    memcpy(x0, a->x, (size_t)a->n * 3 * sizeof(double));
    memcpy(im0, a->image, (size_t)a->n * 3 * sizeof(int));
    jmp_buf jb, *outer = g->err.jmp;
    g->err.jmp = &jb;
    if (setjmp(jb)) {
        g->err.jmp = outer;
        memcpy(a->x, x0, (size_t)a->n * 3 * sizeof(double));
        memcpy(a->image, im0, (size_t)a->n * 3 * sizeof(int));
        free(x0);
        free(im0);
        if (outer)
            longjmp(*outer, 1);
        gr_report_error(g);
        exit(1);
    }
    displace(g, bit, style, argv + 2, sc);
    g->err.jmp = outer;
    free(x0);
    free(im0);

    for (int i = 0; i < a->n; i++)
        domain_remap(g, a->x + 3 * i, a->image + 3 * i);
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < a->n; i++)
        for (int q = 0; q < 3; q++) {
            lo[q] = fmin(lo[q], a->x[3 * i + q]);
            hi[q] = fmax(hi[q], a->x[3 * i + q]);
        }
    domain_shrink_wrap(g, lo, hi);
}
