/* fix_move.c - `fix ID group move style args [units box|lattice]`:
 * prescribed motion of a group, as LAMMPS's fix move (kernels/fix_move.cl):
 *   linear Vx Vy Vz            x = x0 + V t (NULL: that component integrated)
 *   wiggle Ax Ay Az period     x = x0 + A sin(w t), v = A w cos(w t) (NULL: idem)
 *   rotate Px Py Pz Rx Ry Rz period
 *                              x0 turned about the axis R through P by w t,
 *                              v = w R x (x - axis), omega = w R
 *   variable v_dx v_dy v_dz v_vx v_vy v_vz
 *                              equal- or atom-style variables (or NULL; an
 *                              atom-style one gives each atom its own), evaluated each
 *                              step: x = x0 + dx and/or v = vx per component;
 *                              v alone drifts the atom, neither integrates it
 * with t = (step - the step the fix was defined at) dt, w = 2 pi / period,
 * x0 each atom's unwrapped position when the fix was defined (kept by atom
 * ID), `units lattice` (the default) scaling V, A and P by the lattice
 * spacings. The integrated components take LAMMPS's velocity-Verlet kicks.
 * Output: the per-atom array x0 (f_ID[1..3]). reset_timestep moves the
 * motion's clock with the steps (the motion continues where it stood);
 * restart files keep x0 and the clock. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atom_origin.h"
#include "device.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "group.h"
#include "variable.h"

enum move_style { MOVE_LINEAR, MOVE_WIGGLE, MOVE_ROTATE, MOVE_VARIABLE };

struct move {
    enum move_style style;
    int given[3];               /* linear / wiggle: the component is not NULL */
    double vec[3];              /* linear V, wiggle A (scaled) */
    double point[3], runit[3];  /* rotate */
    double omega;               /* wiggle, rotate: 2 pi / period */
    char *var[6];               /* variable: dx dy dz vx vy vz (NULL: none) */
    int aset;                   /* bit k: var[k] is atom-style (each atom's own value) */
    cl_mem dpa;                 /* their values, 6 per atom (device order) */
    size_t dpa_n;
    bigint time_origin;
    struct atom_origin x0;      /* unwrapped positions when defined, by atom ID */
    cl_kernel ini, fin;
    double *out;                /* peratom_values */
};

static void destroy(struct fix *f)
{
    struct move *m = f->data;
    if (!m)
        return;
    for (int k = 0; k < 6; k++)
        free(m->var[k]);
    atom_origin_free(&m->x0);
    free(m->out);
    if (m->dpa)
        clReleaseMemObject(m->dpa);
    free(m);
}

/* a number or NULL (*given 0) */
static double number_or_null(struct gravel *g, const char *s, int *given, const char *what)
{
    *given = strcmp(s, "NULL") != 0;
    return *given ? arg_double(g, s, what) : 0.0;
}

