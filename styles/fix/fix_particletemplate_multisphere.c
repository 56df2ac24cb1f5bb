/* fix_particletemplate_multisphere.c - `fix ID group
 * particletemplate/multisphere seed [atom_type T] density constant RHO
 * [volume_limit V] nspheres N ntry M spheres file F scale S | spheres x1 y1
 * z1 r1 ... type MT [mass M inertia_tensor Ixx Ixy Ixz Iyy Iyz Izz
 * use_volume|use_density] [fflag on on on] [tflag on on on]`: a clump of N
 * overlapping spheres for fix particledistribution/discrete, inserted as a
 * rigid body of fix multisphere (LIGGGHTS-PUBLIC 3.8
 * FixTemplateMultisphere and FixTemplateMultiplespheres).
 *
 * Properties, computed once at creation as LIGGGHTS computes them, with its
 * Monte-Carlo stream (Park-Miller seeded with `seed`, LIGGGHTS's random_mc):
 *   bounding sphere  200 random visiting orders of the spheres (draws
 *                    int(u N) until an unvisited one), each growing a sphere
 *                    to contain the next; the smallest is kept;
 *   volume, centre   M points uniform in the spheres' bounding box (3 draws
 *                    each); a point inside any sphere counts once; volume =
 *                    hits / M x box volume, centre of mass = the hits' mean
 *                    (LIGGGHTS's running mean); mass = volume x density;
 *   inertia          M more points: sum over hits of the point-mass tensor
 *                    about the centre, x density x box volume / M.
 * With `mass` and `inertia_tensor` the given values replace the Monte-Carlo
 * ones: use_volume keeps the Monte-Carlo volume (density = mass / volume),
 * use_density keeps the density (volume = mass / density; no centre shift,
 * the given coordinates are about the centre of mass).
 *
 * The clump becomes a molecule template (struct molecule) of fix rigid/small's
 * machinery: atoms = spheres, each of mass M/N (their weights sum to the
 * body's: gravity on the atoms is M g), centre of mass 0, the tensor above;
 * its principal axes are found by the same Jacobi rotations as rigid/small's
 * bodies. fflag/tflag (on|off per component) hold the inserted bodies'
 * velocity or angular momentum components (fix_rigid_small.h,
 * rigid_small_hold). Not supported (errors naming the keyword): radius,
 * spheres_different_types, bonded yes, a non-constant density. Full contract: doc/styles/fix_particletemplate_multisphere.md. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "error.h"
#include "fix.h"
#include "fix_particletemplate_multisphere.h"
#include "fix_rigid_small.h"
#include "log.h"
#include "molecule.h"

#define WHO "fix particletemplate/multisphere"
#define N_SHUFFLE_BOUND 200
#define LARGE 1e8

void mstemplate_sphere(const struct mstemplate *c, const double rot[3][3], const double xcm[3],
                       int k, double out[3])
{
    const double *d = c->xs + 3 * k;
    for (int q = 0; q < 3; q++)
        out[q] = xcm[q] + rot[q][0] * d[0] + rot[q][1] * d[1] + rot[q][2] * d[2];
}

/* `file F scale S`: N lines "x y z r" ('#' comments and blank lines skipped). */
static void read_spheres(struct gravel *g, struct mstemplate *c, const char *path, double scale)
{
    FILE *fp = fopen(path, "r");
    if (!fp)
        gr_error(g, WHO ": Cannot open clump file %s", path);
    char line[4096];
    int n = 0;
    while (fgets(line, sizeof line, fp)) {
        char *h = strchr(line, '#');
        if (h)
            *h = 0;
        double v[4];
        char extra;
        int got = sscanf(line, "%lf %lf %lf %lf %c", &v[0], &v[1], &v[2], &v[3], &extra);
        if (got <= 0)
            continue;
        if (got < 4) {
            fclose(fp);
            gr_error(g, WHO ": Not enough arguments in one line of clump file %s, need to "
                        "specify [xcoo ycoo zcoo radius] in each line", path);
        }
        if (n >= c->nspheres) {
            fclose(fp);
            gr_error(g, WHO ": Number of clumps in file %s larger than number specified (%d)",
                     path, c->nspheres);
        }
        for (int q = 0; q < 3; q++)
            c->xs[3 * n + q] = v[q] * scale;
        c->rs[n++] = v[3] * scale;
    }
    fclose(fp);
    if (n != c->nspheres)
        gr_error(g, WHO ": Number of clumps in file %s (%d) does not match number of clumps "
                    "that were specified (%d)", path, n, c->nspheres);
}

