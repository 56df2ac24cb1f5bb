/* create_atoms.c - `create_atoms type box | region ID | single x y z |
 * random N seed region-ID` with LAMMPS semantics.
 *
 * `basis M itype` gives basis atom M of the lattice type itype (box, region).
 * New atoms get atom_style sphere defaults: diameter 1, density 1, so
 * radius 0.5 and mass 4/3 pi 0.5^3 (use `set` to change them).
 * Lattice styles place atoms on the current lattice inside the box, using
 * LAMMPS' rule for which boundary points belong to the box: in periodic
 * dimensions [lo - eps, hi - 2 eps) with eps = 1e-6 x length (no duplicate on
 * the upper face), otherwise [lo, hi).
 * Random insertion is LAMMPS's (create_atoms.cpp add_random), draw for
 * draw: a RanPark stream (src/core/random.c) seeded with `seed` and warmed up
 * with 30 draws; each candidate is x = lo + u (hi - lo) per dimension in
 * the box clipped to the region's bounding box (interior regions only),
 * tried up to maxtry times; a candidate outside the region is rejected; with
 * `overlap d` (lattice units unless `units box`, scaled by the x spacing as
 * LAMMPS) one closer than d (center to center, minimum image in periodic
 * dimensions) to any atom is rejected, checked against a cell grid with
 * cells >= d so each test looks at 27 cells: O(N). So `lmp` and gravel
 * create the same atoms in the same order.
 *
 * gravel's keyword `mesh ID d` (repeatable, up to CA_MAXMESH meshes; d in
 * lattice units unless `units box`, scaled by the x spacing as overlap)
 * skips every lattice site or random candidate closer than d to a triangle
 * of the fix mesh/surface `ID` in its pose at the current step (d = the
 * radius the particles will get: no new sphere then touches the mesh). For
 * random insertion a skipped candidate counts as a failed try, as one
 * rejected by overlap. The region test stays LAMMPS's centre test: shrink
 * the region by the radius to keep spheres inside its surface. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "domain.h"
#include "error.h"
#include "lattice.h"
#include "log.h"
#include "random.h"
#include "region.h"
#include "fix_mesh_surface.h"
#include "molecule.h"
#include "rigid_math.h"

#define CA_EPSILON 1.0e-6
#define CA_MAXTRY_DEFAULT 1000
#define CA_MAXMESH 8

/* Sites near meshes are skipped (keyword mesh): each mesh in its current
 * pose, binned with reach d; points go to the mesh frame x0 = R^T (x - d). */
struct mesh_skip {
    int n;
    const struct mesh *m[CA_MAXMESH];
    struct mesh_bins b[CA_MAXMESH];
    double dist[CA_MAXMESH];
    struct mesh_pose pose[CA_MAXMESH];
    bigint skipped;
};

static int mesh_skip_hit(struct mesh_skip *ms, const double x[3])
{
    for (int k = 0; k < ms->n; k++) {
        const struct mesh_pose *p = &ms->pose[k];
        double y[3] = {x[0] - p->d[0], x[1] - p->d[1], x[2] - p->d[2]}, x0[3];
        for (int r = 0; r < 3; r++)
            x0[r] = p->R[r] * y[0] + p->R[3 + r] * y[1] + p->R[6 + r] * y[2];
        if (mesh_near(ms->m[k], &ms->b[k], x0, ms->dist[k])) {
            ms->skipped++;
            return 1;
        }
    }
    return 0;
}

static void mesh_skip_free(struct mesh_skip *ms)
{
    for (int k = 0; k < ms->n; k++)
        mesh_bins_free(&ms->b[k]);
    ms->n = 0;
}

static const double sphere_radius = 0.5;
#define SPHERE_MASS (4.0 * M_PI / 3.0 * 0.125) /* density 1, diameter 1 */
/* atom_style ellipsoid superellipsoid: a new atom is a point particle of
 * mass 1 (radius 0, no shape) until `set shape` / `set block` make it a
 * superellipsoid (LAMMPS AtomVecEllipsoid::create_atom_post) */
#define NEW_RADIUS(g) ((g)->atoms.ellipsoid_flag ? 0.0 : sphere_radius)
#define NEW_MASS(g) ((g)->atoms.ellipsoid_flag ? 1.0 : SPHERE_MASS)

/* ---- molecules (`mol template-ID seed`, LAMMPS's mode MOLECULE) ------------- */

