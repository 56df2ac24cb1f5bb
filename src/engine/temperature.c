/* temperature.c - temperatures and their degrees of freedom (temperature.h). */
#include "comm.h"
#include "par.h"
#include "par_sum.h"
#include "temperature.h"

#include <string.h>

#include "args.h"
#include "atoms.h"
#include "compute.h"
#include "device.h"
#include "error.h"
#include "fix.h"

#define INERTIA 0.4 /* LAMMPS compute temp/sphere: solid sphere, in 2d as well */

double temp_boltz(const struct gravel *g)
{
    switch (g->dom.units) {
    case UNITS_SI: return 1.3806504e-23;
    case UNITS_CGS: return 1.3806504e-16;
    case UNITS_LJ: break;
    }
    return 1.0;
}

/* TEMP_REGION: the region its compute resolved, else NULL */
static const void *temp_region(struct gravel *g, const struct temp_state *t)
{
    if (t->kind != TEMP_REGION)
        return NULL;
    if (!t->region_obj || !t->region_in)
        gr_error(g, "compute temp/region: region %s is not set up", t->region);
    return t->region_obj;
}

/* atom i of the group counts (TEMP_REGION: also inside the region, now) */
static int counts(struct gravel *g, const struct temp_state *t, const void *r, int i)
{
    const struct atoms *a = &g->atoms;
    return (a->mask[i] & t->groupbit) && (!r || t->region_in(r, a->x + 3 * i));
}

static int partial_n(const struct temp_state *t)
{
    return t->flags[0] + t->flags[1] + t->flags[2];
}

/* the degrees of freedom a sphere temperature's bias takes away (LAMMPS's
 * temp/sphere dof_compute): temp/partial's uncounted components of every
 * atom (mode all only), temp/region's every degree of freedom of the atoms
 * outside its region; temp/com none */
static double bias_dof(struct gravel *g, const struct temp_state *t, double natoms)
{
    const struct temp_state *b = t->bias;
    const int dim = g->dom.dimension, all = t->kind == TEMP_SPHERE_ALL;
    if (!b)
        return 0.0;
    if (b->kind == TEMP_PARTIAL)
        return all ? (double)(dim - partial_n(b)) * natoms : 0.0;
    if (b->kind != TEMP_REGION)
        return 0.0;
    const struct atoms *a = &g->atoms;
    const void *r = temp_region(g, b);
    long long n = 0;
    for (int i = 0; i < a->n; i++) {
        if (!(a->mask[i] & t->groupbit) || b->region_in(r, a->x + 3 * i))
            continue;
        const int rot = a->radius[i] > 0.0 ? (dim == 3 ? 3 : 1) : 0;
        n += (all ? dim : 0) + rot;
    }
    return (double)(par_on(g) ? comm_sum_ll(n) : n);
}

static double count_dof(struct gravel *g, const struct temp_state *t, double *natoms_out)
{
    const struct atoms *a = &g->atoms;
    const void *r = temp_region(g, t);
    int dim = g->dom.dimension;
    double count = 0, natoms = 0;
    for (int i = 0; i < a->n; i++) {
        if (!counts(g, t, r, i))
            continue;
        natoms++;
        int finite = a->radius[i] > 0.0;
        switch (t->kind) {
        case TEMP_TRANS:
        case TEMP_COM:
        case TEMP_PROFILE:
        case TEMP_REGION: count += dim; break;
        case TEMP_PARTIAL: count += partial_n(t); break;
        case TEMP_SPHERE_ALL: count += dim + (finite ? (dim == 3 ? 3 : 1) : 0); break;
        case TEMP_SPHERE_ROTATE: count += finite ? (dim == 3 ? 3 : 1) : 0; break;
        }
    }
    if (par_on(g)) { /* integer counts: exact on any number of ranks */
        natoms = (double)comm_sum_ll((long long)natoms);
        count = (double)comm_sum_ll((long long)count);
    }
    double extra = t->extra_set ? t->extra_dof : dim;
    if (t->kind == TEMP_REGION) { /* LAMMPS's temp/region: no fix dof */
        count -= extra;
    } else if (t->kind != TEMP_SPHERE_ROTATE) {
        /* LAMMPS's fix_dof: what fixes (rigid bodies) remove */
        double fixdof = 0;
        for (int i = 0; i < g->styles.nfix; i++)
            if (g->styles.fix[i]->style->dof)
                fixdof += g->styles.fix[i]->style->dof(g, g->styles.fix[i], t->groupbit);
        /* temp/partial: the share of the counted components */
        const double share = t->kind == TEMP_PARTIAL ? (double)partial_n(t) / dim : 1.0;
        count -= share * (extra + fixdof);
    }
    if (t->kind == TEMP_PROFILE) /* each bin's mean velocity (LAMMPS: Evans and Morriss) */
        count -= (double)dim * temp_profile_nbins(t);
    count -= bias_dof(g, t, natoms);
    *natoms_out = natoms;
    return count;
}

