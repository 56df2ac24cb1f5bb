/* fix_rigid_small.c - `fix ID group rigid/small molecule [mol T] [gravity G]
 * [reinit yes|no]`: rigid bodies of spheres, one per molecule ID, LAMMPS's
 * FixRigidSmall (RIGID package, 2021) step for step so the bodies follow
 * LAMMPS's trajectories to round-off.
 *
 * A body's state (mass, centre of mass xcm, velocity vcm, angular momentum,
 * quaternion, principal moments and axes ex ey ez) lives on the host; each
 * member atom keeps its displacement from xcm in the body frame. The step,
 * as LAMMPS's velocity Verlet for bodies:
 *   initial_integrate  vcm += dt/2 F/M; xcm += dt vcm; L += dt/2 T;
 *                      omega from L; quaternion a full step by Richardson
 *                      iteration; then every member's x = xcm + R d (mapped
 *                      by its image shift), v = vcm + omega x (x - xcm), and
 *                      a sphere's omega = the body's.
 *   final_integrate    F, T = sums over the members of f and (x - xcm) x f
 *                      plus the spheres' torques (+ M g with `gravity`;
 *                      2d: z force and x, y torque zeroed); vcm, L half
 *                      kicks; omega; members' v and omega.
 *   setup              the same sums (no gravity, as LAMMPS) and v, omega.
 * At every run's start (unless `reinit no`) the bodies are recomputed from
 * their atoms (mass, xcm, inertia tensor diagonalized by Jacobi rotations,
 * vcm and L from the atoms' velocities and spins), as LAMMPS's
 * setup_bodies_static/dynamic. Bodies inserted by fix pour (`mol`
 * template) take the template's mass, centre of mass, principal moments and
 * body-frame displacements (LAMMPS set_molecule).
 *
 * Device and host: each step rigid_gather (kernels/fix_rigid_small.cl)
 * copies the members' forces and torques into a member-order buffer that
 * the host reads and sums per body in ascending tag order (deterministic,
 * no atomics); rigid_scatter writes the members' positions, velocities and
 * spins computed on the host. O(members) per step. The tag -> device index
 * map, the members' periodic image shifts (LAMMPS xcmimage) and the contact
 * masses are refreshed after every neighbor rebuild (post_neighbor), where
 * LAMMPS remaps xcm into the box (pre_neighbor). gravel wraps atoms every
 * step: a member crossing a periodic face is placed inside by its image
 * shift, its image flag = the body's + the shift.
 *
 * Pair and wall contacts of a member use the body's mass as its mass in the
 * effective mass (LAMMPS's mass_rigid, device.h contact_mass). Degrees of
 * freedom (temperatures): a body wholly in the temperature group keeps 6
 * (3d; 5 if linear) or 3 (2d) of its atoms' 3 + 3 (finite spheres) each.
 *
 * `fix ID group multisphere` (LIGGGHTS's clumps, create_multisphere) is this
 * fix with no body at first: the insertion fixes add one per clump of a
 * particletemplate/multisphere template (rigid_small_add_body), bodies keep
 * the template's mass and inertia (no reinit), their atoms (masses M/n) get
 * the body ID as molecule ID and the group ID_clumps (intra-body pairs
 * excluded from the neighbor lists), fix gravity's torque about xcm is
 * removed (gravity at the centre of mass, LIGGGHTS), no degree of freedom
 * is removed and thermo ke counts 1/2 M vcm^2 per body (ke_adjust).
 *
 * Restart files keep the bodies (write_restart, read_restart below).
 *
 * Several MPI ranks (doc/parallel.md): every rank holds every body and
 * every member's host state and integrates them all the same way; the
 * bodies are built at the run's start from every atom (prepare, before the
 * atoms are split). A member's device slot is on the rank that owns its
 * atom (dev -1 elsewhere): after rigid_gather each rank sends its members'
 * forces and torques to every rank (in member order), so every rank sums
 * each body in the same tag order as one process: the same bits on any
 * number of ranks. rigid_scatter writes the owned members; their ghosts
 * get x, v, omega from the forward communication. Contact masses cover the
 * ghost slots too. Bodies inserted by fix pour and the LIGGGHTS insertion
 * fixes are added on every rank (rigid_small_add_body), their atoms kept by
 * the ranks that own them.
 *
 * Not supported (clear errors): langevin, infile, the custom body ID style,
 * thermostats/barostats of rigid/n?t/small. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "comm.h"
#include "domain.h"
#include "device.h"
#include "error.h"
#include "fix.h"
#include "fix_gravity.h"
#include "fix_rigid_small.h"
#include "group.h"
#include "log.h"
#include "molecule.h"
#include "par.h"
#include "rigid_math.h"
#include "temperature.h"

#define SINERTIA 0.4 /* solid sphere */

struct rbody {
    double mass, xcm[3], xgc[3], vcm[3], fcm[3], torque[3], angmom[3], omega[3];
    double quat[4], inertia[3], ex[3], ey[3], ez[3], xgc_body[3];
    int image[3];           /* periodic image of xcm (LAMMPS body image) */
    int natoms;
    /* fix multisphere (LIGGGHTS fflag, tflag): 0 where the body's velocity or
     * angular momentum component is not kicked (held); 1 otherwise */
    unsigned char fflag[3], tflag[3];
    /* fix insert/stream's approach (LIGGGHTS Multisphere start_step_): until
     * step start_step (>= 0) the body moves at v_int, untouched by forces;
     * at its end it gets v_rel (start_step -1: released or never streamed) */
    int64_t start_step;
    double v_int[3], v_rel[3];
};

struct member {
    int64_t tag;
    int body;
    int ext;                /* finite-size sphere (radius > 0): spins with the body */
    int xbox[3];            /* image of the atom relative to its body's (xcmimage) */
    int dev;                /* device index (valid after post_neighbor; -1: owned by
                             * another rank) */
    unsigned mask;          /* its group bits at the run's start (dof) */
    double displace[3];     /* x - xcm in the body frame */
    double x[3];            /* its position as last written to the device (or inserted) */
};

struct rigid {
    struct molecule *mol;
    int ms;                 /* fix multisphere: bodies only from the insertion fixes */
    unsigned member_bits;   /* mask bits of inserted members (multisphere: its clump group) */
    int gcorr;              /* multisphere: fix gravity acts at the bodies' centres of mass */
    double gacc[3];         /* its acceleration */
    char gravity_id[GR_NAMELEN];
    double gvec[3];
    int reinit, extended, setupflag, mapped;
    int nbody, body_cap;
    struct rbody *b;
    int nmem, mem_cap;
    struct member *m;
    int *order;             /* member indices in ascending tag order */
    int order_ok;
    double dtv, dtf, dtq;
    /* host scratch of whole per-atom arrays (device order; rebuilds only) */
    size_t hcap;
    double *hm;
    int64_t *htag;
    int *himg;
    cl_mem cmass;           /* contact masses (engine contact_mass) */
    size_t cmass_cap;
    /* member-order transfers (kernels/fix_rigid_small.cl) */
    cl_kernel k_gather, k_scatter;
    cl_mem d_idx, d_x, d_xl, d_v, d_w, d_out;
    size_t dcap;            /* members the device buffers hold */
    double *mx, *mxl, *mv, *mw, *mout; /* host side, member order */
    /* scratch a function holds while it may raise an error: owned here so
     * that destroy frees it when the error unwinds (fix.c deletes a fix
     * whose create fails; a run's error keeps the fix, and the next hold
     * frees the old scratch) */
    int *held_i;
    double (*held_it)[6];
};

struct molecule *rigid_small_template(const struct fix *f)
{
    if (!f || strcmp(f->style->name, "rigid/small") || !f->data)
        return NULL;
    return ((const struct rigid *)f->data)->mol;
}

static int *hold_ints(struct gravel *g, struct rigid *r, size_t n)
{
    free(r->held_i);
    r->held_i = NULL;
    r->held_i = gr_calloc(g, n, sizeof(int));
    return r->held_i;
}

static void release_ints(struct rigid *r)
{
    free(r->held_i);
    r->held_i = NULL;
}

static struct rbody *new_body(struct gravel *g, struct rigid *r)
{
    if (r->nbody == r->body_cap) {
        r->body_cap = r->body_cap ? 2 * r->body_cap : 16;
        r->b = gr_realloc(g, r->b, (size_t)r->body_cap * sizeof *r->b);
    }
    struct rbody *b = &r->b[r->nbody++];
    memset(b, 0, sizeof *b);
    for (int q = 0; q < 3; q++)
        b->fflag[q] = b->tflag[q] = 1;
    b->start_step = -1;
    return b;
}

