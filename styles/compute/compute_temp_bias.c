/* compute_temp_bias.c - the temperatures of a part of the motion, as
 * LAMMPS's (src/engine/temperature.h does the sums):
 *   compute ID group temp/com              about the group's centre-of-mass velocity
 *   compute ID group temp/partial xflag yflag zflag   the components flagged 1
 *   compute ID group temp/region regionID  the group's atoms inside the region
 *   compute ID group temp/profile xflag yflag zflag x|y|z|xy|yz|xz|xyz Nx.. [out tensor|bin]
 *                                          about the mean velocity of each of
 *                                          Nx Ny Nz bins of the box (of the
 *                                          flagged components)
 * each a global scalar (intensive) and the kinetic-energy tensor as a
 * 6-vector (extensive); temp/profile out bin: instead of the vector, an
 * array of a row per bin (x fastest, then y, z): its atom count and its
 * temperature, dof = dim count - extra/dof (LAMMPS's). As temperatures of thermo_modify temp, compute
 * pressure, fix temp/rescale's fix_modify temp, their bias (the centre-of-mass
 * velocity, the unflagged components, the atoms outside the region) is
 * left out of the kinetic part and kept when velocities are rescaled.
 * compute_modify extra/dof and dynamic/dof apply. */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "compute.h"
#include "error.h"
#include "par_sum.h"
#include "region.h"
#include "temperature.h"

static void com_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    (void)argv;
    if (argc != 0)
        gr_error(g, "compute temp/com takes no arguments after the style, got %d", argc);
    temp_compute_attach(g, c, TEMP_COM);
}

static void partial_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc != 3)
        gr_error(g, "compute temp/partial expects xflag yflag zflag (0 or 1), got %d arguments",
                 argc);
    temp_compute_attach(g, c, TEMP_PARTIAL);
    for (int d = 0; d < 3; d++) {
        const int f = arg_int(g, argv[d], "compute temp/partial flag");
        if (f != 0 && f != 1)
            gr_error(g, "compute temp/partial: flags must be 0 or 1, got %d", f);
        c->temp->flags[d] = f;
    }
    if (c->temp->flags[2] && g->dom.dimension == 2)
        gr_error(g, "compute temp/partial cannot use the z dimension (zflag) for 2d systems");
}

/* the temperature's region test (temperature.c does not know regions) */
static int inside(const void *r, const double x[3])
{
    return region_match(r, x);
}

static void resolve(struct gravel *g, struct compute *c)
{
    c->temp->region_obj = region_get(g, c->temp->region);
    c->temp->region_in = inside;
}

static void region_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc != 1)
        gr_error(g, "compute temp/region expects a region ID, got %d arguments", argc);
    if (strlen(argv[0]) >= GR_NAMELEN)
        gr_error(g, "compute temp/region: region ID '%.64s...' is too long", argv[0]);
    region_get(g, argv[0]);
    temp_compute_attach(g, c, TEMP_REGION);
    strcpy(c->temp->region, argv[0]);
    resolve(g, c);
}

/* the region may have been deleted or redefined since */
static void region_init(struct gravel *g, struct compute *c)
{
    resolve(g, c);
    temp_compute_init(g, c);
}

/* every evaluation looks the region up again (it may be gone since) */
static double region_scalar(struct gravel *g, struct compute *c)
{
    resolve(g, c);
    return temp_compute_scalar(g, c);
}

static void region_vector(struct gravel *g, struct compute *c)
{
    resolve(g, c);
    temp_compute_vector(g, c);
}

