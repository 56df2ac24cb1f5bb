/* fix_wall_pair.c - `fix ID group wall/pair xplane|yplane|zplane lo hi`:
 * flat, stationary walls whose contact law is the active pair style
 * (kernels/fix_wall_pair.cl). The pair evaluator (PAIR_EVAL) sees the wall as
 * particle j with the contract of src/pair.h: radj = 0, radsum = reff = radi,
 * omega_j = 0, v_j = 0, meff = m_i (the wall is infinitely heavy), and the
 * parameters of type pair (itype, itype). lo or hi may be NULL (no face).
 * Like LAMMPS fix wall/gran, only the nearer face acts on a particle; with a
 * history pair style the contact history of that face is kept per atom.
 * fix wall/gran keeps the LAMMPS models; this fix gives every pair style of
 * gravel (linear/restitution, hertz/mindlin, ...) a wall with the same law. */
#include <string.h>

#include "args.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "pair.h"

#define WALL_PAIR_BIG 1.0e20

struct wallp {
    int dim;
    double lo, hi;
    cl_kernel k;
};

static double face(struct gravel *g, const char *s, double null_value, const char *what)
{
    return !strcmp(s, "NULL") ? null_value : arg_double(g, s, what);
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc != 3)
        gr_error(g, "fix wall/pair expects xplane|yplane|zplane lo hi, got %d argument(s)",
                 argc);
    struct wallp *w = gr_calloc(g, 1, sizeof *w);
    f->data = w;
    if (!strcmp(argv[0], "xplane"))
        w->dim = 0;
    else if (!strcmp(argv[0], "yplane"))
        w->dim = 1;
    else if (!strcmp(argv[0], "zplane"))
        w->dim = 2;
    else
        gr_error(g, "unknown fix wall/pair wall style '%.64s' (expected xplane, yplane or "
                    "zplane)", argv[0]);
    w->lo = face(g, argv[1], -WALL_PAIR_BIG, "wall lo position");
    w->hi = face(g, argv[2], WALL_PAIR_BIG, "wall hi position");
    if (!(w->lo < w->hi))
        gr_error(g, "fix wall/pair %s: lo (%g) must be below hi (%g)", argv[0], w->lo, w->hi);
    if (w->lo == -WALL_PAIR_BIG && w->hi == WALL_PAIR_BIG)
        gr_error(g, "fix wall/pair %s: lo and hi are both NULL (no wall)", argv[0]);
    f->hooks = HOOK_POST_FORCE;
    f->sources[f->nsources++] = "fix_wall_pair.cl";
}

static void init(struct gravel *g, struct fix *f)
{
    struct wallp *w = f->data;
    if (!g->styles.pair)
        gr_error(g, "fix %s wall/pair needs a pair style: the wall uses its contact law",
                 f->id);
    w->k = eng_kernel(g, "wall_pair");
    f->peratom_bytes = g->eng->history ? 3 * g->eng->rsz : 0;
}

static void post_force(struct gravel *g, struct fix *f)
{
    struct wallp *w = f->data;
    struct engine *e = g->eng;
    struct dev_atoms *a = eng_atoms(g);
    cl_kernel k = w->k;
    int i = 0;
    eng_arg_int(g, k, i++, a->n);
    eng_arg_uint(g, k, i++, f->groupbit);
    eng_arg_mem(g, k, i++, a->mask);
    eng_arg_mem(g, k, i++, a->x);
    eng_arg_mem(g, k, i++, a->v);
    eng_arg_mem(g, k, i++, e->rotation ? a->omega : a->v);
    eng_arg_mem(g, k, i++, a->radius);
    eng_arg_mem(g, k, i++, a->rmass);
    eng_arg_mem(g, k, i++, a->type);
    eng_arg_mem(g, k, i++, a->f);
    eng_arg_mem(g, k, i++, e->rotation ? a->torque : a->f);
    eng_arg_mem(g, k, i++, e->history ? f->peratom : a->v);
    eng_arg_mem(g, k, i++, e->pair_param);
    eng_arg_int(g, k, i++, g->atoms.ntypes > 0 ? g->atoms.ntypes : 1);
    eng_arg_int(g, k, i++, g->styles.pair->style->nparam);
    eng_arg_int(g, k, i++, w->dim);
    eng_arg_real(g, k, i++, w->lo);
    eng_arg_real(g, k, i++, w->hi);
    eng_arg_real(g, k, i++, g->dt);
    eng_arg_int(g, k, i++, eng_in_setup(g) ? 0 : 1);
    eng_launch(g, k, (size_t)a->n);
}

const struct fix_style fix_style_wall_pair = {
    .name = "wall/pair",
    .create = create,
    .init = init,
    .post_force = post_force,
};
