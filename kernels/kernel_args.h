/* kernel_args.h - the argument lists of the contact pipeline's kernels,
 * declared once: each list expands to the kernel's .cl parameter list
 * (KA_KERNEL: the scalars in one struct, then the buffers; KA_PARAMS, one
 * parameter per argument, for the functions a kernel calls; the engine
 * prepends this header to every program, after wall_layout.h) and, on the
 * host, to a struct with one field per argument and a binder that sets them
 * (src/engine/kargs.h, src/engine/kargs.c). Valid C and OpenCL C. Adding or moving an argument is one edit here; the kernel
 * body and the host code that fills the struct then read it by name.
 *
 * A list KARGS_<name>(X, Y) names each argument as X(kind, name) for the
 * first and Y(kind, name) for the rest (so the device expansion can place
 * the commas). Kinds (device parameter / host field / how it is bound):
 *   I       const int / int
 *   U       const uint / unsigned
 *   R       const REAL / double (eng_arg_real: converted to the run's REAL)
 *   R3      const REAL <name>x, <name>y, <name>z / double[3]
 *   C3      as R3, a position: the binder subtracts the device origin
 *           (eng_arg_coord)
 *   I3      const int <name>x, <name>y, <name>z / int[3]
 *   BOX     const REAL Lx, Ly, Lz, xy, xz, yz (the minimum-image box of
 *           kernels/common.cl; the name is the host field) / double[6]
 *   M CM    __global REAL * / __global const REAL * ; host cl_mem
 *   MI CMI  __global int * / __global const int * ; host cl_mem
 *   CMU     __global const uint * ; host cl_mem
 *   MUC     __global uchar * ; host cl_mem (one byte per item)
 *   MF      __global float * ; host cl_mem (float in both precisions:
 *           the accuracy records)
 *   CML     __global const long * ; host cl_mem (the atoms' tags)
 *   POS_LO  the low parts of the positions in single precision
 *           (POS_LO_PARAM of kernels/common.cl: absent in double); no
 *           host field, bound from the engine; always last
 *   PART    the arguments of list KARGS_<name>, in place; host field
 *           struct <name>_args <name> (a part holds no part) */
#ifndef GR_KERNEL_ARGS_H
#define GR_KERNEL_ARGS_H

/* ---- the particle-particle stage (kernels/pair_loop.cl) ---- */

/* halt (a part): the kernels of a speculated step (src/engine/neighbor.c,
 * nbr_decide: its rebuild flag not read yet) do nothing once an opening of
 * the speculation asked for a rebuild or met a non-finite particle, i.e.
 * hflags[0] (the neighbor flags) is a stamp in [hlo, hhi]; hlo > hhi: never
 * (KA_HALTED, tested first thing in the kernel) */
#define KARGS_halt(X, Y) X(CMI, hflags) Y(I, hlo) Y(I, hhi)

/* pair_contacts: one work-item per contact; shear is ci when the law keeps
 * no history, omega is v without rotation; rec the contacts' records
 * (REC_W REAL each, kernels/pair_loop.cl); temp / recq (the temperatures,
 * the contacts' heat records) are v / rec without HAS_HEAT;
 * quiet[c] = 1: contact c did not act when last evaluated and its records
 * hold the zeros it wrote (0: unknown, after a rebuild or at a run start) */
#define KARGS_pair_contacts(X, Y)                                                              \
    X(I, ncontact) Y(CMI, ci) Y(CMI, cj) Y(CM, x) Y(CM, v) Y(CM, omega) Y(CM, radius)          \
    Y(CM, rmass) Y(CMI, type) Y(CMU, mask) Y(M, shear) Y(CM, param) Y(I, ntypes) Y(I, nparam)  \
    Y(U, freezebit) Y(R, dt) Y(I, shearupdate) Y(BOX, box) Y(M, rec) Y(MF, acc) Y(MI, astep)   \
    Y(I, step) Y(CM, hrate) Y(U, vgroup) Y(CM, temp) Y(M, recq) Y(MUC, quiet) Y(PART, halt)    \
    Y(POS_LO, xlo)

