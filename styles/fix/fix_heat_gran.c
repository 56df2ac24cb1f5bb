/* fix_heat_gran.c - `fix ID group heat/gran/conduction initial_temperature T0
 * [contact_area overlap|projection|constant A] [area_correction no]
 * [store_contact_data no]`, also spelled `heat/gran` (LIGGGHTS-PUBLIC 3.8
 * FixHeatGranCond with its FixScalarTransportEquation "heattransfer").
 *
 * LIGGGHTS's spelling of gravel's heat machinery: the atoms' temperature
 * (LIGGGHTS's property/atom Temp, default T0: every atom when the fix is
 * made and every atom created later) and heat flow (heatFlux) are the
 * arrays of `fix property/atom temperature heatflow`; the conduction of
 * each particle-particle contact of `pair_style gran` is computed in the
 * pair law (kernels/pair_gran.cl lg_conduction: (T_j - T_i) 4 k_i k_j /
 * (k_i + k_j) sqrt(A)), k from `fix property/global thermalConductivity
 * peratomtype`; the temperature advances as fix heat/flow's, T += dt Q /
 * (m c) at final_integrate, c from `thermalCapacity peratomtype`.
 * Walls exchange no heat (LIGGGHTS: only walls given a temperature).
 *
 * Global scalar (thermo f_ID): the thermal energy sum of c m T over all
 * atoms (LIGGGHTS's compute_scalar), summed in tag order. Contract and
 * differences: doc/styles/fix_heat_gran.md. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "device.h"
#include "error.h"
#include "fix.h"
#include "fix_heat_flow.h"
#include "fix_heat_gran.h"
#include "fix_property_global.h"
#include "pair.h"
#include "par_sum.h"
#include "param_layout.h"

#define WHO "fix heat/gran/conduction"
#define SMALL_K 1e-6    /* LIGGGHTS's SMALL_FIX_HEAT_GRAN */

struct heat_gran {
    double t0;
    int area_mode;      /* LG_H_OVERLAP, LG_H_PROJECTION, LG_H_CONSTANT */
    double area;        /* contact_area constant A */
    int ntypes;
    double *cp;         /* [ntypes] thermalCapacity of the last init */
    cl_mem buf;
    cl_kernel k;
};

static int is_heat_gran(const struct fix *f)
{
    return f->style == &fix_style_heat_gran || f->style == &fix_style_heat_gran_conduction;
}

static struct fix *find(struct gravel *g)
{
    for (int i = 0; i < g->styles.nfix; i++)
        if (is_heat_gran(g->styles.fix[i]))
            return g->styles.fix[i];
    return NULL;
}

int heat_gran_conduction(struct gravel *g, int nt, int I, int J, double *hc, double *area)
{
    const struct fix *f = find(g);
    *hc = *area = 0.;
    if (!f)
        return LG_H_NONE;
    const struct heat_gran *h = f->data;
    const double *k = fpg_pertype(g, "thermalConductivity", nt, WHO);
    const double ki = k[I - 1], kj = k[J - 1];
    *hc = ki < SMALL_K || kj < SMALL_K ? 0. : 4. * ki * kj / (ki + kj);
    *area = h->area;
    return h->area_mode;
}

static int yesno(struct gravel *g, int argc, char **argv, int i)
{
    arg_need(g, argc, i, 1, argv[i]);
    if (!strcmp(argv[i + 1], "yes"))
        return 1;
    if (strcmp(argv[i + 1], "no"))
        gr_error(g, WHO ": expecting 'yes' or 'no' after '%s'", argv[i]);
    return 0;
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 2)
        gr_error(g, WHO ": not enough arguments");
    if (strcmp(argv[0], "initial_temperature"))
        gr_error(g, WHO ": expecting keyword 'initial_temperature'");
    struct heat_gran *h = gr_calloc(g, 1, sizeof *h);
    f->data = h;
    h->t0 = arg_double(g, argv[1], "initial_temperature");
    if (!(h->t0 >= 0) || !isfinite(h->t0))
        gr_error(g, WHO ": initial_temperature must be >= 0 and finite (got %s)", argv[1]);
    h->area_mode = LG_H_OVERLAP;
    int correction = 0;
    for (int i = 2; i < argc;) {
        if (!strcmp(argv[i], "contact_area")) {
            arg_need(g, argc, i, 1, argv[i]);
            if (!strcmp(argv[i + 1], "overlap")) {
                h->area_mode = LG_H_OVERLAP;
            } else if (!strcmp(argv[i + 1], "projection")) {
                h->area_mode = LG_H_PROJECTION;
            } else if (!strcmp(argv[i + 1], "constant")) {
                if (i + 2 >= argc)
                    gr_error(g, WHO ": not enough arguments for keyword 'contact_area constant'");
                h->area_mode = LG_H_CONSTANT;
                h->area = arg_double(g, argv[i + 2], "contact area");
                if (!(h->area > 0.) || !isfinite(h->area))
                    gr_error(g, WHO ": 'contact_area constant' value must be > 0");
                i++;
            } else {
                gr_error(g, WHO ": expecting 'overlap', 'projection' or 'constant' after "
                            "'contact_area'");
            }
            i += 2;
        } else if (!strcmp(argv[i], "area_correction")) {
            correction = yesno(g, argc, argv, i);
            i += 2;
        } else if (!strcmp(argv[i], "store_contact_data")) {
            if (yesno(g, argc, argv, i))
                gr_error(g, WHO ": store_contact_data yes (per-atom contact areas) is not "
                            "supported by gravel");
            i += 2;
        } else {
            gr_error(g, WHO ": unknown keyword '%.64s'", argv[i]);
        }
    }
    if (correction && h->area_mode != LG_H_OVERLAP)
        gr_error(g, WHO ": can use 'area_correction' only for 'contact_area = overlap'");
    if (correction)
        gr_error(g, WHO ": area_correction yes (youngsModulusOriginal) is not supported by "
                    "gravel");
    for (int i = 0; i < g->styles.nfix; i++) {
        const struct fix *o = g->styles.fix[i];
        if (o == f || !strcmp(o->id, f->id))
            continue;
        if (is_heat_gran(o))
            gr_error(g, WHO ": cannot have more than one fix of this style (fix %s)", o->id);
        if (!strcmp(o->style->name, "property/atom") && (g->atoms.heat_flag & ATOM_HEAT_T))
            gr_error(g, WHO ": the atoms' temperature belongs to fix property/atom %s", o->id);
    }
    /* LIGGGHTS's property/atom Temp (default T0) and heatFlux; temperatures
     * a restart file brought back are kept (LIGGGHTS restores its Temp) */
    struct atoms *a = &g->atoms;
    for (int i = 0; i < a->n; i++) {
        if (!(a->heat_flag & ATOM_HEAT_T)) {
            a->temperature[i] = h->t0;
            a->heatsource[i] = 0;
        }
        a->heatflow[i] = 0;
    }
    a->heat_flag = ATOM_HEAT_BOTH;
    a->temp_default = h->t0;
    f->hooks = HOOK_FINAL_INTEGRATE;
    f->sources[f->nsources++] = "fix_heat_flow.cl";
}

