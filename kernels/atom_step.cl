/* atom_step.cl - the opening of a step for one particle, written once for
 * the two kernels that run it: nbr_check (its own launch, at the start of
 * the step) and pair_gather (look = 1: at the end of the step before, right
 * after that step's final_integrate ops, when nothing reads the particles
 * in between; src/engine/run.c). Either way each particle goes through the
 * same operations in the same order, so the two are bit-identical.
 *
 * In order: the fused initial_integrate ops [0, ninit) (kernels/fused.cl;
 * the kick and the drift) on the state *at, stored back; the periodic wrap
 * into [lo, hi) (image flags follow), so positions never depend on when
 * the list was rebuilt; flags[0] = max(flags[0], stamp) if the particle
 * moved (minimum image) more than sqrt(trigsq) since the last build (the
 * host gives each opening a larger stamp, so flags[0] needs no reset
 * between steps: src/engine/neighbor.c, step_args); flags[1] = lowest
 * index with a non-finite position or velocity (which sets flags[0] too,
 * so that a speculated step halts on it: KARGS_halt). *at holds x, xl, v
 * and, when ninit > 0, f, om, tq, m, r, type and mask. */

/* pbc_wrap of component c of (xi, xl, im): vector components have no address */
#define PBC_WRAP_COMPONENT(c, lo, hi, L)                                                       \
    {                                                                                          \
        REAL h_ = xi.c, l_ = xl.c;                                                             \
        int m_ = im.c;                                                                         \
        pbc_wrap(&h_, &l_, &m_, lo, hi, L);                                                    \
        xi.c = h_;                                                                             \
        xl.c = l_;                                                                             \
        im.c = m_;                                                                             \
    }

static inline void atom_step(const int i, struct fused_atom *at, KA_PARAMS(atom_step),
                             __global REAL *v, __global REAL *omega, __global const int *ops,
                             __global const REAL *prm POS_LO_PARAM)
{
    if (ninit > 0) {
        fused_apply(at, ops, 0, ninit, prm, (__global REAL *)0, i); /* no initial op keeps a store */
        vstore3(at->x, i, x);
        POS_STORE_LO(at->xl, i);
        vstore3(at->v, i, v);
#ifdef HAS_ROTATION
        vstore3(at->om, i, omega);
#else
        (void)omega;
#endif
    }
    REAL3 xi = at->x, xl = at->xl, vi = at->v;
#if defined(PERIODIC_X) || defined(PERIODIC_Y) || defined(PERIODIC_Z)
    int3 im = vload3(i, image);
    const int3 im0 = im;
#ifdef TRICLINIC
    pbc_wrap_tri(&xi, &xl, &im, (REAL3)(lox, loy, loz), (REAL3)(hix, hiy, hiz), xy, xz, yz);
#else
#ifdef PERIODIC_X
    PBC_WRAP_COMPONENT(x, lox, hix, Lx);
#endif
#ifdef PERIODIC_Y
    PBC_WRAP_COMPONENT(y, loy, hiy, Ly);
#endif
#ifdef PERIODIC_Z
    PBC_WRAP_COMPONENT(z, loz, hiz, Lz);
#endif
#endif
    if (im.x != im0.x || im.y != im0.y || im.z != im0.z) {
        vstore3(xi, i, x);
        POS_STORE_LO(xl, i);
        vstore3(im, i, image);
#ifdef VREMAP /* LAMMPS's Domain::pbc with deform remap v: v -/+ h_rate per period */
        if (at->mask & vgroup) {
            vi -= image_velocity(im - im0, hrate);
            vstore3(vi, i, v);
        }
#endif
    }
#else
    (void)image;
    (void)lox;
    (void)loy;
    (void)loz;
    (void)hix;
    (void)hiy;
    (void)hiz;
#endif
#ifndef VREMAP
    (void)hrate;
    (void)vgroup;
#endif
    REAL3 d = xi - vload3(i, xhold);
    MINIMG3(d);
    const REAL rsq = d.x * d.x + d.y * d.y + d.z * d.z;
    if (rsq > trigsq)
        atomic_max(&flags[0], stamp);
    /* x - x is 0 for a finite x and NaN otherwise: one test for the six */
    const REAL3 zx = xi - xi, zv = vi - vi;
    if (zx.x + zx.y + zx.z + zv.x + zv.y + zv.z != (REAL)0) {
        atomic_max(&flags[0], stamp); /* a speculation stops here too (KARGS_halt) */
        atomic_min(&flags[1], i);
    }
}