/* pair_gather: one work-item per particle, then the fused post_force,
 * final_integrate and end_of_step ops [first, first + npost + nfinal)
 * (nfinal counts both of the last two); store: the fused fix's per-atom
 * store (f when none); recq / heatflow as pair_contacts'; ioff, coff,
 * pcon and quiet (read only): the list's (src/engine/neighbor.h); zidx:
 * the record of zeros past the last contact's (src/engine/neighbor.c,
 * zero_record) */
#define KARGS_pair_gather(X, Y)                                                                \
    X(I, n) Y(CMI, ioff) Y(CMI, coff) Y(CMI, pcon) Y(CM, rec) Y(I, zidx) Y(M, f) Y(M, torque) \
    Y(CMI, ops) Y(I, first) Y(I, npost) Y(I, nfinal) Y(CM, prm) Y(M, store) Y(M, v)            \
    Y(M, omega) Y(CM, rmass) Y(CM, radius) Y(CMI, type) Y(CMU, mask) Y(CM, recq)               \
    Y(M, heatflow) Y(I, look) Y(MUC, quiet) Y(PART, atom_step) Y(PART, halt) Y(POS_LO, xlo)

/* force_clear: no pair style (heatflow: f without HAS_HEAT) */
#define KARGS_force_clear(X, Y) X(I, n) Y(M, f) Y(M, torque) Y(M, heatflow)

/* ---- the step's check and wrap (kernels/neighbor.cl) ---- */

#define KARGS_nbr_check(X, Y)                                                                  \
    X(I, n) Y(M, v) Y(CMI, ops) Y(CM, prm) Y(CM, f) Y(M, omega) Y(CM, torque) Y(CM, rmass)     \
    Y(CM, radius) Y(CMI, type) Y(CMU, mask) Y(PART, atom_step) Y(POS_LO, xlo)

/* atom_step (a part; kernels/atom_step.cl): the opening of a step, the
 * fused initial_integrate ops [0, ninit), the periodic wrap and the
 * rebuild and finiteness flags; run by nbr_check, or by pair_gather at the
 * end of the step before (look = 1: src/engine/run.c, step_lookahead) */
#define KARGS_atom_step(X, Y)                                                                  \
    X(M, x) Y(CM, xhold) Y(R, trigsq) Y(MI, flags) Y(I, stamp) Y(MI, image) Y(C3, lo)          \
    Y(C3, hi) Y(BOX, box) Y(CM, hrate) Y(U, vgroup) Y(I, ninit)

/* nbr_wrap_extent: periodic wrap (p: periodic per dimension) and the
 * per-chunk extents */
#define KARGS_nbr_wrap_extent(X, Y)                                                            \
    X(I, n) Y(I, chunk) Y(M, x) Y(M, v) Y(CMU, mask) Y(CM, hrate) Y(U, vgroup) Y(MI, image)    \
    Y(I3, p) Y(C3, lo) Y(C3, hi) Y(R, xy) Y(R, xz) Y(R, yz) Y(M, ext) Y(POS_LO, xlo)

/* ---- the wall stage (kernels/wall.cl, kernels/wall_region.cl) ---- */

/* what every wall kernel starts with: the atoms, the accuracy records
 * (kernels/accuracy.cl: acc, astep, step) and, with HAS_HEAT, the atoms'
 * temperatures and heat flows (temp / heatflow are v / f without HAS_HEAT) */
#define KARGS_wall_atoms(X, Y)                                                                 \
    X(I, n) Y(CMU, mask) Y(CM, x) Y(CM, v) Y(CM, omega) Y(CM, radius) Y(CM, rmass)             \
    Y(CMI, type) Y(M, f) Y(M, torque) Y(MF, acc) Y(MI, astep) Y(I, step) Y(CM, temp)           \
    Y(M, heatflow)