/* LIGGGHTS calc_bounding_sphere (randomized, N_SHUFFLE_BOUND orders). */
static void bounding_sphere(struct gravel *g, struct mstemplate *c, struct rng_park *rng)
{
    int n = c->nspheres;
    int *visited = gr_calloc(g, (size_t)n, sizeof(int));
    c->rbound = LARGE;
    for (int s = 0; s < N_SHUFFLE_BOUND; s++) {
        memset(visited, 0, (size_t)n * sizeof(int));
        int i = -1, nv = 0;
        while (i < 0 || i >= n || visited[i])
            i = (int)(rng_park_uniform(rng) * n);
        nv++;
        visited[i] = 1;
        double xb[3] = {c->xs[3 * i], c->xs[3 * i + 1], c->xs[3 * i + 2]}, rb = c->rs[i];
        while (nv < n) {
            while (i < 0 || i >= n || visited[i])
                i = (int)(rng_park_uniform(rng) * n);
            nv++;
            visited[i] = 1;
            double d[3];
            for (int q = 0; q < 3; q++)
                d[q] = c->xs[3 * i + q] - xb[q];
            double dist = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            if (dist + c->rs[i] > rb) {
                double fact = (dist + c->rs[i] - rb) / (2. * dist);
                for (int q = 0; q < 3; q++) {
                    d[q] *= fact;
                    xb[q] += d[q];
                }
                rb += sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            }
        }
        if (rb < c->rbound) {
            c->rbound = rb;
            memcpy(c->xbound, xb, sizeof xb);
        }
    }
    free(visited);
    for (int i = 0; i < n; i++) {
        double d[3];
        for (int q = 0; q < 3; q++)
            d[q] = c->xbound[q] - c->xs[3 * i + q];
        if (sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) > c->rbound)
            gr_error(g, WHO ": Bounding sphere calculation for template failed");
    }
}

static void try_point(const struct mstemplate *c, struct rng_park *rng, double x[3])
{
    for (int q = 0; q < 3; q++)
        x[q] = c->xmin[q] + (c->xmax[q] - c->xmin[q]) * rng_park_uniform(rng);
}

static int inside(const struct mstemplate *c, const double x[3])
{
    for (int j = 0; j < c->nspheres; j++) {
        const double *s = c->xs + 3 * j;
        double dx = x[0] - s[0], dy = x[1] - s[1], dz = x[2] - s[2];
        if (dx * dx + dy * dy + dz * dz < c->rs[j] * c->rs[j])
            return 1;
    }
    return 0;
}

static double box_volume(const struct mstemplate *c)
{
    return (c->xmax[0] - c->xmin[0]) * (c->xmax[1] - c->xmin[1]) * (c->xmax[2] - c->xmin[2]);
}

/* LIGGGHTS calc_center_of_mass: volume and centre of mass, then every
 * coordinate shifted so that the centre of mass is 0. Returns the volume. */
static double volume_and_center(struct mstemplate *c, struct rng_park *rng)
{
    double xcm[3] = {0, 0, 0}, x[3];
    int nsuccess = 0;
    for (int i = 0; i < c->ntry; i++) {
        try_point(c, rng, x);
        if (inside(c, x)) {
            for (int q = 0; q < 3; q++)
                xcm[q] = (xcm[q] * (double)nsuccess + x[q]) / (double)(nsuccess + 1);
            nsuccess++;
        }
    }
    double vol = (double)nsuccess / (double)c->ntry * box_volume(c);
    for (int q = 0; q < 3; q++) {
        for (int i = 0; i < c->nspheres; i++)
            c->xs[3 * i + q] -= xcm[q];
        c->xmin[q] -= xcm[q];
        c->xmax[q] -= xcm[q];
        c->xbound[q] -= xcm[q];
    }
    return vol;
}

/* LIGGGHTS calc_inertia about the (shifted) centre of mass 0: tensor as
 * xx yy zz yz xz xy (struct molecule's itensor). */
