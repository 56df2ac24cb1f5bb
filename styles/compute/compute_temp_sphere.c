/* compute_temp_sphere.c - `compute ID group temp/sphere [bias ID] [dof
 * all|rotate]`: temperature of finite-size spheres as LAMMPS' compute
 * temp/sphere: translational plus rotational kinetic energy with the
 * solid-sphere inertia 0.4 m r^2 (in 2d too), or (dof rotate) the rotational
 * part only; degrees of freedom 6 per sphere in 3d, 3 per disc in 2d (dof
 * rotate: 3 and 1; point particles count their translations only), minus
 * extra/dof in mode all (src/engine/temperature.h). Global scalar (intensive) and
 * the 6-vector of the kinetic-energy tensor (extensive). A velocity bias
 * (bias ID) is not supported. */
#include <string.h>

#include "compute.h"
#include "error.h"
#include "temperature.h"

static void create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    enum temp_kind kind = TEMP_SPHERE_ALL;
    for (int i = 0; i < argc; i++) {
        if (!strcmp(argv[i], "dof")) {
            if (i + 1 >= argc)
                gr_error(g, "compute temp/sphere: dof needs all or rotate");
            const char *v = argv[++i];
            if (!strcmp(v, "all"))
                kind = TEMP_SPHERE_ALL;
            else if (!strcmp(v, "rotate"))
                kind = TEMP_SPHERE_ROTATE;
            else
                gr_error(g, "compute temp/sphere: dof must be all or rotate, got '%.64s'", v);
        } else if (!strcmp(argv[i], "bias")) {
            gr_error(g, "compute temp/sphere: bias is not supported (no velocity-bias "
                        "temperatures)");
        } else {
            gr_error(g, "compute temp/sphere: unknown keyword '%.64s' (dof, bias)", argv[i]);
        }
    }
    temp_compute_attach(g, c, kind);
}

const struct compute_style compute_style_temp_sphere = {
    .name = "temp/sphere",
    .ranks = COMPUTE_RANKS_SUMS,
    .create = create,
    .init = temp_compute_init,
    .scalar = temp_compute_scalar,
    .vector = temp_compute_vector,
};
