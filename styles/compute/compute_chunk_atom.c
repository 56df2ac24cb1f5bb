/* compute_chunk_atom.c - `compute ID group chunk/atom bin/1d|bin/2d|bin/3d
 * dim origin delta [dim origin delta ...] keyword value ...`, LAMMPS's
 * spatial-bin chunks (compute_chunk_atom.cpp), and its shells:
 * `bin/sphere xc yc zc rmin rmax nbin` and `bin/cylinder dim origin delta
 * c1 c2 rmin rmax nbin` (the axis binned as bin/1d, each plane's atoms in
 * nbin rings about (c1, c2)):
 *
 *   dim = x|y|z, origin = lower|center|upper|value, delta = bin width.
 *   keywords: units box|lattice|reduced (default lattice), bound dim lo hi
 *   (lo = lower|value, hi = upper|value), discard mixed|yes|no (default
 *   mixed; without bins yes|no, default yes: an ID outside 1..nchunk in no
 *   chunk or in the last), region ID, nchunk once|every (default every; once
 *   with units reduced or ids once), ids once|every (once: each atom's first
 *   chunk kept by tag), limit N max|exact (non-bin styles), pbc yes|no
 *   (shells only), compress (molecule and value styles: the IDs present
 *   numbered 1..N in ascending order, the original IDs kept for
 *   property/chunk).
 *
 * Bins: in each binned dimension the lattice of edges origin + k delta is
 * extended to cover [boxlo, boxhi] (or the bound), exactly as LAMMPS: lo is
 * the edge at or below the lower bound, hi the edge at or above the upper
 * bound, nlayers = (hi - lo) / delta rounded. An atom's bin is
 * floor((x - lo) / delta) of its coordinate (periodic coordinates remapped
 * into the box first); out of range it is clamped (discard no), excluded
 * (yes) or, with mixed, clamped at a box face and excluded at a bound given
 * as a value. Chunk IDs run 1..nchunk with the last binned dimension
 * varying fastest. Output: per-atom chunk ID (0 = excluded), and the
 * scalar nchunk. The chunk volume is LAMMPS's: box volume x product of
 * delta / box length over the binned dimensions.
 *
 * Shells, as LAMMPS: shell k spans rmin + k (rmax - rmin) / nbin to the
 * next; the distance from the centre (axis) of the atom's position mapped
 * into the box, with pbc yes its nearest image per dimension; outside
 * [rmin, rmax) clamped into the end shells (discard mixed, no) or excluded
 * (yes). A cylinder's chunk is ring x planes + axial bin + 1. Volumes
 * per chunk: 4/3 pi (r_hi^3 - r_lo^3) (in 2d too, as LAMMPS) and
 * pi (r_hi^2 - r_lo^2) x the axial bin width. Units lattice scale a sphere's
 * centre and radii (radii by the x spacing) and a cylinder's axial bins, not
 * its centre or radii (LAMMPS's scaling skips them); units reduced take the
 * centre in box fractions and the radii in fractions of the box length along
 * x (a cylinder: its first dimension across the axis). */
#include "compute_chunk_atom.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "domain.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "par.h"
#include "peratom_input.h"
#include "region.h"

enum { LOWER, CENTER, UPPER, COORD };
enum { SC_BOX, SC_LATTICE, SC_REDUCED };
enum { DISCARD_NO, DISCARD_MIXED, DISCARD_YES };

/* The chunk styles: spatial bins, or one chunk per atom type, molecule ID or
 * integer value of a per-atom input (c_ID, f_ID, v_name: (int) value, below
 * 1 excluded) */
enum chunk_style { CHUNK_BIN, CHUNK_TYPE, CHUNK_MOLECULE, CHUNK_VALUE };

/* bin/sphere and bin/cylinder: the shells, as given and as laid out */
struct shells {
    double origin_user[3], rmin_user, rmax_user; /* scaled to box units but reduced */
    int nbin, pbc;
    int cdim[2];                    /* the dimensions across a cylinder's axis */
    double origin[3], rmin, rmax, inv; /* laid out: box units, inv = nbin / (rmax - rmin) */
    int nplanes;                    /* a cylinder's axial bins */
    double *volumes;                /* [nchunk] */
};

struct chunk_atom {
    enum chunk_style style;
    enum chunk_radial radial;       /* CHUNK_BIN: shells beside the rectangular bins */
    struct shells sh;
    struct peratom_input value;     /* CHUNK_VALUE */
    int ndim, dim[3], originflag[3];
    double origin_user[3], delta[3], invdelta[3], origin[3];
    int minflag[3], maxflag[3];     /* by box dimension */
    double minvalue[3], maxvalue[3];
    int scaleflag, discard, nchunk_once, laid_out;
    char lock[GR_NAMELEN];          /* ID of the fix that froze the layout ("": none) */
    int compress;                   /* compress yes: ids[] the original IDs, ascending */
    int *ids, nids;
    int limit, limit_exact;         /* limit N max|exact (0: none; non-bin styles) */
    int ids_once;                   /* ids once: each atom's first chunk, kept by tag */
    int *kept, nkept;               /* [nkept] by tag (nkept 0: none taken yet) */
    char region[GR_NAMELEN];        /* "" = none */
    struct chunk_grid grid;
    double *coord;
    int *ichunk;
    int cap;
};