static struct member *new_member(struct gravel *g, struct rigid *r)
{
    if (r->nmem == r->mem_cap) {
        r->mem_cap = r->mem_cap ? 2 * r->mem_cap : 64;
        r->m = gr_realloc(g, r->m, (size_t)r->mem_cap * sizeof *r->m);
    }
    struct member *m = &r->m[r->nmem++];
    memset(m, 0, sizeof *m);
    m->dev = -1;
    r->order_ok = 0;
    r->mapped = 0;
    return m;
}

static const struct member *cmp_base;
static int by_tag(const void *a, const void *b)
{
    int64_t ta = cmp_base[*(const int *)a].tag, tb = cmp_base[*(const int *)b].tag;
    return (ta > tb) - (ta < tb);
}

static void sort_members(struct gravel *g, struct rigid *r)
{
    if (r->order_ok)
        return;
    r->order = gr_realloc(g, r->order, (size_t)(r->nmem + 1) * sizeof(int));
    for (int k = 0; k < r->nmem; k++)
        r->order[k] = k;
    cmp_base = r->m;
    qsort(r->order, (size_t)r->nmem, sizeof(int), by_tag);
    r->order_ok = 1;
}

static int64_t *sort_keys;
static int by_key(const void *a, const void *b)
{
    int64_t ta = sort_keys[*(const int *)a], tb = sort_keys[*(const int *)b];
    return (ta > tb) - (ta < tb);
}

/* idx[k] = index in tags[0..n) of member order[k]'s tag, or -1 (both
 * sorted, then merged). */
static void match_tags(struct gravel *g, struct rigid *r, const int64_t *tags, int n, int *idx)
{
    sort_members(g, r);
    int *p = gr_calloc(g, (size_t)(n + 1), sizeof(int));
    for (int i = 0; i < n; i++)
        p[i] = i;
    sort_keys = (int64_t *)tags;
    qsort(p, (size_t)n, sizeof(int), by_key);
    int j = 0;
    for (int k = 0; k < r->nmem; k++) {
        int64_t t = r->m[r->order[k]].tag;
        while (j < n && tags[p[j]] < t)
            j++;
        idx[k] = j < n && tags[p[j]] == t ? p[j] : -1;
    }
    free(p);
}

/* the member (index into r->m) with this tag, or -1 (binary search) */
static int member_of_tag(struct gravel *g, struct rigid *r, int64_t tag)
{
    sort_members(g, r);
    int lo = 0, hi = r->nmem - 1;
    while (lo <= hi) {
        int mid = (lo + hi) / 2;
        int64_t t = r->m[r->order[mid]].tag;
        if (t == tag)
            return r->order[mid];
        if (t < tag)
            lo = mid + 1;
        else
            hi = mid - 1;
    }
    return -1;
}

static double prd(const struct gravel *g, int d)
{
    return g->dom.hi[d] - g->dom.lo[d];
}

/* ---- creation ------------------------------------------------------------------ */

static const int64_t *cmp_mol;
static const int64_t *cmp_tagv;
static int by_mol(const void *a, const void *b)
{
    int i = *(const int *)a, j = *(const int *)b;
    if (cmp_mol[i] != cmp_mol[j])
        return (cmp_mol[i] > cmp_mol[j]) - (cmp_mol[i] < cmp_mol[j]);
    return (cmp_tagv[i] > cmp_tagv[j]) - (cmp_tagv[i] < cmp_tagv[j]);
}

/* The bodies of the group's atoms, one per value of key[i] (molecule IDs,
 * fix rigid's group index or 0 for `single`; < 0: in no body), in
 * ascending key order (LAMMPS create_bodies). by_molecule: the keys are
 * molecule IDs (messages name them; otherwise bodies count from 1). */
static void create_bodies(struct gravel *g, struct fix *f, struct rigid *r, const int64_t *key,
                          int by_molecule)
{
    struct atoms *a = &g->atoms;
    int n = 0;
    int *list = hold_ints(g, r, (size_t)a->n + 1);
    for (int i = 0; i < a->n; i++)
        if ((a->mask[i] & f->groupbit) && key[i] >= 0)
            list[n++] = i;
    cmp_mol = key;
    cmp_tagv = a->tag;
    qsort(list, (size_t)n, sizeof(int), by_mol);
    for (int s = 0; s < n;) {
        int e = s;
        while (e < n && key[list[e]] == key[list[s]])
            e++;
        double lo[3] = {1e20, 1e20, 1e20}, hi[3] = {-1e20, -1e20, -1e20};
        for (int k = s; k < e; k++) {
            double u[3];
            domain_unmap(g, a->x + 3 * list[k], a->image + 3 * list[k], u);
            for (int d = 0; d < 3; d++) {
                lo[d] = u[d] < lo[d] ? u[d] : lo[d];
                hi[d] = u[d] > hi[d] ? u[d] : hi[d];
            }
        }
        if (lo[0] == hi[0] && lo[1] == hi[1] && lo[2] == hi[2])
            gr_error(g, "fix %s: one or more rigid bodies are a single particle (%s %lld)",
                     f->style->name, by_molecule ? "molecule" : "body",
                     (long long)key[list[s]] + (by_molecule ? 0 : 1));
        int body = r->nbody;
        (void)new_body(g, r);
        for (int k = s; k < e; k++) {
            struct member *m = new_member(g, r);
            m->tag = a->tag[list[k]];
            m->body = body;
        }
        s = e;
    }
    release_ints(r);
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "fix rigid/small expects a body style (molecule)");
    if (!strcmp(argv[0], "custom"))
        gr_error(g, "fix rigid/small custom is not supported (use molecule IDs)");
    if (strcmp(argv[0], "molecule"))
        gr_error(g, "unknown fix rigid/small body style '%.64s' (expected molecule)", argv[0]);
    if (!g->atoms.molecule_flag)
        gr_error(g, "fix rigid/small requires atom attribute molecule (fix property/atom mol)");
    struct rigid *r = gr_calloc(g, 1, sizeof *r);
    f->data = r;
    r->reinit = 1;
    for (int i = 1; i < argc; i++) {
        const char *k = argv[i];
        if (!strcmp(k, "mol")) {
            arg_need(g, argc, i, 1, k);
            r->mol = molecule_find(g, argv[++i]);
            if (!r->mol)
                gr_error(g, "molecule template ID %.64s for fix rigid/small does not exist",
                         argv[i]);
            mol_require_atoms(g, r->mol);
        } else if (!strcmp(k, "gravity")) {
            arg_need(g, argc, i, 1, k);
            snprintf(r->gravity_id, sizeof r->gravity_id, "%s", argv[++i]);
        } else if (!strcmp(k, "reinit")) {
            arg_need(g, argc, i, 1, k);
            r->reinit = arg_yesno(g, argv[++i], k);
        } else if (!strcmp(k, "langevin") || !strcmp(k, "infile") || !strcmp(k, "temp") ||
                   !strcmp(k, "iso") || !strcmp(k, "aniso") || !strcmp(k, "dilate")) {
            gr_error(g, "fix rigid/small keyword '%s' is not supported", k);
        } else {
            gr_error(g, "unknown fix rigid/small keyword '%.64s' (mol, gravity, reinit)", k);
        }
    }
    if (r->mol) {
        mol_compute_center(r->mol);
        mol_compute_mass(g, r->mol);
        mol_compute_com(g, r->mol);
        mol_compute_inertia(g, r->mol);
    }
    create_bodies(g, f, r, g->atoms.mol, 1);
    double rsqfar = 0;
    gr_print(g, "  %d rigid bodies with %d atoms\n", r->nbody, r->nmem);
    (void)rsqfar;
    f->hooks = HOOK_INITIAL_INTEGRATE | HOOK_FINAL_INTEGRATE;
    f->sources[f->nsources++] = "fix_rigid_small.cl";
    f->needs = NEED_ROTATION;
}

/* `fix ID group rigid single|molecule|group N g1 .. gN [reinit yes|no]
 * [force M x y z] [torque M x y z]`: LAMMPS's fix rigid, the same bodies
 * and integration as rigid/small, the bodies set by the body style: the
 * whole group (single), each molecule ID (molecule), each listed group
 * (an atom in two of them is an error; one in none is in no body); force
 * and torque switch the bodies' force and torque components on or off
 * (LAMMPS's fflag, tflag). Global scalar: the bodies' temperature, LAMMPS's
 * sum of M vcm^2 and w I w over the components not held (6 per body) less
 * the linear bodies; global array nbody x 15: xcm, vcm, fcm, torque, image
 * flags of each body. */
