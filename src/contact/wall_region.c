/* wall_region.c - host side of the region kind of the wall stage
 * (kernels/wall_region.cl): a region packed as device nodes (layout RG_* of
 * the kernel file), its motion evaluated once per step (Region::prematch and
 * set_velocity), the launch of a set of walls. */
#include "wall_region.h"

#include <math.h>
#include <string.h>

#include "device.h"
#include "error.h"
#include "fix.h"
#include "region.h"
#include "variable.h"

/* the node layout RG_*: kernels/wall_layout.h (through wall.h) */

static int primitive_kind(const struct region *r)
{
    static const char *const names[] = {"block", "sphere", "cylinder", "cone", "plane"};
    for (int k = 0; k < 5; k++)
        if (!strcmp(r->style->name, names[k]))
            return k + 1;
    return 0;
}

static int compound_kind(const struct region *r)
{
    return !strcmp(r->style->name, "union") ? 1 : !strcmp(r->style->name, "intersect") ? 2 : 0;
}

static const int trans[3][2] = {{1, 2}, {0, 2}, {0, 1}};

/* Device coordinates are relative to the run's origin (eng->origin; 0 in
 * double precision): every position parameter is shifted by it. */
static void pack_node(const struct region *r, int walloff, const double o[3], int c2021,
                      double *nd)
{
    memset(nd, 0, RG_NODE * sizeof *nd);
    nd[RG_KIND] = primitive_kind(r);
    nd[RG_INTERIOR] = r->interior;
    nd[RG_OPENFLAG] = r->openflag;
    int bits = 0;
    for (int k = 0; k < 6; k++)
        bits |= r->open_faces[k] << k;
    nd[RG_OPEN] = bits | c2021 << RG_OPEN_RIM2021;
    nd[RG_AXIS] = r->dim;
    nd[RG_WALLOFF] = walloff;
    nd[RG_MOVE] = r->moveflag;
    nd[RG_ROT] = r->rotateflag;
    memcpy(nd + RG_P, r->p, 8 * sizeof *nd);
    if (nd[RG_KIND] == RG_CONE)
        nd[RG_P + 6] = fmax(r->p[2], r->p[3]);
    for (int k = 0; k < 3; k++) {
        nd[RG_D + k] = r->d[k];
        nd[RG_POINT + k] = r->point[k];
        nd[RG_RUNIT + k] = r->runit[k];
        nd[RG_V + k] = r->v[k];
        nd[RG_OMEGA + k] = r->omega[k];
        nd[RG_RPOINT + k] = r->rpoint[k];
    }
    nd[RG_SIN] = sin(r->theta);
    nd[RG_COS] = cos(r->theta);
    double *p = nd + RG_P;
    int kind = (int)nd[RG_KIND], ax = r->dim;
    if (kind == RG_BLOCK)
        for (int k = 0; k < 6; k++)
            p[k] -= o[k / 2];
    else if (kind == RG_SPHERE || kind == RG_PLANE)
        for (int k = 0; k < 3; k++)
            p[k] -= o[k];
    else {
        p[0] -= o[trans[ax][0]];
        p[1] -= o[trans[ax][1]];
        int lo = kind == RG_CYLINDER ? 3 : 4;
        p[lo] -= o[ax];
        p[lo + 1] -= o[ax];
    }
    for (int k = 0; k < 3; k++) {
        nd[RG_POINT + k] -= o[k];
        nd[RG_RPOINT + k] -= o[k];
    }
}

static void check_vars(struct gravel *g, const struct region *r, const char *who)
{
    for (int k = 0; k < 3; k++)
        if (r->moveflag && r->mvar[k][0] && !var_exists(g, r->mvar[k]))
            gr_error(g, "%s: variable '%s' of region %s does not exist", who, r->mvar[k], r->id);
    if (r->rotateflag && !var_exists(g, r->tvar))
        gr_error(g, "%s: variable '%s' of region %s does not exist", who, r->tvar, r->id);
}

size_t wall_region_init(struct gravel *g, struct wall_region *wr, struct region *r,
                        const struct wall_law *law, const char *who)
{
    region_relink(g, r);
    int comb = compound_kind(r);
    int nnode = comb ? r->nsub : 1;
    if (nnode > WALL_REGION_MAXNODE)
        gr_error(g, "%s: region %s has %d sub-regions, at most %d can be a wall", who, r->id,
                 nnode, WALL_REGION_MAXNODE);
    for (int k = 0; k < nnode; k++) {
        const struct region *s = comb ? r->sub[k] : r;
        if (!primitive_kind(s))
            gr_error(g, "%s: region %s (%s) cannot be a wall: a wall region is a block, sphere, "
                        "cylinder, cone or plane, or a union or intersect of those",
                     who, s->id, s->style->name);
        check_vars(g, s, who);
    }
    wr->nnode = nnode;
    wr->comb = comb;
    wr->interior = r->interior;
    wr->slots = r->cmax < WALL_REGION_MAXC ? r->cmax : WALL_REGION_MAXC;
    if (wr->nodes)
        clReleaseMemObject(wr->nodes);
    wr->nodes = eng_alloc(g, (size_t)nnode * RG_NODE * eng_get(g)->rsz, "wall region nodes");
    if (wr->set)
        clReleaseMemObject(wr->set);
    wr->set = eng_alloc(g, (size_t)RS_SIZE * eng_get(g)->rsz, "wall region set");
    for (int k = 0; k < nnode; k++) /* a new run: velocities by difference restart */
        (comb ? r->sub[k] : r)->vel_step = -1;
    return law->history ? (size_t)(1 + (1 + law->history) * wr->slots) * eng_get(g)->rsz : 0;
}

