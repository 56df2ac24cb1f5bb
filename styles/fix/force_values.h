/* force_values.h - what fix setforce, addforce and aveforce share: their fx
 * fy fz (a number, NULL: the component is left alone, or v_name: an
 * equal-style variable evaluated each time the fix applies, or with
 * allow_atom an atom-style one: each atom's own value), LAMMPS's `region ID` keyword (only the group's
 * atoms inside the region at that moment take the force), the kernel that
 * sets or adds them (kernels/fix_setforce.cl), and their global vector: the
 * force before the fix on the atoms it acted on at its last application,
 * summed over the atoms in tag order. */
#ifndef GR_FORCE_VALUES_H
#define GR_FORCE_VALUES_H

#include "fix.h"

struct force_values {
    double v[3];                /* the values of the last application */
    char *var[3];               /* v_name's name, else NULL */
    int on;                     /* bit d: component d is given (not NULL) */
    int allow_atom;             /* atom-style variables allowed (setforce, addforce) */
    int atom[3];                /* component d is an atom-style variable (at init) */
    char *evar;                 /* addforce's `energy v_name` (atom-style), else NULL */
    /* with an atom-style variable: each atom's values (3 per atom, device
     * order) on the device, and each atom's energy of the last application
     * with its ID (addforce's scalar): -value . unwrapped x, or evar's */
    cl_mem dval;
    size_t dval_n;
    int ne;
    double *eatom;
    int64_t *etag;
    char *region;               /* `region ID`, else NULL */
    cl_uint *sel;               /* with a region: 1 for the atoms of the last application */
    cl_mem dsel;                /* its device copy, dsel_n entries */
    size_t dsel_n;
    cl_kernel k;
};

/* fix setforce's and aveforce's arguments, fx fy fz [region ID], into fv;
 * the post_force hook and the kernel file */
void force_values_create(struct gravel *g, struct fix *f, struct force_values *fv, int argc,
                         char **argv, const char *who);
/* argv[0..2] as above; NULL is allowed only with allow_null (setforce) */
void force_values_parse(struct gravel *g, struct force_values *fv, char **argv, int allow_null,
                        const char *who);
/* at init: the variables exist and are equal-style; the kernel and the
 * per-atom buffer of the forces before the fix (f->peratom) */
void force_values_init(struct gravel *g, struct fix *f, struct force_values *fv,
                       const char *who);
/* `region ID` at argv[i] (keyword, then ID): checks the region exists */
void force_values_region(struct gravel *g, struct force_values *fv, int argc, char **argv, int i,
                         const char *who);
/* 1 when an atom-style variable gives a component or the energy */
int force_values_peratom(const struct force_values *fv);
/* addforce's energy: the sum over every rank's atoms in ID order of the
 * last application's per-atom energies (force_values_peratom only) */
double force_values_energy(struct gravel *g, const struct force_values *fv);
/* force_values_prepare, then force_values_launch with the fix's own values */
void force_values_apply(struct gravel *g, struct fix *f, struct force_values *fv, int add);
/* evaluate the variables into fv->v; with a region, select the group's
 * atoms inside it now (fv->sel) */
void force_values_prepare(struct gravel *g, struct fix *f, struct force_values *fv);
/* keep the forces before the fix of the selected atoms (the group's, or
 * fv->sel) in f->peratom, then set (add 0) or add (add 1) the components of
 * bits `on` to v on the device; v NULL: the fix's own values (each atom's
 * own for the atom-style components, evaluated by force_values_prepare) */
void force_values_launch(struct gravel *g, struct fix *f, struct force_values *fv, int on,
                         const double v[3], int add);
/* 1 if atom i (device order) took the last application: in the group and,
 * with a region, in fv->sel */
int force_values_took(const struct fix *f, const struct force_values *fv, const cl_uint *mask,
                      int i);
/* component d (0..2) of the group's force before the fix, in tag order */
double force_values_original(struct gravel *g, struct fix *f, int d);
void force_values_free(struct force_values *fv);
/* Column col of fix f's per-atom records (f->peratom, `width` REAL per atom,
 * device order), summed over the atoms in tag order (every rank's): 0 before
 * a run has given the fix its records (LAMMPS's zeros). */
double fix_peratom_sum(struct gravel *g, struct fix *f, int width, int col);

#endif
