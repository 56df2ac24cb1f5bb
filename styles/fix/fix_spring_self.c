/* fix_spring_self.c - `fix ID group spring/self K [xyz|xy|xz|yz|x|y|z]`:
 * each atom of the group tied to its position when the fix was defined by
 * a spring of stiffness K in the given components (default xyz), as
 * LAMMPS's fix spring/self (kernels/fix_spring_self.cl): every force
 * evaluation (setup included), f -= K (x_unwrapped - x0). Output: the
 * springs' energy 1/2 K sum |x - x0|^2 as a global scalar (extensive;
 * `fix_modify ID energy yes` adds it to pe), summed in atom-ID order;
 * restart files keep x0. */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atom_origin.h"
#include "device.h"
#include "error.h"
#include "fix.h"
#include "force_values.h"

struct spring_self {
    double k;
    int flags;                  /* bit 0 x, 1 y, 2 z */
    struct atom_origin x0;
    cl_kernel kern;
};

static void destroy(struct fix *f)
{
    struct spring_self *s = f->data;
    if (s)
        atom_origin_free(&s->x0);
    free(s);
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 1 || argc > 2)
        gr_error(g, "fix spring/self expects K [xyz|xy|xz|yz|x|y|z], got %d arguments", argc);
    struct spring_self *s = gr_calloc(g, 1, sizeof *s);
    f->data = s;
    s->k = arg_double(g, argv[0], "fix spring/self K");
    if (!(s->k > 0))
        gr_error(g, "fix spring/self: K must be > 0, got %g", s->k);
    static const char *const dims[] = {"x", "y", "xy", "z", "xz", "yz", "xyz"};
    s->flags = 7;
    if (argc == 2) {
        s->flags = 0;
        for (int k = 0; k < 7; k++)
            if (!strcmp(argv[1], dims[k]))
                s->flags = k + 1;
        if (!s->flags)
            gr_error(g, "fix spring/self: components must be xyz, xy, xz, yz, x, y or z, got "
                        "'%.64s'", argv[1]);
    }
    atom_origin_take(g, &s->x0, f->groupbit);
    f->hooks = HOOK_POST_FORCE;
    f->sources[f->nsources++] = "fix_spring_self.cl";
}

static void init(struct gravel *g, struct fix *f)
{
    struct spring_self *s = f->data;
    atom_origin_setup(g, &s->x0, f->groupbit, "fix spring/self", f->id);
    f->peratom_bytes = g->eng->rsz; /* each atom's k |d|^2 of the last evaluation */
    s->kern = eng_kernel(g, "spring_self");
}

static void post_force(struct gravel *g, struct fix *f)
{
    struct spring_self *s = f->data;
    atom_origin_device(g, &s->x0);
    struct dev_atoms *a = eng_atoms(g);
    const struct domain *d = &g->dom;
    cl_kernel k = s->kern;
    int i = 0;
    eng_arg_int(g, k, i++, a->n);
    eng_arg_uint(g, k, i++, f->groupbit);
    eng_arg_mem(g, k, i++, a->mask);
    eng_arg_mem(g, k, i++, a->tag);
    eng_arg_bytes(g, k, i++, sizeof(cl_long), &(cl_long){s->x0.ntab});
    eng_arg_mem(g, k, i++, s->x0.tab);
    eng_arg_mem(g, k, i++, s->x0.tablo);
    eng_arg_mem(g, k, i++, a->x);
    eng_arg_mem(g, k, i++, a->image);
    eng_arg_mem(g, k, i++, a->f);
    eng_arg_mem(g, k, i++, f->peratom);
    eng_arg_real(g, k, i++, s->k);
    eng_arg_int(g, k, i++, s->flags);
    for (int q = 0; q < 3; q++)
        eng_arg_real(g, k, i++, d->hi[q] - d->lo[q]);
    eng_arg_real(g, k, i++, d->xy);
    eng_arg_real(g, k, i++, d->xz);
    eng_arg_real(g, k, i++, d->yz);
    eng_arg_pos_lo(g, k, i);
    eng_launch(g, k, (size_t)a->n);
}

/* 1/2 sum of k |d|^2 over every rank's atoms, in atom-ID order */
static double scalar(struct gravel *g, struct fix *f)
{
    return 0.5 * fix_peratom_sum(g, f, 1, 0);
}

static size_t write_restart(struct gravel *g, struct fix *f, unsigned char *buf, size_t cap)
{
    (void)g;
    return atom_origin_write(&((struct spring_self *)f->data)->x0, buf, cap);
}

static void read_restart(struct gravel *g, struct fix *f, const unsigned char *buf, size_t len)
{
    atom_origin_read(g, &((struct spring_self *)f->data)->x0, buf, len, f->id);
}

const struct fix_style fix_style_spring_self = {
    .name = "spring/self",
    .create = create,
    .init = init,
    .post_force = post_force,
    .scalar = scalar,
    .energy_global = 1,
    .destroy = destroy,
    .write_restart = write_restart,
    .read_restart = read_restart,
};
