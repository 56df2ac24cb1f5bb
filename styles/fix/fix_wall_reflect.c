/* fix_wall_reflect.c - `fix ID group wall/reflect face arg ... [units
 * box|lattice]`: flat walls that reflect the atoms of the group, as
 * LAMMPS's fix wall/reflect: after every step's initial integration
 * (post_integrate), an atom beyond a wall is put back at its mirror image
 * and its velocity component normal to the wall reversed
 * (kernels/fix_wall_reflect.cl). Faces xlo xhi ylo yhi zlo zhi, each at
 * EDGE (the box's face now), a number or v_name (an equal-style variable,
 * evaluated every step); `units lattice` (the default) scales numbers and
 * variables by the lattice spacing of their dimension. A face may not be
 * periodic, nor z in 2d; each face once. */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "device.h"
#include "error.h"
#include "fix.h"
#include "variable.h"

enum { EDGE, CONSTANT, VARIABLE };

struct reflect_wall {
    int which;                  /* 2 dim + side: xlo 0, xhi 1, ... zhi 5 */
    int style;                  /* EDGE, CONSTANT, VARIABLE */
    double coord;               /* CONSTANT: scaled */
    char *var;                  /* VARIABLE: its name */
};

struct reflect {
    int nwall;
    struct reflect_wall wall[6];
    double scale[3];            /* units lattice: the spacings; box: 1 */
    cl_kernel k;
};

static void destroy(struct fix *f)
{
    struct reflect *r = f->data;
    if (r)
        for (int m = 0; m < r->nwall; m++)
            free(r->wall[m].var);
    free(r);
}

static const char *const faces[6] = {"xlo", "xhi", "ylo", "yhi", "zlo", "zhi"};

static int face_of(const char *s)
{
    for (int k = 0; k < 6; k++)
        if (!strcmp(s, faces[k]))
            return k;
    return -1;
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 2)
        gr_error(g, "fix wall/reflect needs a face (xlo xhi ylo yhi zlo zhi) and its position");
    struct reflect *r = gr_calloc(g, 1, sizeof *r);
    f->data = r;
    int lattice = 1;
    for (int i = 0; i < argc;) {
        int w = face_of(argv[i]);
        if (w >= 0) {
            arg_need(g, argc, i, 1, argv[i]);
            for (int m = 0; m < r->nwall; m++)
                if (r->wall[m].which == w)
                    gr_error(g, "fix wall/reflect: wall %s defined twice", faces[w]);
            if (g->dom.periodic[w / 2])
                gr_error(g, "fix wall/reflect: cannot use a wall in the periodic dimension %c",
                         "xyz"[w / 2]);
            if (w >= 4 && g->dom.dimension == 2)
                gr_error(g, "fix wall/reflect: cannot use a z wall in a 2d simulation");
            struct reflect_wall *wl = &r->wall[r->nwall++];
            wl->which = w;
            const char *a = argv[i + 1];
            if (!strcmp(a, "EDGE")) {
                wl->style = EDGE;
            } else if (!strncmp(a, "v_", 2)) {
                wl->style = VARIABLE;
                wl->var = gr_strdup(g, a + 2);
            } else {
                wl->style = CONSTANT;
                wl->coord = arg_double(g, a, "fix wall/reflect wall position");
            }
            i += 2;
        } else if (!strcmp(argv[i], "units")) {
            arg_need(g, argc, i, 1, "units");
            if (!strcmp(argv[i + 1], "box"))
                lattice = 0;
            else if (strcmp(argv[i + 1], "lattice"))
                gr_error(g, "fix wall/reflect: units must be box or lattice, got '%.64s'",
                         argv[i + 1]);
            i += 2;
        } else {
            gr_error(g, "fix wall/reflect: unknown keyword '%.64s' (xlo xhi ylo yhi zlo zhi, "
                        "units)", argv[i]);
        }
    }
    if (!r->nwall)
        gr_error(g, "fix wall/reflect needs at least one wall");
    for (int d = 0; d < 3; d++) /* LAMMPS's default lattice: spacing 1 */
        r->scale[d] = lattice && g->dom.lat.style ? g->dom.lat.a[d] : 1.0;
    for (int m = 0; m < r->nwall; m++)
        if (r->wall[m].style == CONSTANT)
            r->wall[m].coord *= r->scale[r->wall[m].which / 2];
    f->hooks = HOOK_POST_INTEGRATE;
    f->sources[f->nsources++] = "fix_wall_reflect.cl";
}

static void init(struct gravel *g, struct fix *f)
{
    struct reflect *r = f->data;
    for (int m = 0; m < r->nwall; m++) {
        const char *v = r->wall[m].var;
        if (v && !var_exists(g, v))
            gr_error(g, "fix wall/reflect %s: variable '%s' does not exist", f->id, v);
        if (v && !var_is_equal(g, v))
            gr_error(g, "fix wall/reflect %s: variable '%s' is not equal-style", f->id, v);
    }
    r->k = eng_kernel(g, "wall_reflect");
}

static void post_integrate(struct gravel *g, struct fix *f)
{
    struct reflect *r = f->data;
    struct dev_atoms *a = eng_atoms(g);
    for (int m = 0; m < r->nwall; m++) {
        const struct reflect_wall *w = &r->wall[m];
        const int dim = w->which / 2, side = w->which % 2;
        double coord = w->style == CONSTANT ? w->coord
                       : w->style == VARIABLE
                           ? var_compute_equal(g, w->var) * r->scale[dim]
                           : (side ? g->dom.hi[dim] : g->dom.lo[dim]);
        cl_kernel k = r->k;
        eng_arg_int(g, k, 0, a->n);
        eng_arg_uint(g, k, 1, f->groupbit);
        eng_arg_mem(g, k, 2, a->mask);
        eng_arg_mem(g, k, 3, a->x);
        eng_arg_mem(g, k, 4, a->v);
        eng_arg_int(g, k, 5, dim);
        eng_arg_int(g, k, 6, side);
        eng_arg_coord(g, k, 7, dim, coord);
        eng_arg_pos_lo(g, k, 8);
        eng_launch(g, k, (size_t)a->n);
    }
}

const struct fix_style fix_style_wall_reflect = {
    .name = "wall/reflect",
    .create = create,
    .init = init,
    .post_integrate = post_integrate,
    .destroy = destroy,
};
