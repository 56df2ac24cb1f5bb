/* molecule.c - molecule templates (molecule.h): the `molecule` command, the
 * LAMMPS molecule file reader, and the derived rigid-body quantities. */
#include "molecule.h"

#include <ctype.h>
#include <math.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "error.h"
#include "fileio.h"
#include "log.h"
#include "rigid_math.h"

#define SINERTIA 0.4 /* solid sphere */

struct molecule *molecule_find(struct gravel *g, const char *id)
{
    for (int i = 0; i < g->nmolecule; i++)
        if (!strcmp(g->molecules[i]->id, id))
            return g->molecules[i];
    return NULL;
}

void mol_require_atoms(struct gravel *g, const struct molecule *m)
{
    if (m->natoms < 1)
        gr_error(g, "molecule template %s has no atoms (only surface triangles)", m->id);
}

void mol_free(struct molecule *m)
{
    if (!m)
        return;
    free(m->x);
    free(m->type);
    free(m->radius);
    free(m->rmass);
    free(m->molecule);
    free(m->points);
    free(m->tri);
    free(m->tri_mol);
    free(m->tri_type);
    free(m->dx);
    free(m->dxcom);
    free(m->dxbody);
    free(m);
}

void molecules_free(struct gravel *g)
{
    for (int i = 0; i < g->nmolecule; i++)
        mol_free(g->molecules[i]);
    free(g->molecules);
    g->molecules = NULL;
    g->nmolecule = 0;
}

/* ---- the file ---------------------------------------------------------------- */

/* The open file and every scratch buffer of one read: reader_close frees
 * them all, on success and when an error unwinds through read_guarded. */
struct reader {
    FILE *fp;
    const char *path;
    char *buf;
    size_t cap;
    int line;
    int *seen;              /* section(): how often each atom appeared */
    double *tmp;            /* one value per atom (Types, Molecules), 5 per triangle */
};

static void reader_close(struct reader *r)
{
    free(r->buf);
    free(r->seen);
    free(r->tmp);
    r->buf = NULL;
    r->seen = NULL;
    r->tmp = NULL;
    if (r->fp)
        fclose(r->fp);
    r->fp = NULL;
}

/* Next line without its comment, trimmed; NULL at the end. */
static char *next_line(struct gravel *g, struct reader *r)
{
    ssize_t n = fio_getline(r->fp, &r->buf, &r->cap, 1 << 20);
    if (n == FIO_ERR)
        gr_error(g, "cannot read molecule file '%s' (line %d)", r->path, r->line + 1);
    if (n == FIO_EOF)
        return NULL;
    r->line++;
    char *s = r->buf, *h = strchr(s, '#');
    if (h)
        *h = 0;
    while (isspace((unsigned char)*s))
        s++;
    size_t len = strlen(s);
    while (len && isspace((unsigned char)s[len - 1]))
        s[--len] = 0;
    return s;
}

static int split(char *s, char **w, int max)
{
    int n = 0;
    for (char *t = strtok(s, " \t"); t && n < max; t = strtok(NULL, " \t"))
        w[n++] = t;
    return n;
}

/* A finite number (nan, inf and overflowing values are refused). */
static double num(struct gravel *g, const struct reader *r, const char *s)
{
    char *end;
    double v = strtod(s, &end);
    if (end == s || *end)
        gr_error(g, "molecule file '%s' line %d: expected a number, got '%.40s'", r->path,
                 r->line, s);
    if (!isfinite(v))
        gr_error(g, "molecule file '%s' line %d: expected a finite number, got '%.40s'",
                 r->path, r->line, s);
    return v;
}

/* v times a scale factor, which must stay finite (what: the value's name). */
static double scaled(struct gravel *g, const char *path, double v, double factor,
                     const char *what)
{
    double x = v * factor;
    if (!isfinite(x))
        gr_error(g, "molecule file '%s': %s %g times the scale factor is not finite", path,
                 what, v);
    return x;
}