void temp_setup(struct gravel *g, struct temp_state *t)
{
    double natoms = 0;
    t->dof = count_dof(g, t, &natoms);
    t->dof_natoms = natoms;
    t->dof_valid = 1;
}

/* some fix removes degrees of freedom (fix rigid/small's bodies) */
static int removes_dof(struct gravel *g)
{
    for (int i = 0; i < g->styles.nfix; i++)
        if (g->styles.fix[i]->style->dof)
            return 1;
    return 0;
}

/* LAMMPS raises a negative count when the temperature is evaluated, not
 * when it is set up (a deck whose thermo never reads it runs) */
double temp_dof(struct gravel *g, struct temp_state *t)
{
    int in_run = g->eng && g->eng->active;
    if (t->dynamic || t->kind == TEMP_REGION || (t->bias && t->bias->kind == TEMP_REGION) ||
        !in_run || !t->dof_valid)
        temp_setup(g, t);
    if (t->dof < 0 && t->dof_natoms > 0)
        gr_error(g, "temperature degrees of freedom < 0 (%g atoms, extra/dof %g%s)",
                 t->dof_natoms, t->extra_set ? t->extra_dof : g->dom.dimension,
                 removes_dof(g) ? ", rigid bodies" : "");
    return t->dof;
}

/* TEMP_COM: the group's centre-of-mass velocity (LAMMPS's group vcm), else 0 */
static void bias_velocity(struct gravel *g, const struct temp_state *t, double vb[3])
{
    vb[0] = vb[1] = vb[2] = 0.0;
    if (t->kind != TEMP_COM)
        return;
    const struct atoms *a = &g->atoms;
    const int *order = atoms_tag_order(g);
    struct par_sum s[4] = {{0}}; /* every rank's atoms, in tag order */
    for (int k = 0; k < a->n; k++) {
        const int i = order[k];
        if (!(a->mask[i] & t->groupbit))
            continue;
        const double m = a->rmass[i];
        for (int d = 0; d < 3; d++)
            par_sum_add(g, &s[d], a->tag[i], a->v[3 * i + d] * m);
        par_sum_add(g, &s[3], a->tag[i], m);
    }
    const double mt = par_sum_total(g, &s[3]);
    for (int d = 0; d < 3; d++) {
        const double p = par_sum_total(g, &s[d]);
        vb[d] = mt > 0 ? p / mt : 0.0;
    }
}

int temp_profile_nbins(const struct temp_state *t)
{
    return t->nbin[0] * t->nbin[1] * t->nbin[2];
}

int *temp_profile_bins(struct gravel *g, const struct temp_state *t)
{
    const struct atoms *a = &g->atoms;
    if (g->dom.xy != 0.0 || g->dom.xz != 0.0 || g->dom.yz != 0.0)
        gr_error(g, "compute temp/profile: bins in a tilted triclinic box are not supported");
    int *bin = gr_malloc(g, ((size_t)a->n + 1) * sizeof *bin);
    for (int i = 0; i < a->n; i++) {
        bin[i] = -1;
        if (!(a->mask[i] & t->groupbit))
            continue;
        int ib[3] = {0, 0, 0};
        for (int d = 0; d < 3; d++) {
            if (t->nbin[d] <= 1)
                continue;
            const double lo = g->dom.lo[d], hi = g->dom.hi[d], prd = hi - lo;
            double c = a->x[3 * i + d];
            if (g->dom.periodic[d]) {
                if (c < lo)
                    c += prd;
                if (c >= hi)
                    c -= prd;
            }
            const int k = (int)((c - lo) * (t->nbin[d] / prd));
            ib[d] = k < 0 ? 0 : k > t->nbin[d] - 1 ? t->nbin[d] - 1 : k;
        }
        bin[i] = t->nbin[0] * t->nbin[1] * ib[2] + t->nbin[0] * ib[1] + ib[0];
    }
    return bin;
}

