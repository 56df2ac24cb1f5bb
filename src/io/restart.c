/* restart.c - binary restart files (write_restart, read_restart, restart)
 * and the exact continuation of a run from one (restart_resume).
 *
 * File = 32-byte header + payload. Header: magic "GRAVELRS", a 32-bit
 * endian marker 0x01020304 in the writer's byte order, the format version,
 * the payload length and the FNV-1a 64 hash of the payload (the standard
 * offset basis since format 2). Payload: tagged sections (u32 id, u32 0,
 * u64 length, bytes), values in native byte order
 * (the marker proves it is ours). The reader checks header, length and hash
 * before parsing, parses every section into a private image with bounds
 * checks, validates it, and only then applies it: a bad file never leaves a
 * half-read state. Each section has one writer and, beside it, one reader,
 * listed once in file order in sections[]; the per-atom sections follow the
 * field table (atom_fields.h). See doc/restart.md.
 *
 * Exactness. A run continued from a restart file equals the uninterrupted
 * run bit for bit when the file carries the device state at the written
 * step: atoms in device order (unwrapped as the device holds them), the
 * neighbor list in its order with the contact history (partners by tag), the
 * reference positions and steps since the last build (rebuild decisions),
 * the forces and torques of the step, and the fixes' state. restart_resume()
 * then installs that list instead of rebuilding at setup (a rebuild would
 * wrap, re-sort and re-order the sums) and, when pair style, coefficients,
 * time step and fixes (ID, style, group, arguments, order) are those of the
 * writer, keeps the written forces instead of re-evaluating them (a setup
 * evaluation is not bitwise idempotent for sliding contacts). Anything else
 * falls back to LAMMPS semantics: rebuild, history carried by partner tag,
 * setup forces. */
#include "comm.h"
#include "restart.h"

#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "args.h"
#include "atom_custom.h"
#include "atoms.h"
#include "device.h"
#include "domain.h"
#include "engine.h"
#include "error.h"
#include "fileio.h"
#include "fix.h"
#include "log.h"
#include "neighbor.h"
#include "outfile.h"
#include "pair.h"
#include "par.h"
#include "par_restart.h"

enum sect {
    S_INFO = 1, S_DOMAIN, S_NEIGH, S_GROUPS, S_TYPES, S_ATOMS, S_PAIR, S_LIST, S_FIXES,
    S_MOLECULE, /* optional: molecule IDs (fix property/atom mol, or the atom style's) */
    S_HEAT,     /* optional: temperatures and heat flows (fix property/atom temperature) */
    S_CUSTOM,   /* optional: custom properties (fix property/atom i_ d_ i2_ d2_) */
    S_ELLIPSOID, /* optional: superellipsoid shapes, blockiness, orientations, angular momenta */
    S_PAIR_STATE, /* optional: a pair style's own state (granular/superellipsoid's models
                   * and contact history: pair_style.state_write) */
    S_LAST
};
/* ---- growable output buffer -------------------------------------------------- */

struct wbuf {
    unsigned char *p;
    size_t n, cap;
};

static void put(struct gravel *g, struct wbuf *w, const void *src, size_t len)
{
    if (w->n + len > w->cap) {
        size_t cap = w->cap ? w->cap : 4096;
        while (cap < w->n + len)
            cap *= 2;
        w->p = gr_realloc(g, w->p, cap);
        w->cap = cap;
    }
    if (len)
        memcpy(w->p + w->n, src, len);
    w->n += len;
}
static void put_u32(struct gravel *g, struct wbuf *w, uint32_t v) { put(g, w, &v, 4); }
static void put_i32(struct gravel *g, struct wbuf *w, int32_t v) { put(g, w, &v, 4); }
static void put_u64(struct gravel *g, struct wbuf *w, uint64_t v) { put(g, w, &v, 8); }
static void put_i64(struct gravel *g, struct wbuf *w, int64_t v) { put(g, w, &v, 8); }
static void put_f64(struct gravel *g, struct wbuf *w, double v) { put(g, w, &v, 8); }
static void put_str(struct gravel *g, struct wbuf *w, const char *s)
{
    size_t len = strlen(s);
    put_u32(g, w, (uint32_t)len);
    put(g, w, s, len);
}
/* Section header; returns the offset of the length field (sect_end fills it). */
static size_t sect_begin(struct gravel *g, struct wbuf *w, enum sect id)
{
    put_u32(g, w, (uint32_t)id);
    put_u32(g, w, 0);
    size_t at = w->n;
    put_u64(g, w, 0);
    return at;
}
static void sect_end(struct wbuf *w, size_t at)
{
    uint64_t len = (uint64_t)(w->n - at - 8);
    memcpy(w->p + at, &len, 8);
}

static uint64_t fnv1a(uint64_t h, const void *data, size_t len)
{
    const unsigned char *c = data;
    for (size_t i = 0; i < len; i++)
        h = (h ^ c[i]) * 1099511628211ull;
    return h;
}
#define FNV_INIT 14695981039346656037ull /* the standard FNV-1a 64 offset basis (format 2) */

/* ---- bounds-checked input cursor ------------------------------------------------ */

struct rbuf {
    const unsigned char *p;
    size_t n, off;
    int bad;
};

static int get(struct rbuf *r, void *dst, size_t len)
{
    if (r->bad || len > r->n - r->off) {
        r->bad = 1;
        if (dst)
            memset(dst, 0, len);
        return 0;
    }
    if (dst)
        memcpy(dst, r->p + r->off, len);
    r->off += len;
    return 1;
}
static uint32_t get_u32(struct rbuf *r) { uint32_t v = 0; get(r, &v, 4); return v; }
static int32_t get_i32(struct rbuf *r) { int32_t v = 0; get(r, &v, 4); return v; }
static uint64_t get_u64(struct rbuf *r) { uint64_t v = 0; get(r, &v, 8); return v; }
static int64_t get_i64(struct rbuf *r) { int64_t v = 0; get(r, &v, 8); return v; }
static double get_f64(struct rbuf *r) { double v = 0; get(r, &v, 8); return v; }
/* String of at most maxlen bytes into dst (NUL-terminated). */
static void get_str(struct rbuf *r, char *dst, size_t maxlen)
{
    uint32_t len = get_u32(r);
    if (len >= maxlen) {
        r->bad = 1;
        dst[0] = 0;
        return;
    }
    get(r, dst, len);
    dst[r->bad ? 0 : len] = 0;
}
/* Array of count elements of size sz, freshly allocated (NULL on overflow). */
static void *get_array(struct rbuf *r, size_t count, size_t sz)
{
    if (r->bad || (sz && count > (r->n - r->off) / sz)) {
        r->bad = 1;
        return NULL;
    }
    void *p = malloc(count * sz + 1);
    if (!p) {
        r->bad = 1;
        return NULL;
    }
    get(r, p, count * sz);
    return p;
}

/* ---- state: settings of `restart`, scratch buffers, what read_restart left ----- */

struct fix_saved {
    char id[GR_NAMELEN], style[GR_NAMELEN];
    uint64_t arghash;           /* of the writer's fix: group, style, arguments */
    unsigned char *blob;
    size_t bloblen;
    uint32_t peratom_bytes, rsz;
    int nrows;                  /* rows keyed by the list section's devtag[] */
    unsigned char *peratom;
};

/* The image of a file, parsed and validated before anything is applied. */
struct image {
    char version[64];
    bigint step, laststep_reset;
    double time, dt;
    int dt_set, single;
    uint64_t seed_counter;
    struct domain dom;
    struct neigh_settings neigh;
    struct groups groups;
    int ntypes;
    double *type_mass;
    int64_t maxtag;
    int n;
    ATOM_FIELDS(ATOM_FIELD_MEMBER) /* the per-atom arrays; mol NULL: no molecule IDs */
    int style_molecular;        /* atom_style hybrid sphere molecular */
    int heat_flag;              /* the S_HEAT section's ATOM_HEAT_* bits (0: none) */
    struct atom_custom cus;     /* the S_CUSTOM section's properties (n 0: none) */
    double *custom;             /* ... and their values, cus.slots per atom */
    int has_pair, coeff_set, ncoef;
    char pair_name[GR_NAMELEN];
    double coef[PAIR_MAXCOEF];
    /* the pair style's own state (S_PAIR_STATE): its two parts' bytes, and
     * the data state_read made of them (validate), installed by apply */
    int has_pstate;
    char pstate_name[GR_NAMELEN];
    unsigned char *pcoef, *phist;
    size_t npcoef, nphist;
    void *pdata;
    /* neighbor list (device order of the writer) */
    int has_list, exact, history, ndev, maxn, ago;
    uint64_t fingerprint;
    int64_t *devtag;
    int *ncount;
    int64_t *partner;           /* concatenated rows */
    size_t npartner;
    double *shear;              /* 3 per partner entry, history only */
    double *xhold;              /* 3 ndev, exact only */
    int nfix;
    struct fix_saved *fix;
    /* filled when applied */
    uint64_t atoms_hash;
};

struct restart {
    /* LAMMPS keeps both modes at once: [0] one file per write (root with the
     * step), [1] two files written alternately */
    bigint every[2];
    char *file[3];              /* [0] root with '*', [1] and [2] the pair */
    int toggle;
    struct wbuf wb;             /* scratch of the write in progress */
    unsigned char *filebuf;     /* scratch of the read in progress */
    struct image *loading;      /* being parsed */
    struct image *pending;      /* applied by read_restart, resumed at the next run */
    int ranks_result;           /* several ranks: restart_adopt_ranks's restart_resume level */
    char why[512];              /* ... and why it is not 2 */
};

static void image_free(struct image *im)
{
    if (!im)
        return;
    void *p[] = {im->type_mass, im->devtag, im->ncount, im->partner, im->shear, im->xhold,
                 im->custom, im->pcoef, im->phist};
    if (im->pdata) { /* parsed, not applied: the style's destroy frees it */
        struct pair tmp = {.style = pair_style_find(im->pair_name), .data = im->pdata};
        if (tmp.style && tmp.style->destroy)
            tmp.style->destroy(&tmp);
        else
            free(im->pdata);
    }
    for (size_t i = 0; i < sizeof p / sizeof *p; i++)
        free(p[i]);
#define FREE_FIELD(name, ctype, dev, width, when, life, sect, what) free(im->name);
    ATOM_FIELDS(FREE_FIELD)
#undef FREE_FIELD
    for (int i = 0; i < im->nfix; i++) {
        free(im->fix[i].blob);
        free(im->fix[i].peratom);
    }
    free(im->fix);
    free(im);
}

static struct restart *state(struct gravel *g)
{
    if (!g->restart)
        g->restart = gr_calloc(g, 1, sizeof *g->restart);
    return g->restart;
}