static void inertia_mc(const struct mstemplate *c, struct rng_park *rng, double density,
                       double it[6])
{
    double m[3][3] = {{0}}, x[3];
    for (int i = 0; i < c->ntry; i++) {
        try_point(c, rng, x);
        if (!inside(c, x))
            continue;
        m[0][0] += x[1] * x[1] + x[2] * x[2];
        m[0][1] -= x[0] * x[1];
        m[0][2] -= x[0] * x[2];
        m[1][1] += x[0] * x[0] + x[2] * x[2];
        m[1][2] -= x[1] * x[2];
        m[2][2] += x[0] * x[0] + x[1] * x[1];
    }
    double s = density / (double)c->ntry * box_volume(c);
    it[0] = m[0][0] * s, it[1] = m[1][1] * s, it[2] = m[2][2] * s;
    it[3] = m[1][2] * s, it[4] = m[0][2] * s, it[5] = m[0][1] * s;
}

static void make_molecule(struct gravel *g, struct fix *f, struct mstemplate *c, double mass,
                          const double it[6])
{
    int n = c->nspheres;
    struct molecule *m = c->mol = gr_calloc(g, 1, sizeof *m);
    snprintf(m->id, sizeof m->id, "%s", f->id);
    m->natoms = n;
    m->nmolecules = 1;
    m->ntypes = c->t.type;
    m->x = gr_calloc(g, 3 * (size_t)n, sizeof(double));
    m->type = gr_calloc(g, (size_t)n, sizeof(int));
    m->radius = gr_calloc(g, (size_t)n, sizeof(double));
    m->rmass = gr_calloc(g, (size_t)n, sizeof(double));
    memcpy(m->x, c->xs, 3 * (size_t)n * sizeof(double));
    for (int i = 0; i < n; i++) {
        m->type[i] = c->t.type;
        m->radius[i] = c->rs[i];
        m->rmass[i] = mass / n;
    }
    m->massflag = m->comflag = m->inertiaflag = 1;
    m->masstotal = mass;
    memcpy(m->itensor, it, sizeof m->itensor);
    mol_compute_center(m);
    mol_compute_mass(g, m);
    mol_compute_com(g, m);
    mol_compute_inertia(g, m);
}

