/* wall.c - host side of the wall stage of the contact pipeline
 * (kernels/wall.cl): element counts and the one place where a wall kernel's
 * arguments are bound and launched. */
#include "wall.h"

#include "engine.h"
#include "error.h"
#include "fix.h"
#include "pair.h"

int wall_elements(const struct wall_geom *w) { return w->kind == WALL_PLANE ? 2 : 1; }

size_t wall_peratom_bytes(struct gravel *g, const struct wall_geom *w, const struct wall_law *law)
{
    return law->history ? (size_t)wall_elements(w) * 3 * g->eng->rsz : 0;
}

void wall_apply(struct gravel *g, struct fix *f, const struct wall_geom *w,
                const struct wall_law *law)
{
    struct engine *e = g->eng;
    struct dev_atoms *a = eng_atoms(g);
    cl_kernel k = law->kernel;
    int nt = g->atoms.ntypes > 0 ? g->atoms.ntypes : 1;
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
    eng_arg_mem(g, k, i++, law->history ? f->peratom : a->f);
    eng_arg_int(g, k, i++, law->history);
    eng_arg_mem(g, k, i++, law->param);
    eng_arg_int(g, k, i++, nt);
    eng_arg_int(g, k, i++, law->by_type ? g->styles.pair->style->nparam : 0);
    eng_arg_int(g, k, i++, law->by_type);
    eng_arg_int(g, k, i++, wall_elements(w));
    eng_arg_int(g, k, i++, (int)w->kind);
    eng_arg_int(g, k, i++, w->axis);
    eng_arg_real(g, k, i++, w->lo);
    eng_arg_real(g, k, i++, w->hi);
    eng_arg_real(g, k, i++, w->radius);
    for (int d = 0; d < 3; d++)
        eng_arg_real(g, k, i++, w->v[d]);
    eng_arg_int(g, k, i++, w->cyl_shear);
    eng_arg_real(g, k, i++, w->vshear);
    eng_arg_real(g, k, i++, g->dt);
    eng_arg_int(g, k, i++, !eng_in_setup(g));
    eng_arg_int(g, k, i++, law->inclusive);
    eng_launch(g, k, (size_t)a->n);
}
