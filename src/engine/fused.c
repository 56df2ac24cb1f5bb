/* fused.c - building the fused per-particle stages of a run (fused.h). */
#include "fused.h"

#include <stdlib.h>
#include <string.h>

#include "device.h"
#include "error.h"
#include "fix.h"

void fused_free(struct fused_stages *s)
{
    if (s->ops)
        clReleaseMemObject(s->ops);
    if (s->prm)
        clReleaseMemObject(s->prm);
    memset(s, 0, sizeof *s);
}

struct builder {
    int nops, cap;
    int *ops;
    int nprm, pcap;
    double *prm;
    struct fix *store_fix;      /* the fix whose per-atom store the ops use */
};

static void add(struct gravel *g, struct builder *b, struct fix *f, const struct fused_op *op)
{
    if (b->nops == b->cap) {
        b->cap = b->cap ? 2 * b->cap : 8;
        b->ops = gr_realloc(g, b->ops, (size_t)b->cap * FOP_W * sizeof(int));
    }
    if (b->nprm + op->nprm + 1 > b->pcap) {
        b->pcap = 2 * (b->nprm + op->nprm + 1);
        b->prm = gr_realloc(g, b->prm, (size_t)b->pcap * sizeof(double));
    }
    b->ops[FOP_W * b->nops + FOP_KIND] = (int)op->kind;
    b->ops[FOP_W * b->nops + FOP_GROUP] = (int)f->groupbit;
    b->ops[FOP_W * b->nops + FOP_PRM] = b->nprm;
    if (op->nprm > 0)
        memcpy(b->prm + b->nprm, op->prm, (size_t)op->nprm * sizeof(double));
    b->nprm += op->nprm;
    b->nops++;
}

/* How a stage takes the fixes of its hook, in fix order: every one or none
 * (TAKE_ALL), the longest run from the first (TAKE_PREFIX), or the run after
 * the last one that cannot fuse (TAKE_SUFFIX: the tail's post_force fixes).
 * At most one fused fix keeps per-atom state (store_fix). */
enum stage_take { TAKE_ALL, TAKE_PREFIX, TAKE_SUFFIX };

/* Fuse the fixes of `hook` not fused yet as `take` says; returns the number
 * fused. */
static int stage(struct gravel *g, struct builder *b, unsigned hook, enum stage_take take)
{
    struct fix *list[64];
    struct fused_op ops[64];
    int n = 0;
    struct fix *store_fix = b->store_fix;
    for (int i = 0; i < g->styles.nfix && n < 64; i++) {
        struct fix *f = g->styles.fix[i];
        if (!(f->hooks & hook) || (f->fused_hooks & hook))
            continue;
        ops[n].store = 0;
        if (f->style->fuse && f->style->fuse(g, f, hook, &ops[n]) &&
            (!ops[n].store || !store_fix || store_fix == f)) {
            if (ops[n].store)
                store_fix = f;
            list[n++] = f;
            continue;
        }
        if (take == TAKE_ALL)
            return 0;
        if (take == TAKE_PREFIX)
            break;
        n = 0; /* TAKE_SUFFIX: the run starts after this one */
        store_fix = b->store_fix;
    }
    b->store_fix = store_fix;
    for (int k = 0; k < n; k++) {
        add(g, b, list[k], &ops[k]);
        list[k]->fused_hooks |= hook;
    }
    return n;
}

static int count_hook(struct gravel *g, unsigned hook)
{
    int n = 0;
    for (int i = 0; i < g->styles.nfix; i++)
        n += (g->styles.fix[i]->hooks & hook) != 0;
    return n;
}

void fused_setup(struct gravel *g)
{
    struct engine *e = g->eng;
    struct fused_stages *s = &e->fused;
    fused_free(s);
    for (int i = 0; i < g->styles.nfix; i++)
        g->styles.fix[i]->fused_hooks = 0;
    const char *env = getenv("GRAVEL_FUSE");
    int enabled = !(env && !strcmp(env, "0"));
    s->on = enabled;
    const char *look = getenv("GRAVEL_LOOKAHEAD");
    s->lookahead = !(look && !strcmp(look, "0"));
    struct builder b = {0};
    if (enabled) {
        /* a post_integrate fix acts between the kicks and the rebuild check */
        if (!count_hook(g, HOOK_POST_INTEGRATE))
            s->ninit = stage(g, &b, HOOK_INITIAL_INTEGRATE, TAKE_ALL);
        if (e->k_pair) {
            s->npost = stage(g, &b, HOOK_POST_FORCE, TAKE_PREFIX);
            if (s->npost == count_hook(g, HOOK_POST_FORCE))
                s->nfinal = stage(g, &b, HOOK_FINAL_INTEGRATE, TAKE_ALL);
            if (s->npost == count_hook(g, HOOK_POST_FORCE) &&
                s->nfinal == count_hook(g, HOOK_FINAL_INTEGRATE))
                s->neos = stage(g, &b, HOOK_END_OF_STEP, TAKE_ALL);
            if (s->npost < count_hook(g, HOOK_POST_FORCE)) { /* the tail */
                s->tfirst = b.nops;
                s->tpost = stage(g, &b, HOOK_POST_FORCE, TAKE_SUFFIX);
                int nf = stage(g, &b, HOOK_FINAL_INTEGRATE, TAKE_ALL), ne = 0;
                if (nf == count_hook(g, HOOK_FINAL_INTEGRATE))
                    ne = stage(g, &b, HOOK_END_OF_STEP, TAKE_ALL);
                s->tfinal = nf + ne;
            }
        }
    }
    s->store_fix = b.store_fix;
    /* never empty buffers: kernels take them as arguments */
    int dummy_op[FOP_W] = {0};
    double dummy_prm = 0;
    s->ops = eng_alloc(g, (size_t)(b.nops ? b.nops : 1) * FOP_W * sizeof(int), "fused ops");
    s->prm = eng_alloc(g, (size_t)(b.nprm ? b.nprm : 1) * e->rsz, "fused op parameters");
    eng_write(g, s->ops, 0, (size_t)(b.nops ? b.nops : 1) * FOP_W * sizeof(int),
              b.nops ? b.ops : dummy_op);
    eng_write_reals(g, s->prm, (size_t)(b.nprm ? b.nprm : 1), b.nprm ? b.prm : &dummy_prm);
    free(b.ops);
    free(b.prm);
}
