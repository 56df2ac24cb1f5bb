/* write_data.c - `write_data file [nocoeff] [nofix] [pair ii|ij]`: the current
 * state as a LAMMPS data file for atom_style sphere (read back by read_data
 * and by LAMMPS). Numbers are written with 17 significant digits so that
 * positions, velocities and diameters survive a round trip exactly; density
 * is written as mass / (4/3 pi r^3) (mass for point particles), as LAMMPS.
 * Atoms are written in tag order. Each fix property/atom writes its section
 * after Velocities (unless nofix), as LAMMPS's FixPropertyAtom: keyword
 * "Molecules" when mol is its only property, else the fix ID (with the
 * columns as a comment), then "atom-ID values" in the fix's order: read back
 * by `read_data ... fix ID NULL keyword`. The file is written by outfile.h's rule
 * (a temporary renamed over a regular file, devices and FIFOs written
 * through), so a failed write never leaves a truncated file. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atom_custom.h"
#include "domain.h"
#include "fix.h"
#include "fix_property_atom.h"
#include "error.h"
#include "outfile.h"

static int by_tag(const void *p, const void *q, void *atoms)
{
    const int64_t *tag = ((const struct atoms *)atoms)->tag;
    int64_t a = tag[*(const int *)p], b = tag[*(const int *)q];
    return (a > b) - (a < b);
}

/* The sections of the fix property/atom commands. */
static void write_fix_sections(struct gravel *g, FILE *fp, const int *order)
{
    struct atoms *a = &g->atoms;
    for (int q = 0; q < g->styles.nfix; q++) {
        const struct fix *f = g->styles.fix[q];
        if (!property_atom_is(f))
            continue;
        struct prop_column col[256];
        int nc = property_atom_columns(g, f, col, 256);
        if (nc < 0)
            gr_error(g, "write_data: fix %s has more than 256 values per atom", f->id);
        if (nc == 1 && col[0].kind == PC_MOL) {
            fprintf(fp, "\nMolecules\n\n");
        } else {
            fprintf(fp, "\n%s #", f->id);
            for (int c = 0; c < nc; c++) {
                char buf[GR_CUSTOMLEN + 4];
                if (col[c].kind == PC_CUSTOM && col[c].ref.col > 0)
                    continue; /* an array: its name once */
                fprintf(fp, " %s", col[c].kind == PC_MOL           ? "mol"
                                   : col[c].kind == PC_TEMPERATURE ? "temperature"
                                   : col[c].kind == PC_HEATFLOW    ? "heatflow"
                                   : custom_prefixed(a, col[c].ref.idx, buf));
            }
            fprintf(fp, "\n\n");
        }
        for (int k = 0; k < a->n; k++) {
            int i = order[k];
            fprintf(fp, "%lld", (long long)a->tag[i]);
            for (int c = 0; c < nc; c++) {
                struct custom_ref ref = {col[c].ref.idx, col[c].ref.col};
                switch (col[c].kind) {
                case PC_MOL: fprintf(fp, " %lld", (long long)a->mol[i]); break;
                case PC_TEMPERATURE: fprintf(fp, " %.17g", a->temperature[i]); break;
                case PC_HEATFLOW: fprintf(fp, " %.17g", a->heatflow[i]); break;
                case PC_CUSTOM:
                    if (a->cus.p[ref.idx].isint)
                        fprintf(fp, " %d", (int)custom_get(a, ref, i));
                    else
                        fprintf(fp, " %.17g", custom_get(a, ref, i));
                    break;
                }
            }
            fputc('\n', fp);
        }
    }
}

