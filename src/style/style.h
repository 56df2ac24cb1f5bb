/* style.h - release of every style instance (style.c), called by gravel.c
 * on `clear` and destroy. Each kind owns its own registry table built from
 * styles/styles.def (pair.h, fix.h, compute.h, dump.h). */
#ifndef GR_STYLE_H
#define GR_STYLE_H

struct gravel;

/* Dumps first (they publish their files), then computes, fixes, the pair. */
void styles_free(struct gravel *g);

#endif
