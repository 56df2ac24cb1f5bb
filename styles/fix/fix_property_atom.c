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
    free(f->data);
    f->data = NULL;
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "fix property/atom expects a property name (mol, temperature, heatflow, "
                    "i_name, d_name, i2_name N, d2_name N)");
    struct prop_fix *pf = gr_calloc(g, 1, sizeof *pf);
    f->data = pf;
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
            defs[ndef++] = (struct custom_def){nm, w[0] == 'i', cols};
            pf->kind[pf->n] = 0;
            snprintf(pf->name[pf->n++], GR_CUSTOMLEN, "%s", nm);
        } else if (!strcmp(argv[i], "ghost")) {
            arg_need(g, argc, i, 1, "ghost");
            (void)arg_yesno(g, argv[i + 1], "ghost");
            i++;
        } else {
            gr_error(g, "fix property/atom: property '%.64s' is not supported (gravel "
                        "supports mol, temperature, heatflow, i_name, d_name, i2_name N and "
                        "d2_name N)", argv[i]);
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
};