static void profile_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc < 5)
        gr_error(g, "compute temp/profile expects xflag yflag zflag binstyle N.. [out "
                    "tensor|bin], got %d arguments", argc);
    temp_compute_attach(g, c, TEMP_PROFILE);
    struct temp_state *t = c->temp;
    for (int d = 0; d < 3; d++) {
        const int f = arg_int(g, argv[d], "compute temp/profile flag");
        if (f != 0 && f != 1)
            gr_error(g, "compute temp/profile: flags must be 0 or 1, got %d", f);
        t->flags[d] = f;
        t->nbin[d] = 1;
    }
    const int twod = g->dom.dimension == 2;
    if (t->flags[2] && twod)
        gr_error(g, "compute temp/profile cannot use vz for 2d systems");
    const char *st = argv[3];
    const int n = (int)strlen(st);
    if (n < 1 || n > 3 || strspn(st, "xyz") != (size_t)n ||
        !(!strcmp(st, "x") || !strcmp(st, "y") || !strcmp(st, "z") || !strcmp(st, "xy") ||
          !strcmp(st, "yz") || !strcmp(st, "xz") || !strcmp(st, "xyz")))
        gr_error(g, "compute temp/profile: binstyle must be x, y, z, xy, yz, xz or xyz, got "
                    "'%.16s'", st);
    if (argc < 4 + n)
        gr_error(g, "compute temp/profile %s expects %d bin counts", st, n);
    if (twod && strchr(st, 'z'))
        gr_error(g, "compute temp/profile cannot bin z for 2d systems");
    for (int k = 0; k < n; k++)
        t->nbin[st[k] - 'x'] = arg_int_range(g, argv[4 + k], 1, 1 << 20, "bin count");
    if ((double)t->nbin[0] * t->nbin[1] * t->nbin[2] > (double)(1 << 24))
        gr_error(g, "compute temp/profile: too many bins");
    int bins = 0;
    for (int i = 4 + n; i < argc; i += 2) {
        if (strcmp(argv[i], "out"))
            gr_error(g, "compute temp/profile: unknown keyword '%.32s' (out)", argv[i]);
        arg_need(g, argc, i, 1, "out");
        if (!strcmp(argv[i + 1], "tensor"))
            bins = 0;
        else if (!strcmp(argv[i + 1], "bin"))
            bins = 1;
        else
            gr_error(g, "compute temp/profile: out must be tensor or bin, got '%.32s'",
                     argv[i + 1]);
    }
    if (bins) { /* LAMMPS: the array instead of the tensor */
        c->vector_flag = 0;
        c->size_vector = 0;
        c->array_flag = 1;
        c->size_array_cols = 2;
        c->extarray = 0;
    }
}

/* out bin: each bin's count and temperature (its own dof: dim count - extra/dof) */
static void profile_array(struct gravel *g, struct compute *c)
{
    struct temp_state *t = c->temp;
    const struct atoms *a = &g->atoms;
    const int nb = temp_profile_nbins(t);
    int *bin = temp_profile_bins(g, t);
    double *mean = temp_profile_means(g, t, bin);
    const int *order = atoms_tag_order(g);
    struct par_sum *s = gr_calloc(g, (size_t)nb, sizeof *s);
    for (int k = 0; k < a->n; k++) {
        const int i = order[k];
        if (bin[i] < 0)
            continue;
        double u[3];
        for (int d = 0; d < 3; d++)
            u[d] = a->v[3 * i + d] - temp_profile_bias(t, bin, mean, i, d);
        par_sum_add(g, &s[bin[i]], a->tag[i], (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) *
                                                 a->rmass[i]);
    }
    double *out = compute_array_rows(g, c, nb);
    const int dim = g->dom.dimension;
    const double extra = t->extra_set ? t->extra_dof : dim;
    for (int j = 0; j < nb; j++) {
        const double sum = par_sum_total(g, &s[j]), count = mean[4 * j + 3];
        const double dof = dim * count - extra;
        out[2 * j] = count;
        out[2 * j + 1] = count > 0.0 && dof > 0 ? compute_mvv2e(g) / (dof * temp_boltz(g)) * sum
                                                : 0.0;
    }
    free(s);
    free(bin);
    free(mean);
}

const struct compute_style compute_style_temp_profile = {
    .name = "temp/profile",
    .ranks = COMPUTE_RANKS_SUMS,
    .create = profile_create,
    .init = temp_compute_init,
    .scalar = temp_compute_scalar,
    .vector = temp_compute_vector,
    .array = profile_array,
};

const struct compute_style compute_style_temp_com = {
    .name = "temp/com",
    .ranks = COMPUTE_RANKS_SUMS,
    .create = com_create,
    .init = temp_compute_init,
    .scalar = temp_compute_scalar,
    .vector = temp_compute_vector,
};

const struct compute_style compute_style_temp_partial = {
    .name = "temp/partial",
    .ranks = COMPUTE_RANKS_SUMS,
    .create = partial_create,
    .init = temp_compute_init,
    .scalar = temp_compute_scalar,
    .vector = temp_compute_vector,
};

const struct compute_style compute_style_temp_region = {
    .name = "temp/region",
    .ranks = COMPUTE_RANKS_SUMS,
    .create = region_create,
    .init = region_init,
    .scalar = region_scalar,
    .vector = region_vector,
};
