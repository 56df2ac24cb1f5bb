/* pair_gran_hooke.c - pair_style gran/hooke: LAMMPS granular contact
 * (kernels/pair_gran_hooke.cl holds the evaluator; arguments are shared with
 * the other gran styles, styles/pair/pair_gran_common.c). */
#include "pair_gran_common.h"

static void describe(const struct pair *p, struct pair_caps *c)
{
    pair_gran_describe(p, c, "pair_gran_hooke.cl", "gran_hooke_eval", "gran_hooke",
                       0);
}

const struct pair_style pair_style_gran_hooke = {
    .name = "gran/hooke",
    .nparam = GRAN_NPARAM,
    .settings = pair_gran_settings,
    .pack = pair_gran_pack,
    .describe = describe,
};
