/* region.c - the `region` command, the region registry (styles.def REGION
 * rows) and region lookup and matching. Region styles live in
 * styles/region_<ident>.c. */
#include "region.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "domain.h"
#include "error.h"
#include "rigid_math.h"
#include "variable.h"

#define PAIR(k, i)
#define FIX(k, i)
#define COMPUTE(k, i)
#define DUMP(k, i)
#define REGION(k, i) extern const struct region_style region_style_##i;
#include "styles.def"
#undef REGION
#define REGION(k, i) &region_style_##i,
static const struct region_style *const region_table[] = {
#include "styles.def"
    NULL};
#undef REGION
#undef PAIR
#undef FIX
#undef COMPUTE
#undef DUMP

static const struct region_style *style_find(const char *name)
{
    for (int i = 0; region_table[i]; i++)
        if (strcmp(region_table[i]->name, name) == 0)
            return region_table[i];
    return NULL;
}

void region_rotate(const struct region *r, double x[3], double s, double c)
{
    double d[3], a[3], b[3], cc[3];
    for (int k = 0; k < 3; k++)
        d[k] = x[k] - r->point[k];
    double dot = d[0] * r->runit[0] + d[1] * r->runit[1] + d[2] * r->runit[2];
    for (int k = 0; k < 3; k++) {
        cc[k] = dot * r->runit[k];
        a[k] = d[k] - cc[k];
    }
    b[0] = r->runit[1] * a[2] - r->runit[2] * a[1];
    b[1] = r->runit[2] * a[0] - r->runit[0] * a[2];
    b[2] = r->runit[0] * a[1] - r->runit[1] * a[0];
    for (int k = 0; k < 3; k++)
        x[k] = r->point[k] + cc[k] + (a[k] * c + b[k] * s);
}

int region_match(const struct region *r, const double x[3])
{
    double y[3] = {x[0], x[1], x[2]};
    if (r->moveflag)
        for (int k = 0; k < 3; k++)
            y[k] -= r->d[k];
    if (r->rotateflag)
        region_rotate(r, y, -sin(r->theta), cos(r->theta));
    if (r->openflag)
        return 1;
    return r->style->inside(r, y) == r->interior;
}

int region_dynamic(const struct region *r)
{
    if (r->moveflag || r->rotateflag)
        return 1;
    for (int k = 0; k < r->nsub; k++)
        if (region_dynamic(r->sub[k]))
            return 1;
    return 0;
}

void region_prematch(struct gravel *g, struct region *r)
{
    if (r->nsub)
        region_relink(g, r);
    for (int k = 0; k < r->nsub; k++)
        region_prematch(g, r->sub[k]);
    if (r->moveflag)
        for (int k = 0; k < 3; k++)
            if (r->mvar[k][0])
                r->d[k] = var_compute_equal(g, r->mvar[k]);
    if (r->rotateflag)
        r->theta = var_compute_equal(g, r->tvar);
}

void region_set_velocity(struct gravel *g, struct region *r)
{
    for (int k = 0; k < r->nsub; k++)
        region_set_velocity(g, r->sub[k]);
    if (r->vel_step == g->step)
        return;
    r->vel_step = g->step;
    /* LAMMPS: zero at step 0, where there is no previous motion; after a
     * reset_timestep to 0 the previous evaluation still counts, so the
     * velocity stays continuous across the reset */
    int have_prev = g->step > 0 || r->prev_set;
    r->prev_set = 1;
    if (r->moveflag) {
        for (int k = 0; k < 3; k++) {
            r->v[k] = have_prev ? (r->d[k] - r->prev[k]) / g->dt : 0.0;
            r->prev[k] = r->d[k];
        }
    }
    if (r->rotateflag) {
        double w = have_prev ? (r->theta - r->prev[3]) / g->dt : 0.0;
        for (int k = 0; k < 3; k++) {
            r->rpoint[k] = r->point[k] + r->d[k];
            r->omega[k] = w * r->axis[k];
        }
        r->prev[3] = r->theta;
    }
}