static void chunk_destroy(struct compute *c)
{
    struct chunk_atom *ca = c->data;
    if (ca) {
        free(ca->coord);
        free(ca->ichunk);
        free(ca->ids);
        free(ca->kept);
        free(ca->sh.volumes);
    }
    free(ca);
    c->data = NULL;
}

static int parse_dim(struct gravel *g, const char *s)
{
    if (!strcmp(s, "x"))
        return 0;
    if (!strcmp(s, "y"))
        return 1;
    if (!strcmp(s, "z"))
        return 2;
    gr_error(g, "compute chunk/atom: dimension must be x, y or z, got '%.32s'", s);
    return 0;
}

/* bin/sphere's `xc yc zc rmin rmax nbin` or bin/cylinder's `c1 c2 rmin rmax
 * nbin` from argv[iarg]; returns the index after them. */
static int parse_shells(struct gravel *g, struct chunk_atom *ca, const char *st, int argc,
                        char **argv, int iarg)
{
    struct shells *sh = &ca->sh;
    const int sphere = ca->radial == CHUNK_RADIAL_SPHERE, ncen = sphere ? 3 : 2;
    if (argc < iarg + ncen + 3)
        gr_error(g, "compute chunk/atom %s expects %s rmin rmax nbin", st,
                 sphere ? "xc yc zc" : "dim origin delta c1 c2");
    if (sphere) {
        for (int d = 0; d < 3; d++)
            sh->origin_user[d] = arg_double(g, argv[iarg + d], "sphere centre");
        if (g->dom.dimension == 2 && sh->origin_user[2] != 0.0)
            gr_error(g, "compute chunk/atom bin/sphere: the centre's z must be 0.0 in 2d");
    } else {
        const int axis = ca->dim[0];
        sh->cdim[0] = axis == 0 ? 1 : 0;
        sh->cdim[1] = axis == 2 ? 1 : 2;
        if (g->dom.dimension == 2 && axis != 2)
            gr_error(g, "compute chunk/atom bin/cylinder: the axis must be z in 2d");
        for (int k = 0; k < 2; k++)
            sh->origin_user[sh->cdim[k]] = arg_double(g, argv[iarg + k], "cylinder axis position");
    }
    iarg += ncen;
    sh->rmin_user = arg_double(g, argv[iarg], "rmin");
    sh->rmax_user = arg_double(g, argv[iarg + 1], "rmax");
    sh->nbin = arg_int_range(g, argv[iarg + 2], 1, 1 << 24, "nbin (number of shells)");
    if (sh->rmin_user < 0.0 || sh->rmin_user >= sh->rmax_user)
        gr_error(g, "compute chunk/atom %s: needs 0 <= rmin < rmax, got rmin %g rmax %g", st,
                 sh->rmin_user, sh->rmax_user);
    return iarg + 3;
}