void restart_free(struct gravel *g)
{
    struct restart *r = g->restart;
    if (!r)
        return;
    for (int k = 0; k < 3; k++)
        free(r->file[k]);
    free(r->wb.p);
    free(r->filebuf);
    image_free(r->loading);
    image_free(r->pending);
    free(r);
    g->restart = NULL;
}

/* ---- fingerprints --------------------------------------------------------------- */

/* What the forces of a step depend on besides the atoms and the list: pair
 * style and coefficients, time step, and the fixes in order (an output fix's
 * arguments not: FIX_OUTPUT). */
static uint64_t force_fingerprint(const struct gravel *g)
{
    uint64_t h = FNV_INIT;
    const struct pair *p = g->styles.pair;
    if (p) {
        h = fnv1a(h, p->style->name, strlen(p->style->name) + 1);
        h = fnv1a(h, p->coef, sizeof p->coef);
        h = fnv1a(h, &p->coeff_set, sizeof p->coeff_set);
        size_t n = p->style->state_write ? p->style->state_write(p, PAIR_STATE_COEFF, NULL, 0)
                                         : 0;
        if (n) { /* the style's own coefficients (granular/superellipsoid) */
            unsigned char *b = malloc(n);
            if (b) {
                p->style->state_write(p, PAIR_STATE_COEFF, b, n);
                h = fnv1a(h, b, n);
                free(b);
            }
        }
    }
    h = fnv1a(h, &g->dt, sizeof g->dt);
    h = fnv1a(h, &g->styles.nfix, sizeof g->styles.nfix);
    for (int i = 0; i < g->styles.nfix; i++) {
        const struct fix *f = g->styles.fix[i];
        h = fnv1a(h, f->id, strlen(f->id) + 1);
        h = fnv1a(h, f->style->name, strlen(f->style->name) + 1);
        if (!(f->style->flags & FIX_OUTPUT))
            h = fnv1a(h, &f->arghash, sizeof f->arghash);
    }
    return h;
}


/* ---- sections: each writer beside its reader ------------------------------------------
 *
 * A writer appends its whole section (header included) or nothing (optional
 * sections); a reader parses one section's bytes into the image with bounds
 * checks and returns 0 with a message in err when the values are invalid.
 * The driver (load) then rejects a truncated section or trailing bytes.
 * `seen` has bit id set for every section already read. */

/* What the list writer tells the fixes writer: atoms of the written list,
 * and whether they are the host's of a decomposed run (par_fix_rows). */
struct wctx {
    int ndev, ranks;
};

#define BAD(...)                                                                         \
    do {                                                                                 \
        snprintf(err, errlen, __VA_ARGS__);                                              \
        return 0;                                                                        \
    } while (0)

static void write_info(struct gravel *g, struct wbuf *w, struct wctx *c)
{
    (void)c;
    size_t at = sect_begin(g, w, S_INFO);
    put_str(g, w, GR_VERSION);
    put_i64(g, w, g->step);
    put_i64(g, w, g->laststep_reset);
    put_f64(g, w, g->time);
    put_f64(g, w, g->dt);
    put_i32(g, w, g->dt_set);
    put_i32(g, w, g->eng ? g->eng->single : g->opt.single);
    put_u64(g, w, g->seed_counter);
    sect_end(w, at);
}

static int read_info(struct image *im, struct rbuf *r, unsigned seen, char *err, size_t errlen)
{
    (void)seen;
    get_str(r, im->version, sizeof im->version);
    im->step = get_i64(r);
    im->laststep_reset = get_i64(r);
    im->time = get_f64(r);
    im->dt = get_f64(r);
    im->dt_set = get_i32(r);
    im->single = get_i32(r);
    im->seed_counter = get_u64(r);
    if (!r->bad && (im->step < 0 || !(im->dt > 0) || !isfinite(im->dt) || !isfinite(im->time)))
        BAD("invalid step %lld or time step %g", (long long)im->step, im->dt);
    return 1;
}

static void write_domain(struct gravel *g, struct wbuf *w, struct wctx *c)
{
    (void)c;
    const struct domain *d = &g->dom;
    size_t at = sect_begin(g, w, S_DOMAIN);
    put_i32(g, w, (int32_t)d->units);
    put_i32(g, w, d->dimension);
    for (int q = 0; q < 3; q++)
        for (int s = 0; s < 2; s++)
            put_i32(g, w, d->bnd[q][s]);
    for (int q = 0; q < 3; q++)
        put_i32(g, w, d->periodic[q]);
    const double *vec[] = {d->lo, d->hi, d->minlo, d->minhi, d->small};
    for (int k = 0; k < 5; k++)
        for (int q = 0; q < 3; q++)
            put_f64(g, w, vec[k][q]);
    const struct lattice *l = &d->lat;
    put_i32(g, w, l->style);
    for (int q = 0; q < 3; q++) {
        put_f64(g, w, l->a[q]);
        put_f64(g, w, l->prim[q]);
        put_f64(g, w, l->origin[q]);
    }
    put_i32(g, w, l->nbasis);
    for (int b = 0; b < 8; b++)
        for (int q = 0; q < 3; q++)
            put_f64(g, w, l->basis[b][q]);
    put_i32(g, w, d->triclinic);
    put_f64(g, w, d->xy);
    put_f64(g, w, d->xz);
    put_f64(g, w, d->yz);
    sect_end(w, at);
}

static int read_domain(struct image *im, struct rbuf *r, unsigned seen, char *err, size_t errlen)
{
    (void)seen;
    struct domain *d = &im->dom;
    d->units = (enum units)get_i32(r);
    d->dimension = get_i32(r);
    for (int q = 0; q < 3; q++)
        for (int s = 0; s < 2; s++)
            d->bnd[q][s] = (char)get_i32(r);
    for (int q = 0; q < 3; q++)
        d->periodic[q] = get_i32(r);
    double *vec[] = {d->lo, d->hi, d->minlo, d->minhi, d->small};
    for (int k = 0; k < 5; k++)
        for (int q = 0; q < 3; q++)
            vec[k][q] = get_f64(r);
    struct lattice *l = &d->lat;
    l->style = get_i32(r);
    for (int q = 0; q < 3; q++) {
        l->a[q] = get_f64(r);
        l->prim[q] = get_f64(r);
        l->origin[q] = get_f64(r);
    }
    l->nbasis = get_i32(r);
    for (int b = 0; b < 8; b++)
        for (int q = 0; q < 3; q++)
            l->basis[b][q] = get_f64(r);
    d->triclinic = get_i32(r);
    d->xy = get_f64(r);
    d->xz = get_f64(r);
    d->yz = get_f64(r);
    if (r->bad)
        return 1;
    if ((d->triclinic != 0 && d->triclinic != 1) || !isfinite(d->xy) || !isfinite(d->xz) ||
        !isfinite(d->yz) || (!d->triclinic && (d->xy != 0 || d->xz != 0 || d->yz != 0)))
        BAD("invalid triclinic flag %d or tilt factors %g %g %g", d->triclinic, d->xy, d->xz,
            d->yz);
    if (d->units != UNITS_LJ && d->units != UNITS_SI && d->units != UNITS_CGS)
        BAD("invalid units code %d", (int)d->units);
    if (d->dimension != 2 && d->dimension != 3)
        BAD("invalid dimension %d", d->dimension);
    if (l->nbasis < 0 || l->nbasis > 8)
        BAD("invalid lattice basis count %d", l->nbasis);
    for (int q = 0; q < 3; q++) {
        for (int s = 0; s < 2; s++)
            if (!strchr("pfsm", d->bnd[q][s]) || !d->bnd[q][s])
                BAD("invalid boundary flag in dimension %c", "xyz"[q]);
        if ((d->periodic[q] != 0) != (d->bnd[q][0] == 'p'))
            BAD("inconsistent periodic flag in dimension %c", "xyz"[q]);
        if (!(d->lo[q] < d->hi[q]) || !isfinite(d->lo[q]) || !isfinite(d->hi[q]) ||
            !isfinite(d->minlo[q]) || !isfinite(d->minhi[q]) || !isfinite(d->small[q]))
            BAD("invalid box bounds %g %g in dimension %c", d->lo[q], d->hi[q], "xyz"[q]);
    }
    d->box_exists = 1;
    return 1;
}

static void write_neigh(struct gravel *g, struct wbuf *w, struct wctx *c)
{
    (void)c;
    size_t at = sect_begin(g, w, S_NEIGH);
    const struct neigh_settings *ns = &g->neigh;
    put_f64(g, w, ns->skin);
    int32_t iv[] = {ns->style, ns->every, ns->delay,    ns->check,        ns->once,
                    ns->one,   ns->page,  ns->nexclude, ns->nexclude_type};
    for (size_t k = 0; k < sizeof iv / sizeof *iv; k++)
        put_i32(g, w, iv[k]);
    for (int k = 0; k < 16; k++)
        for (int s = 0; s < 2; s++) {
            put_i32(g, w, ns->exclude_group[k][s]);
            put_i32(g, w, ns->exclude_type[k][s]);
        }
    sect_end(w, at);
}

static int read_neigh(struct image *im, struct rbuf *r, unsigned seen, char *err, size_t errlen)
{
    (void)seen;
    struct neigh_settings *ns = &im->neigh;
    ns->skin = get_f64(r);
    int *iv[] = {&ns->style, &ns->every, &ns->delay,    &ns->check,        &ns->once,
                 &ns->one,   &ns->page,  &ns->nexclude, &ns->nexclude_type};
    for (size_t k = 0; k < sizeof iv / sizeof *iv; k++)
        *iv[k] = get_i32(r);
    for (int k = 0; k < 16; k++)
        for (int s = 0; s < 2; s++) {
            ns->exclude_group[k][s] = get_i32(r);
            ns->exclude_type[k][s] = get_i32(r);
        }
    if (!r->bad && (!(ns->skin >= 0) || !isfinite(ns->skin) || ns->every < 1 || ns->delay < 0 ||
                    ns->nexclude < 0 || ns->nexclude > 16 || ns->nexclude_type < 0 ||
                    ns->nexclude_type > 16))
        BAD("invalid neighbor settings");
    for (int k = 0; k < 16 && !r->bad; k++)
        for (int s = 0; s < 2; s++)
            if (ns->exclude_group[k][s] < 0 || ns->exclude_group[k][s] >= GR_MAXGROUP)
                BAD("invalid neighbor exclusion group");
    return 1;
}

static void write_groups(struct gravel *g, struct wbuf *w, struct wctx *c)
{
    (void)c;
    size_t at = sect_begin(g, w, S_GROUPS);
    put_i32(g, w, g->groups.n);
    for (int k = 0; k < GR_MAXGROUP; k++) {
        put_i32(g, w, g->groups.used[k]);
        put_str(g, w, g->groups.used[k] ? g->groups.name[k] : "");
    }
    sect_end(w, at);
}