/* move v_x v_y v_z: each a v_name or NULL */
static void parse_move(struct gravel *g, struct region *r, char **a)
{
    for (int k = 0; k < 3; k++) {
        if (!strcmp(a[k], "NULL"))
            continue;
        if (strncmp(a[k], "v_", 2) != 0 || !a[k][2])
            gr_error(g, "region move: expected v_name or NULL, got '%.64s'", a[k]);
        if (strlen(a[k] + 2) >= GR_NAMELEN)
            gr_error(g, "region move: variable name too long");
        strcpy(r->mvar[k], a[k] + 2);
    }
    r->moveflag = 1;
}

static void parse_rotate(struct gravel *g, struct region *r, char **a)
{
    if (strncmp(a[0], "v_", 2) != 0 || !a[0][2])
        gr_error(g, "region rotate: expected v_name for the angle, got '%.64s'", a[0]);
    if (strlen(a[0] + 2) >= GR_NAMELEN)
        gr_error(g, "region rotate: variable name too long");
    strcpy(r->tvar, a[0] + 2);
    for (int k = 0; k < 3; k++) {
        r->point[k] = arg_double(g, a[1 + k], "rotation point");
        r->axis[k] = arg_double(g, a[4 + k], "rotation axis");
    }
    if (rm_unit_axis(r->axis, r->runit))
        gr_error(g, "region rotate: the rotation axis cannot have zero length");
    r->rotateflag = 1;
}

struct region *region_find(struct gravel *g, const char *id)
{
    for (int i = 0; i < g->regions.n; i++)
        if (strcmp(g->regions.r[i]->id, id) == 0)
            return g->regions.r[i];
    return NULL;
}

struct region *region_get(struct gravel *g, const char *id)
{
    struct region *r = region_find(g, id);
    if (!r)
        gr_error(g, "unknown region '%.64s'", id);
    return r;
}

int region_box_bounds(struct gravel *g, const struct region *r, double lo[3], double hi[3])
{
    domain_require_box(g);
    domain_bbox(g, lo, hi); /* a tilted box: its bounding box, as LAMMPS */
    for (int d = 0; d < 3; d++) {
        if (r->bbox) {
            lo[d] = fmax(lo[d], r->bbox_lo[d]);
            hi[d] = fmin(hi[d], r->bbox_hi[d]);
        }
        if (!(lo[d] <= hi[d]))
            return 0;
    }
    return 1;
}

double region_parse_bound(struct gravel *g, const char *s, int dim, int is_hi, double scale,
                          const char *what)
{
    if (!strcmp(s, "INF") || !strcmp(s, "+INF") || !strcmp(s, "-INF")) {
        if ((s[0] == '-' && is_hi) || (s[0] == '+' && !is_hi))
            gr_error(g, "%s cannot be %s", what, s);
        return is_hi ? DOMAIN_BIG : -DOMAIN_BIG;
    }
    if (!strcmp(s, "EDGE")) {
        if (!g->dom.box_exists)
            gr_error(g, "cannot use EDGE for %s before the box exists", what);
        double blo[3], bhi[3]; /* a tilted box: the bounding box, as LAMMPS */
        domain_bbox(g, blo, bhi);
        return is_hi ? bhi[dim] : blo[dim];
    }
    return scale * arg_double(g, s, what);
}

static void region_free(struct region *r)
{
    if (r->style && r->style->destroy)
        r->style->destroy(r->data);
    free(r->sub);
    free(r);
}

static void region_release(struct region *r);

/* Drop one reference to s; a deleted region is freed with its last user. */
static void region_unref(struct region *s)
{
    if (--s->nref == 0 && s->deleted)
        region_release(s);
}

static void region_release(struct region *r)
{
    for (int k = 0; k < r->nsub; k++)
        region_unref(r->sub[k]);
    region_free(r);
}