/* one wall's own: its group, `contacts` records (want_contacts:
 * WALL_CONTACT_W REAL per atom, else f), history (has_history REAL per
 * slot), accuracy code acode, and whether it conducts heat (wheat) at
 * temperature twall */
#define KARGS_wall_own(X, Y)                                                                   \
    X(U, groupbit) Y(M, history) Y(I, has_history) Y(I, acode) Y(I, wheat) Y(R, twall)         \
    Y(M, contacts) Y(I, want_contacts)

/* the wall's law: one packed parameter set (by_type 0) or the pair style's
 * sets (ntypes x ntypes of nparam REAL) */
#define KARGS_wall_law(X, Y) X(CM, param) Y(I, ntypes) Y(I, nparam) Y(I, by_type)

/* WALL_KERNEL: plane pair and cylinder (struct wall_geom of kernels/wall.cl) */
#define KARGS_wall_kernel(X, Y)                                                                \
    X(PART, wall_atoms) Y(PART, wall_own) Y(PART, wall_law) Y(I, nelem) Y(I, kind) Y(I, axis)  \
    Y(R, lo) Y(R, hi) Y(R, wradius) Y(R3, vw) Y(I, cyl_shear) Y(R, vshear) Y(R, dt)            \
    Y(I, shearupdate) Y(I, inclusive) Y(PART, halt) Y(POS_LO, xlo)

/* MESH_KERNEL: history at hoff of a per-atom record of hstride REAL; the
 * mesh's triangles, bins (gnx x gny x gnz, reach lreach) and pose (POSE_*);
 * the atoms' triangle lists (mlist, mlpos: MESH_LIST_W int and MESH_LPOS_W
 * REAL per atom, keyed by tag; built lskin beyond the radius; mscale the
 * largest |vertex|_1) */
#define KARGS_mesh_kernel(X, Y)                                                                \
    X(PART, wall_atoms) Y(PART, wall_own) Y(I, hstride) Y(I, hoff) Y(PART, wall_law)           \
    Y(CM, tri) Y(CMI, triv) Y(CMI, cstart) Y(CMI, ctri) Y(CM, pose) Y(I3, gn) Y(I, moving)     \
    Y(M, fmesh) Y(I, want_fmesh) Y(M, mstress) Y(I, want_mstress) Y(R, dt) Y(I, shearupdate)   \
    Y(I, inclusive) Y(CML, tag) Y(MI, mlist) Y(M, mlpos) Y(R, lskin) Y(R, lreach) Y(R, mscale) \
    Y(PART, halt) Y(POS_LO, xlo)

/* REGION_KERNEL: nwall region walls of one law (a set: RS_* of
 * kernels/wall_layout.h); wall w's parameters, history and `contacts`
 * records are param<w>, hist<w> and contacts<w> (the atoms' f where it has
 * none); the wall_own part of each wall is in its header */
#define KARGS_region_kernel(X, Y)                                                              \
    X(PART, wall_atoms) Y(CM, set) Y(I, nwall) Y(I, ntypes) Y(CM, param0) Y(CM, param1)        \
    Y(CM, param2) Y(CM, param3) Y(M, hist0) Y(M, hist1) Y(M, hist2) Y(M, hist3)                \
    Y(M, contacts0) Y(M, contacts1) Y(M, contacts2) Y(M, contacts3) Y(R, dt) Y(I, shearupdate) \
    Y(POS_LO, xlo)

/* region_probe: the region surface contacts of each atom of the group that
 * the region matches (out: RG_PROBE_W REAL per atom, kernels/wall_region.cl) */
#define KARGS_region_probe(X, Y)                                                               \
    X(I, n) Y(U, groupbit) Y(CMU, mask) Y(CM, x) Y(CM, radius) Y(CM, nodes) Y(I, nnode)        \
    Y(I, comb) Y(I, rinterior) Y(I, slots) Y(M, out) Y(POS_LO, xlo)

