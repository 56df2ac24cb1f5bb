/* fix_adapt.c - `fix ID group adapt N atom diameter v_name [atom diameter
 * v_name ...] [reset yes|no] [scale yes|no] [mass yes|no]`: the group's
 * diameters set from a variable every N steps (LIGGGHTS 3.8's and LAMMPS's
 * fix_adapt.cpp, keyword `atom diameter`).
 *
 * At the setup of every run (LAMMPS's setup_pre_force) and at every step
 * that is a multiple of N (0: setup only), after the neighbor decision and
 * before the forces (pre_force), the variable (equal- or atom-style) gives
 * each atom of the group its new diameter d, or with `scale yes` the factor
 * of its diameter; then, as LIGGGHTS, density = m / (4 pi/3 r^3) with the
 * old radius, r = d/2 and m = 4 pi/3 r^3 density (`mass no`, LAMMPS's
 * keyword: the mass is kept). `reset yes` restores nothing for diameters
 * (LIGGGHTS and LAMMPS restore only pair and kspace parameters).
 * The work is on the host (the atoms synced, the radii and masses written
 * back); the neighbor cut-offs then follow the largest radius and the list
 * is rebuilt at the next step (nbr_radii_changed). On several MPI ranks each
 * rank resizes its own atoms and sends the new radii and masses to their
 * ghosts at once (par_forward_radii). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "device.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "neighbor.h"
#include "par.h"
#include "variable.h"

#define ADAPT_MAX 8

struct adapt {
    int nevery;
    int n;                          /* atom diameter terms */
    char var[ADAPT_MAX][GR_NAMELEN];
    int scale, mass;
};

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 4)
        gr_error(g, "fix adapt expects N atom diameter v_name [reset yes|no] [scale yes|no] "
                    "[mass yes|no]");
    struct adapt *a = gr_calloc(g, 1, sizeof *a);
    f->data = a;
    a->nevery = arg_int_range(g, argv[0], 0, 2147483647, "fix adapt N");
    a->mass = 1;
    int i = 1;
    while (i < argc) {
        const char *kw = argv[i];
        if (!strcmp(kw, "pair") || !strcmp(kw, "kspace") || !strcmp(kw, "bond"))
            gr_error(g, "fix adapt %s is not supported (only 'atom diameter')", kw);
        if (strcmp(kw, "atom"))
            break;
        arg_need(g, argc, i, 2, kw);
        if (strcmp(argv[i + 1], "diameter"))
            gr_error(g, "fix adapt atom %.32s is not supported (only 'atom diameter')",
                     argv[i + 1]);
        const char *v = argv[i + 2];
        if (strncmp(v, "v_", 2) || !v[2] || strlen(v + 2) >= GR_NAMELEN)
            gr_error(g, "fix adapt atom diameter expects a variable v_name, got '%.64s'", v);
        if (a->n == ADAPT_MAX)
            gr_error(g, "fix adapt takes at most %d 'atom diameter' terms", ADAPT_MAX);
        strcpy(a->var[a->n++], v + 2);
        i += 3;
    }
    if (a->n == 0)
        gr_error(g, "fix adapt expects 'atom diameter v_name' after N, got '%.32s'", argv[1]);
    for (; i < argc; i += 2) {
        const char *kw = argv[i];
        int reset, *flag = &reset; /* reset: nothing to restore for diameters */
        if (!strcmp(kw, "scale"))
            flag = &a->scale;
        else if (!strcmp(kw, "mass"))
            flag = &a->mass;
        else if (strcmp(kw, "reset"))
            gr_error(g, "unknown fix adapt keyword '%.32s' (expected reset, scale or mass)", kw);
        arg_need(g, argc, i, 1, kw);
        *flag = arg_yesno(g, argv[i + 1], kw);
    }
    f->hooks = HOOK_PRE_FORCE;
}

static void init(struct gravel *g, struct fix *f)
{
    struct adapt *a = f->data;
    for (int k = 0; k < a->n; k++) {
        if (!var_exists(g, a->var[k]))
            gr_error(g, "variable %s for fix adapt does not exist", a->var[k]);
        if (!var_is_equal(g, a->var[k]) && !var_is_atom(g, a->var[k]))
            gr_error(g, "variable %s for fix adapt must be equal- or atom-style", a->var[k]);
    }
}

/* The new radius and mass of one atom of diameter value d (LIGGGHTS's
 * operation order: 4 pi/3 r r r). */
static void resize(double d, int scale, int mass, double *radius, double *rmass)
{
    double r = *radius;
    double density = *rmass / (4.0 * M_PI / 3.0 * r * r * r);
    if (scale)
        d *= r * 2.0;
    *radius = 0.5 * d;
    if (mass)
        *rmass = 4.0 * M_PI / 3.0 * *radius * *radius * *radius * density;
}

static void pre_force(struct gravel *g, struct fix *f)
{
    struct adapt *a = f->data;
    if (!eng_in_setup(g) && (a->nevery == 0 || g->step % a->nevery))
        return;
    run_sync_host(g); /* host order = device order */
    struct atoms *at = &g->atoms;
    double *vals = at->n ? gr_malloc(g, (size_t)at->n * sizeof *vals) : NULL;
    for (int k = 0; k < a->n; k++) {
        int atom = var_is_atom(g, a->var[k]);
        double value = atom ? 0 : var_compute_equal(g, a->var[k]);
        if (atom)
            var_compute_atom(g, a->var[k], vals);
        for (int i = 0; i < at->n; i++)
            if (at->mask[i] & f->groupbit) {
                double d = atom ? vals[i] : value;
                if (!(d > 0) || !isfinite(d)) {
                    free(vals);
                    gr_error(g, "fix adapt: variable %s gives atom %lld the diameter %g "
                                "(must be positive)", a->var[k], (long long)at->tag[i], d);
                }
                resize(d, a->scale, a->mass, &at->radius[i], &at->rmass[i]);
            }
    }
    free(vals);
    struct dev_atoms *s = eng_atoms(g);
    if (!s->shared) {
        eng_write_reals(g, s->radius, (size_t)at->n, at->radius);
        eng_write_reals(g, s->rmass, (size_t)at->n, at->rmass);
    }
    if (par_on(g)) /* several ranks: the ghosts' new radii for this step's contacts */
        par_forward_radii(g);
    nbr_radii_changed(g);
}

const struct fix_style fix_style_adapt = {
    .name = "adapt",
    .create = create,
    .init = init,
    .pre_force = pre_force,
};
