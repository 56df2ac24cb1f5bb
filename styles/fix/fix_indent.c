/* fix_indent.c - `fix ID group indent K sphere x y z R | cylinder dim c1 c2
 * R | plane dim pos lo|hi [side in|out] [units lattice|box]`: LAMMPS's fix
 * indent, an indenter pushing the group's atoms with F(r) = K (r - R)^2 at
 * post_force and at a run's setup (kernels/fix_indent.cl). Every geometric
 * value may be v_name, an equal-style variable evaluated at every step (a
 * moving or growing indenter); the centre is remapped into a periodic box
 * and distances are minimum images, as LAMMPS. units lattice (default)
 * scales the numbers (not the variables) by the lattice spacings (the
 * radius by x's). Global scalar (extensive, `fix_modify energy yes` adds it
 * to pe): the indenter's energy K/3 sum |dr|^3; global vector (extensive):
 * the force on the indenter, summed over the atoms in tag order. */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "device.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "force_values.h"
#include "lattice.h"
#include "variable.h"

#define WHO "fix indent"

enum { IND_SPHERE, IND_CYLINDER, IND_PLANE };
enum { V_X, V_Y, V_Z, V_R, V_P, NV }; /* the geometric values */

struct indent {
    double k;
    int style, cdim, outside, planeside, lattice;
    double val[NV];             /* numbers (scaled), or the variables' last values */
    char *var[NV];              /* v_name, else NULL */
    cl_kernel kern;
};

static void destroy(struct fix *f)
{
    struct indent *d = f->data;
    if (d)
        for (int v = 0; v < NV; v++)
            free(d->var[v]);
    free(d);
}

static void value(struct gravel *g, struct indent *d, int v, const char *s)
{
    if (!strncmp(s, "v_", 2) && s[2])
        d->var[v] = gr_strdup(g, s + 2);
    else
        d->val[v] = arg_double(g, s, WHO " value");
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, WHO " expects K and an indenter (sphere, cylinder, plane)");
    struct indent *d = gr_calloc(g, 1, sizeof *d);
    f->data = d;
    d->k = arg_double(g, argv[0], WHO " K");
    d->style = -1;
    d->outside = 1;
    d->lattice = 1;
    for (int i = 1; i < argc;) {
        const char *kw = argv[i];
        if (!strcmp(kw, "sphere")) {
            arg_need(g, argc, i, 4, kw);
            for (int v = 0; v < 4; v++)
                value(g, d, V_X + v, argv[i + 1 + v]);
            d->style = IND_SPHERE;
            i += 5;
        } else if (!strcmp(kw, "cylinder")) {
            arg_need(g, argc, i, 4, kw);
            d->cdim = arg_axis(g, argv[i + 1], WHO " dim");
            const int c1 = d->cdim == 0 ? V_Y : V_X, c2 = d->cdim == 2 ? V_Y : V_Z;
            value(g, d, c1, argv[i + 2]);
            value(g, d, c2, argv[i + 3]);
            value(g, d, V_R, argv[i + 4]);
            d->style = IND_CYLINDER;
            i += 5;
        } else if (!strcmp(kw, "plane")) {
            arg_need(g, argc, i, 3, kw);
            d->cdim = arg_axis(g, argv[i + 1], WHO " dim");
            value(g, d, V_P, argv[i + 2]);
            if (!strcmp(argv[i + 3], "lo"))
                d->planeside = -1;
            else if (!strcmp(argv[i + 3], "hi"))
                d->planeside = 1;
            else
                gr_error(g, WHO ": plane side must be lo or hi, got '%.32s'", argv[i + 3]);
            d->style = IND_PLANE;
            i += 4;
        } else if (!strcmp(kw, "units")) {
            arg_need(g, argc, i, 1, kw);
            d->lattice = domain_parse_units_kw(g, argv[i + 1]);
            i += 2;
        } else if (!strcmp(kw, "side")) {
            arg_need(g, argc, i, 1, kw);
            if (!strcmp(argv[i + 1], "in"))
                d->outside = 0;
            else if (!strcmp(argv[i + 1], "out"))
                d->outside = 1;
            else
                gr_error(g, WHO ": side must be in or out, got '%.32s'", argv[i + 1]);
            i += 2;
        } else {
            gr_error(g, WHO ": unknown keyword '%.64s' (sphere, cylinder, plane, side, units)",
                     kw);
        }
    }
    if (d->style < 0)
        gr_error(g, WHO ": no indenter given (sphere, cylinder or plane)");
    double sc[3] = {1, 1, 1};
    domain_unit_scale(g, d->lattice, sc);
    for (int v = 0; v < 3; v++)
        if (!d->var[v])
            d->val[v] *= sc[v];
    if (!d->var[V_R])
        d->val[V_R] *= sc[0];
    if (!d->var[V_P])
        d->val[V_P] *= sc[d->cdim];
    f->hooks = HOOK_POST_FORCE;
    f->peratom_bytes = 0; /* set at init: 4 REAL per atom */
    f->sources[f->nsources++] = "fix_indent.cl";
}

