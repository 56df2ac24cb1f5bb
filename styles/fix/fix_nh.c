/* fix_nh.c - the Nose-Hoover integrators of LAMMPS's FixNH, shared by `fix
 * ID group nvt | npt | nph | nvt/sphere | npt/sphere | nph/sphere keyword
 * values...` (styles/fix_<style>.c hold the descriptors; kernels/fix_nh.cl
 * does the per-atom work, this file the thermostat and barostat chains, in
 * LAMMPS's order and arithmetic).
 *
 * Keywords: temp Tstart Tstop Tdamp; iso | aniso | x | y | z Pstart Pstop
 * Pdamp; couple none|xyz|xy|yz|xz; tchain N (3); pchain N (3); mtk yes|no
 * (yes); tloop M (1); ploop M (1); nreset N (0); drag f (0); dilate all |
 * partial | group-ID (all); fixedpoint x y z (box centre at the fix
 * command); disc (/sphere, 2d: inertia 0.5 instead of 0.4). Tilt and
 * off-diagonal components (tri, xy, xz, yz, scale*, flip) are refused: the
 * barostat controls the box lengths only (a triclinic box keeps its tilts,
 * doc/styles/fix_nh.md). nvt needs temp and no pressure, nph a pressure and no temp,
 * npt both.
 *
 * Temperature: the fix's own, as LAMMPS's fix-ID_temp: compute temp (point
 * styles) or temp/sphere (the /sphere styles) of the fix group for nvt, of
 * group all for npt and nph; its degrees of freedom are counted at run
 * setup. Pressure: that temperature's kinetic part plus the pair virial of
 * the last force computation (src/engine/pressure.c), computed once per step
 * (after the step's forces, kept for the next initial_integrate): only runs
 * with a barostat pay for it. The per-atom kinetic terms are summed on the
 * host in tag order (eng_tag_order): deterministic.
 *
 * Box dilation (barostat): the orthogonal box scales about the fixed point
 * by exp(dt/2 omega_dot) twice a step, the atoms of the dilate group with it
 * (LAMMPS remap: x -> lamda -> x), through box_change_apply
 * (src/engine/box_change.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "box_change.h"
#include "compute.h"
#include "device.h"
#include "error.h"
#include "fix.h"
#include "fix_deform.h"
#include "fix_nh.h"
#include "group.h"
#include "par.h"
#include "par_sum.h"
#include "pressure.h"
#include "temperature.h"

enum { NONE, XYZ, XY, YZ, XZ };
enum { ISO, ANISO };
/* kernels/fix_nh.cl flags */
enum { NH_TEMP = 1, NH_PRESS = 2, NH_KICK = 4, NH_DRIFT = 16, NH_SPHERE = 64 };

#define NH_MAXCHAIN 64

struct nh {
    int sphere, tstat, pstat;
    double inertia;                 /* moment of inertia prefactor (sphere 0.4, disc 0.5) */
    /* thermostat */
    double t_start, t_stop, t_period, t_freq, t_target, ke_target, t_current, t0, tdof;
    int mtchain, nc_tchain;
    double eta[NH_MAXCHAIN], eta_dot[NH_MAXCHAIN + 1], eta_dotdot[NH_MAXCHAIN],
        eta_mass[NH_MAXCHAIN];
    double factor_eta;
    /* barostat */
    int pcouple, pstyle, p_flag[3], pdim, mtk, mpchain, nc_pchain, deviatoric, nreset;
    double p_start[3], p_stop[3], p_period[3], p_freq[3], p_target[3], p_hydro, p_freq_max;
    double p_current[3], omega[3], omega_dot[3], omega_mass[3], mtk_term1, mtk_term2;
    double etap[NH_MAXCHAIN], etap_dot[NH_MAXCHAIN + 1], etap_dotdot[NH_MAXCHAIN],
        etap_mass[NH_MAXCHAIN];
    double drag, tdrag_factor, pdrag_factor;
    double vol0, h0_inv[3], sigma[3], fdev[3], fixedpoint[3];
    int allremap;
    unsigned dilatebit;
    char dilate_id[GR_NAMELEN];
    /* time steps */
    double dtv, dtf, dthalf, dt4, dt8, dto;
    /* the fix's temperature and the virial of the last forces */
    struct temp_state temp;
    double mvv[6];                  /* its kinetic tensor diagonal (xx yy zz) */
    double virial[6];
    /* device */
    cl_kernel k_ini, k_fin, k_mvv;
    cl_mem d_mvv;
    int mvv_cap;
    double *h_mvv;
};


static void parse_press(struct gravel *g, struct nh *n, int argc, char **argv, int i, int d0,
                        int d1)
{
    arg_need(g, argc, i, 3, argv[i]);
    for (int d = d0; d <= d1; d++) {
        n->p_start[d] = arg_double(g, argv[i + 1], "Pstart");
        n->p_stop[d] = arg_double(g, argv[i + 2], "Pstop");
        n->p_period[d] = arg_double(g, argv[i + 3], "Pdamp");
        n->p_flag[d] = 1;
    }
}

