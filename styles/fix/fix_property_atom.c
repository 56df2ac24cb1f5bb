/* fix_property_atom.c - `fix ID group property/atom name ... [ghost yes|no]`
 * with the names LAMMPS's FixPropertyAtom gives a granular deck:
 *   mol          per-atom molecule IDs (atom->molecule_flag): g->atoms.mol,
 *                0 for every atom when the fix is created; they follow the
 *                atoms on the device (neighbor exclusion molecule/intra|inter),
 *                are set by `set ... mol`, fix pour's molecule insertion, and
 *                dumped as `mol`;
 *   temperature  per-atom temperature (atom->temperature_flag, LAMMPS 2023):
 *                g->atoms.temperature, 0 at creation, set by `set ...
 *                temperature`, conducted by pair granular's and wall/gran's
 *                `heat` sub-model, integrated by fix heat/flow;
 *   heatflow     the heat flow into each atom of the step
 *                (atom->heatflow_flag): g->atoms.heatflow, the contacts'
 *                conduction summed like the forces.
 *   i_name d_name i2_name N d2_name N
 *                custom integer and floating vectors and N-column arrays
 *                (LAMMPS's Atom::add_custom): 0 for every atom when defined,
 *                stored in atoms.custom (atom_custom.h) and moved with the
 *                atoms like the table's rows.
 * LIGGGHTS's form `NAME scalar|vector restart ghost reverse values`
 * (create_liggghts): the custom d_NAME / d2_NAME N with new-atom values,
 * its values the fix's per-atom output f_ID.
 * `ghost` only matters to LAMMPS's ghost-atom communication: accepted.
 * Other LAMMPS properties (q, rmass ...) are not supported: a clear error.
 * A property is defined by one fix only, as in LAMMPS; unfixing it removes
 * the property (property_atom_release). The fix's own data: its built-in
 * property bits, then the custom names in command order (read_data's fix
 * sections read their values in that order, property_atom_columns). */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atom_custom.h"
#include "error.h"
#include "fix.h"
#include "fix_property_atom.h"

enum { P_MOL = 1, P_T = 2, P_Q = 4 };

/* What one fix property/atom command defined, in command order. */
struct prop_fix {
    unsigned props;             /* P_* bits */
    int liggghts;               /* LIGGGHTS's form: one property, per-atom output f_ID */
    double *out;                /* ... its values in host order (peratom_values) */
    int n;                      /* words of the command that define values */
    int kind[GR_MAXCUSTOM + 3]; /* P_MOL, P_T, P_Q, or 0 for a custom property */
    char name[GR_MAXCUSTOM + 3][GR_CUSTOMLEN];
};

/* The property bits fix f defines (f->data), 0 for another style. */
static unsigned props_of(const struct fix *f)
{
    return strcmp(f->style->name, "property/atom") || !f->data
               ? 0u
               : ((const struct prop_fix *)f->data)->props;
}

static void destroy(struct fix *f)
{
    struct prop_fix *pf = f->data;
    if (pf)
        free(pf->out);
    free(pf);
    f->data = NULL;
}

/* LIGGGHTS's form, `fix ID group property/atom NAME scalar|vector restart
 * ghost reverse v1 [v2 ...]`: the custom property d_NAME (scalar) or d2_NAME N
 * (vector of the N values given), whose new atoms take those values (the
 * atoms present take them when the property is new); its values are the
 * fix's per-atom output f_ID (f_ID[k]); the three yes|no flags concern
 * LIGGGHTS's storage and communication: checked and accepted. */