/* A per-atom integer of a section (type, molecule ID) read as a number:
 * whole and within [1, hi] (no conversion of an out-of-range double). */
static int whole_in(double v, double hi) { return v == floor(v) && v >= 1 && v <= hi; }

static int inum(struct gravel *g, const struct reader *r, const char *s)
{
    char *end;
    long v = strtol(s, &end, 10);
    if (end == s || *end || v < -2147483647L || v > 2147483647L)
        gr_error(g, "molecule file '%s' line %d: expected an integer, got '%.40s'", r->path,
                 r->line, s);
    return (int)v;
}

/* One section of n entries (atoms, points or triangles: `noun`), one line
 * each: "index values..." (nval values), every index 1..n once. */
static void section(struct gravel *g, struct reader *r, int n, const char *noun,
                    const char *name, int nval, double *out)
{
    free(r->seen);
    r->seen = NULL;
    int *seen = r->seen = gr_calloc(g, (size_t)n, sizeof(int));
    for (int k = 0; k < n; k++) {
        char *s;
        do
            s = next_line(g, r);
        while (s && !*s);
        if (!s)
            gr_error(g, "molecule file '%s': %s section ends after %d of %d %ss", r->path,
                     name, k, n, noun);
        char *w[8];
        int nw = split(s, w, 8);
        if (nw != nval + 1)
            gr_error(g, "molecule file '%s' line %d: %s needs an %s index and %d value%s",
                     r->path, r->line, name, noun, nval, nval > 1 ? "s" : "");
        int i = inum(g, r, w[0]) - 1;
        if (i < 0 || i >= n)
            gr_error(g, "molecule file '%s' line %d: invalid %s index %s in %s", r->path,
                     r->line, noun, w[0], name);
        seen[i]++;
        for (int q = 0; q < nval; q++)
            out[(size_t)nval * i + q] = num(g, r, w[1 + q]);
    }
    for (int i = 0; i < n; i++)
        if (seen[i] != 1)
            gr_error(g, "molecule file '%s': %s %d appears %d times in %s", r->path, noun, i + 1,
                     seen[i], name);
    free(r->seen);
    r->seen = NULL;
}

/* The Triangles section read as numbers (tri: 5 per triangle, mol type p1 p2
 * p3) into m's triangle arrays, checked: whole IDs and types >= 1, corner
 * indices 1..npoints. */
static void triangles(struct gravel *g, struct reader *r, struct molecule *m, const double *tri)
{
    m->tri = gr_calloc(g, 3 * (size_t)m->ntris, sizeof(int));
    m->tri_mol = gr_calloc(g, (size_t)m->ntris, sizeof(int));
    m->tri_type = gr_calloc(g, (size_t)m->ntris, sizeof(int));
    for (int t = 0; t < m->ntris; t++) {
        const double *v = tri + 5 * (size_t)t;
        if (!whole_in(v[0], 2147483647.0) || !whole_in(v[1], 2147483647.0))
            gr_error(g, "molecule file '%s': triangle %d has molecule ID %g and type %g "
                        "(whole numbers >= 1)", r->path, t + 1, v[0], v[1]);
        m->tri_mol[t] = (int)v[0];
        m->tri_type[t] = (int)v[1];
        for (int k = 0; k < 3; k++) {
            if (!whole_in(v[2 + k], m->npoints))
                gr_error(g, "molecule file '%s': triangle %d corner %d is point %g (1..%d)",
                         r->path, t + 1, k + 1, v[2 + k], m->npoints);
            m->tri[3 * t + k] = (int)v[2 + k] - 1;
        }
    }
}

/* The file's contents after the open (read_file); every error unwinds
 * through read_guarded, which closes the reader. */
