/* fix_deform.h - what other fixes ask of a fix deform (styles/fix/fix_deform.c). */
#ifndef GR_FIX_DEFORM_H
#define GR_FIX_DEFORM_H

struct fix;

/* 1 when this fix deform changes box parameter p (0 x, 1 y, 2 z, 3 yz,
 * 4 xz, 5 xy; LAMMPS's dimflag), else 0. */
int fix_deform_changes(const struct fix *f, int p);

#endif
