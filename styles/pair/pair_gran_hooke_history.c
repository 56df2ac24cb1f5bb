/* pair_gran_hooke_history.c - pair_style gran/hooke/history: LAMMPS granular contact
 * (kernels/pair_gran_hooke_history.cl holds the evaluator; arguments are shared with
 * the other gran styles, styles/pair/pair_gran_common.c). */
#include "pair_gran_common.h"

static void describe(const struct pair *p, struct pair_caps *c)
{
    pair_gran_describe(p, c, "pair_gran_hooke_history.cl", "gran_hooke_history_eval", "gran_hooke_history",
                       1);
}

const struct pair_style pair_style_gran_hooke_history = {
    .name = "gran/hooke/history",
    .nparam = GRAN_NPARAM,
    .settings = pair_gran_settings,
    .pack = pair_gran_pack,
    .describe = describe,
};