static void read_body(struct gravel *g, struct molecule *m, struct reader *r, double scale,
                      int toff)
{
    const char *path = r->path;
    if (!next_line(g, r)) /* the title line */
        gr_error(g, "molecule file '%s' is empty", path);
    char *s, *w[8];
    /* header: "N atoms", "M mass", "x y z com", "6 values inertia" */
    for (;;) {
        s = next_line(g, r);
        if (!s)
            gr_error(g, "molecule file '%s' has no sections", path);
        if (!*s)
            continue;
        char copy[256];
        snprintf(copy, sizeof copy, "%s", s);
        int n = split(copy, w, 8);
        const char *kw = w[n - 1];
        if (!isdigit((unsigned char)s[0]) && s[0] != '-' && s[0] != '+' && s[0] != '.')
            break; /* a section name */
        if (!strcmp(kw, "atoms") && n == 2) {
            m->natoms = inum(g, r, w[0]);
        } else if (!strcmp(kw, "points") && n == 2) {
            m->npoints = inum(g, r, w[0]);
        } else if (!strcmp(kw, "triangles") && n == 2) {
            m->ntris = inum(g, r, w[0]);
        } else if (!strcmp(kw, "lines") && n == 2) {
            if (inum(g, r, w[0]) != 0)
                gr_error(g, "molecule file '%s' line %d: line segments (2d granular surfaces) "
                            "are not supported (3d triangles are)", path, r->line);
        } else if (!strcmp(kw, "mass") && n == 2) {
            m->massflag = 1;
            m->masstotal = scaled(g, path, num(g, r, w[0]), scale * scale * scale, "mass");
            if (!(m->masstotal > 0))
                gr_error(g, "molecule file '%s' line %d: the mass must be positive, got %g",
                         path, r->line, m->masstotal);
        } else if (!strcmp(kw, "com") && n == 4) {
            m->comflag = 1;
            for (int q = 0; q < 3; q++)
                m->com[q] = scaled(g, path, num(g, r, w[q]), scale, "com");
            if (g->dom.dimension == 2 && m->com[2] != 0.0)
                gr_error(g, "molecule file '%s': z center-of-mass must be 0.0 for 2d", path);
        } else if (!strcmp(kw, "inertia") && n == 7) {
            m->inertiaflag = 1;
            double s5 = scale * scale * scale * scale * scale;
            for (int q = 0; q < 6; q++)
                m->itensor[q] = scaled(g, path, num(g, r, w[q]), s5, "inertia");
        } else if ((!strcmp(kw, "bonds") || !strcmp(kw, "angles") || !strcmp(kw, "dihedrals") ||
                    !strcmp(kw, "impropers") || !strcmp(kw, "fragments")) && n == 2) {
            if (inum(g, r, w[0]) != 0)
                gr_error(g, "molecule file '%s' line %d: %s are not supported (granular "
                            "templates have atoms only)", path, r->line, kw);
        } else {
            gr_error(g, "molecule file '%s' line %d: invalid header line '%.60s'", path, r->line,
                     s);
        }
    }
    if (m->natoms < 0 || m->npoints < 0 || m->ntris < 0 || (m->ntris > 0) != (m->npoints > 0))
        gr_error(g, "molecule file '%s': invalid atom, point or triangle count (triangles "
                    "need points)", path);
    if (m->natoms < 1 && m->ntris < 1)
        gr_error(g, "molecule file '%s': no atoms or invalid atom count", path);
    int nat = m->natoms;
    m->x = gr_calloc(g, 3 * (size_t)(nat ? nat : 1), sizeof(double));
    m->type = gr_calloc(g, (size_t)(nat ? nat : 1), sizeof(int));
    int have_x = 0, have_type = 0, have_tri = 0;
    size_t ntmp = (size_t)nat > 5 * (size_t)m->ntris ? (size_t)nat : 5 * (size_t)m->ntris;
    double *tmp = r->tmp = gr_calloc(g, ntmp ? ntmp : 1, sizeof(double));
    while (s) {
        if (!*s) {
            s = next_line(g, r);
            continue;
        }
        char name[64];
        snprintf(name, sizeof name, "%s", s);
        /* each section once (a second Diameters section leaked the first) */
        if ((!strcmp(name, "Coords") && have_x) || (!strcmp(name, "Types") && have_type) ||
            (!strcmp(name, "Diameters") && m->radius) || (!strcmp(name, "Masses") && m->rmass) ||
            (!strcmp(name, "Molecules") && m->molecule) || (!strcmp(name, "Points") && m->points) ||
            (!strcmp(name, "Triangles") && have_tri))
            gr_error(g, "molecule file '%s' line %d: a second %s section", path, r->line, name);
        if (!strcmp(name, "Coords")) {
            section(g, r, nat, "atom", name, 3, m->x);
            for (int i = 0; i < 3 * nat; i++)
                m->x[i] = scaled(g, path, m->x[i], scale, "coordinate");
            have_x = 1;
        } else if (!strcmp(name, "Types")) {
            section(g, r, nat, "atom", name, 1, tmp);
            for (int i = 0; i < nat; i++) {
                /* in double: a type plus an offset near INT_MAX must not overflow */
                double t = tmp[i] + toff;
                if (tmp[i] != floor(tmp[i]) || !whole_in(t, g->atoms.ntypes))
                    gr_error(g, "molecule file '%s': invalid atom type %g for atom %d "
                                "(1..%d with offset %d)", path, tmp[i], i + 1,
                             g->atoms.ntypes, toff);
                m->type[i] = (int)t;
                if (m->type[i] > m->ntypes)
                    m->ntypes = m->type[i];
            }
            have_type = 1;
        } else if (!strcmp(name, "Diameters")) {
            free(m->radius);
            m->radius = NULL;
            m->radius = gr_calloc(g, (size_t)nat, sizeof(double));
            section(g, r, nat, "atom", name, 1, m->radius);
            for (int i = 0; i < nat; i++) {
                if (m->radius[i] < 0)
                    gr_error(g, "molecule file '%s': invalid diameter %g", path,
                             m->radius[i]);
                m->radius[i] = scaled(g, path, m->radius[i], 0.5 * scale, "diameter");
            }
        } else if (!strcmp(name, "Masses")) {
            free(m->rmass);
            m->rmass = NULL;
            m->rmass = gr_calloc(g, (size_t)nat, sizeof(double));
            section(g, r, nat, "atom", name, 1, m->rmass);
            for (int i = 0; i < nat; i++) {
                if (m->rmass[i] <= 0)
                    gr_error(g, "molecule file '%s': invalid mass %g", path, m->rmass[i]);
                m->rmass[i] = scaled(g, path, m->rmass[i], scale * scale * scale, "mass");
                if (!(m->rmass[i] > 0))
                    gr_error(g, "molecule file '%s': mass %g of atom %d underflows to 0 at "
                                "this scale", path, m->rmass[i], i + 1);
            }
        } else if (!strcmp(name, "Molecules")) {
            free(m->molecule);
            m->molecule = NULL;
            m->molecule = gr_calloc(g, (size_t)nat, sizeof(int64_t));
            section(g, r, nat, "atom", name, 1, tmp);
            int64_t mx = 0;
            for (int i = 0; i < nat; i++) {
                if (!whole_in(tmp[i], 2147483647.0))
                    gr_error(g, "molecule file '%s': invalid molecule ID %g for atom %d "
                                "(an integer 1..2147483647)", path, tmp[i], i + 1);
                m->molecule[i] = (int64_t)tmp[i];
                mx = m->molecule[i] > mx ? m->molecule[i] : mx;
            }
            m->nmolecules = (int)mx;
        } else if (!strcmp(name, "Points") && m->npoints > 0) {
            m->points = gr_calloc(g, 3 * (size_t)m->npoints, sizeof(double));
            section(g, r, m->npoints, "point", name, 3, m->points);
            for (int i = 0; i < 3 * m->npoints; i++)
                m->points[i] = scaled(g, path, m->points[i], scale, "point coordinate");
        } else if (!strcmp(name, "Triangles") && m->ntris > 0) {
            section(g, r, m->ntris, "triangle", name, 5, tmp);
            have_tri = 1;
        } else {
            gr_error(g, "molecule file '%s' line %d: unsupported section '%.40s' (gravel reads "
                        "Coords, Types, Molecules, Diameters, Masses, Points, Triangles)", path,
                     r->line, name);
        }
        s = next_line(g, r);
    }
    if (nat > 0 && (!have_x || !have_type))
        gr_error(g, "molecule file '%s' needs Coords and Types sections", path);
    if (m->ntris > 0) {
        if (!m->points || !have_tri)
            gr_error(g, "molecule file '%s' needs Points and Triangles sections", path);
        triangles(g, r, m, tmp); /* after Points: the corner indices are checked */
    }
    if (!m->molecule)
        m->nmolecules = 1;
}