static void chunk_create(struct gravel *g, struct compute *c, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "compute chunk/atom expects a style: bin/1d, bin/2d, bin/3d, bin/sphere, "
                    "bin/cylinder, type, molecule, c_ID, f_ID or v_name");
    struct chunk_atom *ca = gr_calloc(g, 1, sizeof *ca);
    c->data = ca;
    const char *st = argv[0];
    if (!strcmp(st, "bin/1d"))
        ca->ndim = 1;
    else if (!strcmp(st, "bin/2d"))
        ca->ndim = 2;
    else if (!strcmp(st, "bin/3d"))
        ca->ndim = 3;
    else if (!strcmp(st, "bin/sphere"))
        ca->radial = CHUNK_RADIAL_SPHERE;
    else if (!strcmp(st, "bin/cylinder")) {
        ca->radial = CHUNK_RADIAL_CYLINDER;
        ca->ndim = 1;
    } else if (!strcmp(st, "type"))
        ca->style = CHUNK_TYPE;
    else if (!strcmp(st, "molecule"))
        ca->style = CHUNK_MOLECULE;
    else if (!strncmp(st, "c_", 2) || !strncmp(st, "f_", 2) || !strncmp(st, "v_", 2)) {
        ca->style = CHUNK_VALUE;
        peratom_input_parse(g, st, PERATOM_XVF, &ca->value, "c_ID, c_ID[I], f_ID, f_ID[I], v_name",
                            "compute chunk/atom");
    } else
        gr_error(g, "compute chunk/atom: unknown style '%.32s' (bin/1d, bin/2d, bin/3d, "
                    "bin/sphere, bin/cylinder, type, molecule, c_ID, f_ID, v_name)", st);
    if (ca->style == CHUNK_MOLECULE && !g->atoms.molecule_flag)
        gr_error(g, "compute chunk/atom molecule: the atoms have no molecule IDs (atom_style "
                    "hybrid sphere molecular)");
    if (argc < 1 + 3 * ca->ndim)
        gr_error(g, "compute chunk/atom %s expects %d arguments (dim origin delta each), got "
                    "%d", st, 3 * ca->ndim, argc - 1);
    int iarg = 1;
    for (int m = 0; m < ca->ndim; m++, iarg += 3) {
        ca->dim[m] = parse_dim(g, argv[iarg]);
        if (g->dom.dimension == 2 && ca->dim[m] == 2)
            gr_error(g, "compute chunk/atom: cannot bin z in a 2d model");
        const char *o = argv[iarg + 1];
        if (!strcmp(o, "lower"))
            ca->originflag[m] = LOWER;
        else if (!strcmp(o, "center"))
            ca->originflag[m] = CENTER;
        else if (!strcmp(o, "upper"))
            ca->originflag[m] = UPPER;
        else {
            ca->originflag[m] = COORD;
            ca->origin_user[m] = arg_double(g, o, "bin origin (lower, center, upper or a value)");
        }
        ca->delta[m] = arg_positive(g, argv[iarg + 2], "bin width delta");
        for (int k = 0; k < m; k++)
            if (ca->dim[k] == ca->dim[m])
                gr_error(g, "compute chunk/atom %s: dimension %s is binned twice", st,
                         argv[iarg]);
    }
    if (ca->radial)
        iarg = parse_shells(g, ca, st, argc, argv, iarg);
    for (int d = 0; d < 3; d++) {
        ca->minflag[d] = LOWER;
        ca->maxflag[d] = UPPER;
    }
    ca->scaleflag = SC_LATTICE;
    ca->discard = DISCARD_MIXED;
    int nchunk_set = 0;
    for (int i = iarg; i < argc; i++) {
        const char *kw = argv[i];
        if (ca->style != CHUNK_BIN &&
            (!strcmp(kw, "units") || !strcmp(kw, "bound") || !strcmp(kw, "pbc")))
            gr_error(g, "compute chunk/atom %s: keyword '%s' applies to the bin styles only", st,
                     kw);
        if (!strcmp(kw, "units")) {
            arg_need(g, argc, i, 1, kw);
            const char *v = argv[++i];
            if (!strcmp(v, "box"))
                ca->scaleflag = SC_BOX;
            else if (!strcmp(v, "lattice"))
                ca->scaleflag = SC_LATTICE;
            else if (!strcmp(v, "reduced"))
                ca->scaleflag = SC_REDUCED;
            else
                gr_error(g, "compute chunk/atom: units must be box, lattice or reduced, got "
                            "'%.32s'", v);
        } else if (!strcmp(kw, "bound")) {
            arg_need(g, argc, i, 3, kw);
            int d = parse_dim(g, argv[i + 1]);
            if (!strcmp(argv[i + 2], "lower"))
                ca->minflag[d] = LOWER;
            else {
                ca->minflag[d] = COORD;
                ca->minvalue[d] = arg_double(g, argv[i + 2], "bound lower value");
            }
            if (!strcmp(argv[i + 3], "upper"))
                ca->maxflag[d] = UPPER;
            else {
                ca->maxflag[d] = COORD;
                ca->maxvalue[d] = arg_double(g, argv[i + 3], "bound upper value");
            }
            i += 3;
        } else if (!strcmp(kw, "discard")) {
            arg_need(g, argc, i, 1, kw);
            const char *v = argv[++i];
            if (!strcmp(v, "mixed"))
                ca->discard = DISCARD_MIXED;
            else if (!strcmp(v, "yes"))
                ca->discard = DISCARD_YES;
            else if (!strcmp(v, "no"))
                ca->discard = DISCARD_NO;
            else
                gr_error(g, "compute chunk/atom: discard must be mixed, yes or no, got '%.32s'",
                         v);
            if (ca->style != CHUNK_BIN && ca->discard == DISCARD_MIXED)
                gr_error(g, "compute chunk/atom %s: discard mixed needs bins (yes or no)", st);
        } else if (!strcmp(kw, "region")) {
            arg_need(g, argc, i, 1, kw);
            region_get(g, argv[++i]);
            snprintf(ca->region, sizeof ca->region, "%s", argv[i]);
        } else if (!strcmp(kw, "nchunk")) {
            arg_need(g, argc, i, 1, kw);
            const char *v = argv[++i];
            if (!strcmp(v, "once"))
                ca->nchunk_once = 1;
            else if (!strcmp(v, "every"))
                ca->nchunk_once = 0;
            else
                gr_error(g, "compute chunk/atom: nchunk must be once or every, got '%.32s'", v);
            nchunk_set = 1;
        } else if (!strcmp(kw, "ids")) {
            arg_need(g, argc, i, 1, kw);
            const char *v = argv[++i];
            if (!strcmp(v, "once"))
                ca->ids_once = 1;
            else if (!strcmp(v, "every"))
                ca->ids_once = 0;
            else if (!strcmp(v, "nfreq"))
                gr_error(g, "compute chunk/atom: ids nfreq is not supported (once, every)");
            else
                gr_error(g, "compute chunk/atom: ids must be once, nfreq or every, got '%.32s'",
                         v);
        } else if (!strcmp(kw, "pbc")) {
            arg_need(g, argc, i, 1, kw);
            ca->sh.pbc = arg_yesno(g, argv[++i], "pbc");
        } else if (!strcmp(kw, "compress")) {
            arg_need(g, argc, i, 1, kw);
            ca->compress = arg_yesno(g, argv[++i], "compress");
            if (ca->compress && ca->style != CHUNK_MOLECULE && ca->style != CHUNK_VALUE)
                gr_error(g, "compute chunk/atom %s: compress yes applies to the molecule and "
                            "c_ID/f_ID/v_name styles (gravel)", st);
        } else if (!strcmp(kw, "limit")) {
            arg_need(g, argc, i, 1, kw);
            ca->limit = arg_int_range(g, argv[++i], 0, INT_MAX, "limit");
            if (ca->limit) {
                arg_need(g, argc, i, 1, "limit N");
                const char *v = argv[++i];
                if (!strcmp(v, "max") || !strcmp(v, "exact"))
                    ca->limit_exact = v[0] == 'e';
                else
                    gr_error(g, "compute chunk/atom: limit N expects max or exact, got '%.32s'",
                             v);
            }
        } else {
            gr_error(g, "compute chunk/atom: unknown keyword '%.32s'", kw);
        }
    }
    if (!nchunk_set && ca->scaleflag == SC_REDUCED)
        ca->nchunk_once = 1;
    if (ca->style != CHUNK_BIN && ca->discard == DISCARD_MIXED)
        ca->discard = DISCARD_YES; /* LAMMPS's default without bins */
    if (ca->limit && ca->compress && ca->style != CHUNK_BIN)
        gr_error(g, "compute chunk/atom %s: limit with compress yes is not supported (LAMMPS "
                    "keeps compressed IDs above the limit)", st);
    if (ca->ids_once) { /* frozen IDs need a frozen count (LAMMPS: nchunk once) */
        if (nchunk_set && !ca->nchunk_once)
            gr_error(g, "compute chunk/atom %s: ids once needs nchunk once", st);
        if (!nchunk_set && (ca->compress || ca->style == CHUNK_VALUE ||
                            (ca->style == CHUNK_MOLECULE && ca->region[0])))
            gr_error(g, "compute chunk/atom %s: ids once needs nchunk once (this style's "
                        "default is every)", st);
        ca->nchunk_once = 1;
    }
    /* scale to box units (LAMMPS: delta, origin and bounds times the lattice spacing) */
    double sc[3] = {1, 1, 1};
    if (ca->scaleflag == SC_LATTICE)
        domain_unit_scale(g, 1, sc);
    for (int m = 0; m < ca->ndim; m++) {
        double s = sc[ca->dim[m]];
        ca->delta[m] *= s;
        ca->invdelta[m] = 1.0 / ca->delta[m];
        if (ca->originflag[m] == COORD)
            ca->origin_user[m] *= s;
    }
    for (int d = 0; d < 3; d++) {
        if (ca->minflag[d] == COORD)
            ca->minvalue[d] *= sc[d];
        if (ca->maxflag[d] == COORD)
            ca->maxvalue[d] *= sc[d];
    }
    if (ca->radial == CHUNK_RADIAL_SPHERE) { /* LAMMPS: radii by the x spacing */
        for (int d = 0; d < 3; d++)
            ca->sh.origin_user[d] *= sc[d];
        ca->sh.rmin_user *= sc[0];
        ca->sh.rmax_user *= sc[0];
    }
    c->peratom_flag = 1;
    c->scalar_flag = 1;
    c->extscalar = 0;
}