void fix_nh_create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    struct nh *n = gr_calloc(g, 1, sizeof *n);
    f->data = n;
    int dim = g->dom.dimension;
    n->sphere = strstr(f->style->name, "/sphere") != NULL;
    n->inertia = 0.4;
    n->mtchain = n->mpchain = 3;
    n->nc_tchain = n->nc_pchain = 1;
    n->mtk = 1;
    n->allremap = 1;
    n->pcouple = NONE;
    for (int d = 0; d < 3; d++)
        n->fixedpoint[d] = 0.5 * (g->dom.lo[d] + g->dom.hi[d]);
    const char *name = f->style->name;
    for (int i = 0; i < argc; i++) {
        const char *k = argv[i];
        if (!strcmp(k, "temp")) {
            arg_need(g, argc, i, 3, k);
            n->tstat = 1;
            n->t_start = arg_double(g, argv[i + 1], "Tstart");
            n->t_stop = arg_double(g, argv[i + 2], "Tstop");
            n->t_period = arg_double(g, argv[i + 3], "Tdamp");
            if (n->t_start <= 0 || n->t_stop <= 0)
                gr_error(g, "fix %s: target temperature can not be 0.0", name);
            i += 3;
        } else if (!strcmp(k, "iso") || !strcmp(k, "aniso")) {
            parse_press(g, n, argc, argv, i, 0, 2);
            n->pcouple = !strcmp(k, "iso") ? XYZ : NONE;
            if (dim == 2) {
                n->p_start[2] = n->p_stop[2] = n->p_period[2] = 0;
                n->p_flag[2] = 0;
            }
            i += 3;
        } else if (!strcmp(k, "x") || !strcmp(k, "y") || !strcmp(k, "z")) {
            int d = k[0] - 'x';
            if (d == 2 && dim == 2)
                gr_error(g, "fix %s: z is invalid for a 2d simulation", name);
            parse_press(g, n, argc, argv, i, d, d);
            n->deviatoric = 1;
            i += 3;
        } else if (!strcmp(k, "couple")) {
            arg_need(g, argc, i, 1, k);
            const char *v = argv[++i];
            n->pcouple = !strcmp(v, "xyz") ? XYZ : !strcmp(v, "xy") ? XY : !strcmp(v, "yz") ? YZ
                         : !strcmp(v, "xz") ? XZ : !strcmp(v, "none") ? NONE : -1;
            if (n->pcouple < 0)
                gr_error(g, "fix %s: couple must be none, xyz, xy, yz or xz, got '%.32s'", name,
                         v);
        } else if (!strcmp(k, "drag")) {
            arg_need(g, argc, i, 1, k);
            n->drag = arg_nonneg(g, argv[++i], "drag");
        } else if (!strcmp(k, "dilate")) {
            arg_need(g, argc, i, 1, k);
            const char *v = argv[++i];
            n->allremap = !strcmp(v, "all");
            if (!n->allremap)
                snprintf(n->dilate_id, sizeof n->dilate_id, "%s",
                         !strcmp(v, "partial") ? g->groups.name[f->igroup] : v);
            if (!n->allremap && group_find(g, n->dilate_id) < 0)
                gr_error(g, "fix %s: dilate group '%.64s' does not exist", name, n->dilate_id);
        } else if (!strcmp(k, "tchain") || !strcmp(k, "pchain")) {
            arg_need(g, argc, i, 1, k);
            int v = arg_int(g, argv[++i], k);
            int lo = k[0] == 't' ? 1 : 0;
            if (v < lo || v > NH_MAXCHAIN)
                gr_error(g, "fix %s: %s must be %d to %d, got %d", name, k, lo, NH_MAXCHAIN, v);
            if (k[0] == 't')
                n->mtchain = v;
            else
                n->mpchain = v;
        } else if (!strcmp(k, "mtk")) {
            arg_need(g, argc, i, 1, k);
            n->mtk = arg_yesno(g, argv[++i], k);
        } else if (!strcmp(k, "tloop") || !strcmp(k, "ploop")) {
            arg_need(g, argc, i, 1, k);
            int v = arg_int(g, argv[++i], k);
            if (v < 1) /* LAMMPS accepts 0 and then divides by it */
                gr_error(g, "fix %s: %s must be >= 1, got %d", name, k, v);
            if (k[0] == 't')
                n->nc_tchain = v;
            else
                n->nc_pchain = v;
        } else if (!strcmp(k, "nreset")) {
            arg_need(g, argc, i, 1, k);
            n->nreset = arg_int(g, argv[++i], k);
            if (n->nreset < 0)
                gr_error(g, "fix %s: nreset must be >= 0", name);
        } else if (!strcmp(k, "fixedpoint")) {
            arg_need(g, argc, i, 3, k);
            for (int d = 0; d < 3; d++)
                n->fixedpoint[d] = arg_double(g, argv[i + 1 + d], "fixedpoint");
            i += 3;
        } else if (!strcmp(k, "disc")) {
            if (!n->sphere)
                gr_error(g, "fix %s: unknown keyword 'disc' (a keyword of the /sphere styles)",
                         name);
            if (dim != 2)
                gr_error(g, "fix %s: disc option requires a 2d simulation", name);
            n->inertia = 0.5;
        } else if (!strcmp(k, "tri") || !strcmp(k, "xy") || !strcmp(k, "xz") ||
                   !strcmp(k, "yz") || !strcmp(k, "scalexy") || !strcmp(k, "scalexz") ||
                   !strcmp(k, "scaleyz") || !strcmp(k, "flip")) {
            gr_error(g, "fix %s: keyword '%s' (a tilt factor or off-diagonal stress) is not "
                        "supported: gravel's barostat controls the box lengths only (iso, "
                        "aniso, x, y, z)",
                     name, k);
        } else if (!strcmp(k, "update") || !strcmp(k, "ptemp")) {
            gr_error(g, "fix %s: keyword '%s' is not supported", name, k);
        } else {
            gr_error(g, "fix %s: unknown keyword '%.64s' (expected temp, iso, aniso, x, y, z, "
                        "couple, tchain, pchain, mtk, tloop, ploop, nreset, drag, dilate, "
                        "fixedpoint%s)", name, k, n->sphere ? ", disc" : "");
        }
    }
    for (int d = 0; d < 3; d++)
        n->pstat |= n->p_flag[d];
    /* the style's own requirements (LAMMPS fix_nvt.cpp, fix_npt.cpp, fix_nph.cpp) */
    int wants_t = !strncmp(name, "nvt", 3) || !strncmp(name, "npt", 3);
    int wants_p = !strncmp(name, "npt", 3) || !strncmp(name, "nph", 3);
    if (wants_t && !n->tstat)
        gr_error(g, "temperature control must be used with fix %s (temp Tstart Tstop Tdamp)",
                 name);
    if (!wants_t && n->tstat)
        gr_error(g, "temperature control can not be used with fix %s", name);
    if (wants_p && !n->pstat)
        gr_error(g, "pressure control must be used with fix %s (iso, aniso, x, y or z)", name);
    if (!wants_p && n->pstat)
        gr_error(g, "pressure control can not be used with fix %s", name);
    if (dim == 2 && (n->pcouple == YZ || n->pcouple == XZ))
        gr_error(g, "fix %s: couple %s is invalid for a 2d simulation", name,
                 n->pcouple == YZ ? "yz" : "xz");
    if ((n->pcouple == XYZ && (!n->p_flag[0] || !n->p_flag[1] || (dim == 3 && !n->p_flag[2]))) ||
        (n->pcouple == XY && (!n->p_flag[0] || !n->p_flag[1])) ||
        (n->pcouple == YZ && (!n->p_flag[1] || !n->p_flag[2])) ||
        (n->pcouple == XZ && (!n->p_flag[0] || !n->p_flag[2])))
        gr_error(g, "fix %s: invalid pressure settings (coupled dimensions without a target)",
                 name);
    int cp[3][2] = {{0, 1}, {1, 2}, {0, 2}}, nc = 0, pairs[3];
    if (n->pcouple == XYZ) {
        pairs[nc++] = 0;
        if (dim == 3)
            pairs[nc++] = 2;
    } else if (n->pcouple == XY || n->pcouple == YZ || n->pcouple == XZ) {
        pairs[nc++] = n->pcouple == XY ? 0 : n->pcouple == YZ ? 1 : 2;
    }
    for (int k = 0; k < nc; k++) {
        int a = cp[pairs[k]][0], b = cp[pairs[k]][1];
        if (n->p_start[a] != n->p_start[b] || n->p_stop[a] != n->p_stop[b] ||
            n->p_period[a] != n->p_period[b])
            gr_error(g, "fix %s: invalid pressure settings (coupled dimensions differ)", name);
    }
    for (int d = 0; d < 3; d++)
        if (n->p_flag[d] && !g->dom.periodic[d])
            gr_error(g, "cannot use fix %s on a non-periodic dimension (%c)", name, "xyz"[d]);
    if ((n->tstat && n->t_period <= 0) || (n->p_flag[0] && n->p_period[0] <= 0) ||
        (n->p_flag[1] && n->p_period[1] <= 0) || (n->p_flag[2] && n->p_period[2] <= 0))
        gr_error(g, "fix %s: damping parameters must be > 0.0", name);
    n->pstyle = n->pcouple == XYZ || (dim == 2 && n->pcouple == XY) ? ISO : ANISO;
    if (n->tstat)
        n->t_freq = 1.0 / n->t_period;
    for (int d = 0; d < 3; d++)
        if (n->p_flag[d])
            n->p_freq[d] = 1.0 / n->p_period[d];
    /* the fix's temperature: fix group for nvt, all for npt and nph */
    n->temp.kind = n->sphere ? TEMP_SPHERE_ALL : TEMP_TRANS;
    n->temp.groupbit = !strncmp(name, "nvt", 3) ? f->groupbit : group_bit(0);
    f->hooks = HOOK_INITIAL_INTEGRATE | HOOK_FINAL_INTEGRATE;
    if (n->sphere)
        f->needs |= NEED_ROTATION;
    f->sources[f->nsources++] = "fix_nh.cl";
}