static void create_rigid(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "fix rigid expects a body style (single, molecule, group)");
    struct atoms *a = &g->atoms;
    int64_t *key = gr_calloc(g, (size_t)a->n + 1, sizeof *key);
    int i = 1;
    if (!strcmp(argv[0], "single")) {
        /* every atom of the group: key 0 */
    } else if (!strcmp(argv[0], "molecule")) {
        if (!a->molecule_flag) {
            free(key);
            gr_error(g, "fix rigid molecule requires atom attribute molecule (fix property/atom "
                        "mol)");
        }
        memcpy(key, a->mol, (size_t)a->n * sizeof *key);
    } else if (!strcmp(argv[0], "group")) {
        if (argc < 2) {
            free(key);
            gr_error(g, "fix rigid group expects N and N group IDs");
        }
        const int ng = arg_int(g, argv[1], "fix rigid group N");
        if (ng <= 0 || argc < 2 + ng) {
            free(key);
            gr_error(g, "fix rigid group expects N > 0 and N group IDs, got %d and %d", ng,
                     argc - 2);
        }
        for (int k = 0; k < a->n; k++)
            key[k] = -1;
        for (int q = 0; q < ng; q++) {
            const int ig = group_find(g, argv[2 + q]);
            if (ig < 0) {
                free(key);
                gr_error(g, "could not find fix rigid group ID %.64s", argv[2 + q]);
            }
            for (int k = 0; k < a->n; k++) {
                if (!(a->mask[k] & group_bit(ig)) || !(a->mask[k] & f->groupbit))
                    continue;
                if (key[k] >= 0) {
                    free(key);
                    gr_error(g, "one or more atoms belong to multiple rigid bodies");
                }
                key[k] = q;
            }
        }
        i = 2 + ng; /* atoms in none of the groups are in no body, as LAMMPS */
    } else if (!strcmp(argv[0], "custom")) {
        free(key);
        gr_error(g, "fix rigid custom is not supported (use molecule IDs or groups)");
    } else {
        free(key);
        gr_error(g, "unknown fix rigid body style '%.64s' (single, molecule, group)", argv[0]);
    }
    struct rigid *r = gr_calloc(g, 1, sizeof *r);
    f->data = r;
    r->reinit = 1;
    create_bodies(g, f, r, key, !strcmp(argv[0], "molecule"));
    free(key);
    for (; i < argc; i++) {
        const char *k = argv[i];
        if (!strcmp(k, "reinit")) {
            arg_need(g, argc, i, 1, k);
            r->reinit = arg_yesno(g, argv[++i], k);
        } else if (!strcmp(k, "force") || !strcmp(k, "torque")) {
            arg_need(g, argc, i, 4, k);
            int lo, hi, v[3];
            arg_range(g, argv[i + 1], r->nbody, &lo, &hi, "fix rigid body"); /* 1-based */
            char *w[4] = {argv[i], argv[i + 2], argv[i + 3], argv[i + 4]};
            rigid_small_flags_arg(g, 4, w, 0, v);
            for (int ib = lo - 1; ib < hi; ib++)
                rigid_small_hold(f, ib, k[0] == 'f' ? v : NULL, k[0] == 't' ? v : NULL);
            i += 4;
        } else if (!strcmp(k, "langevin") || !strcmp(k, "infile") || !strcmp(k, "temp") ||
                   !strcmp(k, "iso") || !strcmp(k, "aniso") || !strcmp(k, "dilate") ||
                   !strcmp(k, "x") || !strcmp(k, "y") || !strcmp(k, "z") ||
                   !strcmp(k, "couple") || !strcmp(k, "tparam") || !strcmp(k, "pchain") ||
                   !strcmp(k, "gravity")) {
            gr_error(g, "fix rigid keyword '%s' is not supported", k);
        } else {
            gr_error(g, "unknown fix rigid keyword '%.64s' (reinit, force, torque)", k);
        }
    }
    gr_print(g, "  %d rigid bodies with %d atoms\n", r->nbody, r->nmem);
    f->hooks = HOOK_INITIAL_INTEGRATE | HOOK_FINAL_INTEGRATE;
    f->sources[f->nsources++] = "fix_rigid_small.cl";
    f->needs = NEED_ROTATION;
    f->array_flag = 1;
    f->size_array_rows = r->nbody;
    f->size_array_cols = 15;
    f->extarray = 0;
}

/* fix rigid's scalar: LAMMPS's FixRigid::compute_scalar */
static double rigid_scalar(struct gravel *g, struct fix *f)
{
    const struct rigid *r = f->data;
    double t = 0.0;
    int nlinear = 0, nflags = 0;
    for (int ib = 0; ib < r->nbody; ib++) {
        const struct rbody *b = &r->b[ib];
        for (int q = 0; q < 3; q++)
            nflags += b->fflag[q] + b->tflag[q];
        for (int q = 0; q < 3; q++)
            t += b->mass * (b->fflag[q] * b->vcm[q] * b->vcm[q]);
        /* the angular velocity in the body frame: L projected on the principal axes / I */
        const double *axis[3] = {b->ex, b->ey, b->ez};
        for (int q = 0; q < 3; q++) {
            double w = axis[q][0] * b->angmom[0] + axis[q][1] * b->angmom[1] +
                       axis[q][2] * b->angmom[2];
            w = b->inertia[q] == 0.0 ? 0.0 : w / b->inertia[q];
            t += b->tflag[q] * b->inertia[q] * w * w;
        }
        nlinear += b->inertia[0] == 0.0 || b->inertia[1] == 0.0 || b->inertia[2] == 0.0;
    }
    const double dof = (double)nflags - nlinear; /* 6 per body, less the components held */
    return dof > 0 ? t / (dof * temp_boltz(g)) : 0.0;
}

/* row i (1-based): xcm vcm fcm torque image */
static double rigid_array(struct gravel *g, struct fix *f, int i, int j)
{
    (void)g;
    const struct rigid *r = f->data;
    const struct rbody *b = &r->b[i - 1];
    const int q = (j - 1) % 3;
    switch ((j - 1) / 3) {
    case 0: return b->xcm[q];
    case 1: return b->vcm[q];
    case 2: return b->fcm[q];
    case 3: return b->torque[q];
    default: return b->image[q];
    }
}

/* `fix ID group multisphere [allow_group_and_set yes|no] [allow_heatsource
 * no]`: LIGGGHTS's clump integrator as this fix's bodies. It starts with no
 * body; fix insert/pack, insert/stream and insert/rate/region add one per
 * particletemplate/multisphere clump they place (rigid_small_add_body).
 * The bodies keep the template's mass and inertia (no recomputation at a
 * run's start), their atoms get the body's ID as molecule ID and the group
 * ID_clumps, and pairs within one body are excluded from the neighbor lists
 * (LIGGGHTS: neigh_modify exclude molecule). */
static void create_multisphere(struct gravel *g, struct fix *f, int argc, char **argv)
{
    const char *who = "fix multisphere";
    for (int i = 0; i < g->styles.nfix; i++)
        if (g->styles.fix[i] != f && !strcmp(g->styles.fix[i]->style->name, "multisphere"))
            gr_error(g, "%s %s: only one fix multisphere at a time is allowed (%s exists)", who,
                     f->id, g->styles.fix[i]->id);
    if (g->dom.dimension != 3)
        gr_error(g, "%s: only 3d simulations are supported", who);
    for (int i = 0; i < argc; i += 2) {
        const char *k = argv[i];
        if (!strcmp(k, "allow_group_and_set") || !strcmp(k, "allow_heatsource")) {
            arg_need(g, argc, i, 1, k);
            if (arg_yesno(g, argv[i + 1], k) && k[6] == 'h')
                gr_error(g, "%s: allow_heatsource yes (heat sources in clumps) is not "
                            "supported", who);
        } else if (!strcmp(k, "CAddRhoFluid")) {
            gr_error(g, "%s: keyword CAddRhoFluid (added fluid mass, CFD coupling) is not "
                        "supported", who);
        } else {
            gr_error(g, "%s: unknown keyword '%.64s' (allow_group_and_set, allow_heatsource)",
                     who, k);
        }
    }
    struct rigid *r = gr_calloc(g, 1, sizeof *r);
    f->data = r;
    r->ms = 1;
    r->reinit = 0;
    struct atoms *a = &g->atoms;
    if (!a->molecule_flag) {
        for (int i = 0; i < a->n; i++)
            a->mol[i] = 0;
        a->molecule_flag = 1;
    }
    /* thermo ke as LIGGGHTS: 1/2 sum m v^2 of the atoms of each step (as
     * atom_style granular; the bodies remove no degree of freedom) */
    g->thermo.temp.dynamic = 1;
    g->thermo.temp.extra_set = 1;
    g->thermo.temp.extra_dof = 0;
        char name[GR_NAMELEN + 8];
    snprintf(name, sizeof name, "%s_clumps", f->id);
    int grp = group_create(g, name);
    r->member_bits = group_bit(grp);
    struct neigh_settings *ns = &g->neigh;
    int k;
    for (k = 0; k < ns->nexclude_mol; k++)
        if (ns->exclude_mol[k][0] == grp && ns->exclude_mol[k][1] == 1)
            break;
    if (k == ns->nexclude_mol) {
        if (ns->nexclude_mol >= 16)
            gr_error(g, "%s: too many neigh_modify exclusions (at most 16 of each kind)", who);
        ns->exclude_mol[k][0] = grp;
        ns->exclude_mol[k][1] = 1;
        ns->nexclude_mol++;
    }
    f->hooks = HOOK_INITIAL_INTEGRATE | HOOK_FINAL_INTEGRATE | HOOK_END_OF_STEP;
    f->sources[f->nsources++] = "fix_rigid_small.cl";
    f->needs = NEED_ROTATION;
}

