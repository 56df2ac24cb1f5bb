/* memfit.c - will the run fit? (see memfit.h) */
#include "memfit.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "accuracy.h"
#include "atom_fields.h"
#include "atoms.h"
#include "device.h"
#include "engine.h"
#include "error.h"
#include "neighbor.h"
#include "pair.h"

enum { MARGIN = 16 << 20 }; /* kept free under an address-space limit, as ocl_alloc */

/* Expected contacts (neighbor pairs) per atom of the host atoms: the
 * pairs closer than the neighbor cut-off d = reach(2 r_mean) + skin of an
 * ideal gas at each cell's number density, over a coarse grid of cells
 * (edge >= 2 d, ~32 atoms per cell). */
static double contacts_estimate(struct gravel *g)
{
    const struct atoms *a = &g->atoms;
    int n = a->n, dim = g->dom.dimension == 2 ? 2 : 3;
    if (n < 2 || !g->styles.pair)
        return 0;
    double lo[3], hi[3], rsum = 0;
    for (int q = 0; q < 3; q++)
        lo[q] = hi[q] = a->x[q];
    for (int i = 0; i < n; i++) {
        rsum += a->radius[i];
        for (int q = 0; q < 3; q++) {
            lo[q] = fmin(lo[q], a->x[3 * i + q]);
            hi[q] = fmax(hi[q], a->x[3 * i + q]);
        }
    }
    double d = pair_reach(g, 2 * rsum / n) + g->neigh.skin;
    if (!(d > 0))
        return 0;
    double ext[3], vol = 1;
    for (int q = 0; q < dim; q++) {
        ext[q] = fmax(hi[q] - lo[q], d);
        vol *= ext[q];
    }
    double h = fmax(2 * d, pow(32 * vol / n, 1.0 / dim));
    size_t nb[3] = {1, 1, 1}, ncell;
    for (;;) {
        ncell = 1;
        for (int q = 0; q < dim; q++) {
            nb[q] = (size_t)ceil(ext[q] / h); /* 0 when the reach is too large to */
            if (nb[q] < 1)                     /* multiply out (vol, h infinite) */
                nb[q] = 1;
            ncell *= nb[q];
        }
        if (ncell <= ((size_t)1 << 22))
            break;
        h *= 1.5;
    }
    unsigned *count = gr_calloc(g, ncell, sizeof *count);
    for (int i = 0; i < n; i++) {
        size_t c = 0;
        for (int q = dim - 1; q >= 0; q--) {
            size_t k = (size_t)((a->x[3 * i + q] - lo[q]) / ext[q] * (double)nb[q]);
            c = c * nb[q] + (k < nb[q] ? k : nb[q] - 1);
        }
        count[c]++;
    }
    double vcell = vol / (double)ncell, pairs = 0;
    double reach = dim == 3 ? 4.0 / 3.0 * M_PI * d * d * d : M_PI * d * d;
    for (size_t c = 0; c < ncell; c++)
        pairs += 0.5 * (double)count[c] * ((double)count[c] - 1) * reach / vcell;
    free(count);
    /* never more than every pair (also where reach / vcell is inf / inf) */
    const double z = pairs / n, zall = 0.5 * (n - 1);
    return z < zall ? z : zall;
}

/* Bytes of one atom slot and of one contact of the run. */
static size_t atom_bytes(struct gravel *g) { return eng_atom_bytes(g) + nbr_atom_bytes(g); }

static size_t contact_bytes(struct gravel *g)
{
    return g->styles.pair ? nbr_contact_bytes(g) + acc_contact_bytes(g) : 0;
}

/* Device bytes the engine holds now in the buffers the check counts (they
 * are reused or replaced by the run's). */
static size_t held_bytes(struct gravel *g)
{
    struct engine *e = g->eng;
    return (e->a.x ? (size_t)e->cap * eng_atom_bytes(g) : 0) + nbr_held_bytes(g) +
           acc_held_bytes(g);
}

/* Host bytes of one atom: the field table's host arrays and the custom
 * properties' record (in use already). */
static size_t host_atom_bytes(const struct gravel *g)
{
    size_t b = (size_t)g->atoms.cus.slots * sizeof(double);
#define HOST(name, ctype, dev, width, when, life, sect, what)                                  \
    if (atoms_holds(&g->atoms, when))                                                         \
        b += (width) * sizeof(ctype);
    ATOM_FIELDS(HOST)
#undef HOST
    return b;
}

/* n atom slots and nc contacts (z = nc per particle), `how` the contacts'
 * origin: stop unless they fit every limit. */
static void check(struct gravel *g, int n, size_t nc, double z, const char *how)
{
    struct engine *e = g->eng;
    size_t pa = atom_bytes(g), pc = contact_bytes(g);
    size_t ncap = pc ? nbr_capacity(nc) : 0;
    double need = (double)n * (double)pa + (double)ncap * (double)pc;
    double per = (double)pa + z * 1.125 * (double)pc; /* per particle, 1/8 headroom */
    size_t held = held_bytes(g), live = (size_t)ocl_mem_live();
    size_t other = live > held ? live - held : 0;
    char why[256] = "";
    double avail = 0, fit = 0;
    size_t gm = e->ocl.global_mem;
    if (gm && need > (double)gm - (double)other) {
        avail = (double)gm - (double)other;
        fit = avail / per;
        snprintf(why, sizeof why,
                 "the device has %zu bytes of global memory (%s) and %zu are in use by other "
                 "buffers", gm, getenv("GRAVEL_DEVICE_MEMORY") && *getenv("GRAVEL_DEVICE_MEMORY")
                     ? "GRAVEL_DEVICE_MEMORY" : "CL_DEVICE_GLOBAL_MEM_SIZE", other);
    }
    size_t limit, left = ocl_address_left(&limit);
    if (!why[0] && left != SIZE_MAX && need > (double)left + (double)held - MARGIN) {
        avail = (double)left + (double)held - MARGIN;
        /* the host arrays grow with the atoms too (their capacity by doubling: up to
         * twice the atoms' bytes) */
        double host = (double)host_atom_bytes(g);
        fit = (avail + host * (double)g->atoms.cap) / (per + 2 * host);
        snprintf(why, sizeof why,
                 "the process may allocate only %zu more bytes under its address-space limit "
                 "of %zu bytes (ulimit -v)", left, limit);
    }
    if (!why[0])
        return;
    gr_error(g, "%d particles need about %.0f bytes of device memory (%zu bytes per particle "
                "for its fields and neighbor data, %.2f contacts per particle %s of %zu bytes "
                "each), more than fit: %s; about %.0f particles would fit",
             n, need, pa, z, how, pc, why, fit > 0 ? floor(fit) : 0.0);
}

void mem_fit_run(struct gravel *g, int n)
{
    struct engine *e = g->eng;
    if (e->a.x && n <= e->cap)
        return; /* the atoms' buffers are in place; contacts: mem_fit_contacts */
    double z = contacts_estimate(g);
    check(g, n, (size_t)llround(z * n), z, "(estimated)");
}

void mem_fit_contacts(struct gravel *g, size_t ncontact)
{
    struct engine *e = g->eng;
    check(g, e->cap, ncontact, (double)ncontact / (e->a.n > 0 ? e->a.n : 1), "(counted)");
}
