/* fix_deposit.c - `fix ID group deposit N type M seed region R [keyword
 * value ...]`: LAMMPS's fix deposit for single atoms: every M steps (the
 * first on the step after the command) one atom of `type` is placed at a
 * random point of region R (uniform in its bounding box until the region
 * holds it, or `gaussian xmid ymid zmid sigma`), raised by `rate V` per unit
 * time, or with `global lo hi` / `local lo hi delta` put lo..hi above the
 * highest atom (of those laterally within delta), tried again (up to
 * `attempt Q` times, default 10) while it is nearer than `near R` to an
 * atom; its velocity uniform in `vx`, `vy`, `vz` ranges, turned towards
 * `target x y z` with the same speed. A new atom is LAMMPS's default sphere
 * (diameter 1, density 1), in the group all and the fix's group, with the
 * next atom ID (`id max`: above the largest now, default; `id next`: above
 * the largest when the fix was defined and its own). The draws are LAMMPS's
 * RanPark stream of `seed` (warmed up 30 times), in its order, so one
 * process deposits LAMMPS's atoms. Lengths and velocities are in lattice
 * units unless `units box`. Global scalar: the atoms deposited. Restart
 * files keep the stream, the count and the schedule. Not supported: `mol`,
 * `molfrac`, `rigid`, `shake`, `orient`, `var`, `set`. On MPI ranks every
 * rank draws every atom and its brick's owner keeps it; `near`, `global`
 * and `local` look at every rank's atoms. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "comm.h"
#include "domain.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "par.h"
#include "par_sum.h"
#include "random.h"
#include "region.h"

#define WHO "fix deposit"

struct deposit {
    int ninsert, ntype, nfreq, seed, ninserted;
    char region[GR_NAMELEN];
    double lo[3], hi[3];        /* the region's bounding box */
    int idnext, global, local, gaussian, target, rateflag, maxattempt, warn;
    double glo, ghi, deltasq, nearsq, rate, sigma, mid[3], vlo[3], vhi[3], t[3];
    int64_t maxtag;             /* id next: the largest ID handed out */
    bigint nfirst;
    struct rng_park rng;
};

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 4)
        gr_error(g, WHO " expects N type M seed region ID [keyword value ...], got %d arguments",
                 argc);
    struct deposit *d = gr_calloc(g, 1, sizeof *d);
    f->data = d;
    d->ninsert = arg_int(g, argv[0], WHO " N");
    d->ntype = arg_int(g, argv[1], WHO " type");
    d->nfreq = arg_int(g, argv[2], WHO " M");
    d->seed = arg_int(g, argv[3], WHO " seed");
    if (d->seed <= 0)
        gr_error(g, WHO ": seed must be > 0, got %d", d->seed);
    if (d->nfreq <= 0)
        gr_error(g, WHO ": M must be > 0, got %d", d->nfreq);
    if (d->ntype < 1 || d->ntype > g->atoms.ntypes)
        gr_error(g, "invalid atom type %d in fix deposit command (1..%d)", d->ntype,
                 g->atoms.ntypes);
    d->maxattempt = 10;
    d->sigma = 1.0;
    int lattice = 1;
    for (int i = 4; i < argc;) {
        const char *kw = argv[i];
        int need = !strcmp(kw, "local") ? 3 : !strcmp(kw, "gaussian") ? 4
                   : (!strcmp(kw, "global") || !strcmp(kw, "vx") || !strcmp(kw, "vy") ||
                      !strcmp(kw, "vz")) ? 2
                   : !strcmp(kw, "target") ? 3 : 1;
        arg_need(g, argc, i, need, kw);
        char **v = argv + i + 1;
        if (!strcmp(kw, "region")) {
            if (strlen(v[0]) >= GR_NAMELEN)
                gr_error(g, WHO ": region ID '%.64s...' is too long", v[0]);
            region_get(g, v[0]);
            strcpy(d->region, v[0]);
        } else if (!strcmp(kw, "id")) {
            if (strcmp(v[0], "max") && strcmp(v[0], "next"))
                gr_error(g, WHO ": id must be max or next, got '%.32s'", v[0]);
            d->idnext = !strcmp(v[0], "next");
        } else if (!strcmp(kw, "global") || !strcmp(kw, "local")) {
            d->global = kw[0] == 'g';
            d->local = !d->global;
            d->glo = arg_double(g, v[0], WHO " lo");
            d->ghi = arg_double(g, v[1], WHO " hi");
            if (d->local) {
                const double delta = arg_double(g, v[2], WHO " delta");
                d->deltasq = delta * delta;
            }
        } else if (!strcmp(kw, "near")) {
            const double r = arg_double(g, v[0], WHO " near");
            d->nearsq = r * r;
        } else if (!strcmp(kw, "attempt")) {
            d->maxattempt = arg_int(g, v[0], WHO " attempt");
        } else if (!strcmp(kw, "rate")) {
            d->rateflag = 1;
            d->rate = arg_double(g, v[0], WHO " rate");
        } else if (!strcmp(kw, "vx") || !strcmp(kw, "vy") || !strcmp(kw, "vz")) {
            const int q = kw[1] - 'x';
            d->vlo[q] = arg_double(g, v[0], WHO " velocity");
            d->vhi[q] = arg_double(g, v[1], WHO " velocity");
        } else if (!strcmp(kw, "gaussian")) {
            d->gaussian = 1;
            for (int q = 0; q < 3; q++)
                d->mid[q] = arg_double(g, v[q], WHO " gaussian centre");
            d->sigma = arg_double(g, v[3], WHO " sigma");
        } else if (!strcmp(kw, "target")) {
            d->target = 1;
            for (int q = 0; q < 3; q++)
                d->t[q] = arg_double(g, v[q], WHO " target");
        } else if (!strcmp(kw, "units")) {
            lattice = domain_parse_units_kw(g, v[0]);
        } else if (!strcmp(kw, "mol") || !strcmp(kw, "molfrac") || !strcmp(kw, "rigid") ||
                   !strcmp(kw, "shake") || !strcmp(kw, "orient") || !strcmp(kw, "var") ||
                   !strcmp(kw, "set")) {
            gr_error(g, WHO ": keyword %s is not supported (single atoms only)", kw);
        } else {
            gr_error(g, WHO ": unknown keyword '%.64s'", kw);
        }
        i += 1 + need;
    }
    if (!d->region[0])
        gr_error(g, "must specify a region in fix deposit");
    const struct region *r = region_get(g, d->region);
    if (!r->bbox)
        gr_error(g, "fix deposit region does not support a bounding box");
    if (region_dynamic(r))
        gr_error(g, "fix deposit region cannot be dynamic");
    for (int q = 0; q < 3; q++) {
        d->lo[q] = r->bbox_lo[q];
        d->hi[q] = r->bbox_hi[q];
        if (d->lo[q] < g->dom.lo[q] || d->hi[q] > g->dom.hi[q])
            gr_error(g, "deposition region extends outside simulation box");
    }
    /* LAMMPS's scaling of every length and velocity (units lattice) */
    double s[3] = {1, 1, 1};
    domain_unit_scale(g, lattice, s);
    const int up = g->dom.dimension == 2 ? 1 : 2;
    d->glo *= s[up];
    d->ghi *= s[up];
    d->rate *= s[up];
    d->deltasq *= s[0] * s[0];
    d->nearsq *= s[0] * s[0];
    for (int q = 0; q < 3; q++) {
        d->vlo[q] *= s[q];
        d->vhi[q] *= s[q];
        d->mid[q] *= s[q];
        d->t[q] *= s[q];
    }
    d->sigma *= s[0];
    if (d->idnext)
        d->maxtag = par_max_atom_tag(g);
    rng_park_init(&d->rng, d->seed);
    for (int k = 0; k < 30; k++) /* LAMMPS: warm up against consecutive seeds */
        rng_park_uniform(&d->rng);
    f->force_reneighbor = 1;
    f->next_reneighbor = g->step + 1;
    d->nfirst = f->next_reneighbor - d->nfreq;
    d->warn = 1;
    f->hooks = HOOK_PRE_EXCHANGE;
}