/* ---- body properties from the atoms (LAMMPS setup_bodies_static/dynamic) ------- */

static void setup_bodies(struct gravel *g, struct rigid *r)
{
    struct atoms *a = &g->atoms;
    int *idx = hold_ints(g, r, (size_t)r->nmem + 1);
    match_tags(g, r, a->tag, a->n, idx);
    for (int k = 0; k < r->nmem; k++)
        if (idx[k] < 0)
            gr_error(g, "fix rigid/small: rigid body atom %lld is missing",
                     (long long)r->m[r->order[k]].tag);
    r->extended = r->mol && r->mol->radius;
    for (int k = 0; k < r->nmem; k++) {
        struct member *m = &r->m[r->order[k]];
        m->ext = a->radius[idx[k]] > 0.0;
        r->extended |= m->ext;
    }
    for (int ib = 0; ib < r->nbody; ib++) {
        struct rbody *b = &r->b[ib];
        memset(b->xcm, 0, sizeof b->xcm);
        memset(b->xgc, 0, sizeof b->xgc);
        b->mass = 0;
        b->natoms = 0;
    }
    for (int k = 0; k < r->nmem; k++) {
        int i = idx[k];
        struct member *m = &r->m[r->order[k]];
        struct rbody *b = &r->b[m->body];
        double u[3], w = a->rmass[i];
        domain_unmap(g, a->x + 3 * i, a->image + 3 * i, u);
        for (int d = 0; d < 3; d++) {
            b->xcm[d] += u[d] * w;
            b->xgc[d] += u[d];
        }
        b->mass += w;
        b->natoms++;
    }
    for (int ib = 0; ib < r->nbody; ib++) {
        struct rbody *b = &r->b[ib];
        for (int d = 0; d < 3; d++) {
            b->xcm[d] /= b->mass;
            b->xgc[d] /= b->natoms;
            b->vcm[d] = b->angmom[d] = 0.0;
            b->image[d] = 0;
        }
        domain_remap(g, b->xcm, b->image); /* pre_neighbor */
    }
    free(r->held_it);
    r->held_it = NULL;
    double (*it)[6] = r->held_it = gr_calloc(g, (size_t)r->nbody + 1, sizeof *it);
    for (int k = 0; k < r->nmem; k++) {
        int i = idx[k];
        struct member *m = &r->m[r->order[k]];
        struct rbody *b = &r->b[m->body];
        for (int d = 0; d < 3; d++)
            m->xbox[d] = a->image[3 * i + d] - b->image[d];
        double u[3], w = a->rmass[i];
        domain_unmap(g, a->x + 3 * i, m->xbox, u);
        double dx = u[0] - b->xcm[0], dy = u[1] - b->xcm[1], dz = u[2] - b->xcm[2];
        double *t = it[m->body];
        t[0] += w * (dy * dy + dz * dz);
        t[1] += w * (dx * dx + dz * dz);
        t[2] += w * (dx * dx + dy * dy);
        t[3] -= w * dy * dz;
        t[4] -= w * dx * dz;
        t[5] -= w * dx * dy;
    }
    if (r->extended)
        for (int k = 0; k < r->nmem; k++) {
            int i = idx[k];
            struct member *m = &r->m[r->order[k]];
            if (!m->ext)
                continue;
            double *t = it[m->body], ri = a->radius[i];
            for (int d = 0; d < 3; d++)
                t[d] += SINERTIA * a->rmass[i] * ri * ri;
        }
    for (int ib = 0; ib < r->nbody; ib++) {
        struct rbody *b = &r->b[ib];
        if (rm_principal(it[ib], g->dom.dimension == 2, b->inertia, b->ex, b->ey, b->ez,
                         b->quat))
            gr_error(g, "insufficient Jacobi rotations for rigid body");
        double delta[3] = {b->xgc[0] - b->xcm[0], b->xgc[1] - b->xcm[1], b->xgc[2] - b->xcm[2]};
        domain_minimum_image(g, delta);
        rm_transpose_matvec(b->ex, b->ey, b->ez, delta, b->xgc_body);
        for (int d = 0; d < 3; d++)
            b->xgc[d] = b->xcm[d] + delta[d];
    }
    free(r->held_it);
    r->held_it = NULL;
    for (int k = 0; k < r->nmem; k++) {
        int i = idx[k];
        struct member *m = &r->m[r->order[k]];
        struct rbody *b = &r->b[m->body];
        double u[3], delta[3];
        domain_unmap(g, a->x + 3 * i, m->xbox, u);
        for (int d = 0; d < 3; d++)
            delta[d] = u[d] - b->xcm[d];
        rm_transpose_matvec(b->ex, b->ey, b->ez, delta, m->displace);
    }
    /* dynamic: vcm and angular momentum from the atoms */
    for (int k = 0; k < r->nmem; k++) {
        int i = idx[k];
        struct member *m = &r->m[r->order[k]];
        struct rbody *b = &r->b[m->body];
        double w = a->rmass[i], u[3];
        const double *v = a->v + 3 * i;
        for (int d = 0; d < 3; d++)
            b->vcm[d] += v[d] * w;
        domain_unmap(g, a->x + 3 * i, m->xbox, u);
        double dx = u[0] - b->xcm[0], dy = u[1] - b->xcm[1], dz = u[2] - b->xcm[2];
        b->angmom[0] += dy * w * v[2] - dz * w * v[1];
        b->angmom[1] += dz * w * v[0] - dx * w * v[2];
        b->angmom[2] += dx * w * v[1] - dy * w * v[0];
    }
    if (r->extended)
        for (int k = 0; k < r->nmem; k++) {
            int i = idx[k];
            struct member *m = &r->m[r->order[k]];
            if (!m->ext)
                continue;
            struct rbody *b = &r->b[m->body];
            double ri = a->radius[i];
            for (int d = 0; d < 3; d++)
                b->angmom[d] += SINERTIA * a->rmass[i] * ri * ri * a->omega[3 * i + d];
        }
    for (int ib = 0; ib < r->nbody; ib++)
        for (int d = 0; d < 3; d++)
            r->b[ib].vcm[d] /= r->b[ib].mass;
    release_ints(r);
}

/* ---- device transfers ---------------------------------------------------------- */

static void scratch(struct gravel *g, struct rigid *r, int n)
{
    if ((size_t)n <= r->hcap)
        return;
    size_t c = (size_t)n + (size_t)n / 4 + 16;
    r->hm = gr_realloc(g, r->hm, c * sizeof(double));
    r->htag = gr_realloc(g, r->htag, c * sizeof(int64_t));
    r->himg = gr_realloc(g, r->himg, 3 * c * sizeof(int));
    r->hcap = c;
}