/* Read the file at path into m; the reader is closed on every path out. */
static void read_guarded(struct gravel *g, struct molecule *m, struct reader *r, double scale,
                         int toff)
{
    jmp_buf jb, *outer = g->err.jmp;
    g->err.jmp = &jb;
    if (setjmp(jb)) {
        g->err.jmp = outer;
        reader_close(r);
        if (outer)
            longjmp(*outer, 1);
        gr_report_error(g);
        exit(1);
    }
    read_body(g, m, r, scale, toff);
    g->err.jmp = outer;
    reader_close(r);
}

static void read_file(struct gravel *g, struct molecule *m, const char *path, double scale,
                      int toff)
{
    const char *why = NULL;
    struct reader r = {.path = path};
    r.fp = fio_open_read(path, 0, &why);
    if (!r.fp)
        gr_error(g, "cannot open molecule file '%s': %s", path, why ? why : "error");
    read_guarded(g, m, &r, scale, toff);
}

void cmd_molecule(struct gravel *g, int argc, char **argv)
{
    const char *id = argv[0];
    for (const char *c = id; *c; c++)
        if (!isalnum((unsigned char)*c) && *c != '_')
            gr_error(g, "molecule template ID '%.64s' must be alphanumeric or underscore "
                        "characters", id);
    if (strlen(id) >= GR_NAMELEN)
        gr_error(g, "molecule template ID '%.64s' is too long", id);
    if (molecule_find(g, id))
        gr_error(g, "reuse of molecule template ID '%s'", id);
    if (argc > 2) {
        /* keywords apply to the file before them; one file per template here */
        for (int i = 2; i < argc; i++)
            if (!strcmp(argv[i], "offset") || !strcmp(argv[i], "toff") ||
                !strcmp(argv[i], "scale") || !strcmp(argv[i], "boff") ||
                !strcmp(argv[i], "aoff") || !strcmp(argv[i], "doff") ||
                !strcmp(argv[i], "ioff"))
                continue;
            else if (!arg_is_number(argv[i]))
                gr_error(g, "molecule: one file per template is supported (got '%.64s')",
                         argv[i]);
    }
    int toff = 0;
    double scale = 1.0;
    for (int i = 2; i < argc;) {
        const char *k = argv[i];
        if (!strcmp(k, "offset")) {
            arg_need(g, argc, i, 5, k);
            toff = arg_int(g, argv[i + 1], "offset Toff");
            i += 6;
        } else if (!strcmp(k, "toff")) {
            arg_need(g, argc, i, 1, k);
            toff = arg_int(g, argv[i + 1], "toff");
            i += 2;
        } else if (!strcmp(k, "boff") || !strcmp(k, "aoff") || !strcmp(k, "doff") ||
                   !strcmp(k, "ioff")) {
            arg_need(g, argc, i, 1, k);
            (void)arg_int(g, argv[i + 1], k); /* no bonds: nothing to offset */
            i += 2;
        } else if (!strcmp(k, "scale")) {
            arg_need(g, argc, i, 1, k);
            scale = arg_positive(g, argv[i + 1], "scale");
            i += 2;
        } else {
            gr_error(g, "molecule: unknown keyword '%.64s' (offset, toff, boff, aoff, doff, "
                        "ioff, scale)", k);
        }
    }
    struct molecule *m = gr_calloc(g, 1, sizeof *m);
    snprintf(m->id, sizeof m->id, "%s", id);
    g->molecules = gr_realloc(g, g->molecules, (size_t)(g->nmolecule + 1) * sizeof *g->molecules);
    g->molecules[g->nmolecule++] = m; /* owned now: freed even if reading fails */
    read_file(g, m, argv[1], scale, toff);
    if (g->dom.dimension == 2)
        for (int i = 0; i < m->natoms; i++)
            if (m->x[3 * i + 2] != 0.0)
                gr_error(g, "molecule file '%s': z coord of atom %d must be 0.0 for 2d",
                         argv[1], i + 1);
    if (m->ntris) { /* LAMMPS counts the surface molecules */
        for (int t = 0; t < m->ntris; t++)
            m->nmolecules = m->tri_mol[t] > m->nmolecules ? m->tri_mol[t] : m->nmolecules;
    }
    gr_print(g, "Read molecule template %s:\n  %d molecules\n  %d atoms with max type %d\n",
             m->id, m->nmolecules, m->natoms, m->ntypes);
    if (m->ntris)
        gr_print(g, "  %d triangles\n", m->ntris);
}

