/* compute_temp_bias.c - the temperatures of a part of the motion, as
 * LAMMPS's (src/engine/temperature.h does the sums):
 *   compute ID group temp/com              about the group's centre-of-mass velocity
 *   compute ID group temp/partial xflag yflag zflag   the components flagged 1
 *   compute ID group temp/region regionID  the group's atoms inside the region
 * each a global scalar (intensive) and the kinetic-energy tensor as a
 * 6-vector (extensive). As temperatures of thermo_modify temp, compute
 * pressure, fix temp/rescale's fix_modify temp, their bias (the centre-of-mass
 * velocity, the unflagged components, the atoms outside the region) is
 * left out of the kinetic part and kept when velocities are rescaled.
 * compute_modify extra/dof and dynamic/dof apply. */
#include <string.h>

#include "args.h"
#include "compute.h"
#include "error.h"
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
