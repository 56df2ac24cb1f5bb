/* lattice.c - the `lattice` command and lattice-point enumeration.
 *
 * LAMMPS semantics: `lattice style scale`; for units lj the scale is the
 * reduced density rho* and the cubic lattice constant is
 * (nbasis / (rho* V_unit))^(1/3), with V_unit the unit-cell volume of the
 * primitive vectors (1 for cubic, sqrt(8) for hcp); for other units the
 * scale is the lattice constant itself. `spacing sx sy sz` replaces the
 * per-dimension spacings by sx*a, sy*a, sz*a; `origin` shifts the basis by a
 * fraction of a cell; `orient` is accepted only with the default axes.
 * The 2d styles sq, sq2 (square with a centre atom) and hex (rectangular
 * cell a x sqrt(3) a, two atoms) need `dimension 2`, the others 3d,
 * as LAMMPS; in 2d with units lj rho* is per area, a = (nbasis/(rho* A))^(1/2),
 * and the z spacing is a (the cell's third vector is (0, 0, 1)). */
#include "lattice.h"

#include <math.h>
#include <string.h>

#include "args.h"
#include "error.h"
#include "log.h"

static void set_basis(struct lattice *lat, int n, const double b[][3])
{
    lat->nbasis = n;
    for (int m = 0; m < n; m++)
        for (int d = 0; d < 3; d++)
            lat->basis[m][d] = b[m][d];
}