static void init(struct gravel *g, struct fix *f)
{
    struct heat_gran *h = f->data;
    if (!g->styles.pair || strcmp(g->styles.pair->style->name, "gran"))
        gr_error(g, WHO ": needs a granular pair style to be used (pair_style gran model ...)");
    int nt = g->atoms.ntypes;
    const double *k = fpg_pertype(g, "thermalConductivity", nt, WHO);
    const double *c = fpg_pertype(g, "thermalCapacity", nt, WHO);
    for (int t = 0; t < nt; t++) {
        if (!(k[t] >= 0.))
            gr_error(g, WHO ": Thermal conductivity must not be < 0 (type %d: %g)", t + 1, k[t]);
        if (!(c[t] > 0.) || !isfinite(c[t]))
            gr_error(g, WHO ": thermalCapacity must be > 0 (type %d: %g)", t + 1, c[t]);
    }
    free(h->cp);
    h->cp = gr_malloc(g, (size_t)nt * sizeof *h->cp);
    memcpy(h->cp, c, (size_t)nt * sizeof *h->cp);
    h->ntypes = nt;
    if (h->buf)
        clReleaseMemObject(h->buf);
    h->buf = eng_alloc(g, (size_t)nt * g->eng->rsz, "fix heat/gran thermalCapacity");
    eng_write_reals(g, h->buf, (size_t)nt, h->cp);
    h->k = eng_kernel(g, "heat_flow_final");
}

static void final_integrate(struct gravel *g, struct fix *f)
{
    struct heat_gran *h = f->data;
    heat_flow_integrate(g, f->groupbit, h->k, h->buf);
}

static double scalar(struct gravel *g, struct fix *f)
{
    const struct heat_gran *h = f->data;
    const struct atoms *a = &g->atoms;
    const int *order = atoms_tag_order(g);
    struct par_sum sum = {0}; /* every rank's atoms, in tag order */
    for (int k = 0; k < a->n; k++) {
        int i = order[k];
        int t = a->type[i];
        double c = h->cp && t <= h->ntypes ? h->cp[t - 1] : 0.;
        par_sum_add(g, &sum, a->tag[i], c * a->rmass[i] * a->temperature[i]);
    }
    return par_sum_total(g, &sum);
}

/* unfix: the temperature and heat flow go with the fix */
static void unfix(struct gravel *g, struct fix *f)
{
    (void)f;
    g->atoms.heat_flag = 0;
    g->atoms.temp_default = 0.;
}

static void destroy(struct fix *f)
{
    struct heat_gran *h = f->data;
    if (h) {
        if (h->buf)
            clReleaseMemObject(h->buf);
        free(h->cp);
        free(h);
    }
    f->data = NULL;
}

#define HEAT_GRAN_STYLE(NAME)                                                                  \
    {                                                                                          \
        .name = NAME, .create = create, .init = init, .final_integrate = final_integrate,      \
        .scalar = scalar, .unfix = unfix, .destroy = destroy,                                  \
    }

const struct fix_style fix_style_heat_gran_conduction = HEAT_GRAN_STYLE("heat/gran/conduction");
const struct fix_style fix_style_heat_gran = HEAT_GRAN_STYLE("heat/gran");