void fix_nh_destroy(struct fix *f)
{
    struct nh *n = f->data;
    if (n) {
        if (n->d_mvv)
            clReleaseMemObject(n->d_mvv);
        free(n->h_mvv);
        free(n);
    }
    f->data = NULL;
}

static double volume(const struct gravel *g)
{
    const struct domain *d = &g->dom;
    double v = (d->hi[0] - d->lo[0]) * (d->hi[1] - d->lo[1]);
    return d->dimension == 3 ? v * (d->hi[2] - d->lo[2]) : v;
}

void fix_nh_init(struct gravel *g, struct fix *f)
{
    struct nh *n = f->data;
    const struct atoms *a = &g->atoms;
    if (n->sphere)
        for (int i = 0; i < a->n; i++)
            if ((a->mask[i] & f->groupbit) && a->radius[i] == 0)
                gr_error(g, "fix %s requires extended particles (atom %lld has radius 0)",
                         f->style->name, (long long)a->tag[i]);
    n->dilatebit = group_bit(0); /* all */
    if (!n->allremap) {
        int ig = group_find(g, n->dilate_id);
        if (ig < 0)
            gr_error(g, "fix %s: dilate group '%s' does not exist", f->style->name,
                     n->dilate_id);
        n->dilatebit = group_bit(ig);
    }
    /* LAMMPS: not both on one component of the stress tensor */
    for (int i = 0; n->pstat && i < g->styles.nfix; i++) {
        const struct fix *o = g->styles.fix[i];
        if (!strcmp(o->style->name, "deform"))
            for (int d = 0; d < 3; d++)
                if (n->p_flag[d] && fix_deform_changes(o, d))
                    gr_error(g, "cannot use fix %s and fix deform on the same component of "
                                "the stress tensor (%c)", f->style->name, "xyz"[d]);
    }
    n->k_ini = eng_kernel(g, "nh_initial");
    n->k_fin = eng_kernel(g, "nh_final");
    n->k_mvv = eng_kernel(g, "nh_mvv");
    double dt = g->dt;
    n->dtv = dt;
    n->dtf = 0.5 * dt; /* ftm2v = 1 in lj, si, cgs */
    n->dthalf = 0.5 * dt;
    n->dt4 = 0.25 * dt;
    n->dt8 = 0.125 * dt;
    n->dto = n->dthalf;
    n->p_freq_max = 0;
    if (n->pstat) {
        n->p_freq_max = fmax(fmax(n->p_freq[0], n->p_freq[1]), n->p_freq[2]);
        n->pdrag_factor = 1.0 - (dt * n->p_freq_max * n->drag / n->nc_pchain);
    }
    if (n->tstat)
        n->tdrag_factor = 1.0 - (dt * n->t_freq * n->drag / n->nc_tchain);
    if (n->pstat) {
        n->pdim = n->p_flag[0] + n->p_flag[1] + n->p_flag[2];
        if (n->vol0 == 0) {
            n->vol0 = volume(g);
            for (int d = 0; d < 3; d++)
                n->h0_inv[d] = 1.0 / (g->dom.hi[d] - g->dom.lo[d]);
        }
    }
    temp_setup(g, &n->temp);
    n->tdof = n->temp.dof;
}

