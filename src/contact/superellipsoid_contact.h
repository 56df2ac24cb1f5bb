/* superellipsoid_contact.h - the contact geometry of two superellipsoids
 * (LAMMPS 30 Mar 2026's MathExtraSuperellipsoids): the types and functions
 * of kernels/superellipsoid_geom.h, the one source the host and the device
 * share (superellipsoid_contact.c compiles its bodies for the host). */
#ifndef GR_SUPERELLIPSOID_CONTACT_H
#define GR_SUPERELLIPSOID_CONTACT_H

#include "superellipsoid_geom.h"

#endif
