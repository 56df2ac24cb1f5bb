/* force_values.h - what fix setforce and fix addforce share: their fx fy fz
 * (a number, NULL: the component is left alone, or v_name: an equal-style
 * variable evaluated each time the fix applies; atom-style variables are
 * refused), the kernel that sets or adds them (kernels/fix_setforce.cl),
 * and their global vector: the group's total force before the fix at its
 * last application, summed over the atoms in tag order. */
#ifndef GR_FORCE_VALUES_H
#define GR_FORCE_VALUES_H

#include "fix.h"

struct force_values {
    double v[3];                /* the values of the last application */
    char *var[3];               /* v_name's name, else NULL */
    int on;                     /* bit d: component d is given (not NULL) */
    cl_kernel k;
};

/* fix setforce's and aveforce's arguments, fx fy fz and no keyword (LAMMPS's
 * `region` is refused), into fv; the post_force hook and the kernel file */
void force_values_create(struct gravel *g, struct fix *f, struct force_values *fv, int argc,
                         char **argv, const char *who);
/* argv[0..2] as above; NULL is allowed only with allow_null (setforce) */
void force_values_parse(struct gravel *g, struct force_values *fv, char **argv, int allow_null,
                        const char *who);
/* at init: the variables exist and are equal-style; the kernel and the
 * per-atom buffer of the forces before the fix (f->peratom) */
void force_values_init(struct gravel *g, struct fix *f, struct force_values *fv,
                       const char *who);
/* evaluate the variables, then set (add 0) or add (add 1) on the device */
void force_values_apply(struct gravel *g, struct fix *f, struct force_values *fv, int add);
/* component d (0..2) of the group's force before the fix, in tag order */
double force_values_original(struct gravel *g, struct fix *f, int d);
void force_values_free(struct force_values *fv);
/* Column col of fix f's per-atom records (f->peratom, `width` REAL per atom,
 * device order), summed over the atoms in tag order (every rank's): 0 before
 * a run has given the fix its records (LAMMPS's zeros). */
double fix_peratom_sum(struct gravel *g, struct fix *f, int width, int col);

#endif