void cmd_lattice(struct gravel *g, int argc, char **argv)
{
    static const double sc[1][3] = {{0, 0, 0}};
    static const double bcc[2][3] = {{0, 0, 0}, {0.5, 0.5, 0.5}};
    static const double fcc[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
    static const double sq2[2][3] = {{0, 0, 0}, {0.5, 0.5, 0}};
    static const double hcp[4][3] = {
        {0, 0, 0}, {0.5, 0.5, 0}, {0.5, 5.0 / 6.0, 0.5}, {0, 1.0 / 3.0, 0.5}};
    static const double dia[8][3] = {{0, 0, 0},          {0, 0.5, 0.5},      {0.5, 0, 0.5},
                                     {0.5, 0.5, 0},      {0.25, 0.25, 0.25}, {0.25, 0.75, 0.75},
                                     {0.75, 0.25, 0.75}, {0.75, 0.75, 0.25}};
    struct lattice lat;
    memset(&lat, 0, sizeof lat);
    const char *st = argv[0];
    double cell[3] = {1, 1, 1}; /* primitive vector lengths in units of a */
    if (!strcmp(st, "none")) {
        lat.style = LAT_NONE;
    } else if (!strcmp(st, "sc")) {
        lat.style = LAT_SC;
        set_basis(&lat, 1, sc);
    } else if (!strcmp(st, "bcc")) {
        lat.style = LAT_BCC;
        set_basis(&lat, 2, bcc);
    } else if (!strcmp(st, "fcc")) {
        lat.style = LAT_FCC;
        set_basis(&lat, 4, fcc);
    } else if (!strcmp(st, "hcp")) {
        lat.style = LAT_HCP;
        set_basis(&lat, 4, hcp);
        cell[1] = sqrt(3.0);
        cell[2] = sqrt(8.0 / 3.0);
    } else if (!strcmp(st, "diamond")) {
        lat.style = LAT_DIAMOND;
        set_basis(&lat, 8, dia);
    } else if (!strcmp(st, "sq")) {
        lat.style = LAT_SQ;
        set_basis(&lat, 1, sc);
    } else if (!strcmp(st, "sq2")) {
        lat.style = LAT_SQ2;
        set_basis(&lat, 2, sq2);
    } else if (!strcmp(st, "hex")) {
        lat.style = LAT_HEX;
        set_basis(&lat, 2, sq2);
        cell[1] = sqrt(3.0);
    } else if (!strcmp(st, "custom")) {
        gr_error(g, "lattice custom is not supported: use sc, bcc, fcc, hcp or diamond");
    } else {
        gr_error(g, "unknown lattice style '%.32s': expected none, sc, bcc, fcc, hcp, diamond, "
                    "sq, sq2 or hex", st);
    }
    int two_d = lat.style == LAT_SQ || lat.style == LAT_SQ2 || lat.style == LAT_HEX;
    if (lat.style != LAT_NONE && two_d != (g->dom.dimension == 2))
        gr_error(g, "lattice style %s is incompatible with a %dd simulation (2d: sq, sq2, hex; "
                    "3d: sc, bcc, fcc, hcp, diamond)", st, g->dom.dimension);
    if (argc < 2)
        gr_error(g, "missing scale after lattice style %s", st);
    double scale = arg_positive(g, argv[1], "lattice scale");
    if (lat.style == LAT_NONE) {
        if (argc > 2)
            gr_error(g, "lattice none takes only a scale");
        for (int d = 0; d < 3; d++)
            lat.a[d] = lat.prim[d] = scale;
        g->dom.lat = lat;
        return;
    }
    double spacing[3] = {0, 0, 0};
    int spacing_set = 0;
    for (int i = 2; i < argc; i++) {
        const char *kw = argv[i];
        if (!strcmp(kw, "origin")) {
            arg_need(g, argc, i, 3, kw);
            for (int d = 0; d < 3; d++) {
                lat.origin[d] = arg_double(g, argv[i + 1 + d], "origin");
                if (lat.origin[d] < 0 || lat.origin[d] >= 1)
                    gr_error(g, "origin values must be in [0, 1), got %s", argv[i + 1 + d]);
            }
            i += 3;
        } else if (!strcmp(kw, "spacing")) {
            arg_need(g, argc, i, 3, kw);
            for (int d = 0; d < 3; d++)
                spacing[d] = arg_positive(g, argv[i + 1 + d], "spacing");
            spacing_set = 1;
            i += 3;
        } else if (!strcmp(kw, "orient")) {
            arg_need(g, argc, i, 4, kw);
            const char *ax = argv[i + 1];
            int d = !strcmp(ax, "x") ? 0 : !strcmp(ax, "y") ? 1 : !strcmp(ax, "z") ? 2 : -1;
            if (d < 0)
                gr_error(g, "orient axis must be x, y or z, got '%.32s'", ax);
            for (int k = 0; k < 3; k++) {
                int v = arg_int(g, argv[i + 2 + k], "orient component");
                if (v != (k == d))
                    gr_error(g, "only the default orientation (orient %c with unit vector "
                                "along %c) is supported", "xyz"[d], "xyz"[d]);
            }
            i += 4;
        } else if (!strcmp(kw, "a1") || !strcmp(kw, "a2") || !strcmp(kw, "a3") ||
                   !strcmp(kw, "basis")) {
            gr_error(g, "keyword '%s' (custom lattices) is not supported", kw);
        } else {
            gr_error(g, "unknown keyword '%.32s'", kw);
        }
    }
    if (two_d && lat.origin[2] != 0.0)
        gr_error(g, "a 2d lattice needs origin z = 0");
    double a = scale;
    if (g->dom.units == UNITS_LJ) {
        /* rho* is a number density per area in 2d: a = (nbasis / (rho* A))^(1/2) */
        double vol = two_d ? cell[0] * cell[1] : cell[0] * cell[1] * cell[2];
        a = pow(lat.nbasis / vol / scale, two_d ? 0.5 : 1.0 / 3.0);
    }
    lat.scale = a;
    for (int d = 0; d < 3; d++) {
        lat.cell[d] = cell[d];
        lat.prim[d] = cell[d] * a;
        lat.a[d] = spacing_set ? spacing[d] * a : cell[d] * a;
    }
    g->dom.lat = lat;
    gr_print(g, "Lattice spacing in x,y,z = %.8g %.8g %.8g\n", lat.a[0], lat.a[1], lat.a[2]);
}

void lattice_foreach(struct gravel *g, const double lo[3], const double hi[3],
                     const double *rlo, const double *rhi, lattice_point_fn fn, void *ctx)
{
    const struct lattice *lat = &g->dom.lat;
    if (lat->style == LAT_NONE)
        gr_error(g, "no lattice is defined: use the lattice command first");
    long ilo[3], ihi[3];
    double npts = lat->nbasis;
    for (int d = 0; d < 3; d++) {
        double off = lat->origin[d] * lat->a[d];
        double l0 = rlo ? fmax(lo[d], rlo[d]) : lo[d], h0 = rhi ? fmin(hi[d], rhi[d]) : hi[d];
        if (!(l0 <= h0))
            return; /* nothing to visit */
        double l = (l0 - off) / lat->prim[d], h = (h0 - off) / lat->prim[d];
        if (!(fabs(l) < 1e12 && fabs(h) < 1e12))
            gr_error(g, "lattice range in %c (%g to %g) spans more than 1e12 lattice cells: "
                        "too many points", "xyz"[d], l0, h0);
        ilo[d] = (long)floor(l) - 1;
        ihi[d] = (long)ceil(h) + 1;
        npts *= (double)(ihi[d] - ilo[d] + 1);
    }
    if (npts > 2147483647.0)
        gr_error(g, "lattice range holds too many points (%.3g)", npts);
    for (long k = ilo[2]; k <= ihi[2]; k++)
        for (long j = ilo[1]; j <= ihi[1]; j++)
            for (long i = ilo[0]; i <= ihi[0]; i++)
                for (int m = 0; m < lat->nbasis; m++) {
                    double x[3];
                    long idx[3] = {i, j, k};
                    /* LAMMPS's lattice2box order: (cell (i + b)) scale + origin,
                     * so the coordinate bits (hashed by velocity loop geom) agree */
                    for (int d = 0; d < 3; d++) {
                        double u = idx[d] + lat->basis[m][d];
                        x[d] = (lat->cell[d] > 0 ? (lat->cell[d] * u) * lat->scale
                                                 : u * lat->prim[d]) +
                               lat->origin[d] * lat->a[d];
                    }
                    if (x[0] < lo[0] || x[0] >= hi[0] || x[1] < lo[1] || x[1] >= hi[1] ||
                        x[2] < lo[2] || x[2] >= hi[2])
                        continue;
                    fn(g, x, m, ctx);
                }
}