double *temp_profile_means(struct gravel *g, const struct temp_state *t, const int *bin)
{
    const struct atoms *a = &g->atoms;
    const int nb = temp_profile_nbins(t);
    const int *order = atoms_tag_order(g);
    struct par_sum *s = gr_calloc(g, 4 * (size_t)nb, sizeof *s); /* vx vy vz count */
    for (int k = 0; k < a->n; k++) {
        const int i = order[k];
        if (bin[i] < 0)
            continue;
        for (int d = 0; d < 3; d++)
            if (t->flags[d])
                par_sum_add(g, &s[4 * bin[i] + d], a->tag[i], a->v[3 * i + d]);
        par_sum_add(g, &s[4 * bin[i] + 3], a->tag[i], 1.0);
    }
    double *mean = gr_malloc(g, 4 * (size_t)nb * sizeof *mean);
    for (int j = 0; j < 4 * nb; j++)
        mean[j] = par_sum_total(g, &s[j]);
    free(s);
    for (int j = 0; j < nb; j++)
        if (mean[4 * j + 3] > 0.0)
            for (int d = 0; d < 3; d++)
                mean[4 * j + d] /= mean[4 * j + 3];
    return mean;
}

double temp_profile_bias(const struct temp_state *t, const int *bin, const double *mean, int i,
                         int d)
{
    return t->flags[d] && bin[i] >= 0 ? mean[4 * bin[i] + d] : 0.0;
}

/* the bias an atom's velocity loses: vb (TEMP_COM's, else 0), or with a
 * profile (bin and mean non-NULL) its bin's mean of the flagged components */
static void atom_bias(const struct temp_state *b, const double vb[3], const int *bin,
                      const double *mean, int i, double out[3])
{
    for (int d = 0; d < 3; d++)
        out[d] = mean ? temp_profile_bias(b, bin, mean, i, d) : vb[d];
}

/* the velocity atom i's temperature counts: v minus the bias (TEMP_COM),
 * the uncounted components zeroed (TEMP_PARTIAL); a sphere temperature
 * with `bias` takes its bias's rule, and its atoms outside a temp/region
 * bias's region count no translation (LAMMPS's remove_bias_all) */
static void thermal_velocity(const struct gravel *g, const struct temp_state *t, int i,
                             const double vb[3], double u[3])
{
    const double *v = g->atoms.v + 3 * i;
    const struct temp_state *b = t->bias ? t->bias : t;
    const int out = t->bias && b->kind == TEMP_REGION &&
                    !b->region_in(b->region_obj, g->atoms.x + 3 * i);
    for (int d = 0; d < 3; d++) {
        u[d] = v[d] - vb[d];
        if ((b->kind == TEMP_PARTIAL && !b->flags[d]) || out)
            u[d] = 0.0;
    }
}

/* a profile bias's bins and means (NULL, NULL for the other kinds) */
static void profile_of(struct gravel *g, const struct temp_state *b, int **bin, double **mean)
{
    *bin = NULL;
    *mean = NULL;
    if (b->kind != TEMP_PROFILE)
        return;
    *bin = temp_profile_bins(g, b);
    *mean = temp_profile_means(g, b, *bin);
}

/* sum m u.u (+ I m r^2 w.w) over the counted atoms, tag order. */
static double sum_mv2(struct gravel *g, const struct temp_state *t)
{
    const struct atoms *a = &g->atoms;
    const void *r = temp_region(g, t);
    const int *order = atoms_tag_order(g);
    const struct temp_state *b = t->bias ? t->bias : t;
    double vb0[3], vb[3], *mean;
    int *bin;
    bias_velocity(g, b, vb0);
    profile_of(g, b, &bin, &mean);
    struct par_sum sum = {0}; /* every rank's atoms, in tag order */
    for (int k = 0; k < a->n; k++) {
        const int i = order[k];
        if (!counts(g, t, r, i))
            continue;
        const double *w = a->omega + 3 * i, m = a->rmass[i], rad = a->radius[i];
        double u[3];
        atom_bias(b, vb0, bin, mean, i, vb);
        thermal_velocity(g, t, i, vb, u);
        if (t->kind != TEMP_SPHERE_ROTATE)
            par_sum_add(g, &sum, 2 * a->tag[i], (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) * m);
        if (t->kind == TEMP_SPHERE_ALL || t->kind == TEMP_SPHERE_ROTATE)
            par_sum_add(g, &sum, 2 * a->tag[i] + 1,
                        (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]) * INERTIA * rad * rad * m);
    }
    free(bin);
    free(mean);
    return par_sum_total(g, &sum);
}

