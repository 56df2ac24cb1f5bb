/* styles.h - release functions of the style-owning modules, called by
 * gravel.c on `clear` and destroy. Each module owns its own registry table
 * built from styles/styles.def. */
#ifndef GR_STYLES_H
#define GR_STYLES_H

#include "state.h"

void styles_free(struct gravel *g);                     /* pair, fixes, computes, dumps */
void regions_free(struct gravel *g);                    /* region.c */
void thermo_settings_free(struct thermo_settings *t);   /* thermo settings strings */

#endif