static int read_groups(struct image *im, struct rbuf *r, unsigned seen, char *err, size_t errlen)
{
    (void)seen;
    im->groups.n = get_i32(r);
    for (int k = 0; k < GR_MAXGROUP; k++) {
        im->groups.used[k] = get_i32(r);
        get_str(r, im->groups.name[k], GR_NAMELEN);
    }
    if (!r->bad && (im->groups.n < 1 || im->groups.n > GR_MAXGROUP || !im->groups.used[0] ||
                    strcmp(im->groups.name[0], "all")))
        BAD("invalid group table");
    return 1;
}

static void write_types(struct gravel *g, struct wbuf *w, struct wctx *c)
{
    (void)c;
    const struct atoms *a = &g->atoms;
    size_t at = sect_begin(g, w, S_TYPES);
    put_i32(g, w, a->ntypes);
    for (int t = 0; t <= a->ntypes; t++)
        put_f64(g, w, a->type_mass ? a->type_mass[t] : 0.0);
    put_i64(g, w, a->maxtag);
    sect_end(w, at);
}

static int read_types(struct image *im, struct rbuf *r, unsigned seen, char *err, size_t errlen)
{
    (void)seen;
    im->ntypes = get_i32(r);
    if (r->bad)
        return 1;
    if (im->ntypes < 1 || im->ntypes > 1000000)
        BAD("invalid number of atom types %d", im->ntypes);
    im->type_mass = get_array(r, (size_t)im->ntypes + 1, sizeof(double));
    im->maxtag = get_i64(r);
    return 1;
}

/* The per-atom fields of one restart section (atom_fields.h, column sect), in
 * table order: n * width raw host elements each. */
static void put_fields(struct gravel *g, struct wbuf *w, enum atom_field_sect in)
{
    const struct atoms *a = &g->atoms;
    size_t n = (size_t)a->n;
#define PUT_FIELD(name, ctype, dev, width, when, life, sect, what)                             \
    if (sect == in)                                                                           \
        put(g, w, a->name, n * (width) * sizeof(ctype));
    ATOM_FIELDS(PUT_FIELD)
#undef PUT_FIELD
}

static void get_fields(struct image *im, struct rbuf *r, enum atom_field_sect in)
{
    size_t n = (size_t)im->n;
#define GET_FIELD(name, ctype, dev, width, when, life, sect, what)                             \
    if (sect == in)                                                                           \
        im->name = get_array(r, n * (width), sizeof(ctype));
    ATOM_FIELDS(GET_FIELD)
#undef GET_FIELD
}

static void write_atoms(struct gravel *g, struct wbuf *w, struct wctx *c)
{
    (void)c;
    size_t at = sect_begin(g, w, S_ATOMS);
    put_i32(g, w, g->atoms.n);
    put_fields(g, w, FS_ATOMS);
    sect_end(w, at);
}

static int read_atoms(struct image *im, struct rbuf *r, unsigned seen, char *err, size_t errlen)
{
    (void)seen;
    im->n = get_i32(r);
    if (r->bad)
        return 1;
    if (im->n < 0)
        BAD("invalid atom count %d", im->n);
    get_fields(im, r, FS_ATOMS);
    return 1;
}

/* Optional: the molecule IDs (fix property/atom mol) and the molecule
 * exclusions of neigh_modify. */
static void write_molecule(struct gravel *g, struct wbuf *w, struct wctx *c)
{
    (void)c;
    if (!g->atoms.molecule_flag)
        return;
    size_t at = sect_begin(g, w, S_MOLECULE);
    put_i32(g, w, g->atoms.n);
    put_fields(g, w, FS_MOLECULE);
    put_i32(g, w, g->neigh.nexclude_mol); /* neigh_modify exclude molecule/... */
    for (int k = 0; k < 16; k++)
        for (int q = 0; q < 2; q++)
            put_i32(g, w, g->neigh.exclude_mol[k][q]);
    put_i32(g, w, g->atoms.style_molecular); /* absent in files before hybrid styles */
    sect_end(w, at);
}

static int read_molecule(struct image *im, struct rbuf *r, unsigned seen, char *err,
                         size_t errlen)
{
    int nm = get_i32(r);
    if (r->bad)
        return 1;
    if (!(seen >> S_ATOMS & 1u) || nm != im->n)
        BAD("molecule IDs of %d atoms, not the atoms section's %d", nm, im->n);
    get_fields(im, r, FS_MOLECULE);
    struct neigh_settings *ns = &im->neigh;
    ns->nexclude_mol = get_i32(r);
    for (int k = 0; k < 16; k++)
        for (int q = 0; q < 2; q++)
            ns->exclude_mol[k][q] = get_i32(r);
    if (!r->bad && (ns->nexclude_mol < 0 || ns->nexclude_mol > 16))
        BAD("invalid molecule exclusions");
    for (int k = 0; k < 16 && !r->bad; k++)
        if (ns->exclude_mol[k][0] < 0 || ns->exclude_mol[k][0] >= GR_MAXGROUP)
            BAD("invalid molecule exclusion group");
    im->style_molecular = r->off < r->n ? get_i32(r) : 0;
    if (!r->bad && im->style_molecular != 0 && im->style_molecular != 1)
        BAD("invalid atom style flag %d", im->style_molecular);
    return 1;
}

/* Optional: the temperatures and heat flows (fix property/atom temperature
 * heatflow) with the atoms' ATOM_HEAT_* bits. */
static void write_heat(struct gravel *g, struct wbuf *w, struct wctx *c)
{
    (void)c;
    if (!g->atoms.heat_flag)
        return;
    size_t at = sect_begin(g, w, S_HEAT);
    put_i32(g, w, g->atoms.n);
    put_i32(g, w, g->atoms.heat_flag);
    put_fields(g, w, FS_HEAT);
    sect_end(w, at);
}

static int read_heat(struct image *im, struct rbuf *r, unsigned seen, char *err, size_t errlen)
{
    int nh = get_i32(r);
    im->heat_flag = get_i32(r);
    if (r->bad)
        return 1;
    if (!(seen >> S_ATOMS & 1u) || nh != im->n)
        BAD("temperatures of %d atoms, not the atoms section's %d", nh, im->n);
    if (im->heat_flag < 1 || im->heat_flag > ATOM_HEAT_BOTH)
        BAD("invalid heat properties %d", im->heat_flag);
    get_fields(im, r, FS_HEAT);
    return 1;
}

/* Optional: the custom properties, each as name, fix ID, integer flag and
 * columns, then every atom's record (slots doubles, the properties in
 * order; an integer property's values are exact integers). */
static void write_custom(struct gravel *g, struct wbuf *w, struct wctx *c)
{
    (void)c;
    const struct atoms *a = &g->atoms;
    if (!a->cus.n)
        return;
    size_t at = sect_begin(g, w, S_CUSTOM);
    put_i32(g, w, a->n);
    put_i32(g, w, a->cus.n);
    for (int k = 0; k < a->cus.n; k++) {
        put_str(g, w, a->cus.p[k].name);
        put_str(g, w, a->cus.p[k].fix);
        put_i32(g, w, a->cus.p[k].isint);
        put_i32(g, w, a->cus.p[k].cols);
    }
    put(g, w, a->custom, (size_t)a->n * a->cus.slots * sizeof(double));
    sect_end(w, at);
}

static int read_custom(struct image *im, struct rbuf *r, unsigned seen, char *err,
                       size_t errlen)
{
    int nc = get_i32(r), np = get_i32(r);
    if (r->bad)
        return 1;
    if (!(seen >> S_ATOMS & 1u) || nc != im->n)
        BAD("custom properties of %d atoms, not the atoms section's %d", nc, im->n);
    if (np < 1 || np > GR_MAXCUSTOM)
        BAD("invalid number of custom properties %d", np);
    struct atom_custom *cu = &im->cus;
    cu->n = np;
    for (int k = 0; k < np && !r->bad; k++) {
        struct custom_prop *p = &cu->p[k];
        get_str(r, p->name, sizeof p->name);
        get_str(r, p->fix, sizeof p->fix);
        p->isint = get_i32(r);
        p->cols = get_i32(r);
        if (!r->bad && (!custom_name_ok(p->name) || (p->isint != 0 && p->isint != 1) ||
                        p->cols < 0 || p->cols > 1000))
            BAD("invalid custom property %d", k + 1);
        p->slot = cu->slots;
        p->restored = 1;
        cu->slots += custom_width(p);
    }
    im->custom = get_array(r, (size_t)im->n * cu->slots, sizeof(double));
    return 1;
}

/* Optional: the superellipsoid fields (atom_style ellipsoid superellipsoid),
 * as LAMMPS's restart bonus record: shape, quaternion, blockiness, principal
 * moments, with the angular momenta. */
static void write_ellipsoid(struct gravel *g, struct wbuf *w, struct wctx *c)
{
    (void)c;
    if (!g->atoms.ellipsoid_flag)
        return;
    size_t at = sect_begin(g, w, S_ELLIPSOID);
    put_i32(g, w, g->atoms.n);
    put_fields(g, w, FS_ELLIPSOID);
    sect_end(w, at);
}

static int read_ellipsoid(struct image *im, struct rbuf *r, unsigned seen, char *err,
                          size_t errlen)
{
    int ne = get_i32(r);
    if (r->bad)
        return 1;
    if (!(seen >> S_ATOMS & 1u) || ne != im->n)
        BAD("superellipsoids of %d atoms, not the atoms section's %d", ne, im->n);
    get_fields(im, r, FS_ELLIPSOID);
    return 1;
}

static void write_pair(struct gravel *g, struct wbuf *w, struct wctx *c)
{
    (void)c;
    size_t at = sect_begin(g, w, S_PAIR);
    const struct pair *p = g->styles.pair;
    put_i32(g, w, p != NULL);
    if (p) {
        put_str(g, w, p->style->name);
        put_i32(g, w, p->coeff_set);
        put_i32(g, w, PAIR_MAXCOEF);
        for (int k = 0; k < PAIR_MAXCOEF; k++)
            put_f64(g, w, p->coef[k]);
    }
    sect_end(w, at);
}

static int read_pair(struct image *im, struct rbuf *r, unsigned seen, char *err, size_t errlen)
{
    (void)seen;
    im->has_pair = get_i32(r);
    if (im->has_pair) {
        get_str(r, im->pair_name, sizeof im->pair_name);
        im->coeff_set = get_i32(r);
        im->ncoef = get_i32(r);
        if (!r->bad && (im->ncoef < 0 || im->ncoef > PAIR_MAXCOEF))
            BAD("invalid pair coefficient count %d", im->ncoef);
        for (int k = 0; k < im->ncoef; k++)
            im->coef[k] = get_f64(r);
    }
    return 1;
}