/* ---- the fix's temperature and pressure ---- */

/* T of the fix's temperature from the device velocities (LAMMPS compute
 * temp / temp/sphere scalar) and, with tensor, its kinetic tensor diagonal
 * in n->mvv (the vector). */
static double temperature(struct gravel *g, struct nh *n, int tensor)
{
    struct engine *e = g->eng;
    struct dev_atoms *a = &e->a;
    int na = a->n;
    if (na > n->mvv_cap) {
        if (n->d_mvv)
            clReleaseMemObject(n->d_mvv);
        n->d_mvv = eng_alloc(g, (size_t)e->cap * 8 * e->rsz, "fix nh kinetic terms");
        free(n->h_mvv);
        n->h_mvv = gr_malloc(g, (size_t)e->cap * 8 * sizeof(double));
        n->mvv_cap = e->cap;
    }
    cl_kernel k = n->k_mvv;
    int i = 0;
    eng_arg_int(g, k, i++, na);
    eng_arg_uint(g, k, i++, n->temp.groupbit);
    eng_arg_int(g, k, i++, n->sphere);
    eng_arg_mem(g, k, i++, a->mask);
    eng_arg_mem(g, k, i++, a->v);
    eng_arg_mem(g, k, i++, e->rotation ? a->omega : a->v);
    eng_arg_mem(g, k, i++, a->radius);
    eng_arg_mem(g, k, i++, a->rmass);
    eng_arg_real(g, k, i++, 0.4); /* compute temp/sphere's INERTIA */
    eng_arg_mem(g, k, i++, n->d_mvv);
    eng_launch(g, k, (size_t)na);
    eng_read_reals(g, n->d_mvv, 8 * (size_t)na, n->h_mvv);
    /* every rank's atoms in tag order (keys 2 tag, 2 tag + 1: the spin term
     * after the translational one, as one process adds them) */
    const int *ord = eng_tag_order(g);
    struct par_sum st = {0}, ss[3] = {{0}};
    for (int q = 0; q < na; q++) {
        const double *o = n->h_mvv + 8 * (size_t)ord[q];
        const int64_t key = 2 * g->eng->tag_seen[ord[q]];
        par_sum_add(g, &st, key, o[0]);
        if (n->sphere)
            par_sum_add(g, &st, key + 1, o[1]);
        for (int d = 0; tensor && d < 3; d++) {
            par_sum_add(g, &ss[d], key, o[2 + d]);
            if (n->sphere)
                par_sum_add(g, &ss[d], key + 1, o[5 + d]);
        }
    }
    double t = par_sum_total(g, &st), s[3] = {0, 0, 0};
    for (int d = 0; tensor && d < 3; d++)
        s[d] = par_sum_total(g, &ss[d]);
    double mvv2e = compute_mvv2e(g);
    for (int d = 0; tensor && d < 3; d++)
        n->mvv[d] = s[d] * mvv2e;
    double dof = n->temp.dof;
    double tfactor = dof > 0 ? mvv2e / (dof * temp_boltz(g)) : 0.0;
    return t * tfactor;
}

/* The virial of the forces just computed (kept for the next step's
 * initial_integrate: the forces and positions do not change in between). */
static void take_virial(struct gravel *g, struct nh *n)
{
    pressure_virial(g, n->virial);
}

/* p_current from temperature t (LAMMPS compute pressure with the fix's
 * temperature, then FixNH::couple). */