/* region ID delete: leaves the registry at once. A region a union or
 * intersect uses stays alive for it, marked deleted; the compound takes the
 * region of that ID defined by then, when next used (LAMMPS re-finds its
 * sub-regions by ID in init). */
static void region_delete(struct gravel *g, const char *id)
{
    struct regions *rs = &g->regions;
    for (int i = 0; i < rs->n; i++) {
        struct region *r = rs->r[i];
        if (strcmp(r->id, id) != 0)
            continue;
        memmove(rs->r + i, rs->r + i + 1, (size_t)(rs->n - i - 1) * sizeof *rs->r);
        rs->n--;
        r->deleted = 1;
        if (r->nref == 0)
            region_release(r);
        return;
    }
    gr_error(g, "unknown region '%.64s'", id);
}

void region_relink(struct gravel *g, struct region *r)
{
    int cmax = 0;
    for (int k = 0; k < r->nsub; k++) {
        struct region *s = r->sub[k];
        if (s->deleted) {
            struct region *now = region_find(g, s->id);
            if (!now)
                gr_error(g, "region %s: its sub-region '%s' was deleted", r->id, s->id);
            if (now == r)
                gr_error(g, "region '%s' cannot contain itself", r->id);
            now->nref++;
            r->sub[k] = now;
            region_unref(s);
            s = now;
        }
        region_relink(g, s);
        cmax += s->cmax;
    }
    if (r->nsub)
        r->cmax = cmax;
}

/* region ID style args... [side in|out] [units box|lattice]
 * region ID delete */