/* LAMMPS's init and setup_pre_exchange: the region, the next insertion step */
static void init(struct gravel *g, struct fix *f)
{
    struct deposit *d = f->data;
    region_get(g, d->region);
    d->warn = 1;
    if (d->ninserted < d->ninsert)
        f->next_reneighbor =
            d->nfirst + ((g->step - d->nfirst) / d->nfreq) * d->nfreq + d->nfreq;
    else
        f->next_reneighbor = 0;
}

/* the highest atom (laterally within delta of c with `local`) */
static double highest(struct gravel *g, const struct deposit *d, const double c[3], int up)
{
    const struct atoms *a = &g->atoms;
    double top = g->dom.lo[up];
    for (int i = 0; i < a->n; i++) {
        const double *x = a->x + 3 * i;
        if (d->local) {
            double del[3] = {c[0] - x[0], c[1] - x[1], 0.0};
            domain_minimum_image(g, del);
            const double rsq = up == 1 ? del[0] * del[0] : del[0] * del[0] + del[1] * del[1];
            if (rsq > d->deltasq)
                continue;
        }
        if (x[up] > top)
            top = x[up];
    }
    if (par_on(g)) { /* several ranks: the highest of every rank's atoms */
        double lo = top;
        comm_minmax(&lo, &top, 1);
    }
    return top;
}

/* nearer than `near` to an atom */
static int crowded(struct gravel *g, const struct deposit *d, const double c[3])
{
    const struct atoms *a = &g->atoms;
    int flag = 0;
    for (int i = 0; i < a->n && !flag; i++) {
        double del[3] = {c[0] - a->x[3 * i], c[1] - a->x[3 * i + 1], c[2] - a->x[3 * i + 2]};
        domain_minimum_image(g, del);
        flag = del[0] * del[0] + del[1] * del[1] + del[2] * del[2] < d->nearsq;
    }
    return par_on(g) ? comm_max_int(flag) : flag; /* several ranks: any rank's atom */
}