/* Every list, for the host's structs and binders (src/engine/kargs.h); parts
 * first (a list's struct holds its parts' structs). */
#define KARGS_LISTS(T)                                                                         \
    T(wall_atoms) T(wall_own) T(wall_law) T(atom_step) T(halt) T(pair_contacts) T(pair_gather) \
    T(force_clear) T(nbr_check) T(nbr_wrap_extent) T(wall_kernel) T(mesh_kernel)               \
    T(region_kernel) T(region_probe)

#ifdef __OPENCL_VERSION__
/* ---- device: the parameter list of list `name`, e.g.
 *   __kernel void pair_contacts(KA_PARAMS(pair_contacts))
 * KA_FIRST / KA_NEXT expand a list's own arguments; a part is expanded by
 * copies of them (KA_FIRST2 / KA_NEXT2), as a macro does not expand inside
 * its own expansion. */
#define KA_PARAMS(name) KARGS_##name(KA_FIRST, KA_NEXT)
#define KA_FIRST(kind, name) KA_DECL_##kind(name, KA_FIRST2, KA_NEXT2)
#define KA_NEXT(kind, name) KA_SEP_##kind KA_DECL_##kind(name, KA_NEXT2, KA_NEXT2)
#define KA_FIRST2(kind, name) KA_DECL_##kind(name, , )
#define KA_NEXT2(kind, name) KA_SEP_##kind KA_DECL_##kind(name, , )

#define KA_DECL_I(n, X, Y) const int n
#define KA_DECL_U(n, X, Y) const uint n
#define KA_DECL_R(n, X, Y) const REAL n
#define KA_DECL_R3(n, X, Y) const REAL n##x, const REAL n##y, const REAL n##z
#define KA_DECL_C3(n, X, Y) const REAL n##x, const REAL n##y, const REAL n##z
#define KA_DECL_I3(n, X, Y) const int n##x, const int n##y, const int n##z
#define KA_DECL_BOX(n, X, Y)                                                                   \
    const REAL Lx, const REAL Ly, const REAL Lz, const REAL xy, const REAL xz, const REAL yz
#define KA_DECL_M(n, X, Y) __global REAL *n
#define KA_DECL_CM(n, X, Y) __global const REAL *n
#define KA_DECL_MI(n, X, Y) __global int *n
#define KA_DECL_CMI(n, X, Y) __global const int *n
#define KA_DECL_CMU(n, X, Y) __global const uint *n
#define KA_DECL_MUC(n, X, Y) __global uchar *n
#define KA_DECL_MF(n, X, Y) __global float *n
#define KA_DECL_CML(n, X, Y) __global const long *n
#define KA_DECL_POS_LO(n, X, Y) POS_LO_PARAM
#define KA_DECL_PART(n, X, Y) KARGS_##n(X, Y)

/* the names of list `name`'s arguments, in order: a kernel passes them on
 * to a function declared with KA_PARAMS(name) */
#define KA_ARGS(name) KARGS_##name(KA_AFIRST, KA_ANEXT)
#define KA_AFIRST(kind, name) KA_ARG_##kind(name, KA_AFIRST2, KA_ANEXT2)
#define KA_ANEXT(kind, name) KA_SEP_##kind KA_ARG_##kind(name, KA_ANEXT2, KA_ANEXT2)
#define KA_AFIRST2(kind, name) KA_ARG_##kind(name, , )
#define KA_ANEXT2(kind, name) KA_SEP_##kind KA_ARG_##kind(name, , )
#define KA_ARG_I(n, X, Y) n
#define KA_ARG_U(n, X, Y) n
#define KA_ARG_R(n, X, Y) n
#define KA_ARG_R3(n, X, Y) n##x, n##y, n##z
#define KA_ARG_C3(n, X, Y) n##x, n##y, n##z
#define KA_ARG_I3(n, X, Y) n##x, n##y, n##z
#define KA_ARG_BOX(n, X, Y) Lx, Ly, Lz, xy, xz, yz
#define KA_ARG_M(n, X, Y) n
#define KA_ARG_CM(n, X, Y) n
#define KA_ARG_MI(n, X, Y) n
#define KA_ARG_CMI(n, X, Y) n
#define KA_ARG_CMU(n, X, Y) n
#define KA_ARG_MUC(n, X, Y) n
#define KA_ARG_MF(n, X, Y) n
#define KA_ARG_CML(n, X, Y) n
#define KA_ARG_POS_LO(n, X, Y) POS_LO_ARG
#define KA_ARG_PART(n, X, Y) KARGS_##n(X, Y)