/* ---- derived quantities (LAMMPS Molecule::compute_*) -------------------------- */

void mol_random_quat(int dim, double (*uniform)(void *rng), void *rng, double quat[4])
{
    double r[3] = {0.0, 0.0, 1.0};
    if (dim == 3)
        for (int k = 0; k < 3; k++)
            r[k] = uniform(rng) - 0.5;
    double theta = uniform(rng) * 2.0 * M_PI;
    double scale = 1.0 / sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    for (int k = 0; k < 3; k++)
        r[k] *= scale;
    rm_axisangle_to_quat(r, theta, quat);
}

void mol_place_atom(const struct molecule *m, const double rot[3][3], const double center[3],
                    int k, double out[3])
{
    const double *dx = m->dx + 3 * k;
    for (int q = 0; q < 3; q++)
        out[q] = rot[q][0] * dx[0] + rot[q][1] * dx[1] + rot[q][2] * dx[2] + center[q];
}

void mol_compute_center(struct molecule *m)
{
    if (m->centerflag)
        return;
    m->centerflag = 1;
    int n = m->natoms;
    m->center[0] = m->center[1] = m->center[2] = 0.0;
    for (int i = 0; i < n; i++)
        for (int q = 0; q < 3; q++)
            m->center[q] += m->x[3 * i + q];
    for (int q = 0; q < 3; q++)
        m->center[q] /= n;
    m->dx = realloc(m->dx, 3 * (size_t)n * sizeof(double));
    m->molradius = 0.0;
    for (int i = 0; i < n; i++) {
        double *d = m->dx + 3 * i;
        for (int q = 0; q < 3; q++)
            d[q] = m->x[3 * i + q] - m->center[q];
        double rad = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (m->radius)
            rad += m->radius[i];
        if (rad > m->molradius)
            m->molradius = rad;
    }
}