void cmd_region(struct gravel *g, int argc, char **argv)
{
    const char *id = argv[0];
    if (argc == 2 && strcmp(argv[1], "delete") == 0) {
        region_delete(g, id);
        return;
    }
    if (argc < 2)
        gr_error(g, "expected: region ID style args ...");
    size_t idlen = strlen(id);
    if (idlen == 0 || idlen >= GR_NAMELEN)
        gr_error(g, "region ID must have 1 to %d characters", GR_NAMELEN - 1);
    for (size_t k = 0; k < idlen; k++)
        if (!isalnum((unsigned char)id[k]) && id[k] != '_')
            gr_error(g, "region ID '%.64s' may contain only letters, digits and underscores",
                     id);
    if (region_find(g, id))
        gr_error(g, "region '%s' already exists (use region %s delete first)", id, id);
    const struct region_style *st = style_find(argv[1]);
    if (!st) {
        if (!strcmp(argv[1], "prism") || !strcmp(argv[1], "ellipsoid"))
            gr_error(g, "region style '%s' is not supported", argv[1]);
        gr_error(g, "unknown region style '%.32s'", argv[1]);
    }
    int nstyle = st->nargs;
    if (nstyle < 0) { /* union/intersect: N then N IDs */
        if (argc < 3)
            gr_error(g, "region %s needs: %s", st->name, st->usage);
        int n = arg_int(g, argv[2], "number of sub-regions");
        if (n < 2 || n > argc - 3)
            gr_error(g, "region %s needs at least 2 sub-region IDs and as many as N (%d)",
                     st->name, n);
        nstyle = 1 + n;
    }
    if (argc - 2 < nstyle)
        gr_error(g, "region %s needs %d arguments (%s), got %d", st->name, nstyle, st->usage,
                 argc - 2);
    struct region tmp;
    memset(&tmp, 0, sizeof tmp);
    tmp.interior = 1;
    tmp.lattice_units = 1;
    for (int i = 2 + nstyle; i < argc; i++) {
        const char *kw = argv[i];
        if (!strcmp(kw, "side")) {
            arg_need(g, argc, i, 1, kw);
            const char *v = argv[++i];
            if (!strcmp(v, "in"))
                tmp.interior = 1;
            else if (!strcmp(v, "out"))
                tmp.interior = 0;
            else
                gr_error(g, "side must be 'in' or 'out', got '%.32s'", v);
        } else if (!strcmp(kw, "units")) {
            arg_need(g, argc, i, 1, kw);
            tmp.lattice_units = domain_parse_units_kw(g, argv[++i]);
        } else if (!strcmp(kw, "move")) {
            arg_need(g, argc, i, 3, kw);
            parse_move(g, &tmp, argv + i + 1);
            i += 3;
        } else if (!strcmp(kw, "rotate")) {
            arg_need(g, argc, i, 7, kw);
            parse_rotate(g, &tmp, argv + i + 1);
            i += 7;
        } else if (!strcmp(kw, "open")) {
            arg_need(g, argc, i, 1, kw);
            int face = arg_int_range(g, argv[++i], 1, 6, "open face");
            tmp.open_faces[face - 1] = 1;
            tmp.openflag = 1;
        } else {
            gr_error(g, "unknown keyword '%.32s'", kw);
        }
    }
    int compound = st->nargs < 0;
    if (compound && (tmp.moveflag || tmp.rotateflag))
        gr_error(g, "region %s cannot move or rotate (move or rotate its sub-regions)",
                 st->name);
    if (tmp.openflag) {
        int nface = !strcmp(st->name, "block") ? 6
                    : (!strcmp(st->name, "cylinder") || !strcmp(st->name, "cone")) ? 3 : 0;
        if (nface == 0)
            gr_error(g, "region %s has no faces to open (open applies to block, cylinder "
                        "and cone)", st->name);
        for (int k = nface; k < 6; k++)
            if (tmp.open_faces[k])
                gr_error(g, "region %s has faces 1 to %d, cannot open face %d", st->name,
                         nface, k + 1);
    }
    double scale[3];
    domain_unit_scale(g, tmp.lattice_units, scale);
    if (tmp.rotateflag)
        for (int k = 0; k < 3; k++)
            tmp.point[k] *= scale[k];
    tmp.vel_step = -1;
    struct region *r = gr_calloc(g, 1, sizeof *r);
    *r = tmp;
    memcpy(r->id, id, idlen + 1);
    r->style = st;
    /* parse under a local unwind point so that a failed parse frees r
     * before the error continues to the command boundary */
    struct regions *rs = &g->regions;
    if (rs->n == rs->cap) {
        int cap = rs->cap ? 2 * rs->cap : 8;
        rs->r = gr_realloc(g, rs->r, (size_t)cap * sizeof *rs->r);
        rs->cap = cap;
    }
    jmp_buf *outer = g->err.jmp, here;
    g->err.jmp = &here;
    if (setjmp(here)) {
        g->err.jmp = outer;
        for (int k = 0; k < r->nsub; k++)
            r->sub[k]->nref--;
        region_free(r);
        if (outer)
            longjmp(*outer, 1);
        gr_report_error(g);
        exit(1);
    }
    st->parse(g, r, nstyle, argv + 2, scale);
    /* side out, motion or open faces: the matching points are unbounded here
     * (LAMMPS bboxflag = 0 or a moving extent), so create_atoms searches the
     * whole box */
    if (!r->interior || r->moveflag || r->rotateflag || r->openflag)
        r->bbox = 0;
    r->cmax = !strcmp(st->name, "block") ? 6
              : (!strcmp(st->name, "cylinder") || !strcmp(st->name, "cone")) ? 3 : 1;
    if (compound) {
        r->cmax = 0;
        for (int k = 0; k < r->nsub; k++)
            r->cmax += r->sub[k]->cmax;
    }
    g->err.jmp = outer;
    rs->r[rs->n++] = r;
}

void regions_free(struct gravel *g)
{
    /* the registry holds one reference to each of its regions: take them
     * all, then drop them in turn; a region goes when its last user does */
    for (int i = 0; i < g->regions.n; i++) {
        g->regions.r[i]->deleted = 1;
        g->regions.r[i]->nref++;
    }
    for (int i = 0; i < g->regions.n; i++)
        region_unref(g->regions.r[i]);
    free(g->regions.r);
    memset(&g->regions, 0, sizeof g->regions);
}