static void write_all(struct gravel *g, FILE *fp, const int *order, int nofix)
{
    const struct atoms *a = &g->atoms;
    static const char *un[] = {"lj", "si", "cgs"};
    fprintf(fp, "LAMMPS data file via write_data, gravel %s, timestep = %lld, units = %s\n\n",
            GR_VERSION, (long long)g->step, un[g->dom.units]);
    fprintf(fp, "%d atoms\n%d atom types\n\n", a->n, a->ntypes);
    for (int d = 0; d < 3; d++)
        fprintf(fp, "%.17g %.17g %clo %chi\n", g->dom.lo[d], g->dom.hi[d], "xyz"[d], "xyz"[d]);
    if (g->dom.triclinic)
        fprintf(fp, "%.17g %.17g %.17g xy xz yz\n", g->dom.xy, g->dom.xz, g->dom.yz);
    int any_mass = 0;
    for (int t = 1; t <= a->ntypes; t++)
        any_mass |= a->type_mass[t] > 0;
    if (any_mass) {
        fprintf(fp, "\nMasses\n\n");
        for (int t = 1; t <= a->ntypes; t++)
            fprintf(fp, "%d %.17g\n", t, a->type_mass[t] > 0 ? a->type_mass[t] : 1.0);
    }
    /* LAMMPS's column order: sphere "id type diameter density x y z", hybrid
     * sphere molecular "id type x y z diameter density mol" */
    int hyb = a->style_molecular;
    fprintf(fp, hyb ? "\nAtoms # hybrid\n\n" : "\nAtoms # sphere\n\n");
    for (int k = 0; k < a->n; k++) {
        int i = order[k];
        double r = a->radius[i];
        double dens = r > 0 ? a->rmass[i] / (4.0 * M_PI / 3.0 * r * r * r) : a->rmass[i];
        const double *x = a->x + 3 * i;
        const int *im = a->image + 3 * i;
        if (hyb)
            fprintf(fp, "%lld %d %.17g %.17g %.17g %.17g %.17g %lld %d %d %d\n",
                    (long long)a->tag[i], a->type[i], x[0], x[1], x[2], 2.0 * r, dens,
                    (long long)a->mol[i], im[0], im[1], im[2]);
        else
            fprintf(fp, "%lld %d %.17g %.17g %.17g %.17g %.17g %d %d %d\n",
                    (long long)a->tag[i], a->type[i], 2.0 * r, dens, x[0], x[1], x[2], im[0],
                    im[1], im[2]);
    }
    fprintf(fp, "\nVelocities\n\n");
    for (int k = 0; k < a->n; k++) {
        int i = order[k];
        const double *v = a->v + 3 * i, *w = a->omega + 3 * i;
        fprintf(fp, "%lld %.17g %.17g %.17g %.17g %.17g %.17g\n", (long long)a->tag[i], v[0],
                v[1], v[2], w[0], w[1], w[2]);
    }
    if (!nofix)
        write_fix_sections(g, fp, order);
}

void cmd_write_data(struct gravel *g, int argc, char **argv)
{
    int nofix = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "nocoeff") || !strcmp(argv[i], "nofix")) {
            nofix |= argv[i][2] == 'f'; /* gravel writes no coefficient sections */
            continue;
        } else if (!strcmp(argv[i], "pair")) {
            arg_need(g, argc, i, 1, "pair");
            i++;
            if (strcmp(argv[i], "ii") != 0 && strcmp(argv[i], "ij") != 0)
                gr_error(g, "pair must be ii or ij, got '%.32s'", argv[i]);
        } else {
            gr_error(g, "unknown keyword '%.32s'", argv[i]);
        }
    }
    if (g->atoms.ellipsoid_flag)
        gr_error(g, "write_data with atom_style ellipsoid superellipsoid is not supported (no "
                    "Ellipsoids section is written): use write_restart");
    const char *path = argv[0];
    int *order = gr_malloc(g, (size_t)(g->atoms.n ? g->atoms.n : 1) * sizeof(int));
    struct ofile o;
    int err = of_open(&o, path, ".tmp", OF_TRUNC);
    if (err) {
        free(order);
        gr_error(g, "cannot write data file '%.200s': %s", path, strerror(err));
    }
    for (int i = 0; i < g->atoms.n; i++)
        order[i] = i;
    qsort_r(order, (size_t)g->atoms.n, sizeof(int), by_tag, &g->atoms);
    write_all(g, o.fp, order, nofix);
    free(order);
    if ((err = of_commit(&o, 0)) != 0)
        gr_error(g, "cannot write data file '%.200s': %s", path, strerror(err));
}