double temp_scalar(struct gravel *g, struct temp_state *t)
{
    double dof = temp_dof(g, t);
    if (!(dof > 0))
        return 0.0;
    return sum_mv2(g, t) * (compute_mvv2e(g) / (dof * temp_boltz(g)));
}

void temp_vector(struct gravel *g, struct temp_state *t, double out[6])
{
    const struct atoms *a = &g->atoms;
    const void *r = temp_region(g, t);
    const int *order = atoms_tag_order(g);
    const struct temp_state *b = t->bias ? t->bias : t;
    double vb0[3], vb[3], *mean;
    int *bin;
    bias_velocity(g, b, vb0);
    profile_of(g, b, &bin, &mean);
    struct par_sum s[6] = {{0}}; /* every rank's atoms, in tag order */
    for (int k = 0; k < a->n; k++) {
        const int i = order[k];
        if (!counts(g, t, r, i))
            continue;
        const double *w = a->omega + 3 * i, m = a->rmass[i], rad = a->radius[i];
        double v[3];
        atom_bias(b, vb0, bin, mean, i, vb);
        thermal_velocity(g, t, i, vb, v);
        const int64_t key = 2 * a->tag[i];
        if (t->kind != TEMP_SPHERE_ROTATE) {
            par_sum_add(g, &s[0], key, m * v[0] * v[0]);
            par_sum_add(g, &s[1], key, m * v[1] * v[1]);
            par_sum_add(g, &s[2], key, m * v[2] * v[2]);
            par_sum_add(g, &s[3], key, m * v[0] * v[1]);
            par_sum_add(g, &s[4], key, m * v[0] * v[2]);
            par_sum_add(g, &s[5], key, m * v[1] * v[2]);
        }
        if (t->kind == TEMP_SPHERE_ALL || t->kind == TEMP_SPHERE_ROTATE) {
            double in = INERTIA * m * rad * rad;
            par_sum_add(g, &s[0], key + 1, in * w[0] * w[0]);
            par_sum_add(g, &s[1], key + 1, in * w[1] * w[1]);
            par_sum_add(g, &s[2], key + 1, in * w[2] * w[2]);
            par_sum_add(g, &s[3], key + 1, in * w[0] * w[1]);
            par_sum_add(g, &s[4], key + 1, in * w[0] * w[2]);
            par_sum_add(g, &s[5], key + 1, in * w[1] * w[2]);
        }
    }
    free(bin);
    free(mean);
    for (int d = 0; d < 6; d++)
        out[d] = par_sum_total(g, &s[d]) * compute_mvv2e(g);
}

int temp_has_bias(const struct temp_state *t)
{
    return t->kind == TEMP_COM || t->kind == TEMP_PARTIAL || t->kind == TEMP_REGION ||
           t->kind == TEMP_PROFILE;
}

double *temp_bias_remove(struct gravel *g, struct temp_state *t)
{
    struct atoms *a = &g->atoms;
    const void *r = temp_region(g, t);
    double vcm[3], *mean;
    int *bin;
    bias_velocity(g, t, vcm);
    profile_of(g, t, &bin, &mean);
    double *vb = gr_calloc(g, 3 * (size_t)a->n + 1, sizeof *vb);
    for (int i = 0; i < a->n; i++) {
        if (!(a->mask[i] & t->groupbit))
            continue;
        double *v = a->v + 3 * i, *b = vb + 3 * i;
        for (int d = 0; d < 3; d++) {
            if (t->kind == TEMP_COM || t->kind == TEMP_PROFILE) {
                b[d] = t->kind == TEMP_COM ? vcm[d] : temp_profile_bias(t, bin, mean, i, d);
                v[d] -= b[d];
            } else if ((t->kind == TEMP_PARTIAL && !t->flags[d]) ||
                       (r && !t->region_in(r, a->x + 3 * i))) {
                b[d] = v[d];
                v[d] = 0.0;
            }
        }
    }
    free(bin);
    free(mean);
    return vb;
}

