/* read_data.c - `read_data file [shift dx dy dz] [nocoeff] [extra/atom/types N]
 * [group ID]`: LAMMPS data files
 * for atom_style sphere, as LAMMPS writes them.
 *
 * Layout: a first (comment) line; header lines "N atoms", "N atom types",
 * "lo hi xlo xhi" (and y, z; default -0.5 0.5); zero counts of bonds, angles
 * ... are accepted, non-zero ones are errors; an "xy xz yz" line makes the
 * box triclinic (as LAMMPS, even with zero tilts). Then
 * sections, each a keyword line, blank lines, and exactly the expected number
 * of lines: "Atoms" (optionally "Atoms # sphere", or "# granular" as
 * LIGGGHTS writes): id type diameter density x y z [ix iy iz], N atoms lines; "Velocities": id vx vy vz wx wy wz, N
 * lines; "Masses": type mass, one per type; with `nocoeff`, "Pair Coeffs" and
 * "PairIJ Coeffs" sections are skipped (an error otherwise). `#` starts a
 * comment.
 * As LAMMPS: radius = diameter / 2; mass = 4/3 pi r^3 density, or mass =
 * density for a point particle (diameter 0). Atoms are wrapped into the box in
 * periodic dimensions (image flags updated); non-zero image flags in
 * non-periodic dimensions are reset to 0 with a warning. Errors name the data
 * file and its line. The box and atoms appear only if the whole file reads.
 * Only a regular file is read (a directory, FIFO or device is an error before
 * any byte is read); lines may end in LF, CR LF or a lone CR; a read error is
 * an error, never an early end of the file. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atom_custom.h"
#include "atoms.h"
#include "fix.h"
#include "fix_property_atom.h"
#include "domain.h"
#include "error.h"
#include "fileio.h"
#include "group.h"
#include "log.h"

#define MAXWORDS 256      /* a fix section's lines (an array's columns) */
#define LINEWORDS 16      /* every other line */
#define MAXFIXSECT 8

struct rd {
    struct gravel *g;
    const char *path;
    FILE *fp;
    char *line;
    size_t cap;
    long lineno;
    int nw, maxw;           /* words of the line; the most a line may have */
    char *w[MAXWORDS];
    int nocoeff;            /* skip Pair Coeffs / PairIJ Coeffs sections */
    int extra_types;        /* extra/atom/types: types beyond the file's */
    int nfix;               /* fix ID header section: sections a fix property/atom reads */
    const char *fix_id[MAXFIXSECT], *fix_sect[MAXFIXSECT];
    /* tag -> index lookup, built after Atoms */
    int64_t *stag;
    int *sidx;
};

/* Read the next line, strip the comment, split it into words. Returns 0 at
 * end of file. `keep_comment` keeps the text after '#' in *comment. */
static int rd_next(struct rd *r, char **comment)
{
    ssize_t n = fio_getline(r->fp, &r->line, &r->cap, 0);
    if (n == FIO_ERR)
        gr_error(r->g, "%s:%ld: read error: %s", r->path, r->lineno + 1,
                 strerror(errno ? errno : EIO));
    if (n == FIO_EOF)
        return 0;
    if (r->lineno == 0) {
        size_t bom = fio_bom(r->line, (size_t)n);
        memmove(r->line, r->line + bom, (size_t)n - bom + 1);
        n -= (ssize_t)bom;
    }
    r->lineno++;
    if (memchr(r->line, '\0', (size_t)n))
        gr_error(r->g, "%s:%ld: binary data (a NUL byte) in the data file", r->path, r->lineno);
    char *hash = strchr(r->line, '#');
    if (comment)
        *comment = hash ? hash + 1 : NULL;
    if (hash)
        *hash = '\0';
    r->nw = 0;
    char *save = NULL;
    for (char *t = strtok_r(r->line, " \t\r\n\v\f", &save); t;
         t = strtok_r(NULL, " \t\r\n\v\f", &save)) {
        if (r->nw == (r->maxw ? r->maxw : LINEWORDS))
            gr_error(r->g, "%s:%ld: too many values on one line", r->path, r->lineno);
        r->w[r->nw++] = t;
    }
    return 1;
}

static double rd_num(struct rd *r, const char *s, const char *what)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (*end || end == s || !isfinite(v)) /* ERANGE with a finite v: a denormal, accepted */
        gr_error(r->g, "%s:%ld: expected a number for %s, got '%.64s'", r->path, r->lineno,
                 what, s);
    return v;
}