/* Device and host buffers of the member-order transfers for r->nmem members. */
static void member_buffers(struct gravel *g, struct rigid *r)
{
    if ((size_t)r->nmem <= r->dcap && r->d_idx)
        return;
    size_t c = (size_t)r->nmem + (size_t)r->nmem / 4 + 16, rs = g->eng->rsz;
    cl_mem *m[] = {&r->d_idx, &r->d_x, &r->d_xl, &r->d_v, &r->d_w, &r->d_out};
    for (size_t i = 0; i < sizeof m / sizeof *m; i++)
        if (*m[i]) {
            clReleaseMemObject(*m[i]);
            *m[i] = NULL;
        }
    r->d_idx = eng_alloc(g, c * sizeof(int), "rigid body member indices");
    r->d_x = eng_alloc(g, 3 * c * rs, "rigid body member positions");
    r->d_xl = eng_alloc(g, 3 * c * rs, "rigid body member positions (low parts)");
    r->d_v = eng_alloc(g, 3 * c * rs, "rigid body member velocities");
    r->d_w = eng_alloc(g, 3 * c * rs, "rigid body member spins");
    r->d_out = eng_alloc(g, 6 * c * rs, "rigid body member forces");
    r->mx = gr_realloc(g, r->mx, 3 * c * sizeof(double));
    r->mxl = gr_realloc(g, r->mxl, 3 * c * sizeof(double));
    r->mv = gr_realloc(g, r->mv, 3 * c * sizeof(double));
    r->mw = gr_realloc(g, r->mw, 3 * c * sizeof(double));
    r->mout = gr_realloc(g, r->mout, 6 * c * sizeof(double));
    r->dcap = c;
}

/* Several ranks: row k of rows (w doubles per member, member order) from
 * the rank that owns member k's atom, on every rank. */
static void share_member_rows(struct gravel *g, struct rigid *r, double *rows, size_t w,
                              const char *what)
{
    double *rec = gr_malloc(g, (w + 1) * sizeof(double) * ((size_t)r->nmem + 1));
    size_t nrec = 0;
    for (int k = 0; k < r->nmem; k++)
        if (r->m[k].dev >= 0) {
            double *q = rec + (w + 1) * nrec++;
            q[0] = k;
            memcpy(q + 1, rows + w * (size_t)k, w * sizeof(double));
        }
    void *all = NULL;
    size_t bytes = comm_allgatherv(rec, nrec * (w + 1) * sizeof(double), &all);
    free(rec);
    if (bytes == (size_t)-1)
        gr_error(g, "fix rigid/small: out of memory gathering the members' %s", what);
    const double *q = all;
    for (size_t t = 0; t < bytes / ((w + 1) * sizeof(double)); t++, q += w + 1)
        memcpy(rows + w * (size_t)q[0], q + 1, w * sizeof(double));
    free(all);
}

/* Several ranks: every member's image shift from the rank that owns its atom. */
static void share_xbox(struct gravel *g, struct rigid *r)
{
    double *rows = gr_malloc(g, 3 * sizeof(double) * ((size_t)r->nmem + 1));
    for (int k = 0; k < r->nmem; k++)
        for (int d = 0; d < 3; d++)
            rows[3 * k + d] = r->m[k].xbox[d];
    share_member_rows(g, r, rows, 3, "images");
    for (int k = 0; k < r->nmem; k++)
        for (int d = 0; d < 3; d++)
            r->m[k].xbox[d] = (int)rows[3 * k + d];
    free(rows);
}

/* After a rebuild: device indices of the owned members (-1: another
 * rank's), image shifts (xcm remapped into the box first, LAMMPS
 * pre_neighbor + image_shift) and contact masses (owned and ghost slots). */
static void post_neighbor(struct gravel *g, struct fix *f)
{
    struct rigid *r = f->data;
    struct engine *e = g->eng;
    struct dev_atoms *s = eng_atoms(g);
    int n = s->n, nall = n + par_nghost(g);
    if (r->nmem == 0) {
        r->mapped = 1;
        return;
    }
    scratch(g, r, nall);
    eng_read(g, s->tag, 0, (size_t)nall * sizeof(int64_t), r->htag);
    eng_read(g, s->image, 0, 3 * (size_t)n * sizeof(int), r->himg);
    for (int ib = 0; ib < r->nbody; ib++)
        domain_remap(g, r->b[ib].xcm, r->b[ib].image);
    for (int k = 0; k < r->nmem; k++)
        r->m[k].dev = -1;
    long long owned = 0;
    for (int i = 0; i < n; i++) {
        int k = member_of_tag(g, r, r->htag[i]);
        if (k < 0)
            continue;
        struct member *m = &r->m[k];
        m->dev = i;
        for (int d = 0; d < 3; d++)
            m->xbox[d] = r->himg[3 * i + d] - r->b[m->body].image[d];
        owned++;
    }
    if (par_on(g)) {
        share_xbox(g, r);
        owned = comm_sum_ll(owned);
    }
    if (owned != r->nmem) {
        for (int k = 0; k < r->nmem && !par_on(g); k++)
            if (r->m[r->order[k]].dev < 0)
                gr_error(g, "fix rigid/small: rigid body atom %lld is missing at step %lld "
                            "(lost?)", (long long)r->m[r->order[k]].tag, (long long)g->step);
        gr_error(g, "fix rigid/small: %lld of the %d rigid body atoms are missing at step %lld "
                    "(lost?)", (long long)(r->nmem - owned), r->nmem, (long long)g->step);
    }
    member_buffers(g, r);
    int *di = gr_calloc(g, (size_t)r->nmem + 1, sizeof(int));
    for (int k = 0; k < r->nmem; k++)
        di[k] = r->m[k].dev;
    eng_write(g, r->d_idx, 0, (size_t)r->nmem * sizeof(int), di);
    free(di);
    /* contact masses: the body's for members, the atom's for the others */
    size_t cap = (size_t)(e->cap > nall ? e->cap : nall);
    if (cap > r->cmass_cap || !r->cmass) {
        if (r->cmass)
            clReleaseMemObject(r->cmass);
        r->cmass = eng_alloc(g, cap * e->rsz, "rigid body contact masses");
        r->cmass_cap = cap;
    }
    eng_read_reals(g, s->rmass, (size_t)nall, r->hm);
    for (int i = 0; i < nall; i++) {
        int k = member_of_tag(g, r, r->htag[i]);
        if (k >= 0)
            r->hm[i] = r->b[r->m[k].body].mass;
    }
    eng_write_reals(g, r->cmass, (size_t)nall, r->hm);
    e->contact_mass = r->cmass;
    r->mapped = 1;
}

static void need_map(struct gravel *g, struct fix *f)
{
    struct rigid *r = f->data;
    if (!r->mapped)
        post_neighbor(g, f);
}

/* Members' velocities (and positions with setx) from their bodies, and the
 * spheres' omega; written in member order by rigid_scatter. */
static void set_xv(struct gravel *g, struct fix *f, int setx)
{
    struct rigid *r = f->data;
    if (r->nmem == 0)
        return;
    need_map(g, f);
    struct engine *e = g->eng;
    struct dev_atoms *s = eng_atoms(g);
    int dim2 = g->dom.dimension == 2, setw = r->extended && e->rotation;
    double L[3] = {prd(g, 0), prd(g, 1), prd(g, 2)};
    int per[3], moved = 0;
    for (int q = 0; q < 3; q++)
        per[q] = domain_contact_periodic(g, q);
    for (int k = 0; k < r->nmem; k++) {
        struct member *m = &r->m[k];
        const struct rbody *b = &r->b[m->body];
        double *x = m->x, *v = r->mv + 3 * k, d[3];
        rm_matvec(b->ex, b->ey, b->ez, m->displace, d);
        v[0] = b->omega[1] * d[2] - b->omega[2] * d[1] + b->vcm[0];
        v[1] = b->omega[2] * d[0] - b->omega[0] * d[2] + b->vcm[1];
        v[2] = b->omega[0] * d[1] - b->omega[1] * d[0] + b->vcm[2];
        if (dim2) {
            d[2] = 0.0;
            v[2] = 0.0;
        }
        if (setx)
            for (int q = 0; q < 3; q++) {
                x[q] = d[q] + (b->xcm[q] - m->xbox[q] * L[q]);
                /* gravel wraps positions every step (nbr_check): keep the
                 * member inside the box by its image shift, so the device
                 * wrap leaves it alone and its image flag = body's + shift */
                if (per[q] && (x[q] < g->dom.lo[q] || x[q] >= g->dom.hi[q])) {
                    m->xbox[q] += (int)floor((x[q] - g->dom.lo[q]) / L[q]);
                    x[q] = d[q] + (b->xcm[q] - m->xbox[q] * L[q]);
                    if (x[q] >= g->dom.hi[q])
                        m->xbox[q]++, x[q] = d[q] + (b->xcm[q] - m->xbox[q] * L[q]);
                    if (x[q] < g->dom.lo[q])
                        x[q] = g->dom.lo[q];
                    moved = 1;
                }
            }
        if (setw)
            for (int q = 0; q < 3; q++)
                r->mw[3 * k + q] = b->omega[q];
    }
    size_t c3 = 3 * (size_t)r->nmem;
    if (setx) {
        for (int k = 0; k < r->nmem; k++)
            for (int q = 0; q < 3; q++) {
                double rel = r->m[k].x[q] - e->origin[q];
                double hi = e->single ? (double)(float)rel : rel;
                r->mx[3 * k + q] = hi;
                r->mxl[3 * k + q] = rel - hi;
            }
        eng_write_reals(g, r->d_x, c3, r->mx);
        if (e->single)
            eng_write_reals(g, r->d_xl, c3, r->mxl);
    }
    eng_write_reals(g, r->d_v, c3, r->mv);
    if (setw)
        eng_write_reals(g, r->d_w, c3, r->mw);
    cl_kernel k = r->k_scatter;
    int a = 0;
    eng_arg_int(g, k, a++, r->nmem);
    eng_arg_mem(g, k, a++, r->d_idx);
    eng_arg_mem(g, k, a++, r->d_x);
    eng_arg_mem(g, k, a++, r->d_xl);
    eng_arg_mem(g, k, a++, r->d_v);
    eng_arg_mem(g, k, a++, r->d_w);
    eng_arg_int(g, k, a++, setx);
    eng_arg_int(g, k, a++, setw);
    eng_arg_mem(g, k, a++, s->x);
    eng_arg_mem(g, k, a++, s->v);
    eng_arg_mem(g, k, a++, e->rotation ? s->omega : s->v);
    eng_arg_pos_lo(g, k, a);
    eng_launch(g, k, (size_t)r->nmem);
    if (moved) { /* image flags of the members that crossed a periodic face */
        int n = s->n;
        scratch(g, r, n);
        eng_read(g, s->image, 0, 3 * (size_t)n * sizeof(int), r->himg);
        for (int i = 0; i < r->nmem; i++)
            for (int q = 0; q < 3 && r->m[i].dev >= 0; q++)
                r->himg[3 * r->m[i].dev + q] = r->b[r->m[i].body].image[q] + r->m[i].xbox[q];
        eng_write(g, s->image, 0, 3 * (size_t)n * sizeof(int), r->himg);
    }
}