void temp_bias_reapply(struct gravel *g, const struct temp_state *t)
{
    struct atoms *a = &g->atoms;
    if (t->kind != TEMP_PARTIAL)
        return;
    for (int i = 0; i < a->n; i++)
        if (a->mask[i] & t->groupbit)
            for (int d = 0; d < 3; d++)
                if (!t->flags[d])
                    a->v[3 * i + d] = 0.0;
}

void temp_bias_restore(struct gravel *g, const struct temp_state *t, double *vb)
{
    struct atoms *a = &g->atoms;
    for (int i = 0; i < a->n; i++)
        if (a->mask[i] & t->groupbit)
            for (int d = 0; d < 3; d++)
                a->v[3 * i + d] += vb[3 * i + d];
    free(vb);
}

void temp_scale_thermal(struct gravel *g, struct temp_state *t, unsigned groupbit,
                        double factor)
{
    struct atoms *a = &g->atoms;
    double *vb = temp_has_bias(t) ? temp_bias_remove(g, t) : NULL;
    for (int i = 0; i < a->n; i++)
        if (a->mask[i] & groupbit)
            for (int d = 0; d < 3; d++)
                a->v[3 * i + d] *= factor;
    if (vb)
        temp_bias_restore(g, t, vb);
}

struct temp_state *temp_thermo(struct gravel *g)
{
    if (!g->thermo.temp_id[0])
        return &g->thermo.temp;
    struct compute *c = compute_find(g, g->thermo.temp_id);
    if (!c || !c->temp)
        gr_error(g, "thermo_modify temp: compute '%s' is gone or is not a temperature",
                 g->thermo.temp_id);
    return c->temp;
}

void temp_modify(struct gravel *g, struct temp_state *t, int argc, char **argv)
{
    struct temp_state n = *t;
    for (int i = 0; i < argc; i += 2) {
        const char *kw = argv[i];
        arg_need(g, argc, i, 1, kw);
        if (strcmp(kw, "dynamic/dof") == 0 || strcmp(kw, "dynamic") == 0) {
            n.dynamic = arg_yesno(g, argv[i + 1], kw);
        } else if (strcmp(kw, "extra/dof") == 0 || strcmp(kw, "extra") == 0) {
            n.extra_dof = arg_double(g, argv[i + 1], kw);
            n.extra_set = 1;
        } else {
            gr_error(g, "unknown keyword '%.64s' (dynamic/dof, extra/dof)", kw);
        }
    }
    n.dof_valid = 0;
    *t = n;
}

void temp_compute_attach(struct gravel *g, struct compute *c, enum temp_kind kind)
{
    struct temp_state *t = gr_calloc(g, 1, sizeof *t);
    c->data = c->temp = t;
    t->kind = kind;
    t->groupbit = c->groupbit;
    c->scalar_flag = c->vector_flag = 1;
    c->size_vector = 6;
    c->extvector = 1;
}

void temp_compute_init(struct gravel *g, struct compute *c)
{
    temp_setup(g, c->temp);
}

double temp_compute_scalar(struct gravel *g, struct compute *c)
{
    return temp_scalar(g, c->temp);
}

void temp_compute_vector(struct gravel *g, struct compute *c)
{
    temp_vector(g, c->temp, c->vector);
}

/* `compute_modify ID keyword value ...`: dynamic/dof and extra/dof of a
 * temperature compute (temp, temp/sphere) or of the implicit thermo_temp
 * (thermo `temp`, `ke`, `press`), as LAMMPS (temp_modify). Other
 * computes have no settings to modify. */
void cmd_compute_modify(struct gravel *g, int argc, char **argv)
{
    if (argc < 3)
        gr_error(g, "expected: compute_modify ID keyword value ...");
    struct compute *c = compute_find(g, argv[0]);
    if (!c && strcmp(argv[0], "thermo_temp") == 0) {
        temp_modify(g, &g->thermo.temp, argc - 1, argv + 1);
        return;
    }
    c = compute_get(g, argv[0], "compute_modify");
    if (!c->temp)
        gr_error(g, "compute %s (%s) has no settings to modify", c->id, c->style->name);
    temp_modify(g, c->temp, argc - 1, argv + 1);
}