static int64_t rd_int(struct rd *r, const char *s, const char *what)
{
    char *end;
    errno = 0;
    long long v = strtoll(s, &end, 10);
    if (*end || end == s || errno == ERANGE)
        gr_error(r->g, "%s:%ld: expected an integer for %s, got '%.64s'", r->path, r->lineno,
                 what, s);
    return v;
}

static int words_are(const struct rd *r, int from, const char *a, const char *b, const char *c)
{
    const char *k[3] = {a, b, c};
    int nk = c ? 3 : b ? 2 : 1;
    if (r->nw != from + nk)
        return 0;
    for (int i = 0; i < nk; i++)
        if (strcmp(r->w[from + i], k[i]) != 0)
            return 0;
    return 1;
}

/* Header counts that must be zero for atom_style sphere. */
static int zero_count_keyword(const struct rd *r)
{
    static const char *one[] = {"bonds", "angles", "dihedrals", "impropers", "ellipsoids",
                                "lines", "triangles", "bodies", NULL};
    static const char *types[] = {"bond", "angle", "dihedral", "improper", NULL};
    for (int i = 0; one[i]; i++)
        if (words_are(r, 1, one[i], NULL, NULL))
            return 1;
    for (int i = 0; types[i]; i++)
        if (words_are(r, 1, types[i], "types", NULL))
            return 1;
    if (r->nw == 5 && !strcmp(r->w[1], "extra") && !strcmp(r->w[3], "per") &&
        !strcmp(r->w[4], "atom"))
        return 1;
    if (r->nw == 4 && !strcmp(r->w[1], "extra") && !strcmp(r->w[2], "special") &&
        !strcmp(r->w[3], "per"))
        return 1;
    return 0;
}

static int find_tag(const struct rd *r, int n, int64_t tag)
{
    int lo = 0, hi = n - 1;
    while (lo <= hi) {
        int mid = lo + (hi - lo) / 2;
        if (r->stag[mid] == tag)
            return r->sidx[mid];
        if (r->stag[mid] < tag)
            lo = mid + 1;
        else
            hi = mid - 1;
    }
    return -1;
}

static int cmp_pair(const void *p, const void *q)
{
    const int64_t *a = p, *b = q;
    return (a[0] > b[0]) - (a[0] < b[0]);
}

/* Build the sorted tag lookup and reject duplicate IDs. */
static void build_lookup(struct rd *r)
{
    struct gravel *g = r->g;
    int n = g->atoms.n;
    int64_t *pairs = gr_malloc(g, (size_t)(n ? n : 1) * 2 * sizeof(int64_t));
    r->stag = pairs; /* freed by cleanup even if an error follows */
    for (int i = 0; i < n; i++) {
        pairs[2 * i] = g->atoms.tag[i];
        pairs[2 * i + 1] = i;
    }
    qsort(pairs, (size_t)n, 2 * sizeof(int64_t), cmp_pair);
    r->sidx = gr_malloc(g, (size_t)(n ? n : 1) * sizeof(int));
    for (int i = 0; i < n; i++) {
        if (i > 0 && pairs[2 * i] == pairs[2 * (i - 1)])
            gr_error(g, "%s: duplicate atom ID %lld in Atoms", r->path, (long long)pairs[2 * i]);
        r->sidx[i] = (int)pairs[2 * i + 1];
    }
    for (int i = 0; i < n; i++)
        pairs[i] = pairs[2 * i]; /* compact the tags to the front */
}

/* Skip blank lines after a section keyword; leaves the first data line in r. */
static void first_data_line(struct rd *r, const char *section)
{
    do {
        if (!rd_next(r, NULL))
            gr_error(r->g, "%s:%ld: unexpected end of file in the %s section", r->path,
                     r->lineno, section);
    } while (r->nw == 0);
}

static void next_data_line(struct rd *r, const char *section, bigint k, bigint n)
{
    if (!rd_next(r, NULL))
        gr_error(r->g, "%s:%ld: unexpected end of file in the %s section (read %lld of %lld "
                       "lines)",
                 r->path, r->lineno, section, (long long)k, (long long)n);
    if (r->nw == 0)
        gr_error(r->g, "%s:%ld: blank line inside the %s section (read %lld of %lld lines)",
                 r->path, r->lineno, section, (long long)k, (long long)n);
}