static void init(struct gravel *g, struct fix *f)
{
    struct indent *d = f->data;
    for (int v = 0; v < NV; v++)
        if (d->var[v] && !var_is_equal(g, d->var[v]))
            gr_error(g, WHO " %s: variable %s %s", f->id, d->var[v],
                     var_exists(g, d->var[v]) ? "is not equal-style" : "does not exist");
    f->peratom_bytes = 4 * g->eng->rsz; /* the energy and force records of the step */
    d->kern = eng_kernel(g, "indent_post_force");
}

static void post_force(struct gravel *g, struct fix *f)
{
    struct indent *d = f->data;
    for (int v = 0; v < NV; v++)
        if (d->var[v])
            d->val[v] = var_compute_equal(g, d->var[v]);
    double c[3] = {d->val[V_X], d->val[V_Y], d->val[V_Z]};
    if (d->style == IND_CYLINDER)
        c[d->cdim] = g->dom.lo[d->cdim]; /* LAMMPS: the axis coordinate at the box */
    if (d->style == IND_PLANE) {
        c[0] = c[1] = c[2] = 0.0;
        c[d->cdim] = d->val[V_P];
    } else {
        int image[3] = {0, 0, 0};
        domain_remap(g, c, image); /* into a periodic box */
    }
    if (d->style != IND_PLANE && d->val[V_R] < 0.0)
        gr_error(g, WHO " %s: radius %g < 0 at step %lld", f->id, d->val[V_R],
                 (long long)g->step);
    struct dev_atoms *a = eng_atoms(g);
    cl_kernel k = d->kern;
    int q = 0;
    eng_arg_int(g, k, q++, a->n);
    eng_arg_uint(g, k, q++, f->groupbit);
    eng_arg_mem(g, k, q++, a->mask);
    eng_arg_mem(g, k, q++, a->x);
    eng_arg_mem(g, k, q++, a->f);
    eng_arg_mem(g, k, q++, f->peratom);
    eng_arg_int(g, k, q++, d->style);
    eng_arg_int(g, k, q++, d->cdim);
    eng_arg_int(g, k, q++, d->outside);
    eng_arg_int(g, k, q++, d->planeside);
    for (int dd = 0; dd < 3; dd++)
        eng_arg_coord(g, k, q++, dd, c[dd]);
    eng_arg_real(g, k, q++, d->val[V_R]);
    eng_arg_real(g, k, q++, d->k);
    for (int dd = 0; dd < 3; dd++)
        eng_arg_real(g, k, q++, g->dom.periodic[dd] ? g->dom.hi[dd] - g->dom.lo[dd] : 0.0);
    eng_arg_pos_lo(g, k, q);
    eng_launch(g, k, (size_t)a->n);
}

/* column c (0 energy, 1..3 the force on the indenter) summed in tag order */
static double sum_column(struct gravel *g, struct fix *f, int c)
{
    return fix_peratom_sum(g, f, 4, c);
}

static double scalar(struct gravel *g, struct fix *f) { return sum_column(g, f, 0); }

static double vector(struct gravel *g, struct fix *f, int i) { return sum_column(g, f, i); }

const struct fix_style fix_style_indent = {
    .name = "indent",
    .create = create,
    .init = init,
    .post_force = post_force,
    .destroy = destroy,
    .scalar = scalar,
    .energy_global = 1,
    .size_vector = 3,
    .vector = vector,
};