/* Optional: the pair style's own state (pair_style.state_write), its
 * coefficients and its contact history, each as u64 length + bytes. */
static void put_pair_part(struct gravel *g, struct wbuf *w, const struct pair *p, int part)
{
    size_t n = p->style->state_write(p, part, NULL, 0);
    unsigned char *b = gr_malloc(g, n + 1);
    if (p->style->state_write(p, part, b, n) != n)
        gr_error(g, "pair %s: restart state size changed while writing", p->style->name);
    put_u64(g, w, n);
    put(g, w, b, n);
    free(b);
}

static void write_pair_state(struct gravel *g, struct wbuf *w, struct wctx *c)
{
    (void)c;
    const struct pair *p = g->styles.pair;
    if (!p || !p->style->state_write || !p->data)
        return;
    size_t at = sect_begin(g, w, S_PAIR_STATE);
    put_str(g, w, p->style->name);
    put_pair_part(g, w, p, PAIR_STATE_COEFF);
    put_pair_part(g, w, p, PAIR_STATE_HISTORY);
    sect_end(w, at);
}

static int read_pair_state(struct image *im, struct rbuf *r, unsigned seen, char *err,
                           size_t errlen)
{
    (void)seen;
    (void)err;
    (void)errlen;
    im->has_pstate = 1;
    get_str(r, im->pstate_name, sizeof im->pstate_name);
    im->npcoef = (size_t)get_u64(r);
    im->pcoef = get_array(r, im->npcoef, 1);
    im->nphist = (size_t)get_u64(r);
    im->phist = get_array(r, im->nphist, 1);
    return 1;
}

/* 1 when the device arrays equal the host arrays in the same order (the
 * device list then describes the host atoms exactly). */
static int device_matches_host(struct gravel *g)
{
    struct engine *e = g->eng;
    const struct atoms *at = &g->atoms;
    int n = at->n;
    if (!e || !e->a.x || e->a.n != n)
        return 0;
    size_t sz = 3 * (size_t)n + 1;
    double *buf = gr_malloc(g, sz * sizeof(double));
    int64_t *tags = gr_malloc(g, ((size_t)n + 1) * sizeof(int64_t));
    eng_read(g, e->a.tag, 0, (size_t)n * sizeof(int64_t), tags);
    int same = !memcmp(tags, at->tag, (size_t)n * sizeof(int64_t));
    const double *host[] = {at->x, at->v, at->f, at->omega, at->torque};
    cl_mem dev[] = {e->a.x, e->a.v, e->a.f, e->a.omega, e->a.torque};
    for (int k = 0; k < 5 && same; k++) {
        if (!dev[k])
            continue; /* no rotation: omega/torque not on the device */
        if (k == 0)
            eng_read_positions(g, &e->a, n, buf);
        else
            eng_read_reals(g, dev[k], 3 * (size_t)n, buf);
        same = !memcmp(buf, host[k], 3 * (size_t)n * sizeof(double));
    }
    free(buf);
    free(tags);
    return same;
}

/* Optional: the device neighbor list in device order with its contact
 * history and, when the device holds the host atoms exactly, the reference
 * positions of the last build. */
static void write_list(struct gravel *g, struct wbuf *w, struct wctx *c)
{
    struct engine *e = g->eng;
    struct nbr_state s;
    int exact = 0;
    c->ndev = 0;
    c->ranks = comm_size() > 1; /* the device holds one rank's atoms: the host's list */
    if (c->ranks ? !par_list_export(g, &s, &exact) : !e || !e->a.x || !nbr_export(g, &s)) {
        if (c->ranks && g->par && g->par->ended)
            gr_warn(g, "write_restart: the atoms changed since the last run on %d MPI ranks: "
                       "the contact history and the fixes' per-atom state are not written",
                    comm_size());
        return;
    }
    int n = s.n;
    int64_t *devtag = gr_malloc(g, ((size_t)n + 1) * sizeof(int64_t));
    if (c->ranks)
        memcpy(devtag, g->atoms.tag, (size_t)n * sizeof(int64_t));
    else
        eng_read(g, e->a.tag, 0, (size_t)n * sizeof(int64_t), devtag);
    if (!c->ranks)
        exact = device_matches_host(g);
    size_t at = sect_begin(g, w, S_LIST);
    put_i32(g, w, exact);
    put_i32(g, w, s.history);
    put_i32(g, w, n);
    put_i32(g, w, s.maxn);
    put_i32(g, w, s.ago);
    put_u64(g, w, force_fingerprint(g));
    put(g, w, devtag, (size_t)n * sizeof(int64_t));
    put(g, w, s.ncount, (size_t)n * sizeof(int));
    for (int i = 0; i < n; i++)
        for (int k = 0; k < s.ncount[i]; k++)
            put_i64(g, w, devtag[s.nlist[(size_t)i * s.maxn + k]]);
    if (s.history)
        for (int i = 0; i < n; i++)
            put(g, w, s.shear + (size_t)s.history * i * s.maxn,
                (size_t)s.history * s.ncount[i] * sizeof(double));
    if (exact)
        put(g, w, s.xhold, 3 * (size_t)n * sizeof(double));
    sect_end(w, at);
    nbr_state_free(&s);
    free(devtag);
    c->ndev = n;
}

static int read_list(struct image *im, struct rbuf *r, unsigned seen, char *err, size_t errlen)
{
    if (!(seen >> S_ATOMS & 1u))
        BAD("neighbor list section before the atoms");
    im->has_list = 1;
    im->exact = get_i32(r);
    im->history = get_i32(r);
    im->ndev = get_i32(r);
    im->maxn = get_i32(r);
    im->ago = get_i32(r);
    im->fingerprint = get_u64(r);
    if (r->bad)
        return 1;
    /* a list never holds more slots per atom than atoms (+ its growth margin) */
    if (im->ndev < 0 || im->maxn < 0 || im->ago < 0 ||
        (int64_t)im->maxn > 64 + 2 * (int64_t)im->ndev)
        BAD("invalid neighbor list header");
    size_t n = (size_t)im->ndev;
    im->devtag = get_array(r, n, sizeof(int64_t));
    im->ncount = get_array(r, n, sizeof(int));
    if (r->bad)
        return 1;
    size_t tot = 0;
    for (size_t i = 0; i < n; i++) {
        if (im->ncount[i] < 0 || im->ncount[i] > im->maxn)
            BAD("invalid neighbor count %d (capacity %d)", im->ncount[i], im->maxn);
        tot += (size_t)im->ncount[i];
    }
    im->npartner = tot;
    im->partner = get_array(r, tot, sizeof(int64_t));
    if (im->history == 1) /* files before pair granular: 1 = 3 REAL per contact */
        im->history = 3;
    if (im->history < 0 || im->history > GR_HIST_MAX)
        BAD("invalid contact history width %d", im->history);
    if (im->history)
        im->shear = get_array(r, (size_t)im->history * tot, sizeof(double));
    if (im->exact) {
        if (im->ndev != im->n || (im->n && memcmp(im->devtag, im->tag, n * sizeof(int64_t))))
            BAD("neighbor list marked exact does not match the atoms");
        im->xhold = get_array(r, 3 * n, sizeof(double));
    }
    return 1;
}

/* Fixes: ID, style, global state (write_restart hook) and, with a list of
 * c->ndev atoms written, the engine-managed per-atom state in device order. */
static void write_fixes(struct gravel *g, struct wbuf *w, struct wctx *c)
{
    struct engine *e = g->eng;
    int ndev = c->ndev;
    size_t at = sect_begin(g, w, S_FIXES);
    put_i32(g, w, g->styles.nfix);
    for (int i = 0; i < g->styles.nfix; i++) {
        struct fix *f = g->styles.fix[i];
        put_str(g, w, f->id);
        put_str(g, w, f->style->name);
        put_u64(g, w, f->arghash);
        size_t len = f->style->write_restart ? f->style->write_restart(g, f, NULL, 0) : 0;
        put_u64(g, w, len);
        if (len) {
            unsigned char *b = gr_malloc(g, len);
            size_t got = f->style->write_restart(g, f, b, len);
            put(g, w, b, len);
            free(b);
            if (got != len)
                gr_error(g, "fix %s: restart state size changed while writing", f->id);
        }
        const unsigned char *saved = c->ranks ? par_fix_rows(g, f) : NULL;
        int rows = ndev && f->peratom && f->peratom_bytes && (saved || !c->ranks) ? ndev : 0;
        put_u32(g, w, rows ? (uint32_t)f->peratom_bytes : 0);
        put_u32(g, w, e ? (uint32_t)e->rsz : 0);
        put_i32(g, w, rows);
        if (rows && saved) {
            put(g, w, saved, (size_t)rows * f->peratom_bytes);
        } else if (rows) {
            size_t bytes = (size_t)rows * f->peratom_bytes;
            unsigned char *b = gr_malloc(g, bytes + 1);
            eng_read(g, f->peratom, 0, bytes, b);
            put(g, w, b, bytes);
            free(b);
        }
    }
    sect_end(w, at);
}

static int read_fixes(struct image *im, struct rbuf *r, unsigned seen, char *err, size_t errlen)
{
    (void)seen;
    int nfix = get_i32(r);
    if (r->bad)
        return 1;
    if (nfix < 0 || nfix > 100000)
        BAD("invalid fix count %d", nfix);
    im->fix = calloc((size_t)nfix + 1, sizeof *im->fix);
    if (!im->fix)
        BAD("out of memory");
    im->nfix = nfix;
    for (int i = 0; i < nfix && !r->bad; i++) {
        struct fix_saved *fs = &im->fix[i];
        get_str(r, fs->id, sizeof fs->id);
        get_str(r, fs->style, sizeof fs->style);
        fs->arghash = get_u64(r);
        uint64_t len = get_u64(r);
        if (r->bad)
            break;
        if (len > r->n - r->off)
            BAD("fix %s: state length beyond the section", fs->id);
        fs->bloblen = (size_t)len;
        fs->blob = get_array(r, fs->bloblen, 1);
        fs->peratom_bytes = get_u32(r);
        fs->rsz = get_u32(r);
        fs->nrows = get_i32(r);
        if (r->bad)
            break;
        if (fs->nrows && (fs->nrows != im->ndev || !im->has_list))
            BAD("fix %s: per-atom state of %d atoms does not match the list", fs->id, fs->nrows);
        if (fs->peratom_bytes % 4 || fs->peratom_bytes > 1024)
            BAD("fix %s: invalid per-atom state size %u", fs->id, fs->peratom_bytes);
        fs->peratom = get_array(r, (size_t)fs->nrows, fs->peratom_bytes);
    }
    return 1;
}

/* The sections in file order (the writer's order; a reader accepts any
 * order, each section once, the list after the atoms). */