static void destroy(struct fix *f)
{
    struct mstemplate *c = f->data;
    if (!c)
        return;
    free(c->xs);
    free(c->rs);
    if (c->mol)
        mol_free(c->mol);
    free(c);
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    struct mstemplate *c = gr_calloc(g, 1, sizeof *c);
    f->data = c;
    struct ptemplate *t = &c->t;
    t->ms = c;
    for (int q = 0; q < 3; q++)
        c->fflag[q] = c->tflag[q] = 1;
    ptemplate_start(g, f, t, argc, argv, WHO);
    int i = 1, n;
    while (i < argc && (n = ptemplate_keyword(g, t, argc, argv, i, WHO)))
        i += n;
    if (!t->have_density)
        gr_error(g, WHO ": have to define 'density'");
    if (t->density.style != PDF_CONSTANT)
        gr_error(g, WHO ": currently only supports constant density");
    if (t->have_radius)
        gr_error(g, WHO ": currently does not support keyword 'radius'");
    if (t->type > g->atoms.ntypes)
        gr_error(g, WHO ": atom_type %d is larger than the number of atom types %d", t->type,
                 g->atoms.ntypes);
    if (i >= argc || strcmp(argv[i], "nspheres"))
        gr_error(g, WHO ": expecting argument 'nspheres'%s%.64s", i < argc ? ", got " : "",
                 i < argc ? argv[i] : "");
    arg_need(g, argc, i, 1, "nspheres");
    c->nspheres = arg_int(g, argv[i + 1], "nspheres");
    if (c->nspheres < 2)
        gr_error(g, WHO ": illegal number of spheres %s (at least 2)", argv[i + 1]);
    i += 2;
    if (i >= argc || strcmp(argv[i], "ntry"))
        gr_error(g, WHO ": need 'ntry' to be defined (after nspheres)");
    arg_need(g, argc, i, 1, "ntry");
    c->ntry = arg_int(g, argv[i + 1], "ntry");
    i += 2;
    c->xs = gr_calloc(g, 3 * (size_t)c->nspheres, sizeof(double));
    c->rs = gr_calloc(g, (size_t)c->nspheres, sizeof(double));
    int have_spheres = 0;
    while (i < argc) {
        const char *k = argv[i];
        if (!strcmp(k, "spheres_different_types"))
            gr_error(g, WHO ": 'spheres_different_types' (spheres of several atom types) is "
                        "not supported");
        if (!strcmp(k, "spheres")) {
            arg_need(g, argc, i, 1, k);
            if (!strcmp(argv[i + 1], "file")) {
                arg_need(g, argc, i, 4, "spheres file");
                if (strcmp(argv[i + 3], "scale"))
                    gr_error(g, WHO ": you have to specify a scale factor (spheres file F "
                                "scale S)");
                double s = arg_double(g, argv[i + 4], "scale");
                if (!(s > 0))
                    gr_error(g, WHO ": scale factor must be >0, got %s", argv[i + 4]);
                read_spheres(g, c, argv[i + 2], s);
                i += 5;
            } else {
                if (i + 1 + 4 * c->nspheres > argc)
                    gr_error(g, WHO ": not enough arguments for %d spheres (x y z r each)",
                             c->nspheres);
                for (int j = 0; j < c->nspheres; j++) {
                    for (int q = 0; q < 3; q++)
                        c->xs[3 * j + q] = arg_double(g, argv[i + 1 + 4 * j + q], "spheres");
                    c->rs[j] = arg_double(g, argv[i + 4 + 4 * j], "spheres");
                }
                i += 1 + 4 * c->nspheres;
            }
            have_spheres = 1;
        } else if (!strcmp(k, "bonded")) {
            arg_need(g, argc, i, 1, k);
            if (arg_yesno(g, argv[i + 1], k))
                gr_error(g, WHO ": 'bonded yes' is not supported");
            i += 2;
        } else {
            break;
        }
    }
    if (!have_spheres)
        gr_error(g, WHO ": need to define spheres for the template");
    for (int j = 0; j < c->nspheres; j++)
        if (!(c->rs[j] > 0))
            gr_error(g, WHO ": radius must be > 0 (sphere %d)", j + 1);
    if (c->ntry < 1000)
        gr_error(g, WHO ": ntry is too low (%d < 1000)", c->ntry);
    if (c->ntry < 100000)
        gr_warn(g, "fix particletemplate/multisphere: ntry is very low");
    double mass = 0, it[6] = {0};
    int mass_set = 0, moi_set = 0, use_density = -1;
    for (; i < argc;) {
        const char *k = argv[i];
        if (!strcmp(k, "type")) {
            arg_need(g, argc, i, 1, k);
            c->mstype = arg_int(g, argv[i + 1], k);
            i += 2;
        } else if (!strcmp(k, "mass")) {
            arg_need(g, argc, i, 1, k);
            mass = arg_double(g, argv[i + 1], k);
            if (!(mass > 0))
                gr_error(g, WHO ": mass must be > 0, got %s", argv[i + 1]);
            mass_set = 1;
            i += 2;
        } else if (!strcmp(k, "use_volume") || !strcmp(k, "use_density")) {
            use_density = k[4] == 'd';
            i += 1;
        } else if (!strcmp(k, "inertia_tensor")) {
            arg_need(g, argc, i, 6, k);
            double v[6];
            for (int q = 0; q < 6; q++)
                v[q] = arg_double(g, argv[i + 1 + q], k);
            /* Ixx Ixy Ixz Iyy Iyz Izz -> xx yy zz yz xz xy */
            it[0] = v[0], it[1] = v[3], it[2] = v[5], it[3] = v[4], it[4] = v[2], it[5] = v[1];
            moi_set = 1;
            i += 7;
        } else if (!strcmp(k, "fflag") || !strcmp(k, "tflag")) {
            rigid_small_flags_arg(g, argc, argv, i, k[0] == 'f' ? c->fflag : c->tflag);
            i += 4;
        } else {
            gr_error(g, WHO ": unknown keyword '%.64s' (type, mass, inertia_tensor, "
                        "use_volume, use_density, fflag, tflag)", k);
        }
    }
    if (c->mstype < 1)
        gr_error(g, WHO ": have to provide a type >=1");
    if (mass_set != moi_set)
        gr_error(g, WHO ": have to define either both 'mass' and 'inertia_tensor' or none of "
                    "the two");
    if (mass_set && use_density < 0)
        gr_error(g, WHO ": have to use either 'use_volume' or 'use_density' in case 'mass' and "
                    "'inertia_tensor' are specified");
    for (int q = 0; q < 3; q++)
        c->xmin[q] = LARGE, c->xmax[q] = -LARGE;
    for (int j = 0; j < c->nspheres; j++)
        for (int q = 0; q < 3; q++) {
            double lo = c->xs[3 * j + q] - c->rs[j], hi = c->xs[3 * j + q] + c->rs[j];
            c->xmin[q] = lo < c->xmin[q] ? lo : c->xmin[q];
            c->xmax[q] = hi > c->xmax[q] ? hi : c->xmax[q];
        }
    gr_print(g, "Calculating the properties of the given template.\n   Depending on ntry, this "
                "may take a while...\n");
    struct rng_park mc;
    rng_park_init(&mc, t->seed);
    double rho = t->density.mu;
    bounding_sphere(g, c, &mc);
    if (mass_set && use_density == 1) {
        t->volexpect = mass / rho;
    } else {
        t->volexpect = volume_and_center(c, &mc);
        if (mass_set) {
            rho = mass / t->volexpect;
            t->density.mu = t->density.min = t->density.max = rho;
        } else {
            mass = t->volexpect * rho;
            inertia_mc(c, &mc, rho, it);
        }
    }
    t->massexpect = mass;
    c->requiv = mass_set && use_density == 0 ? cbrt(3. * t->volexpect / (4. * M_PI))
                                              : cbrt(6. * mass / (8. * rho * M_PI));
    /* the insertion fixes see a sphere of the bounding radius; the smallest
     * sphere is the distribution's minimum radius (LIGGGHTS min_rad) */
    double rmin = c->rs[0];
    for (int j = 1; j < c->nspheres; j++)
        rmin = c->rs[j] < rmin ? c->rs[j] : rmin;
    t->radius = (struct pdf){PDF_CONSTANT, c->rbound, 0., rmin, c->rbound};
    t->have_radius = 1;
    make_molecule(g, f, c, mass, it);
    const struct molecule *m = c->mol;
    gr_print(g, "Finished calculating properties of template\n"
                "   mass = %e, radius of bounding sphere = %e, radius of equivalent sphere = "
                "%e\n   center of mass = %e, %e, %e\n"
                "   Principal moments of inertia_: %e, %e, %e\n"
                "     Inertia tensor: %e, %e, %e\n     Inertia tensor: %e, %e, %e\n"
                "     Inertia tensor: %e, %e, %e\n",
             mass, c->rbound, c->requiv, 0., 0., 0., m->inertia[0], m->inertia[1],
             m->inertia[2], it[0], it[5], it[4], it[5], it[1], it[3], it[4], it[3], it[2]);
}

/* LIGGGHTS FixTemplateMultisphere::init: the types of all templates are
 * 1 .. count, each once. */
static void init(struct gravel *g, struct fix *f)
{
    int n = 0, lo = 1 << 30, hi = 0, mine = ((struct mstemplate *)f->data)->mstype;
    for (int i = 0; i < g->styles.nfix; i++) {
        struct fix *o = g->styles.fix[i];
        if (strcmp(o->style->name, f->style->name))
            continue;
        int ty = ((struct mstemplate *)o->data)->mstype;
        if (o != f && ty == mine)
            gr_error(g, WHO " %s: multisphere template types have to be unique (type %d)",
                     f->id, mine);
        n++;
        lo = ty < lo ? ty : lo;
        hi = ty > hi ? ty : hi;
    }
    if (lo != 1 || hi != n)
        gr_error(g, WHO " %s: multisphere template types have to be consecutive starting from "
                    "1", f->id);
}

const struct fix_style fix_style_particletemplate_multisphere = {
    .name = "particletemplate/multisphere",
    .create = create,
    .init = init,
    .write_restart = ptemplate_write_restart,
    .read_restart = ptemplate_read_restart,
    .destroy = destroy,
};