static void read_atoms(struct rd *r, bigint natoms, const double shift[3], int *warned)
{
    struct gravel *g = r->g;
    struct atoms *a = &g->atoms;
    /* reserve at most 1M up front: a header may claim more atoms than the
     * file holds; beyond that the arrays grow as lines are read */
    atoms_reserve(g, (int)(natoms < (1 << 20) ? natoms : (1 << 20)));
    /* columns: sphere "id type diameter density x y z", hybrid sphere
     * molecular "id type x y z diameter density mol" (LAMMPS's sub-style order);
     * image flags follow either */
    int hyb = a->style_molecular;
    int c_diam = hyb ? 5 : 2, c_dens = hyb ? 6 : 3, c_x = hyb ? 2 : 4, c_img = hyb ? 8 : 7;
    int nwords = 0;
    for (bigint k = 0; k < natoms; k++) {
        if (k == 0)
            first_data_line(r, "Atoms");
        else
            next_data_line(r, "Atoms", k, natoms);
        if (k == 0) {
            nwords = r->nw;
            if (nwords != c_img && nwords != c_img + 3)
                gr_error(g, "%s:%ld: Atoms lines for atom_style %s need %d or %d values (%s "
                            "[ix iy iz]), got %d",
                         r->path, r->lineno, hyb ? "hybrid sphere molecular" : "sphere", c_img,
                         c_img + 3,
                         hyb ? "id type x y z diameter density mol" : "id type diameter density x y z",
                         nwords);
        } else if (r->nw != nwords) {
            gr_error(g, "%s:%ld: expected %d values on this Atoms line like the first, got %d",
                     r->path, r->lineno, nwords, r->nw);
        }
        int64_t tag = rd_int(r, r->w[0], "atom ID");
        if (tag <= 0)
            gr_error(g, "%s:%ld: atom ID must be positive, got %s", r->path, r->lineno,
                     r->w[0]);
        int64_t type = rd_int(r, r->w[1], "atom type");
        if (type < 1 || type > a->ntypes - r->extra_types)
            gr_error(g, "%s:%ld: atom type %s is outside 1..%d", r->path, r->lineno, r->w[1],
                     a->ntypes - r->extra_types);
        double diam = rd_num(r, r->w[c_diam], "diameter");
        double dens = rd_num(r, r->w[c_dens], "density");
        if (diam < 0)
            gr_error(g, "%s:%ld: diameter must not be negative, got %s", r->path, r->lineno,
                     r->w[c_diam]);
        if (!(dens > 0))
            gr_error(g, "%s:%ld: density must be positive, got %s", r->path, r->lineno,
                     r->w[c_dens]);
        int64_t molid = 0;
        if (hyb) {
            molid = rd_int(r, r->w[7], "molecule ID");
            if (molid < 0)
                gr_error(g, "%s:%ld: molecule ID must not be negative, got %s", r->path,
                         r->lineno, r->w[7]);
        }
        double x[3];
        int img[3] = {0, 0, 0};
        for (int d = 0; d < 3; d++)
            x[d] = rd_num(r, r->w[c_x + d], "coordinate") + shift[d];
        if (nwords == c_img + 3)
            for (int d = 0; d < 3; d++) {
                int64_t v = rd_int(r, r->w[c_img + d], "image flag");
                if (v < -(1 << 20) || v > (1 << 20))
                    gr_error(g, "%s:%ld: image flag %s is out of range", r->path, r->lineno,
                             r->w[c_img + d]);
                img[d] = (int)v;
                if (img[d] && !g->dom.periodic[d]) {
                    img[d] = 0;
                    if (!warned[d]) {
                        warned[d] = 1;
                        gr_warn(g, "non-zero image flags in non-periodic %c reset to zero",
                                "xyz"[d]);
                    }
                }
            }
        domain_remap(g, x, img);
        for (int d = 0; d < 3; d++)
            if (g->dom.triclinic ? !domain_inside(g, x)
                                 : !(x[d] >= g->dom.lo[d] && x[d] < g->dom.hi[d]))
                gr_error(g, "%s:%ld: atom %lld is outside the box in %c (%g not in [%g, %g))",
                         r->path, r->lineno, (long long)tag, "xyz"[d], x[d], g->dom.lo[d],
                         g->dom.hi[d]);
        double rad = 0.5 * diam;
        double mass = rad > 0 ? 4.0 * M_PI / 3.0 * rad * rad * rad * dens : dens;
        int i = atoms_add(g, tag, (int)type, x, rad, mass);
        for (int d = 0; d < 3; d++)
            a->image[3 * i + d] = img[d];
        if (a->molecule_flag)
            a->mol[i] = molid;
    }
    build_lookup(r);
}

