/* compute_nparticles_tracer_region.c - LIGGGHTS's `compute ID group
 * nparticles/tracer/region region_count R tracer TID [periodic x|y|z
 * image|all] [reset_marker yes|no]`: a global vector of 4 (extensive):
 *   [1] the group's atoms in region R   [2] those marked by fix
 *   [3] their mass                          property/atom/tracer TID
 *   [4] the marked ones' mass
 * With `periodic dim image` only atoms in that periodic image along dim
 * count. reset_marker yes (the default) unmarks the marked atoms it counted:
 * each marked particle is counted once, when it is first seen in R (a
 * residence-time distribution from repeated evaluations). Evaluated once
 * per step of a run: the thermo columns of a row read one count. One
 * process. */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atom_custom.h"
#include "compute.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "fix_property_atom_tracer.h"
#include "region.h"

#define WHO "compute nparticles/tracer/region"

struct ntr {
    char region[GR_NAMELEN], tracer[GR_NAMELEN];
    int image_dim, image_no;    /* image_dim -1: every image */
    int reset;
    bigint last_step, last_first; /* the evaluation held in c->vector: its step and run */
};

static void ntr_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    struct ntr *n = gr_calloc(g, 1, sizeof *n);
    c->data = n;
    n->image_dim = -1;
    n->reset = 1;
    n->last_step = -1;
    for (int i = 0; i < argc;) {
        const char *kw = argv[i];
        if (!strcmp(kw, "periodic")) {
            if (i + 2 >= argc)
                gr_error(g, WHO ": not enough arguments for 'periodic'");
            const char *d = argv[i + 1];
            if (strlen(d) != 1 || d[0] < 'x' || d[0] > 'z')
                gr_error(g, WHO ": 'x', 'y' or 'z' expected after 'periodic', got '%.64s'", d);
            n->image_dim = d[0] - 'x';
            n->image_no = strcmp(argv[i + 2], "all") ? arg_int(g, argv[i + 2], "image") : 0;
            if (!strcmp(argv[i + 2], "all"))
                n->image_dim = -1;
            if (!g->dom.periodic[d[0] - 'x'])
                gr_error(g, WHO ": using 'periodic' in a dimension which is not periodic (%c)",
                         d[0]);
            i += 3;
        } else if (!strcmp(kw, "reset_marker")) {
            if (i + 1 >= argc)
                gr_error(g, WHO ": not enough arguments for 'reset_marker'");
            if (!strcmp(argv[i + 1], "yes"))
                n->reset = 1;
            else if (!strcmp(argv[i + 1], "no"))
                n->reset = 0;
            else
                gr_error(g, WHO ": expecting 'yes' or 'no' for 'reset_marker', got '%.64s'",
                         argv[i + 1]);
            i += 2;
        } else if (!strcmp(kw, "tracer") || !strcmp(kw, "region_count")) {
            if (i + 1 >= argc)
                gr_error(g, WHO ": not enough arguments for '%s'", kw);
            if (strlen(argv[i + 1]) >= GR_NAMELEN)
                gr_error(g, WHO ": ID '%.64s...' is too long", argv[i + 1]);
            if (kw[0] == 'r' && !region_find(g, argv[i + 1]))
                gr_error(g, WHO ": region ID '%.64s' does not exist", argv[i + 1]);
            snprintf(kw[0] == 't' ? n->tracer : n->region, GR_NAMELEN, "%s", argv[i + 1]);
            i += 2;
        } else {
            gr_error(g, WHO ": unknown keyword '%.64s' (region_count tracer periodic "
                        "reset_marker)", kw);
        }
    }
    if (!n->tracer[0])
        gr_error(g, WHO ": have to define 'tracer'");
    if (!n->region[0])
        gr_error(g, WHO ": have to define 'region_count'");
    c->vector_flag = 1;
    c->size_vector = 4;
    c->extvector = 1;
}

/* the tracer fix's marker property */
static int ntr_marker(struct gravel *g, struct compute *c)
{
    const struct ntr *n = c->data;
    struct fix *f = fix_find(g, n->tracer);
    if (!f || strcmp(f->style->name, "property/atom/tracer"))
        gr_error(g, WHO " %s: need a tracer fix of type fix property/atom/tracer ('%s' %s)",
                 c->id, n->tracer, f ? "is another style" : "does not exist");
    const int k = custom_find(&g->atoms, f->id);
    if (k < 0)
        gr_error(g, WHO " %s: fix %s's markers are gone", c->id, f->id);
    return k;
}

static void ntr_init(struct gravel *g, struct compute *c)
{
    const struct ntr *n = c->data;
    ntr_marker(g, c);
    if (!region_find(g, n->region))
        gr_error(g, WHO " %s: region ID (region_count) '%s' does not exist", c->id, n->region);
}

/* Once per step of a run (LAMMPS's invoked_vector): counting unmarks, so the
 * thermo columns of one row read one evaluation. */
static void ntr_vector(struct gravel *g, struct compute *c)
{
    struct ntr *n = c->data;
    if (g->step == n->last_step && g->firststep == n->last_first)
        return;
    n->last_step = g->step;
    n->last_first = g->firststep;
    struct atoms *a = &g->atoms;
    const struct custom_ref ref = {ntr_marker(g, c), 0};
    struct region *r = region_get(g, n->region);
    region_prematch(g, r);
    double v[4] = {0, 0, 0, 0};
    int unmarked = 0;
    for (int i = 0; i < a->n; i++) {
        if (!(a->mask[i] & c->groupbit))
            continue;
        if (n->image_dim >= 0 && a->image[3 * i + n->image_dim] != n->image_no)
            continue;
        if (!region_match(r, a->x + 3 * i))
            continue;
        v[0] += 1.0;
        v[2] += a->rmass[i];
        double *m = custom_at(a, ref, i);
        if (tracer_marked(*m)) {
            v[1] += 1.0;
            v[3] += a->rmass[i];
            if (n->reset) {
                *m = 0.0;
                unmarked = 1;
            }
        }
    }
    if (unmarked && g->eng) /* during a run: the device holds the markers too */
        eng_put_custom(g);
    memcpy(c->vector, v, sizeof v);
}

const struct compute_style compute_style_nparticles_tracer_region = {
    .name = "nparticles/tracer/region",
    .ranks = COMPUTE_RANKS_NO, /* it writes the markers */
    .create = ntr_create,
    .init = ntr_init,
    .vector = ntr_vector,
};