static void pre_exchange(struct gravel *g, struct fix *f)
{
    struct deposit *d = f->data;
    if (f->next_reneighbor != g->step)
        return;
    run_sync_host(g); /* the host arrays = the device's atoms, in device order */
    struct atoms *a = &g->atoms;
    const struct region *r = region_get(g, d->region);
    const int up = g->dom.dimension == 2 ? 1 : 2, nold = a->n;
    const double offset = d->rateflag ? (double)(g->step - d->nfirst) * g->dt * d->rate : 0.0;
    const int64_t maxtag = d->idnext ? d->maxtag : par_max_atom_tag(g);
    int success = 0;
    for (int attempt = 0; attempt < d->maxattempt && !success; attempt++) {
        double c[3];
        do {
            for (int q = 0; q < 3; q++)
                c[q] = d->gaussian ? d->mid[q] + rng_park_gaussian(&d->rng) * d->sigma
                                   : d->lo[q] + rng_park_uniform(&d->rng) * (d->hi[q] - d->lo[q]);
        } while (!region_match(r, c));
        c[up] += offset;
        if (d->global || d->local)
            c[up] = highest(g, d, c, up) + d->glo + rng_park_uniform(&d->rng) * (d->ghi - d->glo);
        if (crowded(g, d, c))
            continue;
        double v[3];
        for (int q = 0; q < 3; q++)
            v[q] = d->vlo[q] + rng_park_uniform(&d->rng) * (d->vhi[q] - d->vlo[q]);
        if (d->target) {
            const double vel = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            const double del[3] = {d->t[0] - c[0], d->t[1] - c[1], d->t[2] - c[2]};
            const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
            if (rsq > 0.0) {
                const double rinv = sqrt(1.0 / rsq);
                for (int q = 0; q < 3; q++)
                    v[q] = del[q] * rinv * vel;
            }
        }
        /* on one process: inside the box, or above its top face */
        int inbox = 1, above = c[up] >= g->dom.hi[up];
        for (int q = 0; q < 3; q++) {
            const int in = c[q] >= g->dom.lo[q] && c[q] < g->dom.hi[q];
            inbox = inbox && in;
            if (q != up && q < g->dom.dimension)
                above = above && in;
        }
        if ((inbox || above) && par_owns(g, c)) {
            const int n = atoms_add(g, maxtag + 1, d->ntype, c, 0.5,
                                    4.0 * M_PI / 3.0 * 0.125); /* LAMMPS's default sphere */
            a->mask[n] = 1u | f->groupbit;
            for (int q = 0; q < 3; q++)
                a->v[3 * n + q] = v[q];
        }
        success = 1;
    }
    if (!success && d->warn) {
        gr_warn(g, "one or more particle depositions were unsuccessful (fix %s at step %lld)",
                f->id, (long long)g->step);
        d->warn = 0;
    }
    if (success) {
        d->ninserted++;
        if (d->idnext)
            d->maxtag = maxtag + 1;
    }
    eng_append(g, nold);
    if (d->ninserted < d->ninsert)
        f->next_reneighbor += d->nfreq;
    else
        f->next_reneighbor = 0;
}

/* one atom per insertion step of the run, at most N in all */
static int reserve(struct gravel *g, struct fix *f, bigint nsteps, double *rmax)
{
    struct deposit *d = f->data;
    *rmax = 0.5;
    const bigint next = f->next_reneighbor, last = g->step + nsteps;
    if (next <= g->step || next > last || d->ninserted >= d->ninsert)
        return 0;
    const bigint steps = (last - next) / d->nfreq + 1, left = d->ninsert - d->ninserted;
    return (int)(steps < left ? steps : left);
}

static double scalar(struct gravel *g, struct fix *f)
{
    (void)g;
    return ((struct deposit *)f->data)->ninserted;
}

/* the stream, the count, the schedule and the ID counter */
struct deposit_saved {
    struct rng_park rng;
    int ninserted;
    bigint nfirst, next;
    int64_t maxtag;
};

static size_t write_restart(struct gravel *g, struct fix *f, unsigned char *buf, size_t cap)
{
    (void)g;
    const struct deposit *d = f->data;
    const struct deposit_saved s = {d->rng, d->ninserted, d->nfirst, f->next_reneighbor,
                                    d->maxtag};
    if (buf && cap >= sizeof s)
        memcpy(buf, &s, sizeof s);
    return sizeof s;
}

static void read_restart(struct gravel *g, struct fix *f, const unsigned char *buf, size_t len)
{
    struct deposit *d = f->data;
    struct deposit_saved s;
    if (len != sizeof s)
        gr_error(g, "fix %s: restart state of %zu bytes, expected %zu", f->id, len, sizeof s);
    memcpy(&s, buf, sizeof s);
    d->rng = s.rng;
    d->ninserted = s.ninserted;
    d->nfirst = s.nfirst;
    d->maxtag = s.maxtag;
    f->next_reneighbor = s.next;
}

const struct fix_style fix_style_deposit = {
    .name = "deposit",
    .create = create,
    .init = init,
    .pre_exchange = pre_exchange,
    .reserve = reserve,
    .scalar = scalar,
    .write_restart = write_restart,
    .read_restart = read_restart,
};