#define KA_SEP_I ,
#define KA_SEP_U ,
#define KA_SEP_R ,
#define KA_SEP_R3 ,
#define KA_SEP_C3 ,
#define KA_SEP_I3 ,
#define KA_SEP_BOX ,
#define KA_SEP_M ,
#define KA_SEP_CM ,
#define KA_SEP_MI ,
#define KA_SEP_CMI ,
#define KA_SEP_CMU ,
#define KA_SEP_MUC ,
#define KA_SEP_MF ,
#define KA_SEP_CML ,
#define KA_SEP_POS_LO /* POS_LO_PARAM brings its own comma */
#define KA_SEP_PART /* the part's first argument brings it */

/* ---- device: a kernel's own parameter list, e.g.
 *   __kernel void pair_contacts(KA_KERNEL(pair_contacts))
 *   {
 *       KA_UNPACK(pair_contacts);
 * A kernel takes its scalars (I U R R3 C3 I3 BOX, its parts' included) in
 * one struct ka_<name> passed by value, first, then its buffers in list
 * order: PoCL copies each argument of a launch into memory of its own, so a
 * scalar costs as much as a buffer (src/engine/kargs.c packs the struct).
 * KA_UNPACK declares each scalar under its own name, as KA_PARAMS does, so
 * the body and the functions it calls with KA_ARGS are unchanged. The
 * struct holds the REALs first, then the ints and uints, then ka_end: the
 * host lays it out by the same rule. */
#define KA_KERNEL(name) const struct ka_##name name##_ks KARGS_##name(KA_KB, KA_KB)
#define KA_KB(kind, name) KA_KB_##kind(name, KA_KB2)
#define KA_KB2(kind, name) KA_KB_##kind(name, )
#define KA_KB_I(n, Z)
#define KA_KB_U(n, Z)
#define KA_KB_R(n, Z)
#define KA_KB_R3(n, Z)
#define KA_KB_C3(n, Z)
#define KA_KB_I3(n, Z)
#define KA_KB_BOX(n, Z)
#define KA_KB_M(n, Z) , KA_DECL_M(n, , )
#define KA_KB_CM(n, Z) , KA_DECL_CM(n, , )
#define KA_KB_MI(n, Z) , KA_DECL_MI(n, , )
#define KA_KB_CMI(n, Z) , KA_DECL_CMI(n, , )
#define KA_KB_CMU(n, Z) , KA_DECL_CMU(n, , )
#define KA_KB_MUC(n, Z) , KA_DECL_MUC(n, , )
#define KA_KB_MF(n, Z) , KA_DECL_MF(n, , )
#define KA_KB_CML(n, Z) , KA_DECL_CML(n, , )
#define KA_KB_POS_LO(n, Z) POS_LO_PARAM
#define KA_KB_PART(n, Z) KARGS_##n(Z, Z)