static const struct section {
    enum sect id;
    const char *name;
    int required;
    void (*write)(struct gravel *g, struct wbuf *w, struct wctx *c);
    int (*read)(struct image *im, struct rbuf *r, unsigned seen, char *err, size_t errlen);
} sections[] = {
    {S_INFO, "info", 1, write_info, read_info},
    {S_DOMAIN, "domain", 1, write_domain, read_domain},
    {S_NEIGH, "neighbor", 1, write_neigh, read_neigh},
    {S_GROUPS, "groups", 1, write_groups, read_groups},
    {S_TYPES, "types", 1, write_types, read_types},
    {S_ATOMS, "atoms", 1, write_atoms, read_atoms},
    {S_MOLECULE, "molecule IDs", 0, write_molecule, read_molecule},
    {S_HEAT, "temperatures", 0, write_heat, read_heat},
    {S_CUSTOM, "custom properties", 0, write_custom, read_custom},
    {S_ELLIPSOID, "superellipsoids", 0, write_ellipsoid, read_ellipsoid},
    {S_PAIR, "pair", 1, write_pair, read_pair},
    {S_PAIR_STATE, "pair state", 0, write_pair_state, read_pair_state},
    {S_LIST, "neighbor list", 0, write_list, read_list},
    {S_FIXES, "fixes", 1, write_fixes, read_fixes},
};
enum { NSECTION = sizeof sections / sizeof *sections };

static const struct section *section_of(uint32_t id)
{
    for (int k = 0; k < NSECTION; k++)
        if (sections[k].id == id)
            return &sections[k];
    return NULL;
}

/* Parse one section's bytes (r) into im: 1, or 0 with the reason in err. */
static int parse_section(struct image *im, uint32_t id, struct rbuf *r, unsigned seen, char *err,
                         size_t errlen)
{
    const struct section *s = section_of(id);
    if (!s)
        BAD("unknown section id %u", id);
    if (!s->read(im, r, seen, err, errlen))
        return 0;
    if (r->bad)
        BAD("%s section is truncated", s->name);
    if (r->off != r->n)
        BAD("%s section has %zu unexpected trailing bytes", s->name, r->n - r->off);
    return 1;
}

/* ---- writing ---------------------------------------------------------------------- */

static void build_payload(struct gravel *g, struct wbuf *w)
{
    struct wctx c = {0};
    for (int k = 0; k < NSECTION; k++)
        sections[k].write(g, w, &c);
}

void restart_write(struct gravel *g, const char *path)
{
    struct restart *r = state(g);
    if (g->eng && g->eng->active)
        run_sync_host(g);
    free(r->wb.p);
    memset(&r->wb, 0, sizeof r->wb);
    struct wbuf *w = &r->wb;
    /* header with the length and hash filled in after the payload */
    put(g, w, RESTART_MAGIC, 8);
    put_u32(g, w, RESTART_ENDIAN_MARKER);
    put_u32(g, w, RESTART_FORMAT_VERSION);
    put_u64(g, w, 0);
    put_u64(g, w, 0);
    build_payload(g, w);
    uint64_t len = (uint64_t)(w->n - RESTART_HEADER_BYTES);
    uint64_t hash = fnv1a(FNV_INIT, w->p + RESTART_HEADER_BYTES, (size_t)len);
    memcpy(w->p + 16, &len, 8);
    memcpy(w->p + 24, &hash, 8);

    char suffix[32];
    snprintf(suffix, sizeof suffix, ".tmp.%ld", (long)getpid());
    struct ofile o;
    int err = of_open(&o, path, suffix, OF_TRUNC);
    if (err)
        gr_error(g, "cannot open restart file '%.200s' for writing: %s", path, strerror(err));
    fwrite(w->p, 1, w->n, o.fp);
    int through = of_through(&o);
    if ((err = of_commit(&o, OF_SYNC)) != 0)
        gr_error(g, "writing restart file '%.200s' failed: %s%s", path, strerror(err),
                 through ? "" : " (the previous file, if any, is unchanged)");
    free(r->wb.p);
    memset(&r->wb, 0, sizeof r->wb);
}

/* name with `*` replaced by the step (LAMMPS) into out. */
static void expand_star(struct gravel *g, const char *name, char *out, size_t len)
{
    const char *star = strchr(name, '*');
    int w = star ? snprintf(out, len, "%.*s%lld%s", (int)(star - name), name,
                            (long long)g->step, star + 1)
                 : snprintf(out, len, "%s", name);
    if (w < 0 || (size_t)w >= len)
        gr_error(g, "restart file name too long");
}

static void check_name(struct gravel *g, const char *name)
{
    if (!name[0])
        gr_error(g, "empty restart file name");
    if (strchr(name, '%'))
        gr_error(g, "'%%' in restart file name '%.200s': per-processor restart files are not "
                    "supported (one process writes one file)", name);
    const char *star = strchr(name, '*');
    if (star && strchr(star + 1, '*'))
        gr_error(g, "restart file name '%.200s' has more than one '*'", name);
}

/* write_restart file */
void cmd_write_restart(struct gravel *g, int argc, char **argv)
{
    if (argc > 1) {
        if (!strcmp(argv[1], "fileper") || !strcmp(argv[1], "nfile"))
            gr_error(g, "keyword '%s' is not supported (one process writes one file)", argv[1]);
        gr_error(g, "unknown keyword '%.64s' (write_restart takes only a file name)", argv[1]);
    }
    check_name(g, argv[0]);
    char path[4096];
    expand_star(g, argv[0], path, sizeof path);
    restart_write(g, path);
    gr_print(g, "Restart file %s written at step %lld (%d atoms)\n", path, (long long)g->step,
             g->atoms.n);
}

/* restart 0 | restart N root | restart N file1 file2 */
void cmd_restart(struct gravel *g, int argc, char **argv)
{
    bigint n = arg_bigint(g, argv[0], "restart interval N");
    if (n < 0)
        gr_error(g, "restart interval must be >= 0, got %lld", (long long)n);
    if (n == 0) {
        if (argc > 1)
            gr_error(g, "restart 0 takes no file names");
        if (g->restart)
            g->restart->every[0] = g->restart->every[1] = 0;
        return;
    }
    if (argc < 2)
        gr_error(g, "restart %lld needs a file name (restart N root or restart N file1 file2)",
                 (long long)n);
    if (argc > 3) {
        if (!strcmp(argv[argc - 2], "fileper") || !strcmp(argv[argc - 2], "nfile"))
            gr_error(g, "keyword '%s' is not supported (one process writes one file)",
                     argv[argc - 2]);
        gr_error(g, "too many arguments: restart N root, or restart N file1 file2");
    }
    for (int i = 1; i < argc; i++)
        check_name(g, argv[i]);
    if (argc == 3 && !strcmp(argv[1], argv[2]))
        gr_error(g, "the two restart files must differ, got '%.200s' twice", argv[1]);
    struct restart *r = state(g);
    if (argc == 2) {
        /* LAMMPS: without '*' the step is appended as root.STEP */
        size_t len = strlen(argv[1]) + 3;
        char *root = gr_malloc(g, len);
        snprintf(root, len, strchr(argv[1], '*') ? "%s" : "%s.*", argv[1]);
        free(r->file[0]);
        r->file[0] = root;
        r->every[0] = n;
    } else {
        char *f1 = gr_strdup(g, argv[1]);
        free(r->file[1]);
        r->file[1] = f1;
        char *f2 = gr_strdup(g, argv[2]);
        free(r->file[2]);
        r->file[2] = f2;
        r->every[1] = n;
        r->toggle = 0;
    }
}

int restart_due(const struct gravel *g, bigint step)
{
    const struct restart *r = g->restart;
    return r && ((r->every[0] > 0 && step % r->every[0] == 0) ||
                 (r->every[1] > 0 && step % r->every[1] == 0));
}

void restart_step(struct gravel *g)
{
    struct restart *r = g->restart;
    if (!restart_due(g, g->step))
        return;
    par_snapshot_begin(g); /* several ranks: every rank's state on the host */
    char path[4096];
    if (r->every[0] > 0 && g->step % r->every[0] == 0) {
        expand_star(g, r->file[0], path, sizeof path);
        restart_write(g, path);
    }
    if (r->every[1] > 0 && g->step % r->every[1] == 0) {
        snprintf(path, sizeof path, "%s", r->file[1 + r->toggle]);
        r->toggle ^= 1;
        restart_write(g, path);
    }
    par_snapshot_end(g);
}

/* ---- reading ------------------------------------------------------------------------ */

