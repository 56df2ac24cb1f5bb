/* domain.c - the `boundary` command and the box API of domain.h: initial box,
 * LAMMPS shrink-wrap rule, volume, periodic remap and unit conversion. */
#include "domain.h"

#include <math.h>
#include <string.h>

#include "error.h"
#include "log.h"

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
            gr_error(g, "box bounds in %c must lie within +-1e20, got %g %g", dimname[d],
                     dm->lo[d], dm->hi[d]);
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

void domain_h(const struct gravel *g, double h[6])
{
    const struct domain *dm = &g->dom;
    for (int d = 0; d < 3; d++)
        h[d] = dm->hi[d] - dm->lo[d];
    h[3] = dm->yz;
    h[4] = dm->xz;
    h[5] = dm->xy;
}

void domain_h_inv(const struct gravel *g, double hinv[6])
{
    double h[6];
    domain_h(g, h);
    hinv[0] = 1.0 / h[0];
    hinv[1] = 1.0 / h[1];
    hinv[2] = 1.0 / h[2];
    hinv[3] = -h[3] / (h[1] * h[2]);
    hinv[4] = (h[3] * h[5] - h[1] * h[4]) / (h[0] * h[1] * h[2]);
    hinv[5] = -h[5] / (h[0] * h[1]);
}

void domain_x2lamda(const struct gravel *g, const double x[3], double lam[3])
{
    const struct domain *dm = &g->dom;
    double hinv[6], dx = x[0] - dm->lo[0], dy = x[1] - dm->lo[1], dz = x[2] - dm->lo[2];
    domain_h_inv(g, hinv);
    lam[0] = hinv[0] * dx + hinv[5] * dy + hinv[4] * dz;
    lam[1] = hinv[1] * dy + hinv[3] * dz;
    lam[2] = hinv[2] * dz;
}

void domain_lamda2x(const struct gravel *g, const double lam[3], double x[3])
{
    const struct domain *dm = &g->dom;
    double h[6], l0 = lam[0], l1 = lam[1], l2 = lam[2];
    domain_h(g, h);
    x[0] = h[0] * l0 + h[5] * l1 + h[4] * l2 + dm->lo[0];
    x[1] = h[1] * l1 + h[3] * l2 + dm->lo[1];
    x[2] = h[2] * l2 + dm->lo[2];
}

void domain_check_tilt(struct gravel *g)
{
    const struct domain *dm = &g->dom;
    if (!dm->triclinic)
        return;
    if (!isfinite(dm->xy) || !isfinite(dm->xz) || !isfinite(dm->yz))
        gr_error(g, "tilt factors must be finite");
    if ((dm->xy != 0.0 && !dm->periodic[1]) || (dm->xz != 0.0 && !dm->periodic[2]) ||
        (dm->yz != 0.0 && !dm->periodic[2]))
        gr_error(g, "cannot skew a triclinic box along a non-periodic dimension (xy needs y "
                    "periodic, xz and yz need z periodic)");
    if (dm->dimension == 2 && (dm->xz != 0.0 || dm->yz != 0.0))
        gr_error(g, "cannot skew a 2d box in z (xz and yz must be 0)");
}

void domain_check_skew(struct gravel *g)
{
    const struct domain *dm = &g->dom;
    if (!dm->triclinic)
        return;
    double lx = dm->hi[0] - dm->lo[0], ly = dm->hi[1] - dm->lo[1];
    /* written so that a NaN ratio fails too */
    if (!(fabs(dm->xy / lx) <= 0.5) || !(fabs(dm->xz / lx) <= 0.5) ||
        !(fabs(dm->yz / ly) <= 0.5))
        gr_error(g, "triclinic box skew is too large: tilts xy %g xz %g yz %g with box lengths "
                    "Lx %g Ly %g (a tilt may be at most half its box length: xy and xz against "
                    "Lx, yz against Ly)",
                 dm->xy, dm->xz, dm->yz, lx, ly);
}

void domain_ufac(const struct domain *d, double f[3])
{
    f[0] = f[1] = f[2] = 1.0;
    if (!d->triclinic)
        return;
    double Ly = d->hi[1] - d->lo[1], Lz = d->hi[2] - d->lo[2];
    double by = d->xy / Ly, cz = (d->xy * d->yz / Ly - d->xz) / Lz, cy = d->yz / Lz;
    f[0] = sqrt(1 + by * by + cz * cz);
    f[1] = sqrt(1 + cy * cy);
}