/* the scalars' struct: REALs (KA_SR), then ints (KA_SI) */
#define KA_SR(kind, name) KA_SR_##kind(name, KA_SR2)
#define KA_SR2(kind, name) KA_SR_##kind(name, )
#define KA_SR_R(n, Z) REAL n;
#define KA_SR_R3(n, Z) REAL n##x, n##y, n##z;
#define KA_SR_C3(n, Z) REAL n##x, n##y, n##z;
#define KA_SR_BOX(n, Z) REAL Lx, Ly, Lz, xy, xz, yz;
#define KA_SI(kind, name) KA_SI_##kind(name, KA_SI2)
#define KA_SI2(kind, name) KA_SI_##kind(name, )
#define KA_SI_I(n, Z) int n;
#define KA_SI_U(n, Z) uint n;
#define KA_SI_I3(n, Z) int n##x, n##y, n##z;
#define KA_SR_PART(n, Z) KARGS_##n(Z, Z)
#define KA_SI_PART(n, Z) KARGS_##n(Z, Z)
#define KA_SR_I(n, Z)
#define KA_SR_U(n, Z)
#define KA_SR_I3(n, Z)
#define KA_SR_M(n, Z)
#define KA_SR_CM(n, Z)
#define KA_SR_MI(n, Z)
#define KA_SR_CMI(n, Z)
#define KA_SR_CMU(n, Z)
#define KA_SR_MUC(n, Z)
#define KA_SR_MF(n, Z)
#define KA_SR_CML(n, Z)
#define KA_SR_POS_LO(n, Z)
#define KA_SI_R(n, Z)
#define KA_SI_R3(n, Z)
#define KA_SI_C3(n, Z)
#define KA_SI_BOX(n, Z)
#define KA_SI_M(n, Z)
#define KA_SI_CM(n, Z)
#define KA_SI_MI(n, Z)
#define KA_SI_CMI(n, Z)
#define KA_SI_CMU(n, Z)
#define KA_SI_MUC(n, Z)
#define KA_SI_MF(n, Z)
#define KA_SI_CML(n, Z)
#define KA_SI_POS_LO(n, Z)
#define KA_KSTRUCT(name)                                                                       \
    struct ka_##name {                                                                         \
        KARGS_##name(KA_SR, KA_SR) KARGS_##name(KA_SI, KA_SI) int ka_end;                      \
    };
KARGS_LISTS(KA_KSTRUCT)
#undef KA_KSTRUCT

/* a speculated step's kernel whose speculation failed (KARGS_halt) */
#define KA_HALTED() (hlo <= hhi && hflags[0] >= hlo && hflags[0] <= hhi)

#define KA_UNPACK(name)                                                                        \
    const struct ka_##name ka_s = name##_ks;                                                   \
    KARGS_##name(KA_UN, KA_UN) (void)ka_s
#define KA_UN(kind, name) KA_UN_##kind(name, KA_UN2)
#define KA_UN2(kind, name) KA_UN_##kind(name, )
#define KA_UN_I(n, Z) const int n = ka_s.n;
#define KA_UN_U(n, Z) const uint n = ka_s.n;
#define KA_UN_R(n, Z) const REAL n = ka_s.n;
#define KA_UN_R3(n, Z) const REAL n##x = ka_s.n##x, n##y = ka_s.n##y, n##z = ka_s.n##z;
#define KA_UN_C3(n, Z) KA_UN_R3(n, Z)
#define KA_UN_I3(n, Z) const int n##x = ka_s.n##x, n##y = ka_s.n##y, n##z = ka_s.n##z;
#define KA_UN_BOX(n, Z)                                                                        \
    const REAL Lx = ka_s.Lx, Ly = ka_s.Ly, Lz = ka_s.Lz, xy = ka_s.xy, xz = ka_s.xz,          \
               yz = ka_s.yz;
#define KA_UN_PART(n, Z) KARGS_##n(Z, Z)
#define KA_UN_M(n, Z)
#define KA_UN_CM(n, Z)
#define KA_UN_MI(n, Z)
#define KA_UN_CMI(n, Z)
#define KA_UN_CMU(n, Z)
#define KA_UN_MUC(n, Z)
#define KA_UN_MF(n, Z)
#define KA_UN_CML(n, Z)
#define KA_UN_POS_LO(n, Z)
#endif

#endif