static void pressure_couple(struct gravel *g, struct nh *n, double t)
{
    int dim = g->dom.dimension;
    double inv_volume = 1.0 / volume(g), nktv2p = 1.0;
    const double *w = n->virial;
    if (n->pstyle == ISO) {
        double ke = n->temp.dof * temp_boltz(g) * t, p;
        if (dim == 3)
            p = (ke + w[0] + w[1] + w[2]) / 3.0 * inv_volume * nktv2p;
        else
            p = (ke + w[0] + w[1]) / 2.0 * inv_volume * nktv2p;
        n->p_current[0] = n->p_current[1] = n->p_current[2] = p;
        return;
    }
    double tensor[3];
    for (int d = 0; d < 3; d++)
        tensor[d] = d < dim ? (n->mvv[d] + w[d]) * inv_volume * nktv2p : 0.0;
    if (n->pcouple == XYZ) {
        double ave = 1.0 / 3.0 * (tensor[0] + tensor[1] + tensor[2]);
        n->p_current[0] = n->p_current[1] = n->p_current[2] = ave;
    } else if (n->pcouple == XY) {
        double ave = 0.5 * (tensor[0] + tensor[1]);
        n->p_current[0] = n->p_current[1] = ave;
        n->p_current[2] = tensor[2];
    } else if (n->pcouple == YZ) {
        double ave = 0.5 * (tensor[1] + tensor[2]);
        n->p_current[1] = n->p_current[2] = ave;
        n->p_current[0] = tensor[0];
    } else if (n->pcouple == XZ) {
        double ave = 0.5 * (tensor[0] + tensor[2]);
        n->p_current[0] = n->p_current[2] = ave;
        n->p_current[1] = tensor[1];
    } else {
        for (int d = 0; d < 3; d++)
            n->p_current[d] = tensor[d];
    }
}

/* ---- the chains (LAMMPS FixNH, operation for operation) ---- */

static double run_fraction(const struct gravel *g)
{
    double delta = (double)(g->step - g->firststep);
    if (delta != 0.0)
        delta /= (double)(g->laststep - g->firststep);
    return delta;
}

static void compute_temp_target(struct gravel *g, struct nh *n)
{
    double delta = run_fraction(g);
    n->t_target = n->t_start + delta * (n->t_stop - n->t_start);
    n->ke_target = n->tdof * temp_boltz(g) * n->t_target;
}

static void compute_sigma(struct gravel *g, struct nh *n)
{
    if (n->nreset > 0) {
        bigint delta = g->step - g->firststep;
        if (delta % n->nreset == 0) {
            n->vol0 = volume(g);
            for (int d = 0; d < 3; d++)
                n->h0_inv[d] = 1.0 / (g->dom.hi[d] - g->dom.lo[d]);
        }
    }
    /* sigma = vol0 h0inv (p_target - p_hydro) h0inv^t, its diagonal
     * (orthogonal: the off-diagonal terms vanish) */
    for (int d = 0; d < 3; d++)
        n->sigma[d] = n->vol0 * (n->h0_inv[d] * ((n->p_target[d] - n->p_hydro) * n->h0_inv[d]));
}

static void compute_press_target(struct gravel *g, struct nh *n)
{
    double delta = run_fraction(g);
    n->p_hydro = 0.0;
    for (int d = 0; d < 3; d++)
        if (n->p_flag[d]) {
            n->p_target[d] = n->p_start[d] + delta * (n->p_stop[d] - n->p_start[d]);
            n->p_hydro += n->p_target[d];
        }
    n->p_hydro /= n->pdim;
    if (n->deviatoric)
        compute_sigma(g, n);
}

/* The atom work: kernels/fix_nh.cl nh_initial with the given flags. */
static void atoms_initial(struct gravel *g, struct fix *f, struct nh *n, int ops, double fe,
                          const double fp[3])
{
    struct engine *e = g->eng;
    struct dev_atoms *a = &e->a;
    cl_kernel k = n->k_ini;
    int i = 0;
    eng_arg_int(g, k, i++, a->n);
    eng_arg_uint(g, k, i++, f->groupbit);
    eng_arg_int(g, k, i++, ops | (n->sphere ? NH_SPHERE : 0));
    eng_arg_mem(g, k, i++, a->mask);
    eng_arg_mem(g, k, i++, a->x);
    eng_arg_mem(g, k, i++, a->v);
    eng_arg_mem(g, k, i++, a->f);
    eng_arg_mem(g, k, i++, e->rotation ? a->omega : a->v);
    eng_arg_mem(g, k, i++, e->rotation ? a->torque : a->f);
    eng_arg_mem(g, k, i++, a->radius);
    eng_arg_mem(g, k, i++, a->rmass);
    eng_arg_real(g, k, i++, fe);
    for (int d = 0; d < 3; d++)
        eng_arg_real(g, k, i++, fp ? fp[d] : 1.0);
    eng_arg_real(g, k, i++, n->dtv);
    eng_arg_real(g, k, i++, n->dtf);
    eng_arg_real(g, k, i++, n->dtf / n->inertia);
    eng_arg_pos_lo(g, k, i);
    eng_launch(g, k, (size_t)a->n);
}

static void nh_v_temp(struct gravel *g, struct fix *f, struct nh *n)
{
    atoms_initial(g, f, n, NH_TEMP, n->factor_eta, NULL);
}


/* The first half of a Nose-Hoover chain update (LAMMPS nhc_*_integrate): each
 * thermostat's velocity, from the last down to the first, scaled by the next
 * one's exp(-ncfac dt8 dot), kicked by dotdot ncfac dt4 and dragged; returns the factor used
 * on dot[0]. dot has m + 1 entries (dot[m] = 0). */
static double chain_half_kick(double *dot, const double *dotdot, int m, double ncfac,
                              double dt8, double dt4, double drag)
{
    double expfac = 1.0;
    for (int ich = m - 1; ich >= 0; ich--) {
        expfac = exp(-ncfac * dt8 * dot[ich + 1]);
        dot[ich] *= expfac;
        dot[ich] += dotdot[ich] * ncfac * dt4;
        dot[ich] *= drag;
        dot[ich] *= expfac;
    }
    return expfac;
}