static double atom_mass(struct gravel *g, const struct molecule *m, int i)
{
    if (m->rmass)
        return m->rmass[i];
    double t = g->atoms.type_mass ? g->atoms.type_mass[m->type[i]] : 0.0;
    if (!(t > 0))
        gr_error(g, "molecule %s: atom %d has no mass (no Masses section and type %d has no "
                    "mass)", m->id, i + 1, m->type[i]);
    return t;
}

void mol_compute_mass(struct gravel *g, struct molecule *m)
{
    if (m->massdone)
        return;
    m->massdone = 1;
    if (m->massflag)
        return;
    m->massflag = 1;
    m->masstotal = 0.0;
    for (int i = 0; i < m->natoms; i++)
        m->masstotal += atom_mass(g, m, i);
}

void mol_compute_com(struct gravel *g, struct molecule *m)
{
    if (m->comdone)
        return;
    m->comdone = 1;
    int n = m->natoms;
    if (!m->comflag) {
        m->comflag = 1;
        m->com[0] = m->com[1] = m->com[2] = 0.0;
        for (int i = 0; i < n; i++) {
            double w = atom_mass(g, m, i);
            for (int q = 0; q < 3; q++)
                m->com[q] += m->x[3 * i + q] * w;
        }
        if (m->masstotal > 0.0)
            for (int q = 0; q < 3; q++)
                m->com[q] /= m->masstotal;
    }
    m->dxcom = realloc(m->dxcom, 3 * (size_t)n * sizeof(double));
    double rsqmin = 1.0e20;
    int ca = 0;
    for (int i = 0; i < n; i++) {
        double *d = m->dxcom + 3 * i;
        for (int q = 0; q < 3; q++)
            d[q] = m->x[3 * i + q] - m->com[q];
        double rsq = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        if (rsq < rsqmin) {
            ca = i;
            rsqmin = rsq;
        }
    }
    double rsqmax = 0.0;
    for (int i = 0; i < n; i++) {
        double dx = m->x[3 * ca] - m->x[3 * i], dy = m->x[3 * ca + 1] - m->x[3 * i + 1],
               dz = m->x[3 * ca + 2] - m->x[3 * i + 2];
        double rsq = dx * dx + dy * dy + dz * dz;
        if (rsq > rsqmax)
            rsqmax = rsq;
    }
    m->comatom = ca + 1;
    m->maxextent = sqrt(rsqmax);
}