/* the nodes of r at its present motion state into nodes */
static void pack_nodes(struct gravel *g, const struct wall_region *wr, const struct region *r,
                       double *nodes)
{
    int walloff = 0;
    for (int k = 0; k < wr->nnode; k++) {
        const struct region *s = wr->comb ? r->sub[k] : r;
        pack_node(s, walloff, g->eng->origin, g->opt.lammps2021, nodes + k * RG_NODE);
        walloff += s->cmax;
    }
}

/* the nodes of r at its present motion state to the device */
static void upload_nodes(struct gravel *g, struct wall_region *wr, const struct region *r)
{
    double nodes[WALL_REGION_MAXNODE * RG_NODE];
    pack_nodes(g, wr, r, nodes);
    eng_write_reals(g, wr->nodes, (size_t)wr->nnode * RG_NODE, nodes);
}

void wall_region_probe(struct gravel *g, struct fix *f, struct wall_region *wr,
                       struct region *r, cl_mem out)
{
    if (region_dynamic(r))
        region_prematch(g, r);
    upload_nodes(g, wr, r);
    struct dev_atoms *a = eng_atoms(g);
    const struct region_probe_args ka = {
        .n = a->n,
        .groupbit = f->groupbit,
        .mask = a->mask,
        .x = a->x,
        .radius = a->radius,
        .nodes = wr->nodes,
        .nnode = wr->nnode,
        .comb = wr->comb,
        .rinterior = wr->interior,
        .slots = wr->slots,
        .out = out,
    };
    cl_kernel k = eng_kernel(g, "region_probe");
    ka_bind_region_probe(g, k, 0, &ka);
    eng_launch(g, k, (size_t)a->n);
}

void wall_region_apply(struct gravel *g, const struct region_wall *set, int nwall)
{
    if (nwall < 1 || nwall > RS_MAXWALL)
        gr_error(g, "internal error: a set of %d region walls", nwall);
    struct dev_atoms *a = eng_atoms(g);
    double buf[RS_SIZE] = {0};
    struct region_kernel_args ka = {
        .wall_atoms = wall_atoms_args(g),
        .set = set[0].wr->set,
        .nwall = nwall,
        .dt = g->dt,
        .shearupdate = !eng_in_setup(g),
    };
    cl_mem *param[RS_MAXWALL] = {&ka.param0, &ka.param1, &ka.param2, &ka.param3};
    cl_mem *hist[RS_MAXWALL] = {&ka.hist0, &ka.hist1, &ka.hist2, &ka.hist3};
    cl_mem *contacts[RS_MAXWALL] = {&ka.contacts0, &ka.contacts1, &ka.contacts2, &ka.contacts3};
    for (int w = 0; w < RS_MAXWALL; w++) { /* the walls past nwall: never read */
        *param[w] = set[0].law->param;
        *hist[w] = *contacts[w] = a->f;
    }
    for (int w = 0; w < nwall; w++) {
        const struct region_wall *s = &set[w];
        struct region *r = s->r;
        int dynamic = region_dynamic(r);
        if (dynamic) {
            region_prematch(g, r);
            region_set_velocity(g, r);
        }
        const struct wall_own_args wa = wall_own_args(g, s->f, s->law);
        const struct wall_law_args wl = wall_law_args(g, s->law);
        ka.ntypes = wl.ntypes; /* the same for every wall */
        double *h = buf + w * RS_HEAD;
        h[RS_GROUPBIT] = wa.groupbit;
        h[RS_HW] = wa.has_history;
        h[RS_ACODE] = wa.acode;
        h[RS_NNODE] = s->wr->nnode;
        h[RS_COMB] = s->wr->comb;
        h[RS_INTERIOR] = s->wr->interior;
        h[RS_SLOTS] = s->wr->slots;
        /* LAMMPS 29Sep2021: a union or intersect has no motion of its own, so
         * Region::velocity_contact gives its contacts a resting surface even
         * where a sub-region moves; matched here */
        h[RS_DYNAMIC] = s->wr->comb ? 0 : dynamic;
        h[RS_BYTYPE] = wl.by_type;
        h[RS_NPARAM] = wl.nparam;
        h[RS_WHEAT] = wa.wheat;
        h[RS_TWALL] = wa.twall;
        h[RS_CONTACTS] = wa.want_contacts;
        pack_nodes(g, s->wr, r, buf + RS_NODES(w));
        *param[w] = wl.param;
        *hist[w] = wa.history;
        *contacts[w] = wa.contacts;
    }
    eng_write_reals(g, ka.set, RS_NODES(nwall), buf);
    cl_kernel k = set[0].law->kernel;
    ka_bind_region_kernel(g, k, 0, &ka);
    eng_launch(g, k, (size_t)a->n);
}

void wall_region_release(struct wall_region *wr)
{
    if (wr->nodes)
        clReleaseMemObject(wr->nodes);
    if (wr->set)
        clReleaseMemObject(wr->set);
    wr->nodes = wr->set = NULL;
}