static void nhc_temp_integrate(struct gravel *g, struct fix *f, struct nh *n)
{
    double boltz = temp_boltz(g), expfac;
    double kecurrent = n->tdof * boltz * n->t_current;
    int m = n->mtchain;
    double t2 = n->t_freq * n->t_freq;
    n->eta_mass[0] = n->tdof * boltz * n->t_target / t2; /* eta_mass_flag */
    for (int ich = 1; ich < m; ich++)
        n->eta_mass[ich] = boltz * n->t_target / t2;
    n->eta_dotdot[0] = n->eta_mass[0] > 0.0 ? (kecurrent - n->ke_target) / n->eta_mass[0] : 0.0;
    double ncfac = 1.0 / n->nc_tchain, dt8 = n->dt8, dt4 = n->dt4, dthalf = n->dthalf;
    for (int iloop = 0; iloop < n->nc_tchain; iloop++) {
        expfac = chain_half_kick(n->eta_dot, n->eta_dotdot, m, ncfac, dt8, dt4, n->tdrag_factor);
        n->factor_eta = exp(-ncfac * dthalf * n->eta_dot[0]);
        nh_v_temp(g, f, n);
        /* the temperature follows the scaling (not recomputed, as LAMMPS) */
        n->t_current *= n->factor_eta * n->factor_eta;
        kecurrent = n->tdof * boltz * n->t_current;
        n->eta_dotdot[0] =
            n->eta_mass[0] > 0.0 ? (kecurrent - n->ke_target) / n->eta_mass[0] : 0.0;
        for (int ich = 0; ich < m; ich++)
            n->eta[ich] += ncfac * dthalf * n->eta_dot[ich];
        n->eta_dot[0] *= expfac;
        n->eta_dot[0] += n->eta_dotdot[0] * ncfac * dt4;
        n->eta_dot[0] *= expfac;
        for (int ich = 1; ich < m; ich++) {
            expfac = exp(-ncfac * dt8 * n->eta_dot[ich + 1]);
            n->eta_dot[ich] *= expfac;
            n->eta_dotdot[ich] = (n->eta_mass[ich - 1] * n->eta_dot[ich - 1] * n->eta_dot[ich - 1] -
                                  boltz * n->t_target) / n->eta_mass[ich];
            n->eta_dot[ich] += n->eta_dotdot[ich] * ncfac * dt4;
            n->eta_dot[ich] *= expfac;
        }
    }
}

static double omega_ke(const struct nh *n)
{
    double ke = 0.0;
    for (int d = 0; d < 3; d++)
        if (n->p_flag[d])
            ke += n->omega_mass[d] * n->omega_dot[d] * n->omega_dot[d];
    return ke;
}

static void nhc_press_integrate(struct gravel *g, struct nh *n)
{
    double boltz = temp_boltz(g), kt = boltz * n->t_target, expfac;
    int m = n->mpchain;
    /* the barostat's kinetic target: kT (ISO), pdof kT otherwise (LAMMPS 2021) */
    double lkt_press = n->pstyle == ISO ? kt : (n->p_flag[0] + n->p_flag[1] + n->p_flag[2]) * kt;
    double kecurrent = omega_ke(n);
    n->etap_dotdot[0] = (kecurrent - lkt_press) / n->etap_mass[0];
    double ncfac = 1.0 / n->nc_pchain, dt8 = n->dt8, dt4 = n->dt4, dthalf = n->dthalf;
    for (int iloop = 0; iloop < n->nc_pchain; iloop++) {
        expfac = chain_half_kick(n->etap_dot, n->etap_dotdot, m, ncfac, dt8, dt4, n->pdrag_factor);
        for (int ich = 0; ich < m; ich++)
            n->etap[ich] += ncfac * dthalf * n->etap_dot[ich];
        double factor_etap = exp(-ncfac * dthalf * n->etap_dot[0]);
        for (int d = 0; d < 3; d++)
            if (n->p_flag[d])
                n->omega_dot[d] *= factor_etap;
        kecurrent = omega_ke(n);
        n->etap_dotdot[0] = (kecurrent - lkt_press) / n->etap_mass[0];
        n->etap_dot[0] *= expfac;
        n->etap_dot[0] += n->etap_dotdot[0] * ncfac * dt4;
        n->etap_dot[0] *= expfac;
        for (int ich = 1; ich < m; ich++) {
            expfac = exp(-ncfac * dt8 * n->etap_dot[ich + 1]);
            n->etap_dot[ich] *= expfac;
            n->etap_dotdot[ich] = (n->etap_mass[ich - 1] * n->etap_dot[ich - 1] *
                                       n->etap_dot[ich - 1] - boltz * n->t_target) /
                                  n->etap_mass[ich];
            n->etap_dot[ich] += n->etap_dotdot[ich] * ncfac * dt4;
            n->etap_dot[ich] *= expfac;
        }
    }
}

static void nh_omega_dot(struct gravel *g, struct nh *n)
{
    /* every rank's atoms (LAMMPS's natoms): one rank's count would give each
     * rank its own barostat and box */
    double vol = volume(g), nktv2p = 1.0, natoms = (double)par_natoms(g);
    if (n->deviatoric) /* h sigma h^t, its diagonal */
        for (int d = 0; d < 3; d++) {
            double h = g->dom.hi[d] - g->dom.lo[d];
            n->fdev[d] = h * (n->sigma[d] * h);
        }
    n->mtk_term1 = 0.0;
    if (n->mtk) {
        if (n->pstyle == ISO) {
            n->mtk_term1 = n->tdof * temp_boltz(g) * n->t_current;
            n->mtk_term1 /= n->pdim * natoms;
        } else {
            for (int d = 0; d < 3; d++)
                if (n->p_flag[d])
                    n->mtk_term1 += n->mvv[d];
            n->mtk_term1 /= n->pdim * natoms;
        }
    }
    for (int d = 0; d < 3; d++)
        if (n->p_flag[d]) {
            double f_omega = (n->p_current[d] - n->p_hydro) * vol / (n->omega_mass[d] * nktv2p) +
                             n->mtk_term1 / n->omega_mass[d];
            if (n->deviatoric)
                f_omega -= n->fdev[d] / (n->omega_mass[d] * nktv2p);
            n->omega_dot[d] += f_omega * n->dthalf;
            n->omega_dot[d] *= n->pdrag_factor;
        }
    n->mtk_term2 = 0.0;
    if (n->mtk) {
        for (int d = 0; d < 3; d++)
            if (n->p_flag[d])
                n->mtk_term2 += n->omega_dot[d];
        n->mtk_term2 /= n->pdim * natoms;
    }
}

