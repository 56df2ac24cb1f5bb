/* change_box.c - `change_box group-ID op args ... [units lattice|box]` as
 * LAMMPS (change_box.cpp):
 *   x|y|z final lo hi     set the bounds
 *   x|y|z delta dlo dhi   add to the bounds
 *   x|y|z scale f         scale the length about the centre
 *   xy|xz|yz final t      set a tilt factor (triclinic boxes)
 *   xy|xz|yz delta dt     add to a tilt factor
 *   triclinic             make the box triclinic (tilts 0)
 *   ortho                 make it orthogonal (error unless every tilt is 0)
 *   boundary bx by bz     new boundary flags (as `boundary`); image flags of
 *                         dimensions that become non-periodic are reset
 *   set                   remember the current box for the next remap
 *   remap                 map the group's atoms from the remembered box
 *                         (initially the box before this command) to the
 *                         current one, keeping their lamda (fractional)
 *                         coordinates; the current box is remembered
 * Operations run in order; units lattice (the default) multiplies final and
 * delta values by the lattice spacings (xy, xz by the x spacing, yz by y).
 * Each box change prints the new box; as LAMMPS, each is checked as
 * create_box checks a box (a finite length below 1e19, a triclinic skew of
 * at most half a box length).
 * Afterwards shrink-wrapped faces are refitted, atoms are wrapped into
 * periodic dimensions, and atoms left outside a fixed face are lost with a
 * warning ("Lost atoms via change_box"). The volume style is not supported
 * (a clear error). */
#include <math.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "command.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "log.h"

enum { OP_FINAL, OP_DELTA, OP_SCALE, OP_BOUNDARY, OP_SET, OP_REMAP, OP_ORTHO, OP_TRICLINIC,
       OP_TILT_FINAL, OP_TILT_DELTA };

/* the box a remap maps from (LAMMPS's save_box_state) */
struct saved_box {
    double lo[3], hinv[6];
};

static void save_box(struct gravel *g, struct saved_box *s)
{
    for (int q = 0; q < 3; q++)
        s->lo[q] = g->dom.lo[q];
    domain_h_inv(g, s->hinv);
}

struct op {
    int kind, dim;
    double v[2];
    char **bnd;
};

