/* write_coeff.c - `write_coeff file` as LAMMPS 2021 (write_coeff.cpp):
 * the pair style is first checked as a run would check it (LAMMPS calls
 * init(): "all pair coeffs are not set" and the styles' own checks raise
 * here), then the file gets LAMMPS's header line and one `pair_coeff I J
 * ...` line per type pair of a style that writes its coefficients to data
 * files. LAMMPS's granular styles (gran/hooke, gran/hooke/history,
 * gran/hertz/history, granular) write none, and neither do gravel's pair
 * styles (write_data writes no Pair Coeffs either), so the file holds the
 * header alone, exactly as lmp writes it for these styles; there are no
 * bond, angle, dihedral or improper styles. */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "command.h"
#include "domain.h"
#include "error.h"
#include "pair.h"

void cmd_write_coeff(struct gravel *g, int argc, char **argv)
{
    (void)argc;
    domain_require_box(g);
    if (g->styles.pair)
        pair_setup(g);
    FILE *fp = fopen(argv[0], "w");
    if (!fp)
        gr_error(g, "cannot open coeff file '%s': %s", argv[0], strerror(errno));
    fprintf(fp, "# LAMMPS coeff file via write_coeff, version gravel %s\n", GR_VERSION);
    int bad = ferror(fp);
    if (fclose(fp) != 0 || bad)
        gr_error(g, "cannot write coeff file '%s': %s", argv[0], strerror(errno));
}