/* Each point (lattice site, random point, the single point) gets a copy of
 * the template about its geometric centre, turned by `rotate` or else by a
 * random quaternion from a RanMars stream seeded with `seed` (LAMMPS
 * add_molecule); atom types are the type argument plus the template's. */
struct mol_job {
    struct molecule *mol;       /* NULL: single atoms */
    int type_offset;
    int quat_user;
    double quat[4];
    struct rng_mars rng;
    int nmol;                   /* molecules placed so far */
};

static void add_molecule(struct gravel *g, struct mol_job *mj, const double center[3])
{
    const struct molecule *m = mj->mol;
    double quat[4], rot[3][3];
    if (mj->quat_user)
        memcpy(quat, mj->quat, sizeof quat);
    else
        mol_random_quat(g->dom.dimension, rng_mars_draw, &mj->rng, quat);
    rm_quat_to_mat(quat, rot);
    for (int k = 0; k < m->natoms; k++) {
        double x[3];
        mol_place_atom(m, rot, center, k, x);
        double r = m->radius ? m->radius[k] : sphere_radius;
        double mass = m->rmass ? m->rmass[k] : 4.0 * M_PI / 3.0 * r * r * r;
        int i = atoms_add(g, 0, mj->type_offset + m->type[k], x, r, mass);
        domain_remap(g, g->atoms.x + 3 * i, g->atoms.image + 3 * i);
        g->atoms.mol[i] = mj->nmol + 1; /* made absolute by set_molecule_ids */
    }
    mj->nmol++;
}

/* LAMMPS: the molecules created get IDs after the largest ID of the atoms
 * that existed before, one per molecule in creation order. */
static void set_molecule_ids(struct gravel *g, int first)
{
    struct atoms *a = &g->atoms;
    if (!a->molecule_flag) {
        for (int i = first; i < a->n; i++)
            a->mol[i] = 0;
        return;
    }
    int64_t maxmol = 0;
    for (int i = 0; i < first; i++)
        if (a->mol[i] > maxmol)
            maxmol = a->mol[i];
    for (int i = first; i < a->n; i++)
        a->mol[i] += maxmol;
}

struct lat_ctx {
    int basis_type[8];          /* type per basis atom (keyword basis) */
    const struct region *r;
    struct mesh_skip *skip;
    struct mol_job *mj;
    bigint n;
};

static void add_lattice_point(struct gravel *g, const double x[3], int basis, void *vctx)
{
    struct lat_ctx *c = vctx;
    if (c->r && !region_match(c->r, x))
        return;
    if (c->skip->n && mesh_skip_hit(c->skip, x))
        return;
    if (c->mj->mol) {
        add_molecule(g, c->mj, x);
        c->n += c->mj->mol->natoms;
        return;
    }
    atoms_add(g, 0, c->basis_type[basis], x, NEW_RADIUS(g), NEW_MASS(g));
    c->n++;
}

/* ---- cell grid for the overlap test ---------------------------------------- */

struct grid {
    int n[3];
    double lo[3], inv[3];
    int *head, *next;
    int cap_next;
};

static void grid_init(struct gravel *g, struct grid *gr, double cut, bigint nmax)
{
    double len[3];
    double maxcells = fmax(64.0, 2.0 * (double)nmax);
    double h = cut;
    for (int d = 0; d < 3; d++) {
        gr->lo[d] = g->dom.lo[d];
        len[d] = g->dom.hi[d] - g->dom.lo[d];
    }
    for (;;) {
        double tot = 1;
        for (int d = 0; d < 3; d++) {
            gr->n[d] = (int)fmax(1.0, fmin(floor(len[d] / h), 1 << 20));
            tot *= gr->n[d];
        }
        if (tot <= maxcells)
            break;
        h *= 1.25;
    }
    for (int d = 0; d < 3; d++)
        gr->inv[d] = gr->n[d] / len[d];
    size_t nc = (size_t)gr->n[0] * gr->n[1] * gr->n[2];
    gr->head = gr_malloc(g, nc * sizeof(int));
    memset(gr->head, 0xff, nc * sizeof(int)); /* -1 */
    gr->next = NULL;
    gr->cap_next = 0;
}

static void grid_cell(const struct grid *gr, const double x[3], int c[3])
{
    for (int d = 0; d < 3; d++) {
        double f = (x[d] - gr->lo[d]) * gr->inv[d];
        int k = f < 0 ? 0 : f >= gr->n[d] ? gr->n[d] - 1 : (int)f;
        c[d] = k;
    }
}