static int cmp_i64(const void *a, const void *b)
{
    int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

/* Cross-section checks of a fully parsed image. */
static int validate(struct image *im, char *err, size_t errlen)
{
    if (im->has_pair && !pair_style_find(im->pair_name))
        BAD("pair style '%s' of the file is not in this build", im->pair_name);
    if (im->has_pstate) {
        const struct pair_style *st = pair_style_find(im->pstate_name);
        if (!im->has_pair || strcmp(im->pstate_name, im->pair_name))
            BAD("pair state of style '%s', not the pair section's '%s'", im->pstate_name,
                im->has_pair ? im->pair_name : "none");
        if (!st->state_read)
            BAD("pair style '%s' of this build keeps no restart state", im->pstate_name);
        char why[200] = "";
        im->pdata = st->state_read(im->pcoef, im->npcoef, im->phist, im->nphist, why,
                                   sizeof why);
        if (!im->pdata)
            BAD("%s", why);
    }
    for (int i = 0; i < im->n; i++) {
        if (im->tag[i] < 1 || im->tag[i] > im->maxtag)
            BAD("atom tag %lld outside 1..%lld", (long long)im->tag[i], (long long)im->maxtag);
        if (im->type[i] < 1 || im->type[i] > im->ntypes)
            BAD("atom %lld has type %d outside 1..%d", (long long)im->tag[i], im->type[i],
                im->ntypes);
        if (!(im->mask[i] & 1u))
            BAD("atom %lld is not in group all", (long long)im->tag[i]);
        for (int k = 1; k < GR_MAXGROUP; k++)
            if ((im->mask[i] >> k & 1u) && !im->groups.used[k])
                BAD("atom %lld is in an undefined group", (long long)im->tag[i]);
    }
    int64_t *t = malloc(((size_t)im->n + 1) * sizeof *t);
    if (!t)
        BAD("out of memory");
    memcpy(t, im->tag, (size_t)im->n * sizeof *t);
    qsort(t, (size_t)im->n, sizeof *t, cmp_i64);
    for (int i = 1; i < im->n; i++)
        if (t[i] == t[i - 1]) {
            long long dup = (long long)t[i];
            free(t);
            BAD("duplicate atom tag %lld", dup);
        }
    free(t);
    return 1;
}

/* Read and check the whole file into r->loading; on any failure free it and
 * raise a clear error naming the file. */
static void load(struct gravel *g, const char *path)
{
    struct restart *r = state(g);
    free(r->filebuf);
    r->filebuf = NULL;
    image_free(r->loading);
    r->loading = NULL;
    /* a regular file only (a FIFO would block, a directory has no size); the
     * header is read and checked before the payload, whose length must be
     * the file's own: a corrupt length never sizes an allocation */
    const char *why;
    FILE *fp = fio_open_read(path, 0, &why);
    if (!fp)
        gr_error(g, "cannot open restart file '%.200s': %s", path, why);
    struct stat fst;
    if (fstat(fileno(fp), &fst) != 0) {
        int e = errno;
        fclose(fp);
        gr_error(g, "cannot read restart file '%.200s': %s", path, strerror(e));
    }
    uint64_t size = (uint64_t)fst.st_size;
    unsigned char b[RESTART_HEADER_BYTES];
    size_t hgot = fread(b, 1, sizeof b, fp);
    if (hgot < sizeof b && ferror(fp)) {
        int e = errno ? errno : EIO;
        fclose(fp);
        gr_error(g, "reading restart file '%.200s' failed: %s", path, strerror(e));
    }
    if (hgot < RESTART_HEADER_BYTES || memcmp(b, RESTART_MAGIC, 8)) {
        fclose(fp);
        gr_error(g, "'%.200s' is not a gravel restart file (%s)", path,
                 hgot < 8                        ? "too short"
                 : memcmp(b, RESTART_MAGIC, 8) ? "no GRAVELRS signature"
                                               : "truncated header");
    }
    uint32_t marker, version;
    uint64_t len, hash;
    memcpy(&marker, b + 8, 4);
    memcpy(&version, b + 12, 4);
    memcpy(&len, b + 16, 8);
    memcpy(&hash, b + 24, 8);
    if (marker != RESTART_ENDIAN_MARKER) {
        fclose(fp);
        if (marker == __builtin_bswap32(RESTART_ENDIAN_MARKER))
            gr_error(g, "restart file '%.200s' was written on a machine of the other byte order",
                     path);
        gr_error(g, "restart file '%.200s' has an invalid byte-order marker 0x%08x (corrupted)",
                 path, marker);
    }
    if (version != RESTART_FORMAT_VERSION) {
        fclose(fp);
        if (version < RESTART_FORMAT_VERSION)
            gr_error(g, "restart file '%.200s' has format version %u, older than the version %u "
                        "this gravel (%s) reads; write it again with the gravel that made it "
                        "(or with write_data)", path, version, RESTART_FORMAT_VERSION, GR_VERSION);
        gr_error(g, "restart file '%.200s' has format version %u; this gravel (%s) reads "
                    "version %u", path, version, GR_VERSION, RESTART_FORMAT_VERSION);
    }
    uint64_t have = size >= RESTART_HEADER_BYTES ? size - RESTART_HEADER_BYTES : 0;
    if (len != have) {
        fclose(fp);
        gr_error(g, "restart file '%.200s' is %s: the header announces %llu bytes of data, the "
                    "file holds %llu", path, len > have ? "truncated" : "corrupted (too long)",
                 (unsigned long long)len, (unsigned long long)have);
    }
    if (len > (uint64_t)SIZE_MAX - 1 || !(r->filebuf = malloc((size_t)len + 1))) {
        fclose(fp);
        gr_error(g, "restart file '%.200s' of %llu bytes does not fit in memory", path,
                 (unsigned long long)size);
    }
    size_t got = fread(r->filebuf, 1, (size_t)len, fp);
    int rerr = ferror(fp) ? (errno ? errno : EIO) : 0;
    fclose(fp);
    if (got != (size_t)len) {
        free(r->filebuf);
        r->filebuf = NULL;
        if (rerr)
            gr_error(g, "reading restart file '%.200s' failed: %s", path, strerror(rerr));
        gr_error(g, "restart file '%.200s' is truncated: it shrank while being read", path);
    }
    const unsigned char *pl = r->filebuf;
    if (fnv1a(FNV_INIT, pl, (size_t)len) != hash)
        gr_error(g, "restart file '%.200s' is corrupted (checksum mismatch)", path);

    struct image *im = calloc(1, sizeof *im);
    if (!im)
        gr_error(g, "out of memory reading restart file '%.200s'", path);
    r->loading = im;
    char err[300] = "";
    struct rbuf all = {pl, (size_t)len, 0, 0};
    unsigned seen = 0;
    while (all.off < all.n && !err[0]) {
        uint32_t id = get_u32(&all);
        uint32_t zero = get_u32(&all);
        uint64_t slen = get_u64(&all);
        if (all.bad || zero != 0 || slen > all.n - all.off) {
            snprintf(err, sizeof err, "bad section header at byte %zu",
                     all.off + RESTART_HEADER_BYTES);
            break;
        }
        if (section_of(id) && (seen >> id & 1u)) {
            snprintf(err, sizeof err, "duplicate %s section", section_of(id)->name);
            break;
        }
        struct rbuf s = {all.p + all.off, (size_t)slen, 0, 0};
        if (parse_section(im, id, &s, seen, err, sizeof err))
            seen |= 1u << id;
        all.off += (size_t)slen;
    }
    for (int k = 0; k < NSECTION && !err[0]; k++)
        if (sections[k].required && !(seen >> sections[k].id & 1u))
            snprintf(err, sizeof err, "the %s section is missing", sections[k].name);
    if (!err[0])
        validate(im, err, sizeof err);
    free(r->filebuf);
    r->filebuf = NULL;
    if (err[0]) {
        image_free(im);
        r->loading = NULL;
        gr_error(g, "restart file '%.200s' is invalid: %s", path, err);
    }
}

/* read_restart with `*`: the matching file with the largest step (LAMMPS). */
static void resolve_star(struct gravel *g, const char *pattern, char *out, size_t outlen)
{
    const char *star = strchr(pattern, '*');
    const char *slash = strrchr(pattern, '/');
    if (slash && slash > star)
        gr_error(g, "'*' in a directory name is not supported: '%.200s'", pattern);
    char dir[4096] = ".";
    const char *base = pattern;
    if (slash) {
        snprintf(dir, sizeof dir, "%.*s", (int)(slash - pattern), pattern);
        if (!dir[0])
            snprintf(dir, sizeof dir, "/");
        base = slash + 1;
    }
    size_t pre = (size_t)(star - base);
    const char *suf = star + 1;
    size_t slen = strlen(suf);
    DIR *dp = opendir(dir);
    if (!dp)
        gr_error(g, "cannot list directory '%.200s' for '%.200s': %s", dir, pattern,
                 strerror(errno));
    long long best = -1;
    struct dirent *de;
    while ((de = readdir(dp))) {
        const char *nm = de->d_name;
        size_t nl = strlen(nm);
        if (nl <= pre + slen || strncmp(nm, base, pre) || strcmp(nm + nl - slen, suf))
            continue;
        long long v = 0;
        int ok = 1;
        for (size_t i = pre; i < nl - slen; i++) {
            if (nm[i] < '0' || nm[i] > '9' || v > (1LL << 58)) {
                ok = 0;
                break;
            }
            v = 10 * v + (nm[i] - '0');
        }
        if (ok && v > best)
            best = v;
    }
    closedir(dp);
    if (best < 0)
        gr_error(g, "no restart file matches '%.200s'", pattern);
    snprintf(out, outlen, "%.*s%lld%s", (int)(star - pattern), pattern, best, suf);
}

/* read_restart file: verify, then apply. */
void cmd_read_restart(struct gravel *g, int argc, char **argv)
{
    if (argc > 1) {
        if (!strcmp(argv[1], "remap"))
            gr_error(g, "keyword 'remap' is not needed: atoms are kept as written");
        gr_error(g, "unknown keyword '%.64s' (read_restart takes only a file name)", argv[1]);
    }
    char path[4096];
    if (strchr(argv[0], '%'))
        gr_error(g, "'%%' in restart file name '%.200s': per-processor restart files are not "
                    "supported", argv[0]);
    if (strchr(argv[0], '*'))
        resolve_star(g, argv[0], path, sizeof path);
    else
        snprintf(path, sizeof path, "%s", argv[0]);
    load(g, path);
    struct restart *r = g->restart;
    struct image *im = r->loading;

    /* apply: nothing below can fail on the file's content */
    g->dom = im->dom;
    if (!g->thermo.norm_set) /* as the units command: thermo normalization follows units */
        g->thermo.norm = g->dom.units == UNITS_LJ;
    g->neigh = im->neigh;
    g->groups = im->groups;
    g->step = im->step;
    g->laststep_reset = im->laststep_reset;
    g->time = im->time;
    g->dt = im->dt;
    g->dt_set = im->dt_set;
    g->seed_counter = im->seed_counter;
    struct atoms *a = &g->atoms;
    atoms_set_ntypes(g, im->ntypes);
    memcpy(a->type_mass, im->type_mass, ((size_t)im->ntypes + 1) * sizeof(double));
    a->n = 0;
    if (im->cus.n || a->cus.n) { /* the file's custom properties; ours it lacks stay, zero */
        struct atom_custom to = im->cus;
        int from[GR_MAXCUSTOM];
        for (int k = 0; k < to.n; k++) {
            int o = custom_find(a, to.p[k].name);
            from[k] = -1;
            if (o >= 0 && !strcmp(a->cus.p[o].fix, to.p[k].fix) &&
                a->cus.p[o].isint == to.p[k].isint && a->cus.p[o].cols == to.p[k].cols)
                to.p[k].restored = 0; /* its fix is defined already */
        }
        for (int k = 0; k < a->cus.n; k++)
            if (custom_find_in(&to, a->cus.p[k].name) < 0 && to.n < GR_MAXCUSTOM) {
                to.p[to.n] = a->cus.p[k];
                to.p[to.n].slot = to.slots;
                to.slots += custom_width(&to.p[to.n]);
                from[to.n++] = -1;
            }
        atoms_custom_relayout(g, &to, from);
    }
    atoms_reserve(g, im->n);
    size_t n = (size_t)im->n;
    if (im->custom && n) /* the file's properties are the layout's first slots */
        for (size_t i = 0; i < n; i++)
            memcpy(a->custom + i * a->cus.slots, im->custom + i * im->cus.slots,
                   (size_t)im->cus.slots * sizeof(double));
    /* every field the file holds (an optional section's may be absent) */
#define APPLY_FIELD(name, ctype, dev, width, when, life, sect, what)                           \
    if (im->name)                                                                             \
        memcpy(a->name, im->name, n * (width) * sizeof(ctype));
    ATOM_FIELDS(APPLY_FIELD)
#undef APPLY_FIELD
    a->molecule_flag = im->mol != NULL; /* fix property/atom mol keeps them */
    a->style_molecular = im->mol != NULL && im->style_molecular;
    a->heat_flag = im->temperature ? im->heat_flag : 0; /* ... temperature heatflow */
    a->ellipsoid_flag = im->shape != NULL; /* atom_style ellipsoid superellipsoid */
    a->n = im->n;
    a->maxtag = im->maxtag;
    pair_free(g);
    if (im->has_pair) {
        struct pair *p = gr_calloc(g, 1, sizeof *p);
        p->style = pair_style_find(im->pair_name);
        memcpy(p->coef, im->coef, (size_t)im->ncoef * sizeof(double));
        p->coeff_set = im->coeff_set;
        p->data = im->pdata; /* the style's own state (section 14), or none */
        im->pdata = NULL;
        g->styles.pair = p;
    }
    im->atoms_hash = atoms_fingerprint(&g->atoms);
    image_free(r->pending);
    r->pending = im;
    r->loading = NULL;
    if (im->single != g->opt.single && im->has_list)
        gr_warn(g, "restart file written in %s precision, running in %s: the continuation "
                   "is not bitwise exact", im->single ? "single" : "double",
                g->opt.single ? "single" : "double");
    gr_print(g, "Reading restart file %s (written by gravel %s at step %lld)\n  %d atoms, %d "
                "atom types%s%s\n", path, im->version, (long long)im->step, im->n, im->ntypes,
             im->has_pair ? ", pair style " : "", im->has_pair ? im->pair_name : "");
    if (im->has_list) {
        size_t nshear = 0;
        for (size_t k = 0; im->history && k < im->npartner; k++)
            for (int d = 0; d < im->history; d++)
                if (im->shear[(size_t)im->history * k + d] != 0) {
                    nshear++;
                    break;
                }
        gr_print(g, "  %zu neighbor entries, %zu with contact history; state of %d fix(es)%s\n",
                 im->npartner, nshear, im->nfix, im->exact ? "; exact continuation data" : "");
    }
}

/* ---- resuming at the next run --------------------------------------------------------- */

struct tagidx {
    int64_t tag;
    int idx;
};
static int cmp_tagidx(const void *a, const void *b)
{
    return cmp_i64(&((const struct tagidx *)a)->tag, &((const struct tagidx *)b)->tag);
}
static int find_idx(const struct tagidx *map, int n, int64_t tag)
{
    struct tagidx key = {tag, 0};
    const struct tagidx *hit = bsearch(&key, map, (size_t)n, sizeof *map, cmp_tagidx);
    return hit ? hit->idx : -1;
}

/* Name of group index k for messages (the groups are the current ones:
 * read_restart restored the writer's). */
static const char *gname(const struct gravel *g, int k)
{
    return k >= 0 && k < GR_MAXGROUP && g->groups.used[k] ? g->groups.name[k] : "?";
}

/* 1 when the exclusion lists hold the same unordered pairs, in any order. */
static int same_pairs(const int a[16][2], int na, const int b[16][2], int nb)
{
    if (na != nb)
        return 0;
    for (int i = 0; i < na; i++) {
        int found = 0;
        for (int k = 0; k < nb && !found; k++)
            found = (a[i][0] == b[k][0] && a[i][1] == b[k][1]) ||
                    (a[i][0] == b[k][1] && a[i][1] == b[k][0]);
        if (!found)
            return 0;
    }
    return 1;
}

static void pairs_text(const struct gravel *g, const int p[16][2], int n, int group, char *out,
                       size_t len)
{
    size_t o = 0;
    out[0] = '\0';
    if (!n)
        snprintf(out, len, "none");
    for (int k = 0; k < n && o < len; k++) {
        int w = group ? snprintf(out + o, len - o, "%s%s %s", k ? ", " : "", gname(g, p[k][0]),
                                 gname(g, p[k][1]))
                      : snprintf(out + o, len - o, "%s%d %d", k ? ", " : "", p[k][0], p[k][1]);
        o += w > 0 ? (size_t)w : 0;
    }
}

/* The first neighbor setting that differs between now (a) and the file (b),
 * written into why as "setting now (file: value)"; 0 when all are equal.
 * Every setting that can change the list or its build steps counts. */
static int neigh_diff(const struct gravel *g, const struct neigh_settings *a,
                      const struct neigh_settings *b, char *why, size_t len)
{
    const char *yn[] = {"no", "yes"};
    if (a->skin != b->skin)
        return snprintf(why, len, "neighbor skin %.15g (file: %.15g)", a->skin, b->skin) > 0;
    if (a->style != b->style)
        return snprintf(why, len, "neighbor style %s (file: %s)",
                        a->style == NEIGH_MULTI ? "multi" : "bin",
                        b->style == NEIGH_MULTI ? "multi" : "bin") > 0;
    struct { const char *kw; int now, was, yesno; } iv[] = {
        {"every", a->every, b->every, 0}, {"delay", a->delay, b->delay, 0},
        {"check", a->check, b->check, 1}, {"once", a->once, b->once, 1},
        {"one", a->one, b->one, 0},       {"page", a->page, b->page, 0}};
    for (size_t k = 0; k < sizeof iv / sizeof *iv; k++)
        if (iv[k].now != iv[k].was) {
            if (iv[k].yesno)
                return snprintf(why, len, "neigh_modify %s %s (file: %s)", iv[k].kw,
                                yn[iv[k].now != 0], yn[iv[k].was != 0]) > 0;
            return snprintf(why, len, "neigh_modify %s %d (file: %d)", iv[k].kw, iv[k].now,
                            iv[k].was) > 0;
        }
    char t1[200], t2[200];
    if (!same_pairs(a->exclude_group, a->nexclude, b->exclude_group, b->nexclude)) {
        pairs_text(g, a->exclude_group, a->nexclude, 1, t1, sizeof t1);
        pairs_text(g, b->exclude_group, b->nexclude, 1, t2, sizeof t2);
        return snprintf(why, len, "neigh_modify exclude group: %s (file: %s)", t1, t2) > 0;
    }
    if (!same_pairs(a->exclude_type, a->nexclude_type, b->exclude_type, b->nexclude_type)) {
        pairs_text(g, a->exclude_type, a->nexclude_type, 0, t1, sizeof t1);
        pairs_text(g, b->exclude_type, b->nexclude_type, 0, t2, sizeof t2);
        return snprintf(why, len, "neigh_modify exclude type: %s (file: %s)", t1, t2) > 0;
    }
    return 0;
}

/* Why the written list cannot be continued exactly, into why; 0 when it can.
 * Checked in this order: the file's exact data, the atoms, the neighbor
 * settings, the box, the precision, the contact history. */
static int list_diff(struct gravel *g, const struct image *im, int n, char *why, size_t len)
{
    struct engine *e = g->eng;
    if (!im->exact)
        return snprintf(why, len, "the file holds no exact continuation data: the atoms were "
                                  "changed after the last run before write_restart") > 0;
    if (n != im->n)
        return snprintf(why, len, "%d atoms (file: %d)", n, im->n) > 0;
    if (atoms_fingerprint(&g->atoms) != im->atoms_hash)
        return snprintf(why, len, "per-atom values were changed after read_restart") > 0;
    if (neigh_diff(g, &g->neigh, &im->neigh, why, len))
        return 1;
    if (memcmp(g->dom.lo, im->dom.lo, sizeof g->dom.lo) ||
        memcmp(g->dom.hi, im->dom.hi, sizeof g->dom.hi) || g->dom.triclinic != im->dom.triclinic ||
        g->dom.xy != im->dom.xy || g->dom.xz != im->dom.xz || g->dom.yz != im->dom.yz)
        return snprintf(why, len, "box bounds") > 0;
    if (e->single != im->single)
        return snprintf(why, len, "%s precision (file: %s)", e->single ? "single" : "double",
                        im->single ? "single" : "double") > 0;
    int hw = e->history ? e->hist_n : 0; /* REALs of history per contact */
    if (hw != im->history)
        return snprintf(why, len, "contact history of %d REAL per contact (file: %d)", hw,
                        im->history) > 0;
    return 0;
}

/* The first force setting (force_fingerprint) that differs from the
 * writer's, into why; 0 when none does. */
static int force_diff(const struct gravel *g, const struct image *im, char *why, size_t len)
{
    const struct pair *p = g->styles.pair;
    if (!p != !im->has_pair || (p && strcmp(p->style->name, im->pair_name)))
        return snprintf(why, len, "pair style %s (file: %s)", p ? p->style->name : "none",
                        im->has_pair ? im->pair_name : "none") > 0;
    if (p && (p->coeff_set != im->coeff_set ||
              memcmp(p->coef, im->coef, (size_t)im->ncoef * sizeof(double))))
        return snprintf(why, len, "pair_style %s coefficients", p->style->name) > 0;
    if (p && p->style->state_write) {
        size_t n = p->style->state_write(p, PAIR_STATE_COEFF, NULL, 0);
        unsigned char *b = malloc(n + 1);
        if (b)
            p->style->state_write(p, PAIR_STATE_COEFF, b, n);
        int differ = !b || n != im->npcoef || (n && memcmp(b, im->pcoef, n));
        free(b);
        if (differ)
            return snprintf(why, len, "pair_coeff of %s", p->style->name) > 0;
    }
    if (g->dt != im->dt)
        return snprintf(why, len, "timestep %.15g (file: %.15g)", g->dt, im->dt) > 0;
    int nf = g->styles.nfix;
    for (int k = 0; k < nf || k < im->nfix; k++) {
        if (k >= nf)
            return snprintf(why, len, "fix %s (%s) of the file is not defined", im->fix[k].id,
                            im->fix[k].style) > 0;
        const struct fix *f = g->styles.fix[k];
        if (k >= im->nfix)
            return snprintf(why, len, "fix %s (%s) is not in the file", f->id,
                            f->style->name) > 0;
        const struct fix_saved *fs = &im->fix[k];
        if (strcmp(f->id, fs->id) || strcmp(f->style->name, fs->style))
            return snprintf(why, len, "fix %d is %s (%s), in the file %s (%s)", k + 1, f->id,
                            f->style->name, fs->id, fs->style) > 0;
        if (f->arghash != fs->arghash && !(f->style->flags & FIX_OUTPUT))
            return snprintf(why, len, "the group or arguments of fix %s (%s)", f->id,
                            fs->style) > 0;
    }
    return 0;
}

/* The host atoms by tag (map) and, per written (device-order) atom, its
 * host row or -1 (row); both malloc'd. */
static void host_rows(struct gravel *g, const struct image *im, struct tagidx **mapp, int **rowp)
{
    int n = g->atoms.n;
    struct tagidx *map = gr_malloc(g, ((size_t)n + 1) * sizeof *map);
    for (int i = 0; i < n; i++) {
        map[i].tag = g->atoms.tag[i];
        map[i].idx = i;
    }
    qsort(map, (size_t)n, sizeof *map, cmp_tagidx);
    int *row = gr_malloc(g, ((size_t)im->ndev + 1) * sizeof(int));
    for (int i = 0; i < im->ndev; i++)
        row[i] = find_idx(map, n, im->devtag[i]);
    *mapp = map;
    *rowp = row;
}

/* The file's list as rows of the host atoms (nbr_state's form), partners
 * mapped by tag (unknown ones dropped); the exact list keeps its capacity,
 * reference positions and steps since the build. */
static void host_list(struct gravel *g, const struct image *im, const struct tagidx *map,
                      const int *row, int exact, struct nbr_state *s)
{
    struct engine *e = g->eng;
    int n = g->atoms.n;
    memset(s, 0, sizeof *s);
    s->n = n;
    const int hw = e->history ? e->hist_n : 0;
    s->history = hw;
    s->ncount = gr_calloc(g, (size_t)n + 1, sizeof(int));
    size_t *first = gr_malloc(g, ((size_t)im->ndev + 1) * sizeof(size_t));
    size_t off = 0;
    for (int i = 0; i < im->ndev; i++) {
        first[i] = off;
        off += (size_t)im->ncount[i];
    }
    int maxn = exact ? im->maxn : 1;
    if (!exact)
        for (int i = 0; i < im->ndev; i++)
            if (row[i] >= 0 && im->ncount[i] > maxn)
                maxn = im->ncount[i];
    s->maxn = maxn > 0 ? maxn : 1;
    s->nlist = gr_calloc(g, (size_t)n * s->maxn + 1, sizeof(int));
    if (e->history)
        s->shear = gr_calloc(g, (size_t)hw * n * s->maxn + 1, sizeof(double));
    for (int i = 0; i < im->ndev; i++) {
        int ri = row[i];
        if (ri < 0)
            continue;
        for (int k = 0; k < im->ncount[i]; k++) {
            int j = find_idx(map, n, im->partner[first[i] + k]);
            if (j < 0)
                continue;
            size_t slot = (size_t)ri * s->maxn + (size_t)s->ncount[ri]++;
            s->nlist[slot] = j;
            if (e->history && im->history) /* the common part of the two widths */
                memcpy(s->shear + (size_t)hw * slot,
                       im->shear + (size_t)im->history * (first[i] + k),
                       (size_t)(hw < im->history ? hw : im->history) * sizeof(double));
        }
    }
    free(first);
    s->xhold = gr_malloc(g, (3 * (size_t)n + 1) * sizeof(double));
    memcpy(s->xhold, exact ? im->xhold : g->atoms.x, 3 * (size_t)n * sizeof(double));
    s->ago = exact ? im->ago : 0;
}

/* A fix's written per-atom rows in the order of the n host atoms (row[i]:
 * written atom i's host row, or -1; atoms not written get zeros); malloc'd. */
static unsigned char *host_fix_rows(struct gravel *g, const struct fix_saved *fs,
                                    const int *row, int n)
{
    size_t pb = fs->peratom_bytes;
    unsigned char *buf = gr_calloc(g, (size_t)n * pb + 1, 1);
    for (int i = 0; i < fs->nrows; i++)
        if (row[i] >= 0)
            memcpy(buf + (size_t)row[i] * pb, fs->peratom + (size_t)i * pb, pb);
    return buf;
}

/* The fix of a saved state (same ID and style), or NULL with a warning when
 * the file holds state for it. */
static struct fix *saved_fix(struct gravel *g, const struct fix_saved *fs)
{
    struct fix *f = fix_find(g, fs->id);
    if (f && !strcmp(f->style->name, fs->style))
        return f;
    if (fs->bloblen || fs->nrows)
        gr_warn(g, "restart: state of fix %s (%s) not restored: no fix with this ID and style",
                fs->id, fs->style);
    return NULL;
}

/* A fix's global state (its read_restart hook). */
static void resume_blob(struct gravel *g, struct fix *f, const struct fix_saved *fs)
{
    if (!fs->bloblen)
        return;
    if (f->style->read_restart)
        f->style->read_restart(g, f, fs->blob, fs->bloblen);
    else
        gr_warn(g, "restart: fix %s (%s) of this build keeps no restart state", fs->id,
                fs->style);
}

/* 2: the written step's forces are the continued run's; 1: the exact list,
 * forces recomputed (why: the setting that differs); 0: neither. */
static int resume_level(struct gravel *g, const struct image *im, int exact, char *why,
                        size_t len)
{
    if (!exact)
        return 0;
    if (force_fingerprint(g) == im->fingerprint)
        return 2;
    if (!force_diff(g, im, why, len))
        snprintf(why, len, "force settings");
    return 1;
}

static void resume_report(struct gravel *g, const struct image *im, int result,
                          const char *why)
{
    if (result == 1)
        gr_print(g, "Restart: continuing with the written neighbor list; forces recomputed: "
                    "%s differs from the writer\n", why);
    else if (result == 2)
        gr_print(g, "Restart: exact continuation of step %lld\n", (long long)im->step);
    else if (im->has_list)
        gr_print(g, "Restart: atoms or settings changed since the file was written (%s); "
                    "contact history carried into a new neighbor list\n", why);
}

/* What the setup exchange of a decomposed run does that one process defers
 * to its next neighbor rebuild (why[0] = 0: nothing): wrap the atoms that
 * left a periodic box, shrink-wrap the box. */
static void setup_exchange_note(struct gravel *g, char *why, size_t len)
{
    const struct domain *d = &g->dom;
    const struct atoms *a = &g->atoms;
    long out = 0;
    int shrink = 0;
    for (int q = 0; q < 3; q++) {
        if (!d->periodic[q]) {
            shrink |= d->bnd[q][0] != BND_F || d->bnd[q][1] != BND_F;
            continue;
        }
        for (int i = 0; i < a->n; i++) {
            const double *x = a->x + 3 * (size_t)i;
            if (d->triclinic) { /* inside a tilted box: lamda in [0, 1) */
                double lam[3];
                domain_x2lamda(g, x, lam);
                out += lam[q] < 0 || lam[q] >= 1;
            } else {
                out += x[q] < d->lo[q] || x[q] >= d->hi[q];
            }
        }
    }
    why[0] = 0;
    if (out)
        snprintf(why, len, "wraps %ld atoms into the periodic box%s", out,
                 shrink ? " and shrink-wraps it" : "");
    else if (shrink)
        snprintf(why, len, "shrink-wraps the box");
}

void restart_adopt_ranks(struct gravel *g)
{
    struct restart *r = g->restart;
    if (comm_size() < 2 || !r || !r->pending)
        return;
    struct image *im = r->pending;
    struct engine *e = g->eng;
    int n = g->atoms.n;
    struct tagidx *map;
    int *row;
    host_rows(g, im, &map, &row);
    r->why[0] = 0;
    int exact = im->has_list && !list_diff(g, im, n, r->why, sizeof r->why);
    par_adopt_begin(g);
    for (int k = 0; k < im->nfix; k++) {
        const struct fix_saved *fs = &im->fix[k];
        struct fix *f = fs->nrows ? fix_find(g, fs->id) : NULL;
        if (!f || strcmp(f->style->name, fs->style))
            continue; /* restart_resume warns */
        if (fs->rsz != e->rsz) {
            gr_warn(g, "restart: per-atom state of fix %s not restored (precision differs)",
                    fs->id);
            if (exact)
                snprintf(r->why, sizeof r->why, "per-atom state of fix %s", fs->id);
            exact = 0;
            continue;
        }
        unsigned char *buf = host_fix_rows(g, fs, row, n);
        par_adopt_fix_rows(g, f, fs->peratom_bytes, buf);
        free(buf);
    }
    if (im->has_list && n > 0) {
        struct nbr_state s;
        host_list(g, im, map, row, exact, &s);
        par_adopt_list(g, &s);
        nbr_state_free(&s);
    }
    r->ranks_result = resume_level(g, im, exact, r->why, sizeof r->why);
    if (r->ranks_result == 2) {
        par_adopt_forces(g);
        setup_exchange_note(g, r->why, sizeof r->why);
    }
    free(row);
    free(map);
}

int restart_resume(struct gravel *g)
{
    struct restart *r = g->restart;
    if (!r || !r->pending)
        return 0;
    struct image *im = r->pending;
    if (par_on(g)) { /* the list and per-atom state went with the atoms (adopt above) */
        for (int k = 0; k < im->nfix; k++) {
            struct fix *f = saved_fix(g, &im->fix[k]);
            if (f)
                resume_blob(g, f, &im->fix[k]);
        }
        int result = r->ranks_result;
        if (result == 2 && r->why[0])
            gr_print(g, "Restart: continuation of step %lld with its forces; the setup exchange "
                        "%s, which one process does at its next neighbor rebuild: not "
                        "bit-identical to one process from here\n", (long long)im->step, r->why);
        else
            resume_report(g, im, result, r->why);
        image_free(im);
        r->pending = NULL;
        return result;
    }
    struct engine *e = g->eng;
    int n = e->a.n;
    /* the device holds the host atoms in host order (just uploaded) */
    struct tagidx *map;
    int *row;
    host_rows(g, im, &map, &row);

    char why[512] = "";
    int exact = im->has_list && !list_diff(g, im, n, why, sizeof why);

    /* fix state, for fixes re-created with the same ID and style */
    for (int k = 0; k < im->nfix; k++) {
        struct fix_saved *fs = &im->fix[k];
        struct fix *f = saved_fix(g, fs);
        if (!f)
            continue;
        resume_blob(g, f, fs);
        if (fs->nrows) {
            if (!f->peratom || f->peratom_bytes != fs->peratom_bytes || fs->rsz != e->rsz) {
                gr_warn(g, "restart: per-atom state of fix %s not restored (size or precision "
                           "differs)", fs->id);
                if (exact)
                    snprintf(why, sizeof why, "per-atom state of fix %s", fs->id);
                exact = 0;
                continue;
            }
            unsigned char *buf = host_fix_rows(g, fs, row, n);
            eng_write(g, f->peratom, 0, (size_t)n * fs->peratom_bytes, buf);
            free(buf);
        }
    }

    int result = 0;
    if (im->has_list && n > 0) {
        struct nbr_state s;
        host_list(g, im, map, row, exact, &s);
        exact = exact && s.history == im->history;
        int imported = nbr_import(g, &s);
        nbr_state_free(&s);
        if (!imported) {
            gr_warn(g, "restart: the neighbor list in the file is not symmetric; it is "
                       "rebuilt and the contact history is lost");
            exact = 0;
            snprintf(why, sizeof why, "the file's neighbor list is not symmetric");
        } else {
            result = resume_level(g, im, exact, why, sizeof why);
        }
    }
    free(row);
    free(map);
    resume_report(g, im, result, why);
    image_free(im);
    r->pending = NULL;
    return result;
}
