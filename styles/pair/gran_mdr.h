/* gran_mdr.h - the physics of LAMMPS's `mdr` normal model of pair granular
 * (today's LAMMPS GranSubModNormalMDR with GranSubModDampingMDR and the
 * per-atom bookkeeping of its fix granular/mdr; Zunker and Kamrin 2024 I
 * and II, Zunker et al. 2025) as pure functions of one contact or one atom.
 * fix granular/mdr (styles/fix/fix_granular_mdr.c) calls them on the host
 * before the forces of every step; the kernel (kernels/pair_granular.cl)
 * reads the normal force they leave in the contact's history row
 * (kernels/param_layout.h, enum mdr_hist) and adds damping mdr, friction,
 * rolling and twisting as for every other normal model.
 *
 * A contact is seen from two rigid flats, one per side: side 0 is the
 * higher-tag atom's, side 1 the lower-tag atom's (LAMMPS's contactSide). */
#ifndef GR_GRAN_MDR_H
#define GR_GRAN_MDR_H

/* The material of `mdr E nu Y gamma psi_b eta_n0` and its derived moduli */
struct mdr_mat {
    double E, nu, Y, gamma, psi_b;
    double G;       /* shear modulus E / (2 (1 + nu)) */
    double kappa;   /* bulk modulus E / (3 (1 - 2 nu)) */
    double Eeff;    /* plane strain modulus E / (1 - nu^2) */
};

/* The per-atom state of fix granular/mdr (LAMMPS's d_ vectors): the
 * apparent radius R lives in the atom's radius; Ro its initial radius. The
 * sums (Vcaps ... Atot_sum) are gathered over the atom's contacts by the
 * force of a step and read by the next step's update. */
struct mdr_atom {
    double Ro, Vgeo, Velas, Acon0, Acon1, Atot, psi, ddelta_bar, dRavg;
    double Vcaps, eps_bar, dRnum, dRden, Atot_sum;
    double sigma[3];    /* the contacts' f_q b_q / Velas summed (LAMMPS's d_sigmaxx, yy, zz) */
    int ready;      /* 0: not yet initialised (LAMMPS's history_setup_flag) */
    double Rlist;   /* gravel's: the apparent radius at the last neighbor build */
};

void mdr_mat_set(struct mdr_mat *m, double E, double nu, double Y, double gamma,
                 double psi_b);

/* A new atom of radius R (fix granular/mdr, history_setup_flag 0): Ro = R,
 * its sums and areas zero. */
void mdr_atom_init(struct mdr_atom *a, double R);

/* fix granular/mdr's update of one atom before the forces (not at a run's
 * setup, except for a new atom): geometric and elastic volumes, free
 * surface ratio psi, and while psi > psi_b the apparent radius *R grows by
 * the running mean of the increments the plastic contacts ask (at most to
 * 1.5 Ro); then Acon0 = Acon1. */
void mdr_atom_update(const struct mdr_mat *m, struct mdr_atom *a, double *R);

/* The step's sums zeroed (after the update; not at setup). */
void mdr_atom_zero_sums(struct mdr_atom *a);

/* The overlaps of the two sides (out[0] side 0, out[1] side 1) at total
 * overlap delta, from the contact's largest total overlap dmax (>= delta)
 * and the sides' plastic rest overlaps dp0, dp1: dmax splits where the
 * apparent spheres' caps meet (a side capped at 0.95 of its radius leaves
 * the other the remainder), then each side moves linearly to its rest
 * overlap. R0 is side 0's apparent radius (the higher tag's), R1 side 1's.
 * force_form 1: LAMMPS's calculate_forces order of operations and cap
 * tests, 0: its mean_surf_disp's (they differ in rounding, and in which
 * cap wins when both sides pass 0.95). */
void mdr_side_deltas(double dmax, double dp0, double dp1, double delta, double R0, double R1,
                     int force_form, double out[2]);

/* One pair contact's normal force at total overlap delta (LAMMPS's
 * GranSubModNormalMDR::calculate_forces, contact_type PAIR): h the mdr
 * block of its history row, a[0] / a[1] and R[0] / R[1] the atoms and
 * apparent radii of sides 0 and 1, n the unit normal, meff the contact's
 * effective mass.
 * With update (every step but a run's setup) the history advances, the
 * damping scale is stored, and the two atoms' sums gather this contact.
 * Returns the force (the sides' mean, times the penalty weight) and
 * stores it at h[MH_FN], the mean contact area at h[MH_AC_AVG] (LAMMPS's
 * svector value, compute pair/local p13). *yield_new is set to 1 (else
 * left) when, without update, a contact never evaluated before is already
 * past yield (LAMMPS's warning for atoms inserted with a plastic overlap). */
double mdr_pair_force(const struct mdr_mat *m, double *h, double delta, struct mdr_atom *a[2],
                      const double R[2], const double n[3], double meff, int update,
                      int *yield_new);

/* One wall contact's normal force at overlap delta (calculate_forces,
 * contact_type WALLREGION: side 0 only, the whole overlap the atom's, no
 * penalty): h the mdr block of the wall contact's history, a and R the
 * atom and its apparent radius, n the unit normal from the wall to the
 * atom, meff the atom's mass. The side's force is magnified by
 * exp(10.7 deltao / Ro - 10) + 1 (deltao: the stored overlap from the
 * initial sphere) and the damping scale is sqrt(meff E* a / 2) (half the
 * side's damping radius, half the plane strain modulus). Stores and
 * returns as mdr_pair_force. */
double mdr_wall_force(const struct mdr_mat *m, double *h, double delta, struct mdr_atom *a,
                      double R, const double n[3], double meff, int update, int *yield_new);

/* The penalty increment of a contact screened by a central particle at
 * angle alpha (radians) between the directions to the two others
 * (Zunker et al. 2025): 1 / (1 + exp(-50 (alpha / pi - 1/2))). */
double mdr_penalty(double alpha);

#endif