static void press_factors(const struct nh *n, double fp[3])
{
    for (int d = 0; d < 3; d++)
        fp[d] = exp(-n->dt4 * (n->omega_dot[d] + n->mtk_term2));
}

/* One half-step box change, LAMMPS remap: the box scales about the fixed
 * point by exp(dto omega_dot) in each barostatted dimension, the atoms of
 * the dilate group keep their lamda coordinates (src/engine/box_change.c). */
static void remap(struct gravel *g, struct nh *n)
{
    for (int q = 0; q < 3; q++)
        n->omega[q] += n->dto * n->omega_dot[q];
    struct box_target b;
    box_current(g, &b);
    for (int q = 0; q < 3; q++)
        if (n->p_flag[q]) {
            double oldlo = b.lo[q], oldhi = b.hi[q];
            double expfac = exp(n->dto * n->omega_dot[q]);
            b.lo[q] = (oldlo - n->fixedpoint[q]) * expfac + n->fixedpoint[q];
            b.hi[q] = (oldhi - n->fixedpoint[q]) * expfac + n->fixedpoint[q];
        }
    box_change_apply(g, &b, BOX_REMAP_X, n->dilatebit);
}

/* ---- hooks ---- */

void fix_nh_setup(struct gravel *g, struct fix *f)
{
    struct nh *n = f->data;
    double boltz = temp_boltz(g);
    n->tdof = n->temp.dof;
    if (n->tstat) {
        compute_temp_target(g, n);
    } else if (n->pstat) {
        if (n->t0 == 0.0) { /* reference temperature of the barostat masses */
            n->t0 = temperature(g, n, 1);
            if (n->t0 == 0.0)
                n->t0 = g->dom.units == UNITS_LJ ? 1.0 : 300.0;
        }
        n->t_target = n->t0;
    }
    if (n->pstat)
        compute_press_target(g, n);
    n->t_current = temperature(g, n, 1);
    if (n->pstat) {
        take_virial(g, n);
        pressure_couple(g, n, n->t_current);
    }
    if (n->tstat) {
        double t2 = n->t_freq * n->t_freq;
        n->eta_mass[0] = n->tdof * boltz * n->t_target / t2;
        for (int ich = 1; ich < n->mtchain; ich++)
            n->eta_mass[ich] = boltz * n->t_target / t2;
        for (int ich = 1; ich < n->mtchain; ich++)
            n->eta_dotdot[ich] = (n->eta_mass[ich - 1] * n->eta_dot[ich - 1] *
                                      n->eta_dot[ich - 1] - boltz * n->t_target) /
                                 n->eta_mass[ich];
    }
    if (n->pstat) {
        /* W = (N + 1) kT / p_freq^2 (LAMMPS since 2019), N over every rank */
        double kt = boltz * n->t_target, nkt = ((double)par_natoms(g) + 1) * kt;
        for (int d = 0; d < 3; d++)
            if (n->p_flag[d])
                n->omega_mass[d] = nkt / (n->p_freq[d] * n->p_freq[d]);
        if (n->mpchain) {
            double pf2 = n->p_freq_max * n->p_freq_max;
            n->etap_mass[0] = boltz * n->t_target / pf2;
            for (int ich = 1; ich < n->mpchain; ich++)
                n->etap_mass[ich] = boltz * n->t_target / pf2;
            for (int ich = 1; ich < n->mpchain; ich++)
                n->etap_dotdot[ich] = (n->etap_mass[ich - 1] * n->etap_dot[ich - 1] *
                                           n->etap_dot[ich - 1] - boltz * n->t_target) /
                                      n->etap_mass[ich];
        }
    }
}

void fix_nh_initial_integrate(struct gravel *g, struct fix *f)
{
    struct nh *n = f->data;
    if (n->pstat && n->mpchain)
        nhc_press_integrate(g, n);
    if (n->tstat) {
        compute_temp_target(g, n);
        nhc_temp_integrate(g, f, n);
    }
    if (!n->pstat) {
        atoms_initial(g, f, n, NH_KICK | NH_DRIFT, 1.0, NULL);
        return;
    }
    /* the kinetic part after the thermostat's scaling, with the virial of
     * the last forces */
    double t = temperature(g, n, 1), fp[3];
    pressure_couple(g, n, t);
    compute_press_target(g, n);
    nh_omega_dot(g, n);
    press_factors(n, fp);
    atoms_initial(g, f, n, NH_PRESS | NH_KICK, 1.0, fp);
    remap(g, n);
    atoms_initial(g, f, n, NH_DRIFT, 1.0, NULL);
    remap(g, n);
}