static void enforce2d(struct rigid *r)
{
    for (int ib = 0; ib < r->nbody; ib++) {
        struct rbody *b = &r->b[ib];
        b->xcm[2] = b->vcm[2] = b->fcm[2] = b->xgc[2] = 0.0;
        b->torque[0] = b->torque[1] = 0.0;
        b->angmom[0] = b->angmom[1] = 0.0;
        b->omega[0] = b->omega[1] = 0.0;
    }
}

/* F and T of every body from its members' f and torque (tag order),
 * gathered in member order by rigid_gather. */
static void forces_and_torques(struct gravel *g, struct fix *f, int gravity)
{
    struct rigid *r = f->data;
    need_map(g, f);
    struct engine *e = g->eng;
    struct dev_atoms *s = eng_atoms(g);
    int ext = r->extended && e->rotation;
    cl_kernel k = r->k_gather;
    eng_arg_int(g, k, 0, r->nmem);
    eng_arg_mem(g, k, 1, r->d_idx);
    eng_arg_mem(g, k, 2, s->f);
    eng_arg_mem(g, k, 3, e->rotation ? s->torque : s->f);
    eng_arg_int(g, k, 4, ext);
    eng_arg_mem(g, k, 5, r->d_out);
    eng_launch(g, k, (size_t)r->nmem);
    eng_read_reals(g, r->d_out, 6 * (size_t)r->nmem, r->mout);
    if (par_on(g)) /* every member's force and torque from its owner */
        share_member_rows(g, r, r->mout, 6, "forces");
    for (int ib = 0; ib < r->nbody; ib++) {
        memset(r->b[ib].fcm, 0, sizeof r->b[ib].fcm);
        memset(r->b[ib].torque, 0, sizeof r->b[ib].torque);
    }
    sort_members(g, r);
    for (int j = 0; j < r->nmem; j++) {
        int kk = r->order[j];
        const struct member *m = &r->m[kk];
        struct rbody *b = &r->b[m->body];
        const double *fi = r->mout + 6 * kk;
        double u[3];
        for (int q = 0; q < 3; q++)
            b->fcm[q] += fi[q];
        domain_unmap(g, m->x, m->xbox, u);
        double dx = u[0] - b->xcm[0], dy = u[1] - b->xcm[1], dz = u[2] - b->xcm[2];
        b->torque[0] += dy * fi[2] - dz * fi[1];
        b->torque[1] += dz * fi[0] - dx * fi[2];
        b->torque[2] += dx * fi[1] - dy * fi[0];
        if (r->gcorr) { /* remove the torque of the members' gravity m g (m = M/n) */
            double mg[3], w = b->mass / b->natoms;
            for (int q = 0; q < 3; q++)
                mg[q] = w * r->gacc[q];
            b->torque[0] -= dy * mg[2] - dz * mg[1];
            b->torque[1] -= dz * mg[0] - dx * mg[2];
            b->torque[2] -= dx * mg[1] - dy * mg[0];
        }
    }
    if (ext)
        for (int j = 0; j < r->nmem; j++) {
            int kk = r->order[j];
            const struct member *m = &r->m[kk];
            if (!m->ext)
                continue;
            for (int q = 0; q < 3; q++)
                r->b[m->body].torque[q] += r->mout[6 * kk + 3 + q];
        }
    if (gravity && r->gravity_id[0])
        for (int ib = 0; ib < r->nbody; ib++)
            for (int q = 0; q < 3; q++)
                r->b[ib].fcm[q] += r->gvec[q] * r->b[ib].mass;
}

/* ---- the hooks ----------------------------------------------------------------- */

static void init(struct gravel *g, struct fix *f)
{
    struct rigid *r = f->data;
    if (r->gravity_id[0]) {
        struct fix *fg = fix_find(g, r->gravity_id);
        if (!fg)
            gr_error(g, "fix rigid/small %s cannot find fix gravity ID %s", f->id,
                     r->gravity_id);
        if (!fix_gravity_vector(fg, r->gvec))
            gr_error(g, "fix rigid/small %s gravity fix ID %s is not a gravity fix style",
                     f->id, r->gravity_id);
    } else if ((r->mol) && fix_find_style(g, "gravity")) {
        gr_warn(g, "Gravity may not be correctly applied to rigid bodies if they consist of "
                   "overlapped particles");
    }
    if (r->ms) {
        gr_warn(g, "Energy calculated for multisphere particles is currently not correct");
        /* LIGGGHTS applies gravity to a clump at its centre of mass: the members
         * (masses M/n at the sphere centres) get the force, the torque that
         * puts about the body's centre of mass is taken out again */
        r->gcorr = 0;
        for (int i = 0; i < g->styles.nfix; i++) {
            struct fix *o = g->styles.fix[i];
            if (strcmp(o->style->name, "gravity"))
                continue;
            if (r->gcorr)
                gr_error(g, "fix multisphere %s: only one fix gravity supported", f->id);
            if (o->groupbit != 1u)
                gr_error(g, "fix multisphere %s: fix gravity %s must act on group all (its "
                            "clumps' atoms)", f->id, o->id);
            r->gcorr = fix_gravity_vector(o, r->gacc);
        }
    }
    r->k_gather = eng_kernel(g, "rigid_gather");
    r->k_scatter = eng_kernel(g, "rigid_scatter");
    r->dcap = 0; /* device buffers of an earlier run: regrown at the first map */
    r->dtv = g->dt;
    r->dtf = 0.5 * g->dt;
    r->dtq = 0.5 * g->dt;
    r->mapped = 0;
}

/* At every run's start, while the host holds every atom (before a run on
 * several ranks splits them): the members' positions and group bits, and
 * the bodies recomputed from their atoms (unless `reinit no` after the
 * first run, or fix multisphere). */
static void prepare(struct gravel *g, struct fix *f)
{
    struct rigid *r = f->data;
    unsigned integ = 0; /* groups other integrators move */
    for (int i = 0; i < g->styles.nfix; i++) {
        struct fix *o = g->styles.fix[i];
        if (o != f && (!strcmp(o->style->name, "nve") || !strcmp(o->style->name, "nve/sphere")))
            integ |= o->groupbit;
    }
    if (integ && r->nmem) {
        int *idx = gr_calloc(g, (size_t)r->nmem + 1, sizeof(int));
        match_tags(g, r, g->atoms.tag, g->atoms.n, idx);
        int k;
        for (k = 0; k < r->nmem; k++)
            if (idx[k] >= 0 && (g->atoms.mask[idx[k]] & integ))
                break;
        free(idx);
        if (k < r->nmem)
            gr_warn(g, "fix nve or nve/sphere also integrates atoms of the rigid bodies of fix "
                       "%s", f->id);
    }
    if (r->nmem) { /* positions: the host atoms are the device's at the upload */
        int *idx = gr_calloc(g, (size_t)r->nmem + 1, sizeof(int));
        match_tags(g, r, g->atoms.tag, g->atoms.n, idx);
        for (int k = 0; k < r->nmem; k++)
            if (idx[k] >= 0) {
                memcpy(r->m[r->order[k]].x, g->atoms.x + 3 * idx[k], 3 * sizeof(double));
                r->m[r->order[k]].mask = g->atoms.mask[idx[k]];
            }
        free(idx);
    }
    if (r->nbody && !r->ms && (r->reinit || !r->setupflag))
        setup_bodies(g, r);
    r->setupflag = 1;
}

