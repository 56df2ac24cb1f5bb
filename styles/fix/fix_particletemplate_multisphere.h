/* fix_particletemplate_multisphere.h - the clump template of LIGGGHTS's fix
 * particletemplate/multisphere, read by fix particledistribution/discrete
 * and the insertion fixes (fix_insert.h), inserted as bodies of fix
 * multisphere (fix_rigid_small.h). */
#ifndef GR_FIX_PARTICLETEMPLATE_MULTISPHERE_H
#define GR_FIX_PARTICLETEMPLATE_MULTISPHERE_H

#include "fix_particletemplate_sphere.h"

struct molecule;

struct mstemplate {
    struct ptemplate t;         /* first: what ptemplate_of returns; t.ms points here */
    int nspheres, ntry, mstype;
    double *xs, *rs;            /* sphere centres (relative to the centre of mass), radii */
    double xmin[3], xmax[3];    /* bounding box of the spheres (same frame) */
    double rbound, xbound[3];   /* bounding sphere */
    double requiv;
    int fflag[3], tflag[3];     /* LIGGGHTS's fflag, tflag: 0 = that component held */
    /* the clump as a rigid-body template: atoms = spheres, masses M/n, centre of
     * mass at 0, the Monte-Carlo (or given) inertia tensor */
    struct molecule *mol;
};

/* Position of sphere k of clump c with its centre of mass at xcm, turned by
 * the rotation matrix rot. */
void mstemplate_sphere(const struct mstemplate *c, const double rot[3][3], const double xcm[3],
                       int k, double out[3]);

#endif
