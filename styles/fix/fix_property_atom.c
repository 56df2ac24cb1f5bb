/* fix_property_atom.c - `fix ID group property/atom mol [ghost yes|no]`:
 * per-atom molecule IDs (LAMMPS's FixPropertyAtom with the `mol` name,
 * which turns on atom->molecule_flag). The IDs live in g->atoms.mol (0 for
 * every atom when the fix is created), follow the atoms on the device
 * (neighbor exclusion molecule/intra|inter), are set by `set ... mol`, fix
 * pour's molecule insertion, and dumped as `mol`. `ghost` only matters to
 * LAMMPS's ghost-atom communication: accepted. Other LAMMPS properties
 * (q, rmass, i_name, d_name ...) are not supported: a clear error. Only one
 * fix may define mol, as in LAMMPS. Unfixing it removes the IDs. */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "error.h"
#include "fix.h"

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "fix property/atom expects a property name (mol)");
    int mol = 0;
    for (int i = 0; i < argc; i++) {
        if (!strcmp(argv[i], "mol")) {
            if (mol)
                gr_error(g, "fix property/atom: mol given twice");
            mol = 1;
        } else if (!strcmp(argv[i], "ghost")) {
            arg_need(g, argc, i, 1, "ghost");
            (void)arg_yesno(g, argv[i + 1], "ghost");
            i++;
        } else {
            gr_error(g, "fix property/atom: property '%.64s' is not supported (gravel "
                        "supports mol)", argv[i]);
        }
    }
    if (!mol)
        gr_error(g, "fix property/atom expects the mol property");
    if (g->atoms.style_molecular)
        gr_error(g, "fix property/atom mol when atom_style already has molecule attribute "
                    "(atom_style hybrid sphere molecular)");
    for (int i = 0; i < g->styles.nfix; i++)
        if (g->styles.fix[i] != f && !strcmp(g->styles.fix[i]->style->name, "property/atom") &&
            strcmp(g->styles.fix[i]->id, f->id))
            gr_error(g, "fix property/atom vector mol already exists (fix %s)",
                     g->styles.fix[i]->id);
    if (!g->atoms.molecule_flag)
        for (int i = 0; i < g->atoms.n; i++)
            g->atoms.mol[i] = 0;
    g->atoms.molecule_flag = 1;
    f->data = NULL;
}

const struct fix_style fix_style_property_atom = {
    .name = "property/atom",
    .create = create,
};