static int style_args(struct gravel *g, struct move *m, int argc, char **argv)
{
    static const char *const vnames[6] = {"dx", "dy", "dz", "vx", "vy", "vz"};
    const char *s = argv[0];
    int need = !strcmp(s, "linear")   ? 4
               : !strcmp(s, "wiggle") ? 5
               : !strcmp(s, "rotate") ? 8
               : !strcmp(s, "variable") ? 7
                                        : 0;
    if (!need)
        gr_error(g, "fix move: unknown style '%.64s' (linear, wiggle, rotate, variable)", s);
    if (argc < need)
        gr_error(g, "fix move %s needs %d values, got %d", s, need - 1, argc - 1);
    if (!strcmp(s, "linear") || !strcmp(s, "wiggle")) {
        m->style = s[0] == 'l' ? MOVE_LINEAR : MOVE_WIGGLE;
        for (int d = 0; d < 3; d++)
            m->vec[d] = number_or_null(g, argv[1 + d], &m->given[d], m->style == MOVE_LINEAR
                                                                         ? "fix move velocity"
                                                                         : "fix move amplitude");
        if (m->style == MOVE_WIGGLE)
            m->omega = 2.0 * M_PI / arg_positive(g, argv[4], "fix move period");
    } else if (!strcmp(s, "rotate")) {
        m->style = MOVE_ROTATE;
        double axis[3];
        for (int d = 0; d < 3; d++) {
            m->point[d] = arg_double(g, argv[1 + d], "fix move rotation point");
            axis[d] = arg_double(g, argv[4 + d], "fix move rotation axis");
        }
        m->omega = 2.0 * M_PI / arg_positive(g, argv[7], "fix move period");
        double len = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
        if (len == 0.0)
            gr_error(g, "fix move: zero length rotation vector");
        for (int d = 0; d < 3; d++)
            m->runit[d] = axis[d] / len;
    } else {
        m->style = MOVE_VARIABLE;
        for (int k = 0; k < 6; k++) {
            const char *a = argv[1 + k];
            if (!strcmp(a, "NULL"))
                continue;
            if (strncmp(a, "v_", 2) || !a[2])
                gr_error(g, "fix move variable: %s must be v_name or NULL, got '%.64s'",
                         vnames[k], a);
            m->var[k] = gr_strdup(g, a + 2);
        }
    }
    return need;
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "fix move needs a style (linear, wiggle, rotate, variable)");
    struct move *m = gr_calloc(g, 1, sizeof *m);
    f->data = m;
    int i = style_args(g, m, argc, argv), lattice = 1;
    while (i < argc) {
        if (strcmp(argv[i], "units"))
            gr_error(g, "fix move: unknown keyword '%.64s' (units)", argv[i]);
        arg_need(g, argc, i, 1, "units");
        if (!strcmp(argv[i + 1], "box"))
            lattice = 0;
        else if (strcmp(argv[i + 1], "lattice"))
            gr_error(g, "fix move: units must be box or lattice, got '%.64s'", argv[i + 1]);
        i += 2;
    }
    if (g->dom.dimension == 2) {
        if ((m->style == MOVE_LINEAR || m->style == MOVE_WIGGLE) && m->given[2] && m->vec[2] != 0)
            gr_error(g, "fix move cannot set %s z motion for a 2d problem",
                     m->style == MOVE_LINEAR ? "linear" : "wiggle");
        if (m->style == MOVE_ROTATE && (m->runit[0] != 0 || m->runit[1] != 0))
            gr_error(g, "fix move cannot rotate around a non-z axis for a 2d problem");
        if (m->style == MOVE_VARIABLE && (m->var[2] || m->var[5]))
            gr_error(g, "fix move cannot define a z or vz variable for a 2d problem");
    }
    if (lattice && m->style != MOVE_VARIABLE) /* LAMMPS's default lattice: spacing 1 */
        for (int d = 0; d < 3; d++) {
            double s = g->dom.lat.style ? g->dom.lat.a[d] : 1.0;
            if (m->style == MOVE_ROTATE)
                m->point[d] *= s;
            else if (m->given[d])
                m->vec[d] *= s;
        }
    atom_origin_take(g, &m->x0, f->groupbit); /* x0: the group's positions now */
    /* LAMMPS moves the local triangles of fix surface/local this way; here they
     * are no atoms (its group would be empty and nothing would move) */
    for (int k = 0; k < g->styles.nfix && group_count(g, f->igroup) == 0; k++)
        if (!strcmp(g->styles.fix[k]->style->name, "surface/local"))
            gr_error(g, "fix move: group %s has no atoms; the triangles of fix surface/local %s "
                        "are not atoms here and cannot be moved by fix move (define them with "
                        "fix surface/global: its fix_modify move turns them)", g->groups.name[f->igroup],
                     g->styles.fix[k]->id);
    m->time_origin = g->step;
    f->hooks = HOOK_INITIAL_INTEGRATE | HOOK_FINAL_INTEGRATE;
    if (m->style == MOVE_ROTATE)
        f->needs |= NEED_ROTATION;
    f->sources[f->nsources++] = "fix_move.cl";
    f->peratom_flag = 1;
    f->size_peratom_cols = 3;
}

static void init(struct gravel *g, struct fix *f)
{
    struct move *m = f->data;
    if (g->dom.triclinic)
        gr_error(g, "fix move %s: triclinic boxes are not supported yet", f->id);
    m->aset = 0;
    for (int k = 0; k < 6; k++) {
        if (!m->var[k])
            continue;
        if (!var_exists(g, m->var[k]))
            gr_error(g, "fix move %s: variable '%s' does not exist", f->id, m->var[k]);
        if (var_is_atom(g, m->var[k]))
            m->aset |= 1 << k;
        else if (!var_is_equal(g, m->var[k]))
            gr_error(g, "fix move %s: variable '%s' is neither equal- nor atom-style", f->id,
                     m->var[k]);
    }
    atom_origin_setup(g, &m->x0, f->groupbit, "fix move", f->id);
    m->ini = eng_kernel(g, "move_initial");
    m->fin = eng_kernel(g, "move_final");
}

