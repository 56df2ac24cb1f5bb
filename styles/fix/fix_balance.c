/* fix_balance.c - `fix ID group balance Nfreq thresh style args ...`: LAMMPS's
 * dynamic load balancing across MPI ranks. gravel runs on one device, so
 * there is nothing to balance: the fix is accepted (its arguments checked
 * for the Nfreq and threshold LAMMPS requires) with a one-line warning,
 * and does nothing. */
#include "args.h"
#include "error.h"
#include "fix.h"

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 3)
        gr_error(g, "fix balance needs Nfreq thresh style ... (LAMMPS syntax)");
    int nfreq = arg_int(g, argv[0], "Nfreq");
    double thresh = arg_double(g, argv[1], "thresh");
    if (nfreq < 0)
        gr_error(g, "fix balance Nfreq must be >= 0");
    if (thresh < 1.0)
        gr_error(g, "fix balance thresh must be >= 1.0");
    gr_warn(g, "fix %s balance: gravel runs on one device, there is nothing to balance "
               "(accepted, ignored)", f->id);
    f->hooks = 0;
}

const struct fix_style fix_style_balance = {
    .name = "balance",
    .create = create,
};
