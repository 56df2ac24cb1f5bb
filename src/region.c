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
#include "styles.h"

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

int region_match(const struct region *r, const double x[3])
{
    return r->style->inside(r, x) == r->interior;
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
    for (int d = 0; d < 3; d++) {
        lo[d] = g->dom.lo[d];
        hi[d] = g->dom.hi[d];
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
        return is_hi ? g->dom.hi[dim] : g->dom.lo[dim];
    }
    return scale * arg_double(g, s, what);
}

static void region_free(struct region *r)
{
    free(r->sub);
    free(r);
}

static void region_delete(struct gravel *g, const char *id)
{
    struct regions *rs = &g->regions;
    for (int i = 0; i < rs->n; i++) {
        struct region *r = rs->r[i];
        if (strcmp(r->id, id) != 0)
            continue;
        if (r->nref > 0)
            gr_error(g, "region '%s' is used by a union or intersect region and cannot be "
                        "deleted",
                     id);
        for (int k = 0; k < r->nsub; k++)
            r->sub[k]->nref--;
        region_free(r);
        memmove(rs->r + i, rs->r + i + 1, (size_t)(rs->n - i - 1) * sizeof *rs->r);
        rs->n--;
        return;
    }
    gr_error(g, "unknown region '%.64s'", id);
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
        } else if (!strcmp(kw, "move") || !strcmp(kw, "rotate") || !strcmp(kw, "open")) {
            gr_error(g, "keyword '%s' is not supported", kw);
        } else {
            gr_error(g, "unknown keyword '%.32s'", kw);
        }
    }
    double scale[3];
    domain_unit_scale(g, tmp.lattice_units, scale);
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
    /* side out: the matching points are unbounded (LAMMPS bboxflag = 0), so
     * create_atoms searches the whole box */
    if (!r->interior)
        r->bbox = 0;
    g->err.jmp = outer;
    rs->r[rs->n++] = r;
}

void regions_free(struct gravel *g)
{
    for (int i = 0; i < g->regions.n; i++)
        region_free(g->regions.r[i]);
    free(g->regions.r);
    memset(&g->regions, 0, sizeof g->regions);
}
