/* pair_gran_hooke_history.c - pair_style gran/hooke/history: LAMMPS granular contact
 * (kernels/pair_gran_hooke_history.cl holds the evaluator; arguments are shared with
 * the other gran styles, styles/pair_gran_common.c). */
#include "pair.h"

double pair_gran_collision_time(const struct pair *p, double m, double r, double vn);
int pair_gran_conservative(const struct pair *p);
double pair_gran_contact_energy(const struct pair *p, double delta, double reff);

const struct pair_style pair_style_gran_hooke_history = {
    .name = "gran/hooke/history",
    .source = "pair_gran_hooke_history.cl",
    .eval = "gran_hooke_history_eval",
    .history = 1,
    .rotation = 1,
    .nparam = GRAN_NPARAM,
    .settings = pair_gran_settings,
    .pack = pair_gran_pack,
    .collision_time = pair_gran_collision_time,
    .conservative = pair_gran_conservative,
    .contact_energy = pair_gran_contact_energy,
};