void cmd_change_box(struct gravel *g, int argc, char **argv)
{
    domain_require_box(g);
    int ig = arg_group(g, argv[0]);
    struct op ops[64];
    int nops = 0, lattice = 1;
    for (int i = 1; i < argc;) {
        const char *w = argv[i];
        if (nops == 64)
            gr_error(g, "too many operations (at most 64)");
        struct op *o = &ops[nops];
        memset(o, 0, sizeof *o);
        if (!strcmp(w, "x") || !strcmp(w, "y") || !strcmp(w, "z")) {
            o->dim = w[0] - 'x';
            arg_need(g, argc, i, 1, w);
            const char *st = argv[i + 1];
            if (!strcmp(st, "final") || !strcmp(st, "delta")) {
                arg_need(g, argc, i + 1, 2, st);
                o->kind = st[0] == 'f' ? OP_FINAL : OP_DELTA;
                o->v[0] = arg_double(g, argv[i + 2], st);
                o->v[1] = arg_double(g, argv[i + 3], st);
                i += 4;
            } else if (!strcmp(st, "scale")) {
                arg_need(g, argc, i + 1, 1, st);
                o->kind = OP_SCALE;
                o->v[0] = arg_positive(g, argv[i + 2], "scale factor");
                i += 3;
            } else if (!strcmp(st, "volume")) {
                gr_error(g, "%s volume is not supported: use final, delta or scale", w);
            } else {
                gr_error(g, "%s needs final, delta or scale, got '%.32s'", w, st);
            }
            if (o->dim == 2 && g->dom.dimension == 2)
                gr_error(g, "cannot change the z dimension of a 2d simulation");
        } else if (!strcmp(w, "xy") || !strcmp(w, "xz") || !strcmp(w, "yz")) {
            /* dim: the tilt index 0 xy, 1 xz, 2 yz */
            o->dim = !strcmp(w, "xy") ? 0 : !strcmp(w, "xz") ? 1 : 2;
            arg_need(g, argc, i, 2, w);
            const char *st = argv[i + 1];
            if (!strcmp(st, "final"))
                o->kind = OP_TILT_FINAL;
            else if (!strcmp(st, "delta"))
                o->kind = OP_TILT_DELTA;
            else
                gr_error(g, "%s needs final or delta, got '%.32s'", w, st);
            o->v[0] = arg_double(g, argv[i + 2], st);
            i += 3;
            if (o->dim > 0 && g->dom.dimension == 2)
                gr_error(g, "cannot change the %s tilt of a 2d simulation", w);
        } else if (!strcmp(w, "triclinic")) {
            o->kind = OP_TRICLINIC;
            i++;
        } else if (!strcmp(w, "boundary")) {
            arg_need(g, argc, i, 3, w);
            o->kind = OP_BOUNDARY;
            o->bnd = argv + i + 1;
            i += 4;
        } else if (!strcmp(w, "set")) {
            o->kind = OP_SET;
            i++;
        } else if (!strcmp(w, "remap")) {
            o->kind = OP_REMAP;
            i++;
        } else if (!strcmp(w, "ortho")) {
            o->kind = OP_ORTHO;
            i++;
        } else if (!strcmp(w, "units")) {
            arg_need(g, argc, i, 1, w);
            lattice = domain_parse_units_kw(g, argv[i + 1]);
            i += 2;
            continue;
        } else {
            gr_error(g, "unknown operation '%.32s' (x, y, z, boundary, set, remap, ortho, units)",
                     w);
        }
        nops++;
    }
    if (nops == 0)
        gr_error(g, "no operation given");
    /* validate the boundary words before changing anything */
    struct domain save = g->dom;
    for (int k = 0; k < nops; k++)
        if (ops[k].kind == OP_BOUNDARY)
            domain_set_boundary(g, ops[k].bnd);
    g->dom = save;

    double sc[3];
    domain_unit_scale(g, lattice, sc);
    struct domain *d = &g->dom;
    struct atoms *a = &g->atoms;
    unsigned bit = group_bit(ig);
    /* LAMMPS first wraps the atoms into the current box (pbc() on lamda
     * coordinates when triclinic: a lamda round trip of every atom) */
    int was_tri = d->triclinic, remapped = 0;
    if (was_tri)
        for (int i = 0; i < a->n; i++)
            domain_remap(g, a->x + 3 * i, a->image + 3 * i);
    struct saved_box sb;
    save_box(g, &sb);
    gr_print(g, "Changing box ...\n");
    for (int k = 0; k < nops; k++) {
        const struct op *o = &ops[k];
        int q = o->dim;
        switch (o->kind) {
        case OP_FINAL:
        case OP_DELTA:
        case OP_SCALE: {
            double lo = d->lo[q], hi = d->hi[q];
            if (o->kind == OP_FINAL) {
                lo = o->v[0] * sc[q];
                hi = o->v[1] * sc[q];
            } else if (o->kind == OP_DELTA) {
                lo += o->v[0] * sc[q];
                hi += o->v[1] * sc[q];
            } else { /* LAMMPS's arithmetic, for its bits */
                double mid = 0.5 * (lo + hi);
                lo = mid + o->v[0] * (lo - mid);
                hi = mid + o->v[0] * (hi - mid);
            }
            if (!(lo < hi) || !isfinite(lo) || !isfinite(hi))
                gr_error(g, "the new %c bounds %g %g are not lo < hi", "xyz"[q], lo, hi);
            /* the limits of create_box: a length that fits a double */
            if (!(hi - lo < 1e19) || fabs(lo) >= DOMAIN_BIG || fabs(hi) >= DOMAIN_BIG)
                gr_error(g, "the new %c bounds %g %g give a box length of %g: too large (the "
                            "length must be below 1e19, the bounds within +-1e20)",
                         "xyz"[q], lo, hi, hi - lo);
            d->lo[q] = lo;
            d->hi[q] = hi;
            domain_check_skew(g);
            domain_print_box(g, "  ");
            break;
        }
        case OP_TILT_FINAL:
        case OP_TILT_DELTA: {
            if (!d->triclinic)
                gr_error(g, "cannot change the tilt factors of an orthogonal box (change_box "
                            "... triclinic first)");
            double *t = q == 0 ? &d->xy : q == 1 ? &d->xz : &d->yz;
            double v = o->v[0] * sc[q == 2 ? 1 : 0];
            *t = o->kind == OP_TILT_FINAL ? v : *t + v;
            domain_check_tilt(g);
            domain_check_skew(g);
            domain_print_box(g, "  ");
            break;
        }
        case OP_TRICLINIC:
            d->triclinic = 1;
            domain_print_box(g, "  ");
            break;
        case OP_ORTHO:
            if (d->xy != 0.0 || d->xz != 0.0 || d->yz != 0.0)
                gr_error(g, "cannot change the box to orthogonal when a tilt factor is non-zero");
            d->triclinic = 0;
            domain_print_box(g, "  ");
            break;
        case OP_BOUNDARY:
            domain_set_boundary(g, o->bnd);
            for (int p = 0; p < 3; p++) {
                if (!d->periodic[p])
                    for (int i = 0; i < a->n; i++)
                        a->image[3 * i + p] = 0;
                if (d->bnd[p][0] == BND_M)
                    d->minlo[p] = d->lo[p];
                if (d->bnd[p][1] == BND_M)
                    d->minhi[p] = d->hi[p];
            }
            break;
        case OP_SET: save_box(g, &sb); break;
        case OP_REMAP:
            for (int i = 0; i < a->n; i++) {
                if (!(a->mask[i] & bit))
                    continue;
                /* LAMMPS's x2lamda with the remembered box, lamda2x with
                 * the current one (the bits matter: velocity loop geom
                 * hashes coordinates) */
                double *x = a->x + 3 * i, lam[3];
                double dx = x[0] - sb.lo[0], dy = x[1] - sb.lo[1], dz = x[2] - sb.lo[2];
                lam[0] = sb.hinv[0] * dx + sb.hinv[5] * dy + sb.hinv[4] * dz;
                lam[1] = sb.hinv[1] * dy + sb.hinv[3] * dz;
                lam[2] = sb.hinv[2] * dz;
                domain_lamda2x(g, lam, x);
            }
            save_box(g, &sb);
            remapped = 1;
            break;
        }
    }
    for (int q = 0; q < 3; q++)
        d->small[q] = DOMAIN_SMALL * (d->hi[q] - d->lo[q]);
    /* refit shrink-wrapped faces to the atoms */
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < a->n; i++)
        for (int q = 0; q < 3; q++) {
            lo[q] = fmin(lo[q], a->x[3 * i + q]);
            hi[q] = fmax(hi[q], a->x[3 * i + q]);
        }
    domain_shrink_wrap(g, lo, hi);
    /* wrap periodic dimensions; atoms outside a fixed face are lost */
    /* triclinic: LAMMPS's remap() (x -> lamda, wrapped into [0, 1), -> x),
     * then the lamda round trip of its migration, for its bits (velocity
     * loop geom hashes them): an atom a remap left on a face lands where
     * LAMMPS puts it. lmp 2021 leaves the bits of the atoms inside a box
     * that only became triclinic, tilts zero, nothing remapped
     * (multi/in.granular's `change_box all triclinic`): so does gravel. */
    int trips = d->triclinic && (was_tri || remapped || d->xy != 0.0 || d->xz != 0.0 ||
                                 d->yz != 0.0);
    int n0 = a->n;
    for (int i = 0; i < a->n;) {
        if (trips || !domain_inside(g, a->x + 3 * i))
            domain_remap(g, a->x + 3 * i, a->image + 3 * i);
        if (trips) {
            double lam[3];
            domain_x2lamda(g, a->x + 3 * i, lam);
            domain_lamda2x(g, lam, a->x + 3 * i);
        }
        int out = 0;
        for (int q = 0; q < 3; q++)
            if (!d->periodic[q] && (a->x[3 * i + q] < d->lo[q] || a->x[3 * i + q] > d->hi[q]))
                out = 1;
        if (out)
            atoms_remove(g, i);
        else
            i++;
    }
    if (a->n != n0)
        gr_warn(g, "Lost atoms via change_box: original %d current %d", n0, a->n);
}