static void read_velocities(struct rd *r, bigint natoms)
{
    struct gravel *g = r->g;
    struct atoms *a = &g->atoms;
    for (bigint k = 0; k < natoms; k++) {
        if (k == 0)
            first_data_line(r, "Velocities");
        else
            next_data_line(r, "Velocities", k, natoms);
        if (r->nw != 7)
            gr_error(g, "%s:%ld: Velocities lines for atom_style sphere need 7 values "
                        "(id vx vy vz wx wy wz), got %d",
                     r->path, r->lineno, r->nw);
        int64_t tag = rd_int(r, r->w[0], "atom ID");
        int i = find_tag(r, a->n, tag);
        if (i < 0)
            gr_error(g, "%s:%ld: Velocities for unknown atom ID %s", r->path, r->lineno,
                     r->w[0]);
        for (int d = 0; d < 3; d++) {
            a->v[3 * i + d] = rd_num(r, r->w[1 + d], "velocity");
            a->omega[3 * i + d] = rd_num(r, r->w[4 + d], "angular velocity");
        }
    }
}

/* A fix property/atom's section (read_data ... fix ID NULL Section): lines
 * "atom-ID value ...", the fix's properties in command order (an array's N
 * columns in turn), one line per atom of the file, as LAMMPS's
 * FixPropertyAtom::read_data_section. */
static void read_fix_section(struct rd *r, const char *fix_id, const char *sec, bigint natoms)
{
    struct gravel *g = r->g;
    struct atoms *a = &g->atoms;
    const struct fix *f = NULL;
    for (int i = 0; i < g->styles.nfix; i++)
        if (!strcmp(g->styles.fix[i]->id, fix_id))
            f = g->styles.fix[i];
    struct prop_column col[MAXWORDS];
    int nc = property_atom_columns(g, f, col, MAXWORDS - 1);
    if (nc < 0)
        gr_error(g, "%s:%ld: fix %s has more than %d values per atom for its %s section",
                 r->path, r->lineno, fix_id, MAXWORDS - 1, sec);
    r->maxw = natoms > 0 ? MAXWORDS : 0;
    for (bigint k = 0; k < natoms; k++) {
        if (k == 0)
            first_data_line(r, sec);
        else
            next_data_line(r, sec, k, natoms);
        if (k == natoms - 1)
            r->maxw = 0; /* the next section's keyword: the usual limit */
        if (r->nw != nc + 1)
            gr_error(g, "%s:%ld: %s lines of fix %s need %d values (atom-ID and %d of the "
                        "fix's properties), got %d",
                     r->path, r->lineno, sec, fix_id, nc + 1, nc, r->nw);
        int64_t tag = rd_int(r, r->w[0], "atom ID");
        int i = find_tag(r, a->n, tag);
        if (i < 0)
            gr_error(g, "%s:%ld: %s for unknown atom ID %s", r->path, r->lineno, sec, r->w[0]);
        for (int c = 0; c < nc; c++) {
            const char *w = r->w[1 + c];
            switch (col[c].kind) {
            case PC_MOL: {
                int64_t m = rd_int(r, w, "molecule ID");
                if (m < 0)
                    gr_error(g, "%s:%ld: invalid molecule ID %s", r->path, r->lineno, w);
                a->mol[i] = m;
                break;
            }
            case PC_TEMPERATURE: a->temperature[i] = rd_num(r, w, "temperature"); break;
            case PC_HEATFLOW: a->heatflow[i] = rd_num(r, w, "heat flow"); break;
            case PC_CUSTOM: {
                const struct custom_prop *p = &a->cus.p[col[c].ref.idx];
                double v = p->isint ? (double)rd_int(r, w, p->name) : rd_num(r, w, p->name);
                if (p->isint && (v < -2147483648.0 || v > 2147483647.0))
                    gr_error(g, "%s:%ld: value %s of integer property %s does not fit an int",
                             r->path, r->lineno, w, p->name);
                struct custom_ref ref = {col[c].ref.idx, col[c].ref.col};
                *custom_at(a, ref, i) = v;
                break;
            }
            }
        }
    }
}

