/* superellipsoid_contact.c - the host's copy of the superellipsoid contact
 * geometry: the bodies of kernels/superellipsoid_geom.h (the device
 * compiles the same file). */
#define SQE_DEFINE
#include "superellipsoid_contact.h"