void mol_compute_inertia(struct gravel *g, struct molecule *m)
{
    if (m->inertiadone)
        return;
    m->inertiadone = 1;
    int n = m->natoms;
    if (!m->inertiaflag) {
        m->inertiaflag = 1;
        for (int q = 0; q < 6; q++)
            m->itensor[q] = 0.0;
        for (int i = 0; i < n; i++) {
            double w = atom_mass(g, m, i);
            const double *d = m->dxcom + 3 * i;
            m->itensor[0] += w * (d[1] * d[1] + d[2] * d[2]);
            m->itensor[1] += w * (d[0] * d[0] + d[2] * d[2]);
            m->itensor[2] += w * (d[0] * d[0] + d[1] * d[1]);
            m->itensor[3] -= w * d[1] * d[2];
            m->itensor[4] -= w * d[0] * d[2];
            m->itensor[5] -= w * d[0] * d[1];
        }
        if (m->radius)
            for (int i = 0; i < n; i++) {
                double w = atom_mass(g, m, i);
                for (int q = 0; q < 3; q++)
                    m->itensor[q] += SINERTIA * w * m->radius[i] * m->radius[i];
            }
    }
    /* LAMMPS reads the header's "Ixx Iyy Izz Ixy Ixz Iyz inertia" into the
     * slots its tensor uses as xx yy zz yz xz xy: kept, so templates with
     * off-diagonal header values give LAMMPS's bodies */
    if (rm_principal(m->itensor, 0, m->inertia, m->ex, m->ey, m->ez, m->quat))
        gr_error(g, "insufficient Jacobi rotations for rigid molecule %s", m->id);
    m->dxbody = realloc(m->dxbody, 3 * (size_t)n * sizeof(double));
    for (int i = 0; i < n; i++)
        rm_transpose_matvec(m->ex, m->ey, m->ez, m->dxcom + 3 * i, m->dxbody + 3 * i);
}
