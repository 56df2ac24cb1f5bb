/* feature.h - LAMMPS's feature functions of variables (Info's queries):
 * is_active(category,name), is_defined(category,ID), is_available(category,
 * name), is_file(name), is_os(regex). Word arguments, not expressions. */
#ifndef GR_FEATURE_H
#define GR_FEATURE_H

#include <stddef.h>

#include "state.h"

/* 1 when fn is one of them. */
int feature_is_function(const char *fn);
/* Its value, 0 or 1, for its n word arguments; on a bad call -1 with the
 * reason in err (LAMMPS's errors: an unknown category or name).
 * is_defined(group|region|variable, ...) is the caller's (expr.c). */
int feature_value(struct gravel *g, const char *fn, int n, char args[][GR_NAMELEN], char *err,
                  size_t errlen);

#endif
