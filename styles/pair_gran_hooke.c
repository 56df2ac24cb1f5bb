/* pair_gran_hooke.c - pair_style gran/hooke: LAMMPS granular contact
 * (kernels/pair_gran_hooke.cl holds the evaluator; arguments are shared with
 * the other gran styles, styles/pair_gran_common.c). */
#include "pair.h"

double pair_gran_collision_time(const struct pair *p, double m, double r, double vn);
int pair_gran_conservative(const struct pair *p);
double pair_gran_contact_energy(const struct pair *p, double delta, double reff);

const struct pair_style pair_style_gran_hooke = {
    .name = "gran/hooke",
    .source = "pair_gran_hooke.cl",
    .eval = "gran_hooke_eval",
    .history = 0,
    .rotation = 1,
    .nparam = GRAN_NPARAM,
    .settings = pair_gran_settings,
    .pack = pair_gran_pack,
    .collision_time = pair_gran_collision_time,
    .conservative = pair_gran_conservative,
    .contact_energy = pair_gran_contact_energy,
};