void fix_nh_final_integrate(struct gravel *g, struct fix *f)
{
    struct nh *n = f->data;
    struct engine *e = g->eng;
    struct dev_atoms *a = &e->a;
    double fp[3] = {1, 1, 1};
    if (n->pstat)
        press_factors(n, fp);
    cl_kernel k = n->k_fin;
    int i = 0;
    eng_arg_int(g, k, i++, a->n);
    eng_arg_uint(g, k, i++, f->groupbit);
    eng_arg_int(g, k, i++, (n->pstat ? NH_PRESS : 0) | (n->sphere ? NH_SPHERE : 0));
    eng_arg_mem(g, k, i++, a->mask);
    eng_arg_mem(g, k, i++, a->v);
    eng_arg_mem(g, k, i++, a->f);
    eng_arg_mem(g, k, i++, e->rotation ? a->omega : a->v);
    eng_arg_mem(g, k, i++, e->rotation ? a->torque : a->f);
    eng_arg_mem(g, k, i++, a->radius);
    eng_arg_mem(g, k, i++, a->rmass);
    for (int d = 0; d < 3; d++)
        eng_arg_real(g, k, i++, fp[d]);
    eng_arg_real(g, k, i++, n->dtf);
    eng_arg_real(g, k, i++, n->dtf / n->inertia);
    eng_launch(g, k, (size_t)a->n);
    n->t_current = temperature(g, n, 1);
    n->tdof = n->temp.dof;
    if (n->pstat) {
        take_virial(g, n);
        pressure_couple(g, n, n->t_current);
        nh_omega_dot(g, n);
    }
    if (n->tstat)
        nhc_temp_integrate(g, f, n);
    if (n->pstat && n->mpchain)
        nhc_press_integrate(g, n);
}

/* The conserved quantity's extra energy (LAMMPS's compute_scalar, after
 * Martyna, Tuckerman, Tobias and Klein 1996, eqs. 2 and 8): the thermostat
 * chain's kinetic and potential terms, the barostat's kinetic energy and
 * P_hydro (V - V0) per barostatted dimension, its chain, and with a
 * deviatoric target the strain energy 1/2 Tr(sigma h h^t) (orthogonal box:
 * the diagonal). */
double fix_nh_scalar(struct gravel *g, struct fix *f)
{
    const struct nh *n = f->data;
    const double kt = temp_boltz(g) * n->t_target, nktv2p = 1.0;
    double energy = 0.0;
    if (n->tstat) {
        energy += n->ke_target * n->eta[0] + 0.5 * n->eta_mass[0] * n->eta_dot[0] * n->eta_dot[0];
        for (int ich = 1; ich < n->mtchain; ich++)
            energy += kt * n->eta[ich] + 0.5 * n->eta_mass[ich] * n->eta_dot[ich] * n->eta_dot[ich];
    }
    if (n->pstat) {
        const double vol = volume(g);
        double lkt_press = 0.0;
        for (int d = 0; d < 3; d++)
            if (n->p_flag[d]) {
                energy += 0.5 * n->omega_dot[d] * n->omega_dot[d] * n->omega_mass[d] +
                          n->p_hydro * (vol - n->vol0) / (n->pdim * nktv2p);
                lkt_press += kt;
            }
        if (n->mpchain) {
            energy += lkt_press * n->etap[0] +
                      0.5 * n->etap_mass[0] * n->etap_dot[0] * n->etap_dot[0];
            for (int ich = 1; ich < n->mpchain; ich++)
                energy += kt * n->etap[ich] +
                          0.5 * n->etap_mass[ich] * n->etap_dot[ich] * n->etap_dot[ich];
        }
        if (n->deviatoric) {
            double d = 0.0;
            for (int q = 0; q < 3; q++) {
                const double h = g->dom.hi[q] - g->dom.lo[q];
                d += n->sigma[q] * (h * h);
            }
            energy += 0.5 * d / nktv2p;
        }
    }
    return energy;
}

/* ---- restart: the chains' state (LAMMPS pack_restart_data) ---- */

size_t fix_nh_write_restart(struct gravel *g, struct fix *f, unsigned char *buf, size_t cap)
{
    (void)g;
    struct nh *n = f->data;
    double v[8 + 4 * NH_MAXCHAIN];
    size_t k = 0;
    for (int q = 0; q < n->mtchain; q++)
        v[k++] = n->eta[q], v[k++] = n->eta_dot[q];
    for (int q = 0; q < 3; q++)
        v[k++] = n->omega[q], v[k++] = n->omega_dot[q];
    v[k++] = n->vol0;
    v[k++] = n->t0;
    for (int q = 0; q < n->mpchain; q++)
        v[k++] = n->etap[q], v[k++] = n->etap_dot[q];
    size_t bytes = k * sizeof(double);
    if (buf && bytes <= cap)
        memcpy(buf, v, bytes);
    return bytes;
}

void fix_nh_read_restart(struct gravel *g, struct fix *f, const unsigned char *buf,
                         size_t len)
{
    struct nh *n = f->data;
    size_t want = (size_t)(2 * n->mtchain + 8 + 2 * n->mpchain) * sizeof(double);
    if (len != want)
        gr_error(g, "fix %s %s: restart state of %zu bytes, expected %zu (other chain "
                    "lengths)", f->id, f->style->name, len, want);
    double v[8 + 4 * NH_MAXCHAIN];
    memcpy(v, buf, len);
    size_t k = 0;
    for (int q = 0; q < n->mtchain; q++)
        n->eta[q] = v[k++], n->eta_dot[q] = v[k++];
    for (int q = 0; q < 3; q++)
        n->omega[q] = v[k++], n->omega_dot[q] = v[k++];
    n->vol0 = v[k++];
    n->t0 = v[k++];
    for (int q = 0; q < n->mpchain; q++)
        n->etap[q] = v[k++], n->etap_dot[q] = v[k++];
}
