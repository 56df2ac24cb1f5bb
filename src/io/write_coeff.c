/* write_coeff.c - `write_coeff file` as LAMMPS 2021 (write_coeff.cpp):
 * the pair style is first checked as a run would check it (LAMMPS calls
 * init(): "all pair coeffs are not set" and the styles' own checks raise
 * here), then the file gets LAMMPS's header line and one `pair_coeff I J
 * ...` line per type pair of a style that writes its coefficients to data
 * files. LAMMPS's granular styles (gran/hooke, gran/hooke/history,
 * gran/hertz/history, granular) write none, and neither do gravel's pair
 * styles (write_data writes no Pair Coeffs either), so the file holds the
 * header alone, exactly as lmp writes it for these styles; there are no
 * bond, angle, dihedral or improper styles. The file is written by
 * outfile.h's rule, every write checked. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "command.h"
#include "domain.h"
#include "error.h"
#include "outfile.h"
#include "pair.h"

void cmd_write_coeff(struct gravel *g, int argc, char **argv)
{
    (void)argc;
    domain_require_box(g);
    if (g->styles.pair) {
        /* the checks of a run's start: pair_setup, then the packing that
         * refuses missing coefficients */
        pair_setup(g);
        int nt;
        free(pair_pack(g, &nt));
    }
    struct ofile o;
    int e = of_open(&o, argv[0], ".tmp", OF_TRUNC);
    if (e)
        gr_error(g, "cannot open coeff file '%.200s': %s", argv[0], strerror(e));
    fprintf(o.fp, "# LAMMPS coeff file via write_coeff, version gravel %s\n", GR_VERSION);
    if ((e = of_commit(&o, 0)) != 0)
        gr_error(g, "cannot write coeff file '%.200s': %s", argv[0], strerror(e));
}