struct compute *chunk_atom_get(struct gravel *g, const char *id, const char *who)
{
    struct compute *c = compute_find(g, id);
    if (!c)
        gr_error(g, "%s: unknown compute ID '%.64s' (a compute chunk/atom)", who, id);
    if (strcmp(c->style->name, "chunk/atom") != 0)
        gr_error(g, "%s: compute %s is %s, not chunk/atom", who, id, c->style->name);
    return c;
}

int chunk_atom_compressed(const struct compute *c)
{
    return ((const struct chunk_atom *)c->data)->compress;
}

enum chunk_radial chunk_atom_radial(const struct compute *c)
{
    return ((const struct chunk_atom *)c->data)->radial;
}

int chunk_atom_ncoord(const struct compute *c)
{
    const struct chunk_atom *ca = c->data;
    return ca->radial == CHUNK_RADIAL_SPHERE     ? 1
           : ca->radial == CHUNK_RADIAL_CYLINDER ? 2
                                                 : ca->ndim;
}

static int int_cmp(const void *a, const void *b)
{
    const int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

/* ids once: the chunks just assigned, kept by tag (at the first assignment) */
static void keep_ids(struct gravel *g, struct chunk_atom *ca)
{
    const struct atoms *a = &g->atoms;
    if (!ca->ids_once || ca->nkept)
        return;
    int64_t top = 0;
    for (int i = 0; i < a->n; i++)
        top = a->tag[i] > top ? a->tag[i] : top;
    if (top >= INT_MAX)
        gr_error(g, "compute chunk/atom ids once: atom IDs up to %lld are too large",
                 (long long)top);
    ca->nkept = (int)top + 1;
    ca->kept = gr_calloc(g, (size_t)ca->nkept, sizeof *ca->kept);
    for (int i = 0; i < a->n; i++)
        ca->kept[a->tag[i]] = ca->ichunk[i];
}

static void ichunk_room(struct gravel *g, struct compute *c, struct chunk_atom *ca, int n)
{
    if (n <= ca->cap)
        return;
    int cap = n > 16 ? n : 16;
    int *p = realloc(ca->ichunk, (size_t)cap * sizeof(int));
    if (!p)
        gr_error(g, "out of memory for compute %s", c->id);
    ca->ichunk = p;
    ca->cap = cap;
}

/* The non-bin styles' chunk ID of every host atom in the group and region
 * (any integer: 0 and negative ones too, as LAMMPS hashes them with compress)
 * and CHUNK_OUT for the others. Returns the largest ID, at least 0. */
#define CHUNK_OUT INT_MIN
static int assign_ids(struct gravel *g, struct compute *c, struct chunk_atom *ca)
{
    const struct atoms *a = &g->atoms;
    ichunk_room(g, c, ca, a->n);
    const struct region *r = ca->region[0] ? region_get(g, ca->region) : NULL;
    int stride = 1, hi = 0;
    double *owned = NULL;
    const double *val = ca->style == CHUNK_VALUE
                            ? peratom_input_values(g, &ca->value, &stride, &owned,
                                                   "compute chunk/atom")
                            : NULL;
    for (int i = 0; i < a->n; i++) {
        int id = CHUNK_OUT;
        if ((a->mask[i] & c->groupbit) && !(r && !region_match(r, a->x + 3 * (size_t)i))) {
            double v = ca->style == CHUNK_TYPE       ? a->type[i]
                       : ca->style == CHUNK_MOLECULE ? (double)a->mol[i]
                                                     : val[(size_t)i * stride];
            v = v > 1073741823.0 ? 1073741823.0 : v < -1073741823.0 ? -1073741823.0 : v;
            id = (int)v; /* LAMMPS's (int) cast */
        }
        ca->ichunk[i] = id;
        hi = id > hi ? id : hi;
    }
    free(owned);
    return hi;
}

/* The non-bin styles' layout: nchunk the atom types, or the largest ID
 * (at least 1); no coordinates; the box's volume. */
static const struct chunk_grid *setup_ids(struct gravel *g, struct compute *c,
                                          struct chunk_atom *ca)
{
    struct chunk_grid *gr = &ca->grid;
    const int hi = assign_ids(g, c, ca);
    gr->ndim = 0;
    gr->nchunk = ca->style == CHUNK_TYPE ? g->atoms.ntypes : hi > 0 ? hi : 1;
    if (ca->limit) /* LAMMPS: limit N max or exact (not with compress) */
        gr->nchunk = ca->limit_exact || ca->limit < gr->nchunk ? ca->limit : gr->nchunk;
    gr->ids = NULL;
    if (ca->compress) { /* the IDs present, ascending: chunk k is ids[k - 1] */
        free(ca->ids);
        ca->ids = gr_malloc(g, ((size_t)g->atoms.n + 1) * sizeof *ca->ids);
        ca->nids = 0;
        for (int i = 0; i < g->atoms.n; i++)
            if (ca->ichunk[i] != CHUNK_OUT)
                ca->ids[ca->nids++] = ca->ichunk[i];
        qsort(ca->ids, (size_t)ca->nids, sizeof *ca->ids, int_cmp);
        int u = 0;
        for (int k = 0; k < ca->nids; k++)
            if (u == 0 || ca->ids[k] != ca->ids[u - 1])
                ca->ids[u++] = ca->ids[k];
        ca->nids = u;
        gr->nchunk = u > 0 ? u : 1;
        gr->ids = ca->ids;
    }
    gr->coord = NULL;
    const double *lo = g->dom.lo, *up = g->dom.hi;
    gr->volume = (up[0] - lo[0]) * (up[1] - lo[1]) * (g->dom.dimension == 3 ? up[2] - lo[2] : 1.0);
    ca->laid_out = 1;
    return gr;
}

/* The shells on the current box, around the rectangular layout of the grid
 * (a cylinder's axial bins, none for a sphere: one plane): nchunk, coord,
 * volumes (LAMMPS setup_sphere_bins, setup_cylinder_bins, bin_volumes). */
static void setup_shells(struct gravel *g, struct compute *c, struct chunk_atom *ca,
                         const double prd[3])
{
    struct shells *sh = &ca->sh;
    struct chunk_grid *gr = &ca->grid;
    const int sphere = ca->radial == CHUNK_RADIAL_SPHERE;
    const int *cd = sh->cdim, ncross = sphere ? 3 : 2;
    const double rscale = ca->scaleflag != SC_REDUCED ? 1.0 : prd[sphere ? 0 : cd[0]];
    for (int k = 0; k < ncross; k++) {
        const int d = sphere ? k : cd[k];
        sh->origin[d] = ca->scaleflag == SC_REDUCED
                            ? g->dom.lo[d] + sh->origin_user[d] * prd[d]
                            : sh->origin_user[d];
        if (sh->pbc && g->dom.periodic[d] && (d < 2 || g->dom.dimension == 3) &&
            sh->rmax_user * rscale > 0.5 * prd[d])
            gr_error(g, "compute %s chunk/atom %s: rmax %g is more than half the periodic box "
                        "along %c (pbc yes)", c->id, sphere ? "bin/sphere" : "bin/cylinder",
                     sh->rmax_user * rscale, "xyz"[d]);
    }
    sh->rmin = sh->rmin_user * rscale;
    sh->rmax = sh->rmax_user * rscale;
    sh->inv = sh->nbin / (sh->rmax - sh->rmin);
    sh->nplanes = gr->nchunk;
    if ((double)sh->nbin * sh->nplanes > (double)(1 << 28))
        gr_error(g, "compute %s chunk/atom: too many bins (%d shells x %d planes)", c->id,
                 sh->nbin, sh->nplanes);
    const int n = sh->nbin * sh->nplanes, nc = sphere ? 1 : 2;
    double *axial = ca->coord; /* [nplanes] a cylinder's bin/1d centres */
    ca->coord = gr_malloc(g, (size_t)n * nc * sizeof(double));
    free(sh->volumes);
    sh->volumes = gr_malloc(g, (size_t)n * sizeof(double));
    /* the axial bin's length in box units, LAMMPS's slab thickness */
    const double slab = sphere ? 1.0
                               : prd[ca->dim[0]] * gr->delta[0] /
                                     (gr->reduced ? 1.0 : prd[ca->dim[0]]);
    for (int k = 0; k < n; k++) {
        const int ir = k / sh->nplanes, ip = k % sh->nplanes;
        const double w = sh->rmax - sh->rmin, lo = sh->rmin + ir * w / sh->nbin;
        const double hi = ir == sh->nbin - 1 ? sh->rmax : sh->rmin + (ir + 1) * w / sh->nbin;
        ca->coord[(size_t)k * nc] = 0.5 * (lo + hi);
        if (!sphere)
            ca->coord[(size_t)k * nc + 1] = axial[ip];
        sh->volumes[k] = sphere ? 4.0 / 3.0 * M_PI * hi * hi * hi - 4.0 / 3.0 * M_PI * lo * lo * lo
                                : (M_PI * hi * hi - M_PI * lo * lo) * slab;
    }
    free(axial);
    gr->nchunk = n;
    gr->ncoord = nc;
    gr->coord = ca->coord;
    gr->volumes = sh->volumes;
}

/* Shell of the atom at x (0..nbin-1), or -1 excluded (discard yes) */
static int shell_of(const struct gravel *g, const struct chunk_atom *ca, const double *x)
{
    const struct shells *sh = &ca->sh;
    const int sphere = ca->radial == CHUNK_RADIAL_SPHERE, ncross = sphere ? 3 : 2;
    double r2 = 0;
    for (int k = 0; k < ncross; k++) {
        const int d = sphere ? k : sh->cdim[k];
        const double lo = g->dom.lo[d], hi = g->dom.hi[d], prd = hi - lo;
        double xr = x[d];
        if (g->dom.periodic[d]) { /* LAMMPS: a sphere maps any distance, a cylinder one box */
            do {
                if (xr < lo)
                    xr += prd;
                else if (xr >= hi)
                    xr -= prd;
            } while (sphere && (xr < lo || xr >= hi));
        }
        double dx = xr - sh->origin[d];
        if (sh->pbc && g->dom.periodic[d]) {
            do {
                if (fabs(dx) > 0.5 * prd)
                    dx += dx < 0.0 ? prd : -prd;
            } while (sphere && fabs(dx) > 0.5 * prd);
        }
        r2 += dx * dx;
    }
    const double r = sqrt(r2);
    int ib = (int)((r - sh->rmin) * sh->inv);
    if (r < sh->rmin)
        ib--;
    if (ca->discard == DISCARD_YES)
        return ib < 0 || ib >= sh->nbin ? -1 : ib;
    return ib < 0 ? 0 : ib >= sh->nbin ? sh->nbin - 1 : ib;
}

const struct chunk_grid *chunk_atom_setup(struct gravel *g, struct compute *c)
{
    struct chunk_atom *ca = c->data;
    if (ca->laid_out && (ca->nchunk_once || (ca->lock[0] && fix_find(g, ca->lock))))
        return &ca->grid;
    if (ca->style != CHUNK_BIN)
        return setup_ids(g, c, ca);
    double binlo[3], binhi[3], prd[3];
    if (g->dom.xy != 0.0 || g->dom.xz != 0.0 || g->dom.yz != 0.0)
        gr_error(g, "compute %s chunk/atom: spatial bins in a tilted triclinic box are not "
                    "supported", c->id);
    for (int d = 0; d < 3; d++) {
        prd[d] = g->dom.hi[d] - g->dom.lo[d];
        binlo[d] = ca->scaleflag == SC_REDUCED ? 0.0 : g->dom.lo[d];
        binhi[d] = ca->scaleflag == SC_REDUCED ? 1.0 : g->dom.hi[d];
        if (ca->minflag[d] == COORD)
            binlo[d] = ca->minvalue[d];
        if (ca->maxflag[d] == COORD)
            binhi[d] = ca->maxvalue[d];
    }
    struct chunk_grid *gr = &ca->grid;
    int nbins = 1;
    for (int m = 0; m < ca->ndim; m++) {
        int d = ca->dim[m];
        double o = ca->origin_user[m], lo, hi, del = ca->delta[m], inv = ca->invdelta[m];
        if (ca->originflag[m] == LOWER)
            o = binlo[d];
        else if (ca->originflag[m] == UPPER)
            o = binhi[d];
        else if (ca->originflag[m] == CENTER)
            o = 0.5 * (binlo[d] + binhi[d]);
        ca->origin[m] = o;
        if (o < binlo[d]) {
            int n = (int)((binlo[d] - o) * inv);
            lo = o + n * del;
        } else {
            int n = (int)((o - binlo[d]) * inv);
            lo = o - n * del;
            if (lo > binlo[d])
                lo -= del;
        }
        if (o < binhi[d]) {
            int n = (int)((binhi[d] - o) * inv);
            hi = o + n * del;
            if (hi < binhi[d])
                hi += del;
        } else {
            int n = (int)((o - binhi[d]) * inv);
            hi = o - n * del;
        }
        if (lo > hi)
            gr_error(g, "compute chunk/atom %s: invalid bin bounds", c->id);
        double nl = (hi - lo) * inv + 0.5;
        if (nl > 1 << 24 || (double)nbins * nl > (double)(1 << 28))
            gr_error(g, "compute chunk/atom %s: too many bins (%g along %c)", c->id, floor(nl),
                     "xyz"[d]);
        gr->offset[m] = lo;
        gr->delta[m] = del;
        gr->dim[m] = d;
        gr->nlayers[m] = (int)nl;
        nbins *= gr->nlayers[m];
    }
    gr->ndim = ca->ndim;
    gr->nchunk = nbins;
    gr->reduced = ca->scaleflag == SC_REDUCED;
    gr->discard_no = ca->discard == DISCARD_NO;
    gr->radial = ca->radial;
    gr->ncoord = ca->ndim;
    gr->volumes = NULL;
    double vol = g->dom.dimension == 3 ? prd[0] * prd[1] * prd[2] : prd[0] * prd[1];
    for (int m = 0; m < ca->ndim; m++)
        vol *= gr->delta[m] / (gr->reduced ? 1.0 : prd[gr->dim[m]]);
    gr->volume = vol;
    free(ca->coord);
    ca->coord = gr_malloc(g, (size_t)nbins * (ca->ndim + 1) * sizeof(double));
    for (int k = 0; k < nbins; k++) {
        int rem = k;
        for (int m = ca->ndim - 1; m >= 0; m--) {
            int im = rem % gr->nlayers[m];
            rem /= gr->nlayers[m];
            ca->coord[(size_t)k * ca->ndim + m] = gr->offset[m] + (im + 0.5) * gr->delta[m];
        }
    }
    gr->coord = ca->coord;
    if (ca->radial)
        setup_shells(g, c, ca, prd);
    ca->laid_out = 1;
    return gr;
}

const int *chunk_atom_assign(struct gravel *g, struct compute *c)
{
    struct chunk_atom *ca = c->data;
    const struct atoms *a = &g->atoms;
    if (!ca->laid_out)
        chunk_atom_setup(g, c);
    if (ca->ids_once && ca->nkept) { /* LAMMPS's stored IDs: 0 for atoms since */
        ichunk_room(g, c, ca, a->n);
        for (int i = 0; i < a->n; i++)
            ca->ichunk[i] = a->tag[i] < ca->nkept ? ca->kept[a->tag[i]] : 0;
        return ca->ichunk;
    }
    if (ca->style != CHUNK_BIN) {
        /* LAMMPS's discard rule: an ID outside 1..nchunk (beyond a frozen
         * count too; with compress one not in the layout) is in no chunk, or
         * with discard no in the last */
        assign_ids(g, c, ca);
        const int n = ca->grid.nchunk, out = ca->discard == DISCARD_NO ? n : 0;
        for (int i = 0; i < a->n; i++) {
            int *id = &ca->ichunk[i];
            if (*id == CHUNK_OUT) {
                *id = 0;
                continue;
            }
            if (ca->compress) { /* its place among the layout's IDs, or none */
                const int *hit = bsearch(id, ca->ids, (size_t)ca->nids, sizeof *id, int_cmp);
                *id = hit ? (int)(hit - ca->ids) + 1 : out;
            }
            if (*id < 1 || *id > n)
                *id = out;
        }
        keep_ids(g, ca);
        return ca->ichunk;
    }
    ichunk_room(g, c, ca, a->n);
    const struct region *r = ca->region[0] ? region_get(g, ca->region) : NULL;
    const struct chunk_grid *gr = &ca->grid;
    for (int i = 0; i < a->n; i++) {
        const double *x = a->x + 3 * (size_t)i;
        ca->ichunk[i] = 0;
        if (!(a->mask[i] & c->groupbit) || (r && !region_match(r, x)))
            continue;
        int id = 0, keep = 1;
        for (int m = 0; m < gr->ndim && keep; m++) {
            int d = gr->dim[m];
            double lo = g->dom.lo[d], hi = g->dom.hi[d], prd = hi - lo, xr = x[d];
            if (gr->reduced) {
                xr = (xr - lo) / prd;
                lo = 0;
                hi = prd = 1;
            }
            if (g->dom.periodic[d]) {
                if (xr < lo)
                    xr += prd;
                if (xr >= hi)
                    xr -= prd;
            }
            int ib = (int)((xr - gr->offset[m]) * ca->invdelta[m]);
            if (xr < gr->offset[m])
                ib--;
            int top = gr->nlayers[m] - 1;
            if (ca->discard == DISCARD_MIXED) {
                /* LAMMPS: clamp only at a lower bound left at the box face
                 * (LOWER == 0); at the upper end only values are tested */
                if (ca->minflag[d] == LOWER)
                    ib = ib < 0 ? 0 : ib;
                else if (ib < 0)
                    keep = 0;
                if (ca->maxflag[d] == LOWER)
                    ib = ib > top ? top : ib;
                else if (ib > top)
                    keep = 0;
            } else if (ca->discard == DISCARD_NO) {
                ib = ib < 0 ? 0 : ib > top ? top : ib;
            } else if (ib < 0 || ib > top) {
                keep = 0;
            }
            id = id * gr->nlayers[m] + ib;
        }
        if (keep && ca->radial) {
            const int ir = shell_of(g, ca, x);
            keep = ir >= 0;
            id += ir * ca->sh.nplanes;
        }
        if (keep)
            ca->ichunk[i] = id + 1;
    }
    keep_ids(g, ca);
    return ca->ichunk;
}

/* run setup: with ids once, the first run's setup takes every atom's chunk
 * (LAMMPS's setup), on several ranks on every rank's atoms gathered: every
 * rank keeps every tag's */
static void chunk_init(struct gravel *g, struct compute *c)
{
    struct chunk_atom *ca = c->data;
    if (!ca->ids_once || ca->nkept)
        return;
    run_sync_host(g);
    const int gather = par_on(g) && !par_gathered(g);
    if (gather)
        par_gather_begin(g);
    chunk_atom_setup(g, c);
    chunk_atom_assign(g, c);
    if (gather)
        par_gather_end(g);
}

void chunk_atom_lock(struct gravel *g, struct compute *c, const char *fix_id)
{
    struct chunk_atom *ca = c->data;
    if (ca->lock[0] && strcmp(ca->lock, fix_id) && fix_find(g, ca->lock))
        gr_error(g, "compute %s chunk/atom: fixes %s and %s average over it with epochs that "
                    "do not line up (LAMMPS: incompatible ways)", c->id, ca->lock, fix_id);
    snprintf(ca->lock, sizeof ca->lock, "%s", fix_id);
}

void chunk_atom_unlock(struct compute *c, const char *fix_id)
{
    struct chunk_atom *ca = c->data;
    if (!strcmp(ca->lock, fix_id))
        ca->lock[0] = '\0';
}

void chunk_mass_mean(struct gravel *g, unsigned groupbit, const int *ichunk, int nchunk,
                     const double *u, double *mean, double *mass)
{
    const struct atoms *a = &g->atoms;
    double *m = gr_calloc(g, (size_t)nchunk + 1, sizeof *m);
    memset(mean, 0, 3 * (size_t)nchunk * sizeof *mean);
    const int *order = atoms_tag_order(g); /* sums that depend on the atoms only */
    for (int q = 0; q < a->n; q++) {
        const int i = order[q], k = ichunk[i] - 1;
        if (!(a->mask[i] & groupbit) || k < 0 || k >= nchunk)
            continue;
        double x[3];
        if (u)
            memcpy(x, u + 3 * (size_t)i, sizeof x);
        else
            domain_unmap(g, a->x + 3 * (size_t)i, a->image + 3 * (size_t)i, x);
        m[k] += a->rmass[i];
        for (int d = 0; d < 3; d++)
            mean[3 * k + d] += x[d] * a->rmass[i];
    }
    for (int k = 0; k < nchunk; k++)
        for (int d = 0; d < 3; d++)
            mean[3 * k + d] = m[k] > 0 ? mean[3 * k + d] / m[k] : 0.0;
    if (mass)
        memcpy(mass, m, (size_t)nchunk * sizeof *m);
    free(m);
}

static double chunk_scalar(struct gravel *g, struct compute *c)
{
    return chunk_atom_setup(g, c)->nchunk;
}

static void chunk_peratom(struct gravel *g, struct compute *c)
{
    chunk_atom_setup(g, c);
    const int *ic = chunk_atom_assign(g, c);
    for (int i = 0; i < g->atoms.n; i++)
        c->peratom[i] = ic[i];
}

const struct compute_style compute_style_chunk_atom = {
    .name = "chunk/atom",
    .ranks = COMPUTE_RANKS_GATHER,
    .create = chunk_create,
    .init = chunk_init,
    .scalar = chunk_scalar,
    .peratom = chunk_peratom,
    .destroy = chunk_destroy,
};
