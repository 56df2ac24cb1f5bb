/* domain.c - the `boundary` command and the box API of domain.h: initial box,
 * LAMMPS shrink-wrap rule, volume, periodic remap and unit conversion. */
#include "domain.h"

#include <math.h>
#include <string.h>

#include "error.h"

void domain_set_boundary(struct gravel *g, char **argv)
{
    static const char dimname[3] = {'x', 'y', 'z'};
    char bnd[3][2];
    for (int d = 0; d < 3; d++) {
        const char *s = argv[d];
        size_t n = strlen(s);
        if (n < 1 || n > 2)
            gr_error(g, "boundary for %c must be one or two of p f s m, got '%.32s'", dimname[d],
                     s);
        for (int f = 0; f < 2; f++) {
            char c = s[n == 1 ? 0 : f];
            if (c != 'p' && c != 'f' && c != 's' && c != 'm')
                gr_error(g, "unknown boundary '%c' for %c: expected p, f, s or m", c,
                         dimname[d]);
            bnd[d][f] = c;
        }
        if ((bnd[d][0] == 'p') != (bnd[d][1] == 'p'))
            gr_error(g, "both faces of %c must be periodic ('p') or neither, got '%s'",
                     dimname[d], s);
    }
    if (g->dom.box_exists && g->dom.dimension == 2 && bnd[2][0] != 'p')
        gr_error(g, "cannot make z non-periodic in a 2d simulation");
    for (int d = 0; d < 3; d++) {
        g->dom.bnd[d][0] = bnd[d][0];
        g->dom.bnd[d][1] = bnd[d][1];
        g->dom.periodic[d] = bnd[d][0] == 'p';
    }
}

/* boundary x y z: each one or two letters of p f s m (lo face, hi face). */
void cmd_boundary(struct gravel *g, int argc, char **argv)
{
    (void)argc;
    if (g->dom.box_exists)
        gr_error(g, "must be used before the simulation box is created");
    domain_set_boundary(g, argv);
}

void domain_set_initial_box(struct gravel *g)
{
    struct domain *dm = &g->dom;
    static const char dimname[3] = {'x', 'y', 'z'};
    if (dm->dimension == 2 && !dm->periodic[2])
        gr_error(g, "cannot run a 2d simulation with a non-periodic z dimension (boundary ... p)");
    for (int d = 0; d < 3; d++) {
        if (!isfinite(dm->lo[d]) || !isfinite(dm->hi[d]) || !(dm->lo[d] < dm->hi[d]))
            gr_error(g, "box bounds in %c must satisfy lo < hi, got %g %g", dimname[d],
                     dm->lo[d], dm->hi[d]);
        if (fabs(dm->lo[d]) >= DOMAIN_BIG || fabs(dm->hi[d]) >= DOMAIN_BIG)
            gr_error(g, "box bounds in %c must be finite, got %g %g", dimname[d], dm->lo[d],
                     dm->hi[d]);
        dm->small[d] = DOMAIN_SMALL * (dm->hi[d] - dm->lo[d]);
    }
    for (int d = 0; d < 3; d++) {
        if (dm->bnd[d][0] == BND_S)
            dm->lo[d] -= dm->small[d];
        else if (dm->bnd[d][0] == BND_M)
            dm->minlo[d] = dm->lo[d];
        if (dm->bnd[d][1] == BND_S)
            dm->hi[d] += dm->small[d];
        else if (dm->bnd[d][1] == BND_M)
            dm->minhi[d] = dm->hi[d];
    }
    dm->box_exists = 1;
}