/* The fix keyword naming this section (a one- or two-word keyword), or -1. */
static int fix_section(const struct rd *r, const char *sec)
{
    for (int k = 0; k < r->nfix; k++)
        if (!strcmp(r->fix_sect[k], sec) || !strcmp(r->fix_sect[k], r->w[0]))
            return k;
    return -1;
}

static void read_masses(struct rd *r)
{
    struct gravel *g = r->g;
    int nt = g->atoms.ntypes;
    for (int k = 0; k < nt; k++) {
        if (k == 0)
            first_data_line(r, "Masses");
        else
            next_data_line(r, "Masses", k, nt);
        if (r->nw != 2)
            gr_error(g, "%s:%ld: Masses lines need 2 values (type mass), got %d", r->path,
                     r->lineno, r->nw);
        int64_t t = rd_int(r, r->w[0], "atom type");
        if (t < 1 || t > nt)
            gr_error(g, "%s:%ld: atom type %s is outside 1..%d", r->path, r->lineno, r->w[0],
                     nt);
        double m = rd_num(r, r->w[1], "mass");
        if (!(m > 0))
            gr_error(g, "%s:%ld: mass must be positive, got %s", r->path, r->lineno, r->w[1]);
        g->atoms.type_mass[t] = m;
    }
}

/* Skip the n lines of a section (nocoeff). */
static void skip_section(struct rd *r, const char *section, bigint n)
{
    for (bigint k = 0; k < n; k++) {
        if (k == 0)
            first_data_line(r, section);
        else
            next_data_line(r, section, k, n);
    }
}