static void setup(struct gravel *g, struct fix *f)
{
    struct rigid *r = f->data;
    if (r->nbody == 0)
        return;
    forces_and_torques(g, f, 0);
    if (g->dom.dimension == 2)
        enforce2d(r);
    for (int ib = 0; ib < r->nbody; ib++) {
        struct rbody *b = &r->b[ib];
        rm_angmom_to_omega(b->angmom, b->ex, b->ey, b->ez, b->inertia, b->omega);
    }
    set_xv(g, f, 0);
}

/* Whether body b is still on fix insert/stream's approach this step. */
static int approaching(const struct gravel *g, const struct rbody *b)
{
    return b->start_step >= 0 && g->step < b->start_step;
}

/* fix multisphere's end of step: a streamed body whose approach ended this
 * step takes its release velocity (LIGGGHTS Multisphere::release, called
 * by insert/stream for the body's atoms at their release step; its omega
 * of the insertion is 0 here, angular momentum untouched). */
static void end_of_step(struct gravel *g, struct fix *f)
{
    struct rigid *r = f->data;
    for (int ib = 0; ib < r->nbody; ib++) {
        struct rbody *b = &r->b[ib];
        if (b->start_step >= 0 && g->step >= b->start_step) {
            memcpy(b->vcm, b->v_rel, sizeof b->vcm);
            memset(b->omega, 0, sizeof b->omega);
            b->start_step = -1;
        }
    }
}

static void reset_step(struct gravel *g, struct fix *f, bigint shift)
{
    (void)g;
    struct rigid *r = f->data;
    for (int ib = 0; ib < r->nbody; ib++)
        if (r->b[ib].start_step >= 0)
            r->b[ib].start_step += shift;
}

int64_t rigid_small_stream(struct gravel *g, struct fix *f, int body, const double p_ref[3],
                           const double normal[3], const double v_normal[3],
                           const double v_rel[3])
{
    struct rigid *r = f->data;
    struct rbody *b = &r->b[body];
    if (b->start_step >= 0)
        return b->start_step;
    double dist = 0, vn = 0;
    for (int q = 0; q < 3; q++) {
        dist += (p_ref[q] - b->xcm[q]) * normal[q];
        vn += v_normal[q] * v_normal[q];
    }
    b->start_step = g->step + (int64_t)(int)(dist / (sqrt(vn) * g->dt));
    memcpy(b->v_int, v_normal, sizeof b->v_int);
    memcpy(b->v_rel, v_rel, sizeof b->v_rel);
    return b->start_step;
}

unsigned rigid_small_member_bits(const struct fix *f)
{
    return ((const struct rigid *)f->data)->member_bits;
}

static void initial_integrate(struct gravel *g, struct fix *f)
{
    struct rigid *r = f->data;
    for (int ib = 0; ib < r->nbody; ib++) {
        struct rbody *b = &r->b[ib];
        if (approaching(g, b)) { /* LIGGGHTS: v_integrate, a full drift, nothing else */
            for (int q = 0; q < 3; q++) {
                b->vcm[q] = b->v_int[q];
                b->xcm[q] += r->dtv * b->vcm[q];
            }
            continue;
        }
        double dtfm = r->dtf / b->mass;
        for (int q = 0; q < 3; q++) {
            if (b->fflag[q])
                b->vcm[q] += dtfm * b->fcm[q];
            b->xcm[q] += r->dtv * b->vcm[q];
            if (b->tflag[q])
                b->angmom[q] += r->dtf * b->torque[q];
        }
        rm_angmom_to_omega(b->angmom, b->ex, b->ey, b->ez, b->inertia, b->omega);
        rm_richardson(b->quat, b->angmom, b->omega, b->inertia, r->dtq);
        rm_q_to_exyz(b->quat, b->ex, b->ey, b->ez);
    }
    set_xv(g, f, 1);
}

static void final_integrate(struct gravel *g, struct fix *f)
{
    struct rigid *r = f->data;
    if (r->nbody == 0)
        return;
    forces_and_torques(g, f, 1);
    if (g->dom.dimension == 2)
        enforce2d(r);
    for (int ib = 0; ib < r->nbody; ib++) {
        struct rbody *b = &r->b[ib];
        if (approaching(g, b))
            continue;
        double dtfm = r->dtf / b->mass;
        for (int q = 0; q < 3; q++) {
            if (b->fflag[q])
                b->vcm[q] += dtfm * b->fcm[q];
            if (b->tflag[q])
                b->angmom[q] += r->dtf * b->torque[q];
        }
        rm_angmom_to_omega(b->angmom, b->ex, b->ey, b->ez, b->inertia, b->omega);
    }
    set_xv(g, f, 0);
}

int rigid_small_add_body(struct gravel *g, struct fix *f, const struct molecule *mol,
                         int first, int64_t tagprev, const double *xs, int xstride,
                         unsigned mask, const double xgeom[3], const double vcm[3],
                         const double quat[4])
{
    struct rigid *r = f->data;
    struct atoms *a = &g->atoms;
    int body = r->nbody;
    struct rbody *b = new_body(g, r);
    for (int k = 0; k < mol->natoms; k++) {
        struct member *m = new_member(g, r);
        m->tag = tagprev + 1 + k;
        m->mask = mask;
        m->body = body;
        m->ext = mol->radius != NULL;
        for (int q = 0; q < 3; q++) {
            m->displace[q] = mol->dxbody[3 * k + q];
            m->x[q] = xs[(size_t)xstride * k + q];
        }
    }
    for (int i = first; i < a->n; i++) { /* the members this rank holds */
        a->mask[i] |= r->member_bits;
        if (r->ms)
            a->mol[i] = body + 1; /* LIGGGHTS: the body's ID */
    }
    if (mol->radius)
        r->extended = 1;
    b->mass = mol->masstotal;
    b->natoms = mol->natoms;
    double rot[3][3], c2c[3], c2r[3];
    rm_quat_to_mat(quat, rot);
    for (int q = 0; q < 3; q++)
        c2c[q] = mol->com[q] - mol->center[q];
    for (int q = 0; q < 3; q++)
        c2r[q] = rot[q][0] * c2c[0] + rot[q][1] * c2c[1] + rot[q][2] * c2c[2];
    for (int q = 0; q < 3; q++) {
        b->xgc[q] = xgeom[q];
        b->xcm[q] = c2r[q] + xgeom[q];
        b->vcm[q] = vcm[q];
        b->inertia[q] = mol->inertia[q];
    }
    rm_quatquat(quat, mol->quat, b->quat);
    rm_q_to_exyz(b->quat, b->ex, b->ey, b->ez);
    rm_transpose_matvec(b->ex, b->ey, b->ez, c2r, b->xgc_body);
    for (int q = 0; q < 3; q++)
        b->xgc_body[q] = -b->xgc_body[q];
    r->mapped = 0; /* a rebuild follows the insertion (post_neighbor) */
    return body;
}

void rigid_small_hold(struct fix *f, int body, const int fflag[3], const int tflag[3])
{
    struct rigid *r = f->data;
    for (int ib = body < 0 ? 0 : body; ib < (body < 0 ? r->nbody : body + 1); ib++)
        for (int q = 0; q < 3; q++) {
            if (fflag)
                r->b[ib].fflag[q] = fflag[q] != 0;
            if (tflag)
                r->b[ib].tflag[q] = tflag[q] != 0;
        }
}

/* `fix_modify ID fflag|tflag X Y Z` (fix multisphere, LIGGGHTS
 * FixMultisphere::modify_param): on/off per component for every body that
 * exists now; bodies inserted later take their template's flags. */
static int modify_param(struct gravel *g, struct fix *f, int argc, char **argv)
{
    struct rigid *r = f->data;
    if (!r->ms || (strcmp(argv[0], "fflag") && strcmp(argv[0], "tflag")))
        return 0;
    int v[3];
    rigid_small_flags_arg(g, argc, argv, 0, v);
    rigid_small_hold(f, -1, argv[0][0] == 'f' ? v : NULL, argv[0][0] == 't' ? v : NULL);
    return 4;
}