void domain_shrink_wrap(struct gravel *g, const double lo[3], const double hi[3])
{
    struct domain *dm = &g->dom;
    for (int d = 0; d < 3; d++)
        if (!(lo[d] <= hi[d]))
            return; /* no atoms: LAMMPS skips reset_box for an empty system */
    for (int d = 0; d < 3; d++) {
        if (dm->periodic[d])
            continue;
        if (dm->bnd[d][0] == BND_S)
            dm->lo[d] = lo[d] - dm->small[d];
        else if (dm->bnd[d][0] == BND_M)
            dm->lo[d] = fmin(lo[d] - dm->small[d], dm->minlo[d]);
        if (dm->bnd[d][1] == BND_S)
            dm->hi[d] = hi[d] + dm->small[d];
        else if (dm->bnd[d][1] == BND_M)
            dm->hi[d] = fmax(hi[d] + dm->small[d], dm->minhi[d]);
        if (dm->lo[d] > dm->hi[d])
            gr_error(g, "illegal simulation box after shrink-wrapping %c: lo %g > hi %g",
                     "xyz"[d], dm->lo[d], dm->hi[d]);
    }
}

int domain_contact_periodic(const struct gravel *g, int d)
{
    return g->dom.periodic[d] && !(d == 2 && g->dom.dimension == 2);
}

double domain_volume(const struct gravel *g)
{
    const struct domain *dm = &g->dom;
    if (!dm->box_exists)
        return 0.0;
    return (dm->hi[0] - dm->lo[0]) * (dm->hi[1] - dm->lo[1]) * (dm->hi[2] - dm->lo[2]);
}

void domain_remap(const struct gravel *g, double x[3], int image[3])
{
    const struct domain *dm = &g->dom;
    for (int d = 0; d < 3; d++) {
        if (!dm->periodic[d] || !isfinite(x[d]))
            continue;
        double len = dm->hi[d] - dm->lo[d];
        if (x[d] >= dm->lo[d] && x[d] < dm->hi[d])
            continue;
        double n = floor((x[d] - dm->lo[d]) / len);
        if (fabs(n) > 1e9)
            continue; /* hopelessly far: leave for the caller's sanity checks */
        x[d] -= n * len;
        /* round-off can leave x a hair outside [lo, hi) */
        if (x[d] >= dm->hi[d]) {
            x[d] -= len;
            n += 1;
        }
        if (x[d] < dm->lo[d])
            x[d] = dm->lo[d];
        if (image)
            image[d] += (int)n;
    }
}

void domain_unmap(const struct gravel *g, const double x[3], const int image[3], double out[3])
{
    const struct domain *dm = &g->dom;
    for (int d = 0; d < 3; d++)
        out[d] = x[d] + (dm->periodic[d] ? image[d] * (dm->hi[d] - dm->lo[d]) : 0.0);
}

void domain_minimum_image(const struct gravel *g, double del[3])
{
    const struct domain *dm = &g->dom;
    for (int d = 0; d < 3; d++) {
        if (!dm->periodic[d])
            continue;
        double len = dm->hi[d] - dm->lo[d];
        if (fabs(del[d]) > 0.5 * len)
            del[d] -= len * nearbyint(del[d] / len);
    }
}

int domain_inside(const struct gravel *g, const double x[3])
{
    const struct domain *dm = &g->dom;
    for (int d = 0; d < 3; d++)
        if (!(x[d] >= dm->lo[d] && x[d] < dm->hi[d]))
            return 0;
    return 1;
}

void domain_unit_scale(const struct gravel *g, int lattice_flag, double scale[3])
{
    for (int d = 0; d < 3; d++)
        scale[d] = lattice_flag ? g->dom.lat.a[d] : 1.0;
}

void domain_lattice_to_box(const struct gravel *g, double v[3])
{
    for (int d = 0; d < 3; d++)
        v[d] *= g->dom.lat.a[d];
}

void domain_box_to_lattice(const struct gravel *g, double v[3])
{
    for (int d = 0; d < 3; d++)
        v[d] /= g->dom.lat.a[d];
}

int domain_parse_units_kw(struct gravel *g, const char *value)
{
    if (strcmp(value, "box") == 0)
        return 0;
    if (strcmp(value, "lattice") == 0)
        return 1;
    gr_error(g, "units must be 'box' or 'lattice', got '%.32s'", value);
}

void domain_require_box(struct gravel *g)
{
    if (!g->dom.box_exists)
        gr_error(g, "the simulation box does not exist yet: use create_box or read_data first");
}