static void read_file(struct rd *r, const double shift[3])
{
    struct gravel *g = r->g;
    bigint natoms = -1;
    int64_t ntypes = -1;
    double lo[3] = {-0.5, -0.5, -0.5}, hi[3] = {0.5, 0.5, 0.5}, tilt[3] = {0, 0, 0};
    int triclinic = 0;
    if (!rd_next(r, NULL))
        gr_error(g, "%s: the data file is empty", r->path);
    /* header */
    int have_section = 0;
    char *comment = NULL;
    while (rd_next(r, &comment)) {
        if (r->nw == 0)
            continue;
        if (words_are(r, 1, "atoms", NULL, NULL)) {
            natoms = rd_int(r, r->w[0], "number of atoms");
            if (natoms < 0 || natoms > 200000000)
                gr_error(g, "%s:%ld: number of atoms must be between 0 and 2e8, got %s",
                         r->path, r->lineno, r->w[0]);
        } else if (words_are(r, 1, "atom", "types", NULL)) {
            ntypes = rd_int(r, r->w[0], "number of atom types");
            if (ntypes < 1 || ntypes > 1000000)
                gr_error(g, "%s:%ld: number of atom types must be between 1 and 1000000, "
                            "got %s",
                         r->path, r->lineno, r->w[0]);
        } else if (r->nw == 4 && r->w[2][0] == r->w[3][0] && r->w[2][0] >= 'x' &&
                   r->w[2][0] <= 'z' && !strcmp(r->w[2] + 1, "lo") &&
                   !strcmp(r->w[3] + 1, "hi")) {
            int d = r->w[2][0] - 'x';
            lo[d] = rd_num(r, r->w[0], "box bound");
            hi[d] = rd_num(r, r->w[1], "box bound");
            if (!(lo[d] < hi[d]))
                gr_error(g, "%s:%ld: box bounds must satisfy %s < %s, got %s %s", r->path,
                         r->lineno, r->w[2], r->w[3], r->w[0], r->w[1]);
        } else if (words_are(r, 3, "xy", "xz", "yz")) {
            for (int q = 0; q < 3; q++)
                tilt[q] = rd_num(r, r->w[q], "tilt factor");
            triclinic = 1;
        } else if (r->nw >= 2 && zero_count_keyword(r)) {
            if (rd_int(r, r->w[0], r->w[1]) != 0)
                gr_error(g, "%s:%ld: atom_style sphere has no %s; the count must be 0", r->path,
                         r->lineno, r->w[1]);
        } else if (isalpha((unsigned char)r->w[0][0])) {
            have_section = 1;
            break;
        } else {
            gr_error(g, "%s:%ld: unknown header line", r->path, r->lineno);
        }
    }
    if (natoms < 0)
        gr_error(g, "%s: the header has no 'N atoms' line", r->path);
    if (ntypes < 0)
        gr_error(g, "%s: the header has no 'N atom types' line", r->path);
    /* the box, as create_box would make it */
    for (int d = 0; d < 3; d++) {
        g->dom.lo[d] = lo[d];
        g->dom.hi[d] = hi[d];
    }
    g->dom.triclinic = triclinic;
    g->dom.xy = tilt[0];
    g->dom.xz = tilt[1];
    g->dom.yz = tilt[2];
    domain_check_tilt(g);
    domain_check_skew(g);
    domain_set_initial_box(g);
    if (ntypes + r->extra_types > 1000000)
        gr_error(g, "%s: atom types plus extra/atom/types exceed 1000000", r->path);
    atoms_set_ntypes(g, (int)ntypes + r->extra_types);
    int atoms_read = 0, vel_read = 0, masses_read = 0, warned[3] = {0, 0, 0};
    while (have_section) {
        char sec[64];
        snprintf(sec, sizeof sec, "%s%s%s", r->w[0], r->nw > 1 ? " " : "",
                 r->nw > 1 ? r->w[1] : "");
        if (!strcmp(sec, "Atoms")) {
            if (atoms_read)
                gr_error(g, "%s:%ld: a second Atoms section", r->path, r->lineno);
            if (comment) {
                char style[32] = "";
                /* LIGGGHTS' atom_style granular has the same columns as sphere */
                int hyb = g->atoms.style_molecular;
                if (sscanf(comment, " %31s", style) == 1 &&
                    (hyb ? strcmp(style, "hybrid") != 0
                         : strcmp(style, "sphere") != 0 && strcmp(style, "granular") != 0))
                    gr_error(g, "%s:%ld: Atoms are for atom_style %s; the script's atom style "
                                "is %s",
                             r->path, r->lineno, style, hyb ? "hybrid sphere molecular" : "sphere");
            }
            read_atoms(r, natoms, shift, warned);
            atoms_read = 1;
        } else if (!strcmp(sec, "Velocities")) {
            if (!atoms_read)
                gr_error(g, "%s:%ld: Velocities must come after Atoms", r->path, r->lineno);
            if (vel_read)
                gr_error(g, "%s:%ld: a second Velocities section", r->path, r->lineno);
            read_velocities(r, natoms);
            vel_read = 1;
        } else if (!strcmp(sec, "Masses")) {
            if (masses_read)
                gr_error(g, "%s:%ld: a second Masses section", r->path, r->lineno);
            read_masses(r);
            masses_read = 1;
        } else if (fix_section(r, sec) >= 0) {
            if (!atoms_read)
                gr_error(g, "%s:%ld: the %s section of fix %s must come after Atoms", r->path,
                         r->lineno, sec, r->fix_id[fix_section(r, sec)]);
            read_fix_section(r, r->fix_id[fix_section(r, sec)], sec, natoms);
        } else if (r->nocoeff && (!strcmp(sec, "Pair Coeffs") || !strcmp(sec, "PairIJ Coeffs"))) {
            skip_section(r, sec, sec[4] == 'I' ? ntypes * (ntypes + 1) / 2 : ntypes);
        } else if (!strcmp(sec, "Bonds") || !strcmp(sec, "Angles") ||
                   !strcmp(sec, "Dihedrals") || !strcmp(sec, "Impropers") ||
                   strstr(sec, "Coeffs") || !strcmp(sec, "Ellipsoids")) {
            gr_error(g, "%s:%ld: section '%s' is not supported (atom_style sphere has no "
                        "bonds; skip coefficient sections with the nocoeff keyword and use "
                        "pair_coeff)",
                     r->path, r->lineno, sec);
        } else {
            gr_error(g, "%s:%ld: unknown section or header line '%.64s'", r->path, r->lineno,
                     sec);
        }
        /* next section keyword */
        have_section = 0;
        while (rd_next(r, &comment)) {
            if (r->nw == 0)
                continue;
            if (!isalpha((unsigned char)r->w[0][0]))
                gr_error(g, "%s:%ld: expected a section keyword, got '%.64s' (too many lines "
                            "in the previous section?)",
                         r->path, r->lineno, r->w[0]);
            have_section = 1;
            break;
        }
    }
    if (natoms > 0 && !atoms_read)
        gr_error(g, "%s: the file has no Atoms section for its %lld atoms", r->path,
                 (long long)natoms);
}