static void grid_insert(struct gravel *g, struct grid *gr, int i)
{
    if (i >= gr->cap_next) {
        int cap = gr->cap_next ? gr->cap_next : 1024;
        while (cap <= i)
            cap *= 2;
        gr->next = gr_realloc(g, gr->next, (size_t)cap * sizeof(int));
        gr->cap_next = cap;
    }
    int c[3];
    grid_cell(gr, g->atoms.x + 3 * (size_t)i, c);
    size_t k = ((size_t)c[2] * gr->n[1] + c[1]) * gr->n[0] + c[0];
    gr->next[i] = gr->head[k];
    gr->head[k] = i;
}

/* 1 if some atom is closer than cut to x. */
static int grid_overlaps(const struct gravel *g, const struct grid *gr, const double x[3],
                         double cut)
{
    int c[3];
    grid_cell(gr, x, c);
    double cut2 = cut * cut;
    int lo[3], hi[3];
    for (int d = 0; d < 3; d++) {
        lo[d] = c[d] - 1;
        hi[d] = c[d] + 1;
        if (gr->n[d] <= 3) { /* every cell is a neighbor; visit each once */
            lo[d] = 0;
            hi[d] = gr->n[d] - 1;
        } else if (!g->dom.periodic[d]) {
            if (lo[d] < 0)
                lo[d] = 0;
            if (hi[d] >= gr->n[d])
                hi[d] = gr->n[d] - 1;
        }
    }
    for (int kz = lo[2]; kz <= hi[2]; kz++)
        for (int ky = lo[1]; ky <= hi[1]; ky++)
            for (int kx = lo[0]; kx <= hi[0]; kx++) {
                int k3[3] = {kx, ky, kz};
                for (int d = 0; d < 3; d++)
                    k3[d] = (k3[d] + gr->n[d]) % gr->n[d];
                size_t k = ((size_t)k3[2] * gr->n[1] + k3[1]) * gr->n[0] + k3[0];
                for (int j = gr->head[k]; j >= 0; j = gr->next[j]) {
                    const double *y = g->atoms.x + 3 * (size_t)j;
                    double del[3] = {x[0] - y[0], x[1] - y[1], x[2] - y[2]};
                    domain_minimum_image(g, del);
                    if (del[0] * del[0] + del[1] * del[1] + del[2] * del[2] < cut2)
                        return 1;
                }
            }
    return 0;
}

static void grid_free(struct grid *gr)
{
    free(gr->head);
    free(gr->next);
    gr->head = gr->next = NULL;
}

/* ---- random insertion ------------------------------------------------------ */

struct random_job {
    bigint n;
    unsigned long seed;
    const struct region *r;
    double overlap;
    int maxtry;
    int type;
    struct mesh_skip *skip;
    struct mol_job *mj;
    /* owned resources, freed by the caller on any exit */
    struct grid grid;
};

static bigint insert_random(struct gravel *g, struct random_job *job)
{
    double lo[3], hi[3];
    if (job->r) {
        if (!region_box_bounds(g, job->r, lo, hi))
            gr_error(g, "region '%s' does not overlap the box", job->r->id);
    } else {
        for (int d = 0; d < 3; d++) {
            lo[d] = g->dom.lo[d];
            hi[d] = g->dom.hi[d];
        }
    }
    struct rng_park rng;
    rng_park_init(&rng, (int)job->seed);
    for (int k = 0; k < 30; k++) /* LAMMPS's warm-up */
        rng_park_uniform(&rng);
    if (job->overlap > 0) {
        grid_init(g, &job->grid, job->overlap, (bigint)g->atoms.n + job->n);
        for (int i = 0; i < g->atoms.n; i++)
            grid_insert(g, &job->grid, i);
    }
    if (job->n > 0) /* grow further only as atoms actually fit */
        atoms_reserve(g, g->atoms.n + (int)(job->n < (1 << 22) ? job->n : (1 << 22)));
    bigint added = 0;
    for (bigint k = 0; k < job->n; k++) {
        int ok = 0;
        double x[3];
        for (int t = 0; t < job->maxtry && !ok; t++) {
            for (int d = 0; d < 3; d++)
                x[d] = lo[d] + rng_park_uniform(&rng) * (hi[d] - lo[d]);
            if (g->dom.dimension == 2) /* LAMMPS: the z draw is made, then the mid-plane */
                x[2] = lo[2] + 0.5 * (hi[2] - lo[2]);
            if (job->r && !region_match(job->r, x))
                continue;
            if (job->overlap > 0 && grid_overlaps(g, &job->grid, x, job->overlap))
                continue;
            if (job->skip->n && mesh_skip_hit(job->skip, x))
                continue;
            ok = 1;
        }
        if (!ok)
            continue;
        added++;
        /* LAMMPS counts it, but creates it only inside [lo, hi) of its
         * sub-domain: hi - lo rounding can land a point on the upper face */
        if (!domain_inside(g, x))
            continue;
        if (job->mj->mol) {
            add_molecule(g, job->mj, x);
            continue;
        }
        int i = atoms_add(g, 0, job->type, x, NEW_RADIUS(g), NEW_MASS(g));
        if (job->overlap > 0)
            grid_insert(g, &job->grid, i);
    }
    if (added < job->n)
        gr_warn(g, "only inserted %lld particles out of %lld (maxtry %d)", (long long)added,
                (long long)job->n, job->maxtry);
    return added;
}