static void create_liggghts(struct gravel *g, struct fix *f, int argc, char **argv)
{
    struct prop_fix *pf = f->data;
    const char *nm = argv[0];
    const int vec = !strcmp(argv[1], "vector");
    if (!custom_name_ok(nm))
        gr_error(g, "fix property/atom: invalid property name '%.80s' (letters, digits and "
                    "underscores, at most %d characters)", nm, GR_CUSTOMLEN - 1);
    if (argc < 6)
        gr_error(g, "fix property/atom %s %s: expected the three yes|no flags (restart, "
                    "communicate ghost, communicate reverse) and %s", nm, argv[1],
                 vec ? "the default values" : "the default value");
    for (int k = 2; k < 5; k++)
        (void)arg_yesno(g, argv[k], "fix property/atom flag");
    const int nv = argc - 5;
    if (!vec && nv != 1)
        gr_error(g, "fix property/atom %s scalar: expected one default value, got %d", nm, nv);
    if (nv > GR_CUSTOM_DEFS)
        gr_error(g, "fix property/atom %s vector: at most %d values, got %d", nm,
                 GR_CUSTOM_DEFS, nv);
    double def[GR_CUSTOM_DEFS];
    for (int k = 0; k < nv; k++)
        def[k] = arg_double(g, argv[5 + k], "fix property/atom default value");
    const struct custom_def d = {nm, 0, vec ? nv : 0, def};
    custom_define(g, f->id, 1, &d);
    pf->liggghts = 1;
    pf->kind[0] = 0;
    snprintf(pf->name[pf->n++], GR_CUSTOMLEN, "%s", nm);
    f->peratom_flag = 1;
    f->size_peratom_cols = vec ? nv : 0;
}

static const double *peratom_values(struct gravel *g, struct fix *f)
{
    struct prop_fix *pf = f->data;
    const struct atoms *a = &g->atoms;
    const int k = custom_find(a, pf->name[0]);
    if (!pf->liggghts || k < 0)
        gr_error(g, "fix %s (property/atom) has no per-atom output (LIGGGHTS's form has: "
                    "fix ID group property/atom NAME scalar|vector ...)", f->id);
    const struct custom_prop *p = &a->cus.p[k];
    const int w = custom_width(p);
    pf->out = gr_realloc(g, pf->out, ((size_t)a->n * w + 1) * sizeof *pf->out);
    for (int i = 0; i < a->n; i++)
        memcpy(pf->out + (size_t)i * w, a->custom + (size_t)i * a->cus.slots + p->slot,
               (size_t)w * sizeof(double));
    return pf->out;
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "fix property/atom expects a property name (mol, temperature, heatflow, "
                    "i_name, d_name, i2_name N, d2_name N)");
    struct prop_fix *pf = gr_calloc(g, 1, sizeof *pf);
    f->data = pf;
    if (argc >= 2 && (!strcmp(argv[1], "scalar") || !strcmp(argv[1], "vector"))) {
        create_liggghts(g, f, argc, argv);
        return;
    }
    unsigned props = 0;
    struct custom_def defs[GR_MAXCUSTOM];
    int ndef = 0;
    static const char *const names[] = {"mol", "temperature", "heatflow"};
    for (int i = 0; i < argc; i++) {
        int k = 0;
        while (k < 3 && strcmp(argv[i], names[k]))
            k++;
        const char *w = argv[i];
        int arr = (w[0] == 'i' || w[0] == 'd') && w[1] == '2' && w[2] == '_';
        if (k < 3) {
            if (props & (1u << k))
                gr_error(g, "fix property/atom: %s given twice", names[k]);
            props |= 1u << k;
            pf->kind[pf->n] = 1 << k;
            snprintf(pf->name[pf->n++], GR_CUSTOMLEN, "%s", names[k]);
        } else if (((w[0] == 'i' || w[0] == 'd') && w[1] == '_') || arr) {
            const char *nm = w + (arr ? 3 : 2);
            if (!custom_name_ok(nm))
                gr_error(g, "fix property/atom: invalid property name '%.80s' (letters, digits "
                            "and underscores after %s, at most %d characters)",
                         w, arr ? "i2_/d2_" : "i_/d_", GR_CUSTOMLEN - 1);
            int cols = 0;
            if (arr) { /* LAMMPS: i2_name N, d2_name N columns */
                arg_need(g, argc, i, 1, w);
                cols = arg_int_range(g, argv[i + 1], 1, 1000, "array columns");
                i++;
            }
            for (int d = 0; d < ndef; d++)
                if (!strcmp(defs[d].name, nm))
                    gr_error(g, "fix property/atom: custom property name %s given twice", nm);
            if (ndef == GR_MAXCUSTOM)
                gr_error(g, "fix property/atom: more than %d custom properties", GR_MAXCUSTOM);
            defs[ndef++] = (struct custom_def){nm, w[0] == 'i', cols, NULL};
            pf->kind[pf->n] = 0;
            snprintf(pf->name[pf->n++], GR_CUSTOMLEN, "%s", nm);
        } else if (!strcmp(argv[i], "ghost")) {
            arg_need(g, argc, i, 1, "ghost");
            (void)arg_yesno(g, argv[i + 1], "ghost");
            i++;
        } else {
            gr_error(g, "fix property/atom: property '%.64s' is not supported (gravel "
                        "supports mol, temperature, heatflow, i_name, d_name, i2_name N and "
                        "d2_name N, and LIGGGHTS's NAME scalar|vector ...)", argv[i]);
        }
    }
    if (!props && !ndef)
        gr_error(g, "fix property/atom expects a property (mol, temperature, heatflow, "
                    "i_name, d_name, i2_name N or d2_name N)");
    if ((props & P_MOL) && g->atoms.style_molecular)
        gr_error(g, "fix property/atom mol when atom_style already has molecule attribute "
                    "(atom_style hybrid sphere molecular)");
    for (int i = 0; i < g->styles.nfix; i++) {
        const struct fix *o = g->styles.fix[i];
        if (o == f || !strcmp(o->id, f->id)) /* a fix replaced by its own ID */
            continue;
        unsigned both = props_of(o) & props;
        if (both)
            gr_error(g, "fix property/atom vector %s already exists (fix %s)",
                     names[both & P_MOL ? 0 : both & P_T ? 1 : 2], o->id);
    }
    custom_define(g, f->id, ndef, defs);
    struct atoms *a = &g->atoms;
    if ((props & P_MOL) && !a->molecule_flag) {
        for (int i = 0; i < a->n; i++)
            a->mol[i] = 0;
        a->molecule_flag = 1;
    }
    if ((props & (P_T | P_Q)) && !a->heat_flag)
        for (int i = 0; i < a->n; i++)
            a->heatsource[i] = 0;
    if ((props & P_T) && !(a->heat_flag & ATOM_HEAT_T)) {
        for (int i = 0; i < a->n; i++)
            a->temperature[i] = 0;
        a->heat_flag |= ATOM_HEAT_T;
    }
    if ((props & P_Q) && !(a->heat_flag & ATOM_HEAT_Q)) {
        for (int i = 0; i < a->n; i++)
            a->heatflow[i] = 0;
        a->heat_flag |= ATOM_HEAT_Q;
    }
    pf->props = props;
}