void cmd_read_data(struct gravel *g, int argc, char **argv)
{
    if (g->atoms.ellipsoid_flag)
        gr_error(g, "read_data with atom_style ellipsoid superellipsoid is not supported (its "
                    "Ellipsoids section is not read): create the atoms and use set shape, "
                    "set block, set quat");
    double shift[3] = {0, 0, 0};
    int nocoeff = 0, extra_types = 0;
    const char *volatile group = NULL; /* read again after the setjmp below */
    const char *fix_id[MAXFIXSECT], *fix_sect[MAXFIXSECT];
    int nfix = 0;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "shift")) {
            arg_need(g, argc, i, 3, "shift");
            for (int d = 0; d < 3; d++)
                shift[d] = arg_double(g, argv[i + 1 + d], "shift");
            i += 3;
        } else if (!strcmp(argv[i], "nocoeff")) {
            nocoeff = 1;
        } else if (!strcmp(argv[i], "extra/atom/types")) {
            arg_need(g, argc, i, 1, argv[i]);
            extra_types = arg_int_range(g, argv[++i], 0, 1000000, "extra/atom/types");
        } else if (!strcmp(argv[i], "group")) {
            arg_need(g, argc, i, 1, argv[i]);
            group = argv[++i];
            if (!strcmp(group, "all"))
                gr_error(g, "group 'all' always holds every atom");
        } else if (!strcmp(argv[i], "fix")) { /* fix ID header-string section-string */
            arg_need(g, argc, i, 3, "fix");
            const struct fix *f = NULL;
            for (int k = 0; k < g->styles.nfix; k++)
                if (!strcmp(g->styles.fix[k]->id, argv[i + 1]))
                    f = g->styles.fix[k];
            if (!f)
                gr_error(g, "fix ID %.64s for read_data does not exist", argv[i + 1]);
            if (!property_atom_is(f))
                gr_error(g, "fix %s (%s) reads no data file sections: only fix property/atom "
                            "does", f->id, f->style->name);
            if (strcmp(argv[i + 2], "NULL"))
                gr_error(g, "fix %s: header string '%.64s' must be NULL (fix property/atom "
                            "reads no header line)", f->id, argv[i + 2]);
            if (nfix == MAXFIXSECT)
                gr_error(g, "more than %d fix keywords", MAXFIXSECT);
            fix_id[nfix] = argv[i + 1];
            fix_sect[nfix++] = argv[i + 3];
            i += 3;
        } else if (!strcmp(argv[i], "add") || !strcmp(argv[i], "offset")) {
            gr_error(g, "keyword '%s' is not supported", argv[i]);
        } else {
            gr_error(g, "unknown keyword '%.32s'", argv[i]);
        }
    }
    struct rd r;
    memset(&r, 0, sizeof r);
    r.g = g;
    r.path = argv[0];
    r.nocoeff = nocoeff;
    r.extra_types = extra_types;
    r.nfix = nfix;
    memcpy(r.fix_id, fix_id, sizeof fix_id);
    memcpy(r.fix_sect, fix_sect, sizeof fix_sect);
    const char *why;
    r.fp = fio_open_read(argv[0], 0, &why);
    if (!r.fp)
        gr_error(g, "cannot open data file '%.200s': %s", argv[0], why);
    struct domain saved = g->dom;
    jmp_buf *outer = g->err.jmp, here;
    g->err.jmp = &here;
    if (setjmp(here)) {
        g->err.jmp = outer;
        fclose(r.fp);
        free(r.line);
        free(r.stag);
        free(r.sidx);
        g->dom = saved; /* no box, no atoms: nothing half-read survives */
        struct atom_custom cus = g->atoms.cus; /* the fixes' properties stay defined */
        atoms_free(&g->atoms);
        g->atoms.cus = cus;
        if (outer)
            longjmp(*outer, 1);
        gr_report_error(g);
        exit(1);
    }
    read_file(&r, shift);
    if (group) {
        unsigned bit = group_bit(group_create(g, group));
        for (int i = 0; i < g->atoms.n; i++)
            g->atoms.mask[i] |= bit;
    }
    g->err.jmp = outer;
    fclose(r.fp);
    free(r.line);
    free(r.stag);
    free(r.sidx);
    gr_print(g, "Reading data file ...\n");
    domain_print_box(g, "  ");
    gr_print(g, "  %d atoms\n", g->atoms.n);
}