/* ---- the command -------------------------------------------------------- */

void cmd_create_atoms(struct gravel *g, int argc, char **argv)
{
    int type = arg_int(g, argv[0], "atom type");
    const char *style = argv[1];
    if ((g->dom.xy != 0.0 || g->dom.xz != 0.0 || g->dom.yz != 0.0) && strcmp(style, "single"))
        gr_error(g, "create_atoms %s in a tilted triclinic box is not supported (single is; or "
                    "create the atoms before tilting the box with change_box, or read_data)",
                 style);
    int iarg;
    struct region *r = NULL;
    double xone[3] = {0, 0, 0};
    bigint nrandom = 0;
    unsigned long seed = 0;
    if (!strcmp(style, "box")) {
        iarg = 2;
    } else if (!strcmp(style, "region")) {
        arg_need(g, argc, 1, 1, "region");
        r = region_get(g, argv[2]);
        iarg = 3;
    } else if (!strcmp(style, "single")) {
        arg_need(g, argc, 1, 3, "single");
        for (int d = 0; d < 3; d++)
            xone[d] = arg_double(g, argv[2 + d], "coordinate");
        iarg = 5;
    } else if (!strcmp(style, "random")) {
        arg_need(g, argc, 1, 3, "random");
        nrandom = arg_bigint(g, argv[2], "number of atoms");
        if (nrandom < 0 || nrandom > 100000000)
            gr_error(g, "number of random atoms must be between 0 and 1e8, got %s", argv[2]);
        int s = arg_int(g, argv[3], "seed");
        if (s <= 0)
            gr_error(g, "seed must be a positive integer, got %s", argv[3]);
        seed = (unsigned long)s;
        if (strcmp(argv[4], "NULL") != 0)
            r = region_get(g, argv[4]);
        iarg = 5;
    } else {
        gr_error(g, "unknown style '%.32s': expected box, region, single or random", style);
    }
    if (r)
        region_prematch(g, r);
    int lattice_units = 1, remap = 0, maxtry = CA_MAXTRY_DEFAULT, maxtry_set = 0;
    int basis_type[8], basis_set = 0;
    for (int m = 0; m < 8; m++)
        basis_type[m] = type;
    double overlap = 0;
    int overlap_set = 0;
    int nmesh = 0;
    char mesh_id[CA_MAXMESH][GR_NAMELEN];
    double mesh_d[CA_MAXMESH];
    struct mol_job mj;
    memset(&mj, 0, sizeof mj);
    int molseed = 0;
    for (int i = iarg; i < argc; i++) {
        const char *kw = argv[i];
        if (!strcmp(kw, "units")) {
            arg_need(g, argc, i, 1, kw);
            lattice_units = domain_parse_units_kw(g, argv[++i]);
        } else if (!strcmp(kw, "remap")) {
            arg_need(g, argc, i, 1, kw);
            remap = arg_yesno(g, argv[++i], "remap");
        } else if (!strcmp(kw, "overlap")) {
            arg_need(g, argc, i, 1, kw);
            overlap = arg_positive(g, argv[++i], "overlap");
            overlap_set = 1;
        } else if (!strcmp(kw, "mesh")) {
            arg_need(g, argc, i, 2, kw);
            if (nmesh == CA_MAXMESH)
                gr_error(g, "at most %d mesh keywords", CA_MAXMESH);
            mesh_surface_get(g, argv[i + 1], "create_atoms mesh");
            snprintf(mesh_id[nmesh], GR_NAMELEN, "%s", argv[i + 1]);
            mesh_d[nmesh++] = arg_positive(g, argv[i + 2], "mesh distance");
            i += 2;
        } else if (!strcmp(kw, "maxtry")) {
            arg_need(g, argc, i, 1, kw);
            maxtry = arg_int_range(g, argv[++i], 1, 1 << 30, "maxtry");
            maxtry_set = 1;
        } else if (!strcmp(kw, "basis")) {
            arg_need(g, argc, i, 2, kw);
            int nb = g->dom.lat.nbasis;
            if (nb < 1)
                gr_error(g, "basis needs a lattice: use the lattice command first");
            int m = arg_int_range(g, argv[i + 1], 1, nb, "basis atom");
            basis_type[m - 1] = arg_int_range(g, argv[i + 2], 1, g->atoms.ntypes, "basis type");
            basis_set = 1;
            i += 2;
        } else if (!strcmp(kw, "mol")) {
            arg_need(g, argc, i, 2, kw);
            mj.mol = molecule_find(g, argv[i + 1]);
            if (!mj.mol)
                gr_error(g, "molecule template ID %.64s for create_atoms does not exist",
                         argv[i + 1]);
            mol_require_atoms(g, mj.mol);
            molseed = arg_int(g, argv[i + 2], "molecule seed");
            if (molseed <= 0 || molseed > 900000000)
                gr_error(g, "molecule seed must be in 1..900000000, got %s", argv[i + 2]);
            i += 2;
        } else if (!strcmp(kw, "rotate")) {
            arg_need(g, argc, i, 4, kw);
            double theta = arg_double(g, argv[i + 1], "rotate angle");
            double axis[3];
            for (int k = 0; k < 3; k++)
                axis[k] = arg_double(g, argv[i + 2 + k], "rotate axis");
            if (axis[0] == 0.0 && axis[1] == 0.0 && axis[2] == 0.0)
                gr_error(g, "rotate axis must not be zero");
            if (g->dom.dimension == 2 && (axis[0] != 0.0 || axis[1] != 0.0))
                gr_error(g, "invalid create_atoms rotation vector for 2d model (must be along z)");
            double s = 1.0 / sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
            for (int k = 0; k < 3; k++)
                axis[k] *= s;
            rm_axisangle_to_quat(axis, theta * M_PI / 180.0, mj.quat);
            mj.quat_user = 1;
            i += 4;
        } else if (!strcmp(kw, "var") || !strcmp(kw, "set")) {
            gr_error(g, "keyword '%s' is not supported", kw);
        } else {
            gr_error(g, "unknown keyword '%.32s'", kw);
        }
    }
    if (mj.mol) {
        /* LAMMPS: the type argument is an offset to the template's types */
        long long lo = (long long)type + 1, hi = (long long)type + mj.mol->ntypes;
        if (lo < 1 || hi > g->atoms.ntypes)
            gr_error(g, "invalid atom type in create_atoms mol command (type offset %d + "
                        "template types 1..%d, box has %d)",
                     type, mj.mol->ntypes, g->atoms.ntypes);
        if (overlap_set || maxtry_set)
            gr_error(g, "overlap and maxtry are not supported with mol (as LAMMPS 29 Sep 2021)");
        if (nmesh)
            gr_error(g, "create_atoms mesh is not compatible with the mol option");
        mol_compute_center(mj.mol);
        rng_mars_init(&mj.rng, molseed);
        mj.type_offset = type;
    } else {
        if (type < 1 || type > g->atoms.ntypes)
            gr_error(g, "atom type must be between 1 and %d, got %d", g->atoms.ntypes, type);
        if (mj.quat_user)
            gr_error(g, "rotate applies only with mol (a molecule template)");
    }
    if ((overlap_set || maxtry_set) && strcmp(style, "random") != 0)
        gr_error(g, "overlap and maxtry apply only to style random");
    if (remap && strcmp(style, "single") != 0)
        gr_error(g, "remap applies only to style single");
    if (basis_set && strcmp(style, "box") != 0 && strcmp(style, "region") != 0)
        gr_error(g, "basis applies only to styles box and region");
    if (nmesh && !strcmp(style, "single"))
        gr_error(g, "mesh applies only to styles box, region and random");
    /* the meshes to keep clear of, binned once; freed however the command ends */
    struct mesh_skip skip;
    memset(&skip, 0, sizeof skip);
    jmp_buf *outer0 = g->err.jmp, here0;
    g->err.jmp = &here0;
    if (setjmp(here0)) {
        g->err.jmp = outer0;
        mesh_skip_free(&skip);
        if (outer0)
            longjmp(*outer0, 1);
        gr_report_error(g);
        exit(1);
    }
    {
        double sc[3];
        domain_unit_scale(g, lattice_units, sc);
        for (int k = 0; k < nmesh; k++) {
            struct mesh_surface *msurf = mesh_surface_get(g, mesh_id[k], "create_atoms mesh");
            char err[256];
            skip.m[k] = &msurf->m;
            skip.dist[k] = mesh_d[k] * sc[0];
            mesh_surface_pose(g, mesh_id[k], &skip.pose[k]);
            if (mesh_bin(&msurf->m, skip.dist[k], &skip.b[k], err, sizeof err) != 0)
                gr_error(g, "create_atoms mesh %s: %s", mesh_id[k], err);
            skip.n = k + 1;
        }
    }
    bigint created = 0;
    int first = g->atoms.n;
    if (!strcmp(style, "box") || !strcmp(style, "region")) {
        double lo[3], hi[3];
        for (int d = 0; d < 3; d++) {
            lo[d] = g->dom.lo[d];
            hi[d] = g->dom.hi[d];
            if (g->dom.periodic[d]) {
                double eps = (hi[d] - lo[d]) * CA_EPSILON;
                lo[d] -= eps;
                hi[d] -= 2.0 * eps;
            }
        }
        struct lat_ctx c;
        memcpy(c.basis_type, basis_type, sizeof basis_type);
        c.r = r;
        c.skip = &skip;
        c.mj = &mj;
        c.n = 0;
        if (r && r->bbox)
            lattice_foreach(g, lo, hi, r->bbox_lo, r->bbox_hi, add_lattice_point, &c);
        else
            lattice_foreach(g, lo, hi, NULL, NULL, add_lattice_point, &c);
        created = c.n;
    } else if (!strcmp(style, "single")) {
        double sc[3];
        domain_unit_scale(g, lattice_units, sc);
        int image[3] = {0, 0, 0};
        for (int d = 0; d < 3; d++)
            xone[d] *= sc[d];
        if (remap)
            domain_remap(g, xone, image);
        if (!domain_inside(g, xone))
            gr_error(g, "point (%g %g %g) is outside the box%s", xone[0], xone[1], xone[2],
                     remap ? "" : " (remap yes wraps periodic dimensions)");
        if (mj.mol) {
            add_molecule(g, &mj, xone);
        } else {
            int i = atoms_add(g, 0, type, xone, NEW_RADIUS(g), NEW_MASS(g));
            for (int d = 0; d < 3; d++)
                g->atoms.image[3 * i + d] = image[d];
        }
        created = g->atoms.n - first;
    } else {
        struct random_job job;
        memset(&job, 0, sizeof job);
        job.n = nrandom;
        job.seed = seed;
        job.r = r;
        double sc[3];
        domain_unit_scale(g, lattice_units, sc);
        job.overlap = overlap * sc[0]; /* LAMMPS: overlap *= xlattice */
        job.maxtry = maxtry;
        job.type = type;
        job.skip = &skip;
        job.mj = &mj;
        /* free the generator and grid however insertion ends */
        jmp_buf *outer = g->err.jmp, here;
        g->err.jmp = &here;
        if (setjmp(here)) {
            g->err.jmp = outer;
            grid_free(&job.grid);
            if (outer)
                longjmp(*outer, 1);
            gr_report_error(g);
            exit(1);
        }
        created = insert_random(g, &job);
        g->err.jmp = outer;
        grid_free(&job.grid);
        if (mj.mol)
            created = g->atoms.n - first;
    }
    if (mj.mol)
        set_molecule_ids(g, first);
    g->err.jmp = outer0;
    if (nmesh)
        gr_print(g, "  %lld sites skipped within the mesh distance of %d mesh%s\n",
                 (long long)skip.skipped, nmesh, nmesh > 1 ? "es" : "");
    mesh_skip_free(&skip);
    gr_print(g, "Created %lld atoms\n", (long long)created);
}
