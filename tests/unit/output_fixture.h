/* output_fixture.h - hand-made systems and helpers for the output module's
 * unit tests (thermo, computes, dumps): a box and atoms filled directly
 * through atoms_add (no create_box/run needed), a protected call of a
 * command handler, and capture of what gr_print writes. */
#ifndef GR_OUTPUT_FIXTURE_H
#define GR_OUTPUT_FIXTURE_H

#include <stdlib.h>
#include <string.h>

#include "atoms.h"
#include "error.h"
#include "test.h"

/* A box [lo, hi] with `ntypes` types and boundary p p f. */
static inline void fx_box(struct gravel *g, const double lo[3], const double hi[3], int ntypes)
{
    g->dom.box_exists = 1;
    for (int d = 0; d < 3; d++) {
        g->dom.lo[d] = lo[d];
        g->dom.hi[d] = hi[d];
        char f = d == 2 ? 'f' : 'p';
        g->dom.bnd[d][0] = g->dom.bnd[d][1] = f;
        g->dom.periodic[d] = d != 2;
    }
    atoms_set_ntypes(g, ntypes);
}

/* Add an atom with position, velocity, omega; returns its index. */
static inline int fx_atom(struct gravel *g, int type, double x, double y, double z, double r,
                          double m, const double v[3], const double w[3])
{
    double p[3] = {x, y, z};
    int i = atoms_add(g, 0, type, p, r, m);
    for (int k = 0; k < 3; k++) {
        if (v)
            g->atoms.v[3 * i + k] = v[k];
        if (w)
            g->atoms.omega[3 * i + k] = w[k];
    }
    return i;
}

/* Define group `name` at slot k holding atoms whose index satisfies i % 2 == parity. */
static inline void fx_group_parity(struct gravel *g, int k, const char *name, int parity)
{
    g->groups.used[k] = 1;
    snprintf(g->groups.name[k], GR_NAMELEN, "%s", name);
    if (g->groups.n <= k)
        g->groups.n = k + 1;
    for (int i = 0; i < g->atoms.n; i++)
        if (i % 2 == parity)
            g->atoms.mask[i] |= 1u << k;
}

/* Call a command handler (or any function) inside an error boundary, as the
 * dispatcher does. Returns 0 on success, 1 when it raised an error (message
 * in g->err.msg). */
typedef void (*fx_cmd)(struct gravel *g, int argc, char **argv);
static inline int fx_call(struct gravel *g, fx_cmd fn, int argc, char **argv)
{
    jmp_buf jb;
    g->err.cmd = "test";
    g->err.file = "test.in";
    g->err.line = 1;
    g->err.jmp = &jb;
    g->err.msg[0] = '\0';
    if (setjmp(jb)) {
        g->err.jmp = NULL;
        return 1;
    }
    fn(g, argc, argv);
    g->err.jmp = NULL;
    return 0;
}

/* Screen capture: gr_print goes to a memory stream until fx_capture_end. */
struct fx_capture {
    char *buf;
    size_t len;
    FILE *fp;
};
static inline void fx_capture_begin(struct gravel *g, struct fx_capture *c)
{
    c->buf = NULL;
    c->len = 0;
    c->fp = open_memstream(&c->buf, &c->len);
    g->screen = c->fp;
}
/* Returns the captured text (caller frees). */
static inline char *fx_capture_end(struct gravel *g, struct fx_capture *c)
{
    fclose(c->fp);
    g->screen = NULL;
    return c->buf;
}

/* Free what the output module owns before gr_destroy: until the core's
 * styles_free calls compute_free_all/dump_free_all, tests do it. */
#include "compute.h"
#include "dump.h"
static inline void fx_destroy(struct gravel *g)
{
    dump_free_all(g);
    compute_free_all(g);
    gr_destroy(g);
}

/* CHECK_ERROR on an engine with a 10^3 box and 2 types, freed with
 * fx_destroy (test.h's version leaks computes and dumps until styles_free
 * releases them). */
#define FX_CHECK_ERROR(text, what, line)                                             \
    do {                                                                             \
        struct gravel *ge_ = test_engine();                                          \
        double lo_[3] = {0, 0, 0}, hi_[3] = {10, 10, 10};                            \
        fx_box(ge_, lo_, hi_, 2);                                                    \
        int rc_ = test_script(ge_, text);                                            \
        char where_[64];                                                             \
        snprintf(where_, sizeof where_, "(test.in:%d)", (line));                     \
        if (rc_ != GR_ERR || !strstr(ge_->err.msg, what) || !strstr(ge_->err.msg, where_)) { \
            printf("  check failed %s:%d: expected error '%s' %s, got rc %d '%s'\n", \
                   __FILE__, __LINE__, what, where_, rc_, ge_->err.msg);             \
            t_failed_checks++;                                                       \
        }                                                                            \
        fx_destroy(ge_);                                                             \
    } while (0)

#endif
