/* replicate.c - `replicate nx ny nz [bbox]` as LAMMPS 2021 (replicate.cpp),
 * orthogonal boxes, one process:
 * the box grows to lo + n (hi - lo) per dimension (shrink-wrapped faces
 * expanded by LAMMPS's small margin, as a new box); for ix, then iy, then iz
 * (iz innermost), every atom in storage order is copied to its unwrapped
 * position plus (ix Lx, iy Ly, iz Lz), remapped into the new box with image
 * flags counted from zero, and given the ID old + (iz ny nx + iy nx + ix)
 * maxID (maxID the largest existing ID). Type, group bits, radius, mass,
 * velocity and angular velocity are carried. A copy outside a non-periodic
 * face of the new box is an error (LAMMPS: "did not assign all atoms"),
 * raised before anything changes; so is a grid of more than 2147483647
 * copies, with or without atoms. Replicating a non-periodic dimension
 * warns; nz > 1 in 2d is an error. `bbox` is accepted (the same result on
 * one process). Prints LAMMPS's lines: the new box and the atom count. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "command.h"
#include "domain.h"
#include "error.h"
#include "log.h"

void cmd_replicate(struct gravel *g, int argc, char **argv)
{
    domain_require_box(g);
    int nrep[3];
    for (int d = 0; d < 3; d++) {
        nrep[d] = arg_int(g, argv[d], "replication count");
        if (nrep[d] <= 0)
            gr_error(g, "illegal replication grid %sx%sx%s: every count must be > 0", argv[0],
                     argv[1], argv[2]);
    }
    if (argc == 4 && strcmp(argv[3], "bbox"))
        gr_error(g, "unknown keyword '%.32s' (bbox)", argv[3]);
    struct domain *dm = &g->dom;
    if (dm->dimension == 2 && nrep[2] != 1)
        gr_error(g, "cannot replicate a 2d simulation in z (nz must be 1)");
    /* the copy count is an int, as in LAMMPS; checked in double (three ints
     * overflow a long long), before any loop over the copies */
    double nrd = (double)nrep[0] * nrep[1] * nrep[2];
    struct atoms *a = &g->atoms;
    int n0 = a->n;
    if (nrd > 2147483647.0)
        gr_error(g, "the replicated system is too big (%.0f copies of the box, at most "
                    "2147483647)", nrd);
    long long nr = (long long)nrd;
    if (nr * n0 > 200000000LL)
        gr_error(g, "the replicated system is too big (%lld atoms)", nr * n0);
    gr_print(g, "Replicating atoms ...\n");
    for (int d = 0; d < 3; d++)
        if (nrep[d] > 1 && !dm->periodic[d]) {
            gr_warn(g, "Replicating in a non-periodic dimension");
            break;
        }
    int64_t maxtag = 0;
    for (int i = 0; i < n0; i++)
        maxtag = a->tag[i] > maxtag ? a->tag[i] : maxtag;
    if (maxtag + (nr - 1) * (long long)n0 >= INT64_MAX / 2)
        gr_error(g, "replicated atom IDs are too big");

    /* the new box, kept aside until every copy is known to fit */
    struct domain old = *dm, nb = *dm;
    double prd[3];
    for (int d = 0; d < 3; d++) {
        prd[d] = old.hi[d] - old.lo[d];
        nb.hi[d] = old.lo[d] + nrep[d] * prd[d];
        /* the limits of create_box */
        if (!(nb.hi[d] - nb.lo[d] < 1e19) || !(fabs(nb.hi[d]) < DOMAIN_BIG))
            gr_error(g, "replicating %d times in %c makes the box %g to %g, a length of %g: "
                        "too large (a box length must be below 1e19, its bounds within +-1e20)",
                     nrep[d], "xyz"[d], nb.lo[d], nb.hi[d], nb.hi[d] - nb.lo[d]);
    }
    *dm = nb;
    domain_set_initial_box(g);
    nb = *dm;
    *dm = old;

    int ntot = (int)(nr * n0);
    double *nx = malloc(((size_t)ntot + 1) * 3 * sizeof(double));
    int *nim = malloc(((size_t)ntot + 1) * 3 * sizeof(int));
    if (!nx || !nim) {
        free(nx);
        free(nim);
        gr_error(g, "out of memory");
    }
    int k = 0, bad = -1;
    for (int ix = 0; ix < nrep[0] && n0 > 0; ix++) /* no atoms: only the box grows */
        for (int iy = 0; iy < nrep[1]; iy++)
            for (int iz = 0; iz < nrep[2]; iz++)
                for (int i = 0; i < n0; i++, k++) {
                    double xu[3];
                    int off[3] = {ix, iy, iz};
                    *dm = old;
                    domain_unmap(g, a->x + 3 * i, a->image + 3 * i, xu);
                    for (int d = 0; d < 3; d++) {
                        nx[3 * k + d] = xu[d] + off[d] * prd[d];
                        nim[3 * k + d] = 0;
                    }
                    *dm = nb;
                    domain_remap(g, nx + 3 * k, nim + 3 * k);
                    for (int d = 0; d < 3; d++) {
                        double eps = nb.periodic[d] ? (nb.hi[d] - nb.lo[d]) * 1e-6 : 0.0;
                        double x = nx[3 * k + d];
                        if (!(x >= nb.lo[d] - eps && x < nb.hi[d] + eps) && bad < 0)
                            bad = k;
                    }
                }
    *dm = old;
    if (bad >= 0) {
        int i = bad % (n0 > 0 ? n0 : 1);
        double p[3] = {nx[3 * bad], nx[3 * bad + 1], nx[3 * bad + 2]};
        free(nx);
        free(nim);
        gr_error(g, "a copy of atom %lld at (%g %g %g) lies outside the new box's non-periodic "
                    "faces (LAMMPS: Replicate did not assign all atoms correctly)",
                 (long long)a->tag[i], p[0], p[1], p[2]);
    }

    /* commit: grow, then fill copies from the back so originals stay intact */
    atoms_reserve(g, ntot > 0 ? ntot : 1);
    for (int c = (int)nr - 1; c >= 0 && n0 > 0; c--) {
        int iz = c % nrep[2], iy = (c / nrep[2]) % nrep[1], ix = c / (nrep[2] * nrep[1]);
        int64_t toff = ((int64_t)iz * nrep[1] * nrep[0] + (int64_t)iy * nrep[0] + ix) * maxtag;
        for (int i = n0 - 1; i >= 0; i--) {
            int j = c * n0 + i;
            a->tag[j] = a->tag[i] + toff;
            a->type[j] = a->type[i];
            a->mask[j] = a->mask[i];
            a->radius[j] = a->radius[i];
            a->rmass[j] = a->rmass[i];
            for (int d = 0; d < 3; d++) {
                a->v[3 * j + d] = a->v[3 * i + d];
                a->omega[3 * j + d] = a->omega[3 * i + d];
                a->f[3 * j + d] = a->torque[3 * j + d] = 0.0;
                a->x[3 * j + d] = nx[3 * j + d];
                a->image[3 * j + d] = nim[3 * j + d];
            }
            if (a->cus.slots) /* custom properties: the copies carry the values */
                memcpy(a->custom + (size_t)j * a->cus.slots,
                       a->custom + (size_t)i * a->cus.slots,
                       (size_t)a->cus.slots * sizeof(double));
        }
    }
    free(nx);
    free(nim);
    a->n = ntot;
    a->maxtag = 0;
    for (int i = 0; i < a->n; i++)
        a->maxtag = a->tag[i] > a->maxtag ? a->tag[i] : a->maxtag;
    *dm = nb;
    gr_print(g, "  orthogonal box = (%.8g %.8g %.8g) to (%.8g %.8g %.8g)\n", dm->lo[0], dm->lo[1],
             dm->lo[2], dm->hi[0], dm->hi[1], dm->hi[2]);
    gr_print(g, "  %d atoms\n", a->n);
}
