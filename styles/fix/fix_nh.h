/* fix_nh.h - the hooks of the Nose-Hoover integrators (styles/fix/fix_nh.c),
 * shared by the descriptors of fix nvt, npt, nph and their /sphere forms. */
#ifndef GR_FIX_NH_H
#define GR_FIX_NH_H

#include <stddef.h>

#include "state.h"

struct fix;

void fix_nh_create(struct gravel *g, struct fix *f, int argc, char **argv);
void fix_nh_init(struct gravel *g, struct fix *f);
void fix_nh_setup(struct gravel *g, struct fix *f);
void fix_nh_initial_integrate(struct gravel *g, struct fix *f);
void fix_nh_final_integrate(struct gravel *g, struct fix *f);
void fix_nh_destroy(struct fix *f);
/* f_ID: the energy of the chains and the barostat (LAMMPS's compute_scalar) */
double fix_nh_scalar(struct gravel *g, struct fix *f);
size_t fix_nh_write_restart(struct gravel *g, struct fix *f, unsigned char *buf, size_t cap);
void fix_nh_read_restart(struct gravel *g, struct fix *f, const unsigned char *buf,
                         size_t len);

/* A descriptor of this family: the style name picks thermostat, barostat
 * and /sphere (fix_nh_create). */
#define FIX_NH_STYLE(ident, nm, fl)                                                            \
    const struct fix_style fix_style_##ident = {                                               \
        .name = nm,                                                                            \
        .flags = fl,                                                                           \
        .create = fix_nh_create,                                                               \
        .init = fix_nh_init,                                                                   \
        .setup = fix_nh_setup,                                                                 \
        .initial_integrate = fix_nh_initial_integrate,                                         \
        .final_integrate = fix_nh_final_integrate,                                             \
        .destroy = fix_nh_destroy,                                                             \
        .scalar = fix_nh_scalar,                                                               \
        .ecouple = 1,                                                                          \
        .write_restart = fix_nh_write_restart,                                                 \
        .read_restart = fix_nh_read_restart,                                                   \
    }

#endif
