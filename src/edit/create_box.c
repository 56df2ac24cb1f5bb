/* create_box.c - `create_box N region-ID`: the box is the bounding box of a
 * bounded side-in region, or with a prism region the triclinic box of the
 * prism (its bounds and tilts, as LAMMPS); N atom types. Shrink-wrapped
 * faces start `small` outside the region (LAMMPS set_initial_box). */
#include <string.h>
#include <math.h>

#include "args.h"
#include "atoms.h"
#include "domain.h"
#include "error.h"
#include "log.h"
#include "region.h"

void cmd_create_box(struct gravel *g, int argc, char **argv)
{
    int ntypes = arg_int_range(g, argv[0], 1, 1000000, "number of atom types");
    struct region *r = region_get(g, argv[1]);
    if (argc > 2)
        gr_error(g, "unsupported keyword '%.32s': atom_style sphere has no bonds or angles",
                 argv[2]);
    if (!r->interior)
        gr_error(g, "region '%s' must be side in to define the box", r->id);
    if (!r->bbox)
        gr_error(g, "region '%s' has no bounding box (style %s) and cannot define the box",
                 r->id, r->style->name);
    for (int d = 0; d < 3; d++) {
        /* INF bounds are exactly +-DOMAIN_BIG (region_parse_bound); huge
         * finite bounds are bounded, only too large for a box */
        if (fabs(r->bbox_lo[d]) == DOMAIN_BIG || fabs(r->bbox_hi[d]) == DOMAIN_BIG)
            gr_error(g, "region '%s' is unbounded in %c and cannot define the box", r->id,
                     "xyz"[d]);
        double len = r->bbox_hi[d] - r->bbox_lo[d];
        if (!(len < 1e19))
            gr_error(g, "region '%s' spans %g to %g in %c: a box length of %g is too large "
                        "(at most 1e19)", r->id, r->bbox_lo[d], r->bbox_hi[d], "xyz"[d], len);
        g->dom.lo[d] = r->bbox_lo[d];
        g->dom.hi[d] = r->bbox_hi[d];
    }
    int prism = !strcmp(r->style->name, "prism");
    g->dom.triclinic = prism;
    g->dom.xy = g->dom.xz = g->dom.yz = 0.0;
    if (prism) {
        for (int d = 0; d < 3; d++) {
            g->dom.lo[d] = r->p[2 * d];
            g->dom.hi[d] = r->p[2 * d + 1];
        }
        g->dom.xy = r->p[6];
        g->dom.xz = r->p[7];
        g->dom.yz = r->p[8];
        domain_check_tilt(g);
        domain_check_skew(g);
    }
    domain_set_initial_box(g);
    atoms_set_ntypes(g, ntypes);
    gr_print(g, "Created ");
    domain_print_box(g, "");
}
