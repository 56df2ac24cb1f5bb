/* fused.h - per-particle fix work fused into the scene's kernels
 * (kernels/fused.cl): the initial_integrate ops run inside nbr_check, the
 * post_force, final_integrate and end_of_step ops inside pair_gather, so a step of
 * "nve/sphere + gravity + freeze + a pair style" is three launches, not
 * seven. At run setup fused_setup() asks each fix (fix_style.fuse) for its
 * op; a stage is fused when every fix of it can be (post_force: the
 * longest prefix, in fix order; final_integrate only after a complete
 * post_force stage, end_of_step only after complete post_force and
 * final_integrate stages; when post_force fused only a prefix, the tail:
 * the post_force fixes after the last unfused one, then final_integrate
 * and end_of_step likewise, in one fused_tail launch after the unfused
 * post_force fixes), and the fused fixes' own hooks are then skipped
 * (fix->fused_hooks). Env GRAVEL_FUSE=0 turns fusion off (the results are
 * the same bit for bit: tests/scripts/determinism.py). */
#ifndef GR_FUSED_H
#define GR_FUSED_H

#include "state.h"
#include "ocl.h"
#include "fused_layout.h" /* enum fused_kind, the op layout */

/* What a fix answers for one hook: its op kind, group and parameters
 * (prm points at nprm doubles owned by the fix, read during setup); store:
 * the op keeps per-atom state in its fix's `peratom` buffer (one such fix
 * per run is fused). */
struct fused_op {
    enum fused_kind kind;
    int nprm;
    const double *prm;
    int store;
};

struct fused_stages;        /* device.h: the run's stages, engine-owned */

/* Run setup, after the fixes' init and the pair kernels: build and upload
 * the stages, mark fused fixes. */
void fused_setup(struct gravel *g);
void fused_free(struct fused_stages *s);

#endif