/* components set by position (pset), by velocity (vset), integrated (nve) */
static void component_sets(const struct move *m, int *pset, int *vset, int *nve)
{
    *pset = *vset = 0;
    for (int d = 0; d < 3; d++) {
        int p, v;
        if (m->style == MOVE_ROTATE)
            p = v = 1;
        else if (m->style == MOVE_VARIABLE)
            p = m->var[d] != NULL, v = m->var[3 + d] != NULL;
        else
            p = v = m->given[d];
        *pset |= p << d;
        *vset |= v << d;
    }
    *nve = 7 & ~(*pset | *vset);
}

/* The atom-style variables' values of every device atom (LAMMPS's
 * compute_atom on the group; the kernel reads the group's), 6 per atom. */
static void atom_values(struct gravel *g, struct move *m)
{
    const int n = eng_atoms(g)->n;
    double *pa = gr_calloc(g, 6 * (size_t)n + 1, sizeof *pa);
    for (int k = 0; k < 6; k++) {
        if (!(m->aset >> k & 1))
            continue;
        double *v = var_atom_values(g, m->var[k]); /* host atoms = device order */
        for (int i = 0; i < n; i++)
            pa[6 * (size_t)i + k] = v[i];
        free(v);
    }
    if (!m->dpa || m->dpa_n < (size_t)n) {
        if (m->dpa)
            clReleaseMemObject(m->dpa);
        m->dpa_n = (size_t)n + (size_t)n / 8 + 16;
        m->dpa = eng_alloc(g, 6 * m->dpa_n * g->eng->rsz, "fix move atom-style values");
    }
    if (n > 0)
        eng_write_reals(g, m->dpa, 6 * (size_t)n, pa);
    free(pa);
}

static void initial_integrate(struct gravel *g, struct fix *f)
{
    struct move *m = f->data;
    atom_origin_device(g, &m->x0);
    struct dev_atoms *a = eng_atoms(g);
    const double delta = (double)(g->step - m->time_origin) * g->dt;
    double disp[3] = {0, 0, 0}, vel[3] = {0, 0, 0}, cosine = 1, sine = 0;
    int pset, vset, nve;
    component_sets(m, &pset, &vset, &nve);
    if (m->style == MOVE_LINEAR) {
        for (int d = 0; d < 3; d++) {
            vel[d] = m->vec[d];
            disp[d] = m->vec[d] * delta;
        }
    } else if (m->style == MOVE_WIGGLE || m->style == MOVE_ROTATE) {
        double arg = m->omega * delta;
        sine = sin(arg);
        cosine = cos(arg);
        for (int d = 0; d < 3 && m->style == MOVE_WIGGLE; d++) {
            vel[d] = m->vec[d] * m->omega * cosine;
            disp[d] = m->vec[d] * sine;
        }
    } else {
        for (int d = 0; d < 3; d++) {
            if (m->var[d] && !(m->aset >> d & 1))
                disp[d] = var_compute_equal(g, m->var[d]);
            if (m->var[3 + d] && !(m->aset >> (3 + d) & 1))
                vel[d] = var_compute_equal(g, m->var[3 + d]);
        }
        if (m->aset)
            atom_values(g, m);
    }
    cl_kernel k = m->ini;
    int i = 0;
    eng_arg_int(g, k, i++, a->n);
    eng_arg_uint(g, k, i++, f->groupbit);
    eng_arg_mem(g, k, i++, a->mask);
    eng_arg_mem(g, k, i++, a->tag);
    eng_arg_bytes(g, k, i++, sizeof(cl_long), &(cl_long){m->x0.ntab});
    eng_arg_mem(g, k, i++, m->x0.tab);
    eng_arg_mem(g, k, i++, m->x0.tablo);
    eng_arg_mem(g, k, i++, a->x);
    eng_arg_mem(g, k, i++, a->v);
    eng_arg_mem(g, k, i++, a->omega ? a->omega : a->v);
    eng_arg_mem(g, k, i++, a->f);
    eng_arg_mem(g, k, i++, a->rmass);
    eng_arg_mem(g, k, i++, a->radius);
    eng_arg_int(g, k, i++, (int)m->style);
    eng_arg_int(g, k, i++, pset);
    eng_arg_int(g, k, i++, vset);
    eng_arg_int(g, k, i++, m->aset);
    eng_arg_mem(g, k, i++, m->aset ? m->dpa : a->v); /* unread without atom-style values */
    for (int d = 0; d < 3; d++)
        eng_arg_real(g, k, i++, disp[d]);
    for (int d = 0; d < 3; d++)
        eng_arg_real(g, k, i++, vel[d]);
    for (int d = 0; d < 3; d++)
        eng_arg_coord(g, k, i++, d, m->point[d]);
    for (int d = 0; d < 3; d++)
        eng_arg_real(g, k, i++, m->runit[d]);
    eng_arg_real(g, k, i++, m->omega);
    eng_arg_real(g, k, i++, cosine);
    eng_arg_real(g, k, i++, sine);
    for (int d = 0; d < 3; d++)
        eng_arg_int(g, k, i++, g->dom.periodic[d]);
    for (int d = 0; d < 3; d++)
        eng_arg_real(g, k, i++, g->dom.hi[d] - g->dom.lo[d]);
    eng_arg_real(g, k, i++, g->dt);
    eng_arg_real(g, k, i++, 0.5 * g->dt);
    eng_arg_pos_lo(g, k, i);
    eng_launch(g, k, (size_t)a->n);
}