int property_atom_columns(struct gravel *g, const struct fix *f, struct prop_column *col,
                          int max)
{
    const struct prop_fix *pf = f->data;
    int n = 0;
    for (int k = 0; k < pf->n; k++) {
        if (pf->kind[k]) {
            if (n == max)
                return -1;
            col[n++] = (struct prop_column){pf->kind[k] == P_MOL   ? PC_MOL
                                            : pf->kind[k] == P_T   ? PC_TEMPERATURE
                                                                   : PC_HEATFLOW,
                                            {0, 0}};
            continue;
        }
        int idx = custom_find(&g->atoms, pf->name[k]);
        if (idx < 0)
            gr_error(g, "internal error: fix %s's property %s is gone", f->id, pf->name[k]);
        int w = custom_width(&g->atoms.cus.p[idx]);
        for (int c = 0; c < w; c++) {
            if (n == max)
                return -1;
            col[n++] = (struct prop_column){PC_CUSTOM, {idx, c}};
        }
    }
    return n;
}

int property_atom_is(const struct fix *f) { return !strcmp(f->style->name, "property/atom"); }

void property_atom_release(struct gravel *g, struct fix *f)
{
    unsigned p = props_of(f);
    if (p & P_MOL)
        g->atoms.molecule_flag = 0; /* the molecule IDs go with their fix */
    if (p & P_T)
        g->atoms.heat_flag &= ~ATOM_HEAT_T;
    if (p & P_Q)
        g->atoms.heat_flag &= ~ATOM_HEAT_Q;
    if (property_atom_is(f))
        custom_remove_fix(g, f->id);
}

const struct fix_style fix_style_property_atom = {
    .name = "property/atom",
    .create = create,
    .destroy = destroy,
    .peratom_values = peratom_values,
};