void domain_bbox(const struct gravel *g, double lo[3], double hi[3])
{
    const struct domain *d = &g->dom;
    double xy = d->xy, xz = d->xz, yz = d->yz;
    lo[0] = d->lo[0] + fmin(fmin(0.0, xy), fmin(xz, xy + xz));
    hi[0] = d->hi[0] + fmax(fmax(0.0, xy), fmax(xz, xy + xz));
    lo[1] = d->lo[1] + fmin(0.0, yz);
    hi[1] = d->hi[1] + fmax(0.0, yz);
    lo[2] = d->lo[2];
    hi[2] = d->hi[2];
}

void domain_print_box(struct gravel *g, const char *indent)
{
    const struct domain *d = &g->dom;
    if (d->triclinic)
        gr_print(g, "%striclinic box = (%#.8g %#.8g %#.8g) to (%#.8g %#.8g %#.8g) with tilt "
                    "(%#.8g %#.8g %#.8g)\n", indent, d->lo[0], d->lo[1], d->lo[2], d->hi[0],
                 d->hi[1], d->hi[2], d->xy, d->xz, d->yz);
    else
        gr_print(g, "%sorthogonal box = (%.8g %.8g %.8g) to (%.8g %.8g %.8g)\n", indent,
                 d->lo[0], d->lo[1], d->lo[2], d->hi[0], d->hi[1], d->hi[2]);
}

/* One wrapped coordinate c in [lo, hi) of period len; returns the image shift. */
static int wrap1(double *c, double lo, double hi, double len)
{
    if (*c >= lo && *c < hi)
        return 0;
    double n = floor((*c - lo) / len);
    if (fabs(n) > 1e9)
        return 0; /* hopelessly far: leave for the caller's sanity checks */
    *c -= n * len;
    /* round-off can leave c a hair outside [lo, hi) */
    if (*c >= hi) {
        *c -= len;
        n += 1;
    }
    if (*c < lo)
        *c = lo;
    return (int)n;
}

void domain_remap(const struct gravel *g, double x[3], int image[3])
{
    const struct domain *dm = &g->dom;
    if (dm->triclinic) { /* LAMMPS: wrap the lamda coordinates in [0, 1), map back */
        if (!isfinite(x[0]) || !isfinite(x[1]) || !isfinite(x[2]))
            return;
        double lam[3];
        domain_x2lamda(g, x, lam);
        for (int d = 0; d < 3; d++) {
            if (!dm->periodic[d])
                continue;
            int n = wrap1(&lam[d], 0.0, 1.0, 1.0);
            if (image)
                image[d] += n;
        }
        domain_lamda2x(g, lam, x);
        return;
    }
    for (int d = 0; d < 3; d++) {
        if (!dm->periodic[d] || !isfinite(x[d]))
            continue;
        int n = wrap1(&x[d], dm->lo[d], dm->hi[d], dm->hi[d] - dm->lo[d]);
        if (image)
            image[d] += n;
    }
}

void domain_unmap(const struct gravel *g, const double x[3], const int image[3], double out[3])
{
    const struct domain *dm = &g->dom;
    int im[3];
    for (int d = 0; d < 3; d++)
        im[d] = dm->periodic[d] ? image[d] : 0;
    double h[6];
    domain_h(g, h);
    out[0] = x[0] + h[0] * im[0] + h[5] * im[1] + h[4] * im[2];
    out[1] = x[1] + h[1] * im[1] + h[3] * im[2];
    out[2] = x[2] + h[2] * im[2];
}

void domain_minimum_image(const struct gravel *g, double del[3])
{
    const struct domain *dm = &g->dom;
    /* z first (its image shifts y and x by the tilts), then y, then x */
    double h[6];
    domain_h(g, h);
    if (dm->periodic[2] && fabs(del[2]) > 0.5 * h[2]) {
        double n = nearbyint(del[2] / h[2]);
        del[2] -= n * h[2];
        del[1] -= n * h[3];
        del[0] -= n * h[4];
    }
    if (dm->periodic[1] && fabs(del[1]) > 0.5 * h[1]) {
        double n = nearbyint(del[1] / h[1]);
        del[1] -= n * h[1];
        del[0] -= n * h[5];
    }
    if (dm->periodic[0] && fabs(del[0]) > 0.5 * h[0])
        del[0] -= h[0] * nearbyint(del[0] / h[0]);
}

int domain_inside(const struct gravel *g, const double x[3])
{
    const struct domain *dm = &g->dom;
    if (dm->triclinic) {
        double lam[3];
        domain_x2lamda(g, x, lam);
        for (int d = 0; d < 3; d++)
            if (!(lam[d] >= 0.0 && lam[d] < 1.0))
                return 0;
        return 1;
    }
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