void rigid_small_flags_arg(struct gravel *g, int argc, char **argv, int i, int v[3])
{
    arg_need(g, argc, i, 3, argv[i]);
    for (int k = 0; k < 3; k++) {
        const char *w = argv[i + 1 + k];
        if (strcmp(w, "on") && strcmp(w, "off"))
            gr_error(g, "expecting 'on or 'off' after '%s', got '%.64s'", argv[i], w);
        v[k] = !strcmp(w, "on");
    }
}

void rigid_small_body_energy(const struct fix *f, double *ke, double *erot)
{
    const struct rigid *r = f->data;
    double t = 0, w = 0;
    for (int ib = 0; ib < r->nbody; ib++) {
        const struct rbody *b = &r->b[ib];
        const double *v = b->vcm, *om = b->omega;
        t += 0.5 * b->mass * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        const double *axis[3] = {b->ex, b->ey, b->ez};
        for (int k = 0; k < 3; k++) {
            const double wk = axis[k][0] * om[0] + axis[k][1] * om[1] + axis[k][2] * om[2];
            w += 0.5 * b->inertia[k] * wk * wk;
        }
    }
    *ke = t;
    *erot = w;
}

/* LAMMPS FixRigidSmall::dof */
static double dof(struct gravel *g, struct fix *f, unsigned groupbit)
{
    struct rigid *r = f->data;
    if (r->ms) /* LIGGGHTS FixMultisphere::dof (its warning: init) */
        return 0;
    if (!r->setupflag) {
        if (r->nbody)
            gr_warn(g, "Cannot count rigid body degrees-of-freedom before bodies are fully "
                       "initialized");
        return 0;
    }
    if (r->nbody == 0)
        return 0;
    int (*c)[3] = gr_calloc(g, (size_t)r->nbody, sizeof *c);
    for (int k = 0; k < r->nmem; k++) { /* the group bits of the run's start (prepare) */
        const struct member *m = &r->m[k];
        c[m->body][2]++;
        if (m->mask & groupbit)
            c[m->body][m->ext && r->extended ? 1 : 0]++;
    }
    double n = 0;
    for (int ib = 0; ib < r->nbody; ib++) {
        if (c[ib][0] + c[ib][1] != c[ib][2])
            continue;
        if (g->dom.dimension == 3) {
            n += 3 * c[ib][0] + 6 * c[ib][1] - 6;
            const double *I = r->b[ib].inertia;
            if (I[0] == 0.0 || I[1] == 0.0 || I[2] == 0.0)
                n++;
        } else {
            n += 2 * c[ib][0] + 3 * c[ib][1] - 3;
        }
    }
    free(c);
    return n;
}

/* LIGGGHTS's thermo ke of clumps (Multisphere::extract_ke): 1/2 M vcm^2 per
 * body in place of its atoms' 1/2 sum m v^2 (the velocities set_xv wrote). */
static double ke_adjust(struct gravel *g, struct fix *f)
{
    (void)g;
    const struct rigid *r = f->data;
    double d = 0;
    for (int ib = 0; ib < r->nbody; ib++) {
        const double *v = r->b[ib].vcm;
        d += 0.5 * r->b[ib].mass * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    }
    for (int k = 0; k < r->nmem && r->mv; k++) {
        const double *v = r->mv + 3 * k;
        const struct rbody *b = &r->b[r->m[k].body];
        d -= 0.5 * (b->mass / b->natoms) * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    }
    return d;
}

/* Restart state: the bodies and their members as the run left them (this
 * build's layout: restart files are read by the build that wrote them,
 * doc/restart.md). A fix that recomputes its bodies at every run's start
 * (rigid/small, reinit yes: LAMMPS setup_bodies_static/dynamic) continues
 * from the atoms as a second run in one deck does; with `reinit no` and for
 * fix multisphere (bodies from the insertion fixes, the template's mass and
 * inertia) the bodies are restored and the run continues exactly. */
struct rigid_saved {
    int32_t version, nbody, nmem, setupflag, extended;
};
#define RIGID_SAVED_VERSION 1

static size_t write_restart(struct gravel *g, struct fix *f, unsigned char *buf, size_t cap)
{
    (void)g;
    const struct rigid *r = f->data;
    const size_t bb = (size_t)r->nbody * sizeof *r->b, mb = (size_t)r->nmem * sizeof *r->m;
    const size_t len = sizeof(struct rigid_saved) + bb + mb;
    if (!buf || cap < len)
        return len;
    struct rigid_saved h = {RIGID_SAVED_VERSION, r->nbody, r->nmem, r->setupflag, r->extended};
    memcpy(buf, &h, sizeof h);
    if (bb)
        memcpy(buf + sizeof h, r->b, bb);
    if (mb)
        memcpy(buf + sizeof h + bb, r->m, mb);
    return len;
}

static void read_restart(struct gravel *g, struct fix *f, const unsigned char *buf, size_t len)
{
    struct rigid *r = f->data;
    struct rigid_saved h;
    if (len < sizeof h)
        gr_error(g, "fix %s: restart state of %zu bytes is too short", f->id, len);
    memcpy(&h, buf, sizeof h);
    const size_t bb = (size_t)h.nbody * sizeof *r->b, mb = (size_t)h.nmem * sizeof *r->m;
    if (h.version != RIGID_SAVED_VERSION || h.nbody < 0 || h.nmem < 0 ||
        len != sizeof h + bb + mb)
        gr_error(g, "fix %s: restart state of %zu bytes does not hold rigid bodies of this "
                    "build (written by another version?)", f->id, len);
    if (!r->ms && r->reinit) { /* recomputed from the atoms at the run's start */
        if (h.nbody != r->nbody || h.nmem != r->nmem)
            gr_error(g, "fix %s: the restart file holds %d rigid bodies of %d atoms, the atoms' "
                        "molecule IDs make %d bodies of %d atoms", f->id, h.nbody, h.nmem,
                     r->nbody, r->nmem);
        return;
    }
    r->nbody = r->nmem = 0;
    for (int ib = 0; ib < h.nbody; ib++)
        memcpy(new_body(g, r), buf + sizeof h + (size_t)ib * sizeof *r->b, sizeof *r->b);
    for (int k = 0; k < h.nmem; k++) {
        struct member *m = new_member(g, r);
        memcpy(m, buf + sizeof h + bb + (size_t)k * sizeof *r->m, sizeof *r->m);
        m->dev = -1;
        if (m->body < 0 || m->body >= r->nbody)
            gr_error(g, "fix %s: restart state names rigid body %d of %d", f->id, m->body + 1,
                     r->nbody);
    }
    sort_members(g, r);
    r->setupflag = h.setupflag;
    r->extended = h.extended;
    r->dcap = 0;
    r->mapped = 0;
}

static void destroy(struct fix *f)
{
    struct rigid *r = f->data;
    if (!r)
        return;
    free(r->b);
    free(r->m);
    free(r->order);
    free(r->hm);
    free(r->mx);
    free(r->mxl);
    free(r->mv);
    free(r->mw);
    free(r->mout);
    cl_mem *m[] = {&r->d_idx, &r->d_x, &r->d_xl, &r->d_v, &r->d_w, &r->d_out};
    for (size_t i = 0; i < sizeof m / sizeof *m; i++)
        if (*m[i])
            clReleaseMemObject(*m[i]);
    free(r->htag);
    free(r->himg);
    free(r->held_i);
    free(r->held_it);
    if (r->cmass)
        clReleaseMemObject(r->cmass);
    free(r);
}

/* the hooks fix rigid/small and fix multisphere share */
#define RIGID_HOOKS                                                                          \
    .flags = FIX_STORES_IDS, .prepare = prepare, .init = init, .setup = setup,               \
    .initial_integrate = initial_integrate, .final_integrate = final_integrate,              \
    .post_neighbor = post_neighbor, .dof = dof, .write_restart = write_restart,              \
    .read_restart = read_restart, .modify_param = modify_param, .reset_step = reset_step,     \
    .destroy = destroy

const struct fix_style fix_style_rigid_small = {
    .name = "rigid/small",
    .create = create,
    RIGID_HOOKS,
};

const struct fix_style fix_style_multisphere = {
    .name = "multisphere",
    .create = create_multisphere,
    .ke_adjust = ke_adjust,
    .end_of_step = end_of_step,
    RIGID_HOOKS,
};

const struct fix_style fix_style_rigid = {
    .name = "rigid",
    .create = create_rigid,
    .scalar = rigid_scalar,
    .array = rigid_array,
    RIGID_HOOKS,
};