static void final_integrate(struct gravel *g, struct fix *f)
{
    struct move *m = f->data;
    int pset, vset, nve;
    component_sets(m, &pset, &vset, &nve);
    if (!nve)
        return;
    struct dev_atoms *a = eng_atoms(g);
    cl_kernel k = m->fin;
    eng_arg_int(g, k, 0, a->n);
    eng_arg_uint(g, k, 1, f->groupbit);
    eng_arg_mem(g, k, 2, a->mask);
    eng_arg_mem(g, k, 3, a->tag);
    eng_arg_bytes(g, k, 4, sizeof(cl_long), &(cl_long){m->x0.ntab});
    eng_arg_mem(g, k, 5, a->v);
    eng_arg_mem(g, k, 6, a->f);
    eng_arg_mem(g, k, 7, a->rmass);
    eng_arg_int(g, k, 8, nve);
    eng_arg_real(g, k, 9, 0.5 * g->dt);
    eng_launch(g, k, (size_t)a->n);
}

/* f_ID[1..3]: the origins x0 (0 for atoms outside the group, LAMMPS's) */
static const double *peratom_values(struct gravel *g, struct fix *f)
{
    struct move *m = f->data;
    return atom_origin_values(g, &m->x0, f->groupbit, &m->out);
}

/* reset_timestep: the motion keeps its own clock (t = step - origin) */
static void reset_step(struct gravel *g, struct fix *f, bigint shift)
{
    (void)g;
    ((struct move *)f->data)->time_origin += shift;
}

/* restart: the clock, then the origins (atom_origin_write) */
static size_t write_restart(struct gravel *g, struct fix *f, unsigned char *buf, size_t cap)
{
    (void)g;
    const struct move *m = f->data;
    int64_t origin = m->time_origin;
    size_t need = sizeof origin + atom_origin_write(&m->x0, NULL, 0);
    if (!buf || cap < need)
        return need;
    memcpy(buf, &origin, sizeof origin);
    atom_origin_write(&m->x0, buf + sizeof origin, cap - sizeof origin);
    return need;
}

static void read_restart(struct gravel *g, struct fix *f, const unsigned char *buf, size_t len)
{
    struct move *m = f->data;
    int64_t origin;
    if (len < sizeof origin)
        gr_error(g, "fix %s: restart state of %zu bytes is too short", f->id, len);
    memcpy(&origin, buf, sizeof origin);
    atom_origin_read(g, &m->x0, buf + sizeof origin, len - sizeof origin, f->id);
    m->time_origin = origin;
}

const struct fix_style fix_style_move = {
    .name = "move",
    .create = create,
    .init = init,
    .initial_integrate = initial_integrate,
    .final_integrate = final_integrate,
    .destroy = destroy,
    .peratom_values = peratom_values,
    .reset_step = reset_step,
    .write_restart = write_restart,
    .read_restart = read_restart,
};
