/* fix_damping_cundall.c - `fix ID group damping/cundall gamma_l gamma_a
 * [scale type ratio ...] | [scale v_name]`: Cundall's non-viscous damping
 * as today's LAMMPS's fix damping/cundall (GRANULAR package; Cundall 1987,
 * as in Yade and PFC): at post_force, each component k of an atom's force
 * becomes f_k (1 - gamma_l s_k), s_k = 1 if f_k v_k >= 0 else -1, and of
 * its torque t_k (1 - gamma_a s_k) with omega_k (kernels/fix_damping_cundall.cl).
 * gamma_l and gamma_a are times the atom type's ratio (`scale type ratio`,
 * 1 otherwise) or the value of an atom-style variable (`scale v_name`,
 * evaluated on the host at every step, as LAMMPS does). It damps the force
 * as it stands when the fix runs: a post_force fix after it (fix gravity,
 * addforce) is not damped, and LAMMPS's warning names it. Not fused into
 * the gather kernel: one launch per step. */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "device.h"
#include "error.h"
#include "fix.h"
#include "variable.h"

#define WHO "fix damping/cundall"

struct cundall {
    double gl, ga;
    int ntypes;
    double *ratio;       /* [ntypes] (scale type ratio; 1 by default) */
    char *var;           /* scale v_name, else NULL */
    double *scale;       /* the variable's values, host order */
    cl_mem gam, dscale;
    size_t dscale_n;
    cl_kernel k;
};

static void destroy(struct fix *f)
{
    struct cundall *c = f->data;
    if (c) {
        if (c->gam)
            clReleaseMemObject(c->gam);
        if (c->dscale)
            clReleaseMemObject(c->dscale);
        free(c->ratio);
        free(c->var);
        free(c->scale);
        free(c);
    }
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 2)
        gr_error(g, WHO " expects gamma_l gamma_a [scale type ratio | scale v_name], got %d "
                    "arguments", argc);
    if (g->atoms.ntypes < 1)
        gr_error(g, WHO " needs atom types (create the box first)");
    struct cundall *c = gr_calloc(g, 1, sizeof *c);
    f->data = c;
    c->gl = arg_double(g, argv[0], WHO " gamma_l");
    c->ga = arg_double(g, argv[1], WHO " gamma_a");
    c->ntypes = g->atoms.ntypes;
    c->ratio = gr_malloc(g, (size_t)c->ntypes * sizeof *c->ratio);
    for (int t = 0; t < c->ntypes; t++)
        c->ratio[t] = 1.0;
    int bytype = 0;
    for (int i = 2; i < argc;) {
        if (strcmp(argv[i], "scale"))
            gr_error(g, "unknown " WHO " keyword '%.64s' (scale)", argv[i]);
        arg_need(g, argc, i, 1, "scale");
        if (!strncmp(argv[i + 1], "v_", 2)) {
            if (bytype || c->var)
                gr_error(g, WHO ": must use only one style of scaling");
            c->var = gr_strdup(g, argv[i + 1] + 2);
            var_check_atom(g, c->var, WHO " scale");
            i += 2;
        } else {
            if (c->var)
                gr_error(g, WHO ": must use only one style of scaling");
            arg_need(g, argc, i, 2, "scale");
            const int t = arg_int_range(g, argv[i + 1], 1, c->ntypes, WHO " scale type");
            c->ratio[t - 1] = arg_double(g, argv[i + 2], WHO " scale ratio");
            bytype = 1;
            i += 3;
        }
    }
    f->hooks = HOOK_POST_FORCE;
    f->sources[f->nsources++] = "fix_damping_cundall.cl";
}

static void init(struct gravel *g, struct fix *f)
{
    struct cundall *c = f->data;
    if (c->ntypes < g->atoms.ntypes)
        gr_error(g, "fix %s damping/cundall was defined for %d atom types, now there are %d",
                 f->id, c->ntypes, g->atoms.ntypes);
    if (c->var)
        var_check_atom(g, c->var, WHO " scale");
    int after = 0;
    for (int k = 0; k < g->styles.nfix; k++) {
        const struct fix *o = g->styles.fix[k];
        if (after && (o->hooks & HOOK_POST_FORCE))
            gr_warn(g, "fix %s alters forces after fix damping/cundall %s", o->id, f->id);
        after |= o == f;
    }
    double *gam = gr_malloc(g, 2 * (size_t)c->ntypes * sizeof *gam);
    for (int t = 0; t < c->ntypes; t++) {
        gam[2 * t] = c->gl * c->ratio[t];
        gam[2 * t + 1] = c->ga * c->ratio[t];
    }
    if (c->gam)
        clReleaseMemObject(c->gam);
    c->gam = eng_alloc(g, 2 * (size_t)c->ntypes * g->eng->rsz, WHO " gamma");
    eng_write_reals(g, c->gam, 2 * (size_t)c->ntypes, gam);
    free(gam);
    c->k = eng_kernel(g, "damping_cundall_post_force");
}

/* scale v_name: the variable's value of every atom, uploaded in device order */
static cl_mem scale_values(struct gravel *g, struct cundall *c)
{
    const int n = g->atoms.n;
    free(c->scale);
    c->scale = gr_malloc(g, ((size_t)n + 1) * sizeof *c->scale);
    var_compute_atom(g, c->var, c->scale); /* syncs the host arrays: host order = device order */
    if (!c->dscale || c->dscale_n < (size_t)n) {
        if (c->dscale)
            clReleaseMemObject(c->dscale);
        c->dscale_n = (size_t)n + (size_t)n / 8 + 16;
        c->dscale = eng_alloc(g, c->dscale_n * g->eng->rsz, WHO " scale");
    }
    eng_write_reals(g, c->dscale, (size_t)n, c->scale);
    return c->dscale;
}

static void post_force(struct gravel *g, struct fix *f)
{
    struct cundall *c = f->data;
    struct dev_atoms *a = eng_atoms(g);
    const int rot = g->eng->rotation;
    cl_mem scale = c->var ? scale_values(g, c) : c->gam;
    cl_kernel k = c->k;
    int q = 0;
    eng_arg_int(g, k, q++, a->n);
    eng_arg_uint(g, k, q++, f->groupbit);
    eng_arg_mem(g, k, q++, a->mask);
    eng_arg_mem(g, k, q++, a->type);
    eng_arg_mem(g, k, q++, a->v);
    eng_arg_mem(g, k, q++, rot ? a->omega : a->v);
    eng_arg_mem(g, k, q++, a->f);
    eng_arg_mem(g, k, q++, rot ? a->torque : a->f);
    eng_arg_mem(g, k, q++, c->gam);
    eng_arg_mem(g, k, q++, scale);
    eng_arg_int(g, k, q++, c->var != NULL);
    eng_arg_real(g, k, q++, c->gl);
    eng_arg_real(g, k, q++, c->ga);
    eng_launch(g, k, (size_t)a->n);
}

const struct fix_style fix_style_damping_cundall = {
    .name = "damping/cundall",
    .create = create,
    .init = init,
    .post_force = post_force,
    .destroy = destroy,
};
