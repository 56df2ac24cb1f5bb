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
 * `ghost` only matters to LAMMPS's ghost-atom communication: accepted.
 * Other LAMMPS properties (q, rmass, i_name, d_name ...) are not supported:
 * a clear error. A property is defined by one fix only, as in LAMMPS;
 * unfixing it removes the property (property_atom_release). */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "error.h"
#include "fix.h"
#include "fix_property_atom.h"

enum { P_MOL = 1, P_T = 2, P_Q = 4 };

/* The property bits fix f defines (f->data), 0 for another style. */
static unsigned props_of(const struct fix *f)
{
    return strcmp(f->style->name, "property/atom") || !f->data ? 0u : *(unsigned *)f->data;
}

static void destroy(struct fix *f)
{
    free(f->data);
    f->data = NULL;
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "fix property/atom expects a property name (mol, temperature, heatflow)");
    unsigned props = 0;
    static const char *const names[] = {"mol", "temperature", "heatflow"};
    for (int i = 0; i < argc; i++) {
        int k = 0;
        while (k < 3 && strcmp(argv[i], names[k]))
            k++;
        if (k < 3) {
            if (props & (1u << k))
                gr_error(g, "fix property/atom: %s given twice", names[k]);
            props |= 1u << k;
        } else if (!strcmp(argv[i], "ghost")) {
            arg_need(g, argc, i, 1, "ghost");
            (void)arg_yesno(g, argv[i + 1], "ghost");
            i++;
        } else {
            gr_error(g, "fix property/atom: property '%.64s' is not supported (gravel "
                        "supports mol, temperature and heatflow)", argv[i]);
        }
    }
    if (!props)
        gr_error(g, "fix property/atom expects a property (mol, temperature or heatflow)");
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
    unsigned *d = gr_calloc(g, 1, sizeof *d);
    *d = props;
    f->data = d;
}

void property_atom_release(struct gravel *g, struct fix *f)
{
    unsigned p = props_of(f);
    if (p & P_MOL)
        g->atoms.molecule_flag = 0; /* the molecule IDs go with their fix */
    if (p & P_T)
        g->atoms.heat_flag &= ~ATOM_HEAT_T;
    if (p & P_Q)
        g->atoms.heat_flag &= ~ATOM_HEAT_Q;
}

const struct fix_style fix_style_property_atom = {
    .name = "property/atom",
    .create = create,
    .destroy = destroy,
};
