/* temperature.h - temperatures as LAMMPS computes them (compute temp,
 * compute temp/sphere, the implicit thermo_temp), shared by those computes
 * and the thermo keywords temp, ke, etotal and press.
 *
 * T = mvv2e sum(...) / (dof kB), summed over the group in tag order:
 *   TEMP_TRANS          m v.v (all three components, also in 2d);
 *   TEMP_SPHERE_ALL     m v.v + 0.4 m r^2 w.w (solid-sphere inertia, also in 2d);
 *   TEMP_SPHERE_ROTATE  0.4 m r^2 w.w only;
 *   TEMP_COM            m (v - vcm).(v - vcm), vcm the group's (temp/com);
 *   TEMP_PARTIAL        m v.v over the components of flags (temp/partial);
 *   TEMP_REGION         m v.v of the group's atoms in the region now (temp/region);
 *   TEMP_PROFILE        m (v - vbin).(v - vbin), vbin the mean velocity of the
 *                       atom's spatial bin over the flagged components
 *                       (temp/profile; dim x bins fewer degrees of freedom).
 * Degrees of freedom, per atom of the group (LAMMPS 2021 dof_compute):
 *   TRANS: dim;  SPHERE_ALL: 3d 6 (3 if r = 0), 2d 3 (2 if r = 0);
 *   SPHERE_ROTATE: 3d 3, 2d 1 (0 if r = 0); COM, REGION: dim; PARTIAL: the
 * components counted; minus extra/dof (default: the dimension) and the
 * fixes' dof except in ROTATE mode (PARTIAL: their share n/dim; REGION:
 * extra/dof only, counted at every evaluation, as LAMMPS). dof < 0
 * with atoms in the group is an error; dof = 0 gives T = 0. The count is
 * taken at run setup and kept through the run (dynamic/dof no, LAMMPS's
 * default) or retaken at every evaluation (dynamic/dof yes); outside a run
 * it is always the current one. */
#ifndef GR_TEMPERATURE_H
#define GR_TEMPERATURE_H

#include "state.h"

/* Boltzmann constant of the current units (LAMMPS 2021 force->boltz). */
double temp_boltz(const struct gravel *g);
/* Count the degrees of freedom now (run setup). */
void temp_setup(struct gravel *g, struct temp_state *t);
/* The degrees of freedom the next temp_scalar divides by. */
double temp_dof(struct gravel *g, struct temp_state *t);
/* The temperature (host arrays must be current). */
double temp_scalar(struct gravel *g, struct temp_state *t);
/* Kinetic-energy tensor xx yy zz xy xz yz (mvv2e sum m v_a v_b, plus the
 * rotational terms for the sphere kinds), extensive, as LAMMPS's vector. */
void temp_vector(struct gravel *g, struct temp_state *t, double out[6]);
/* A temperature with a velocity bias (temp/com, temp/partial, temp/region),
 * LAMMPS's remove_bias_all / reapply_bias_all / restore_bias_all on the host
 * arrays over the temperature's group: remove takes the bias out (the
 * centre-of-mass velocity subtracted; the uncounted components, the atoms
 * outside the region: kept aside and zeroed) and returns it per atom
 * (malloc'd); reapply zeroes what temp/partial does not count again;
 * restore adds the bias back and frees it. */
int temp_has_bias(const struct temp_state *t);
double *temp_bias_remove(struct gravel *g, struct temp_state *t);
void temp_bias_reapply(struct gravel *g, const struct temp_state *t);
void temp_bias_restore(struct gravel *g, const struct temp_state *t, double *vb);
/* Scale the velocities of the atoms in groupbit by factor, a bias
 * temperature's bias removed before and restored after (LAMMPS's fix
 * temp/rescale, velocity scale ... bias yes). Host arrays. */
void temp_scale_thermal(struct gravel *g, struct temp_state *t, unsigned groupbit,
                        double factor);
/* TEMP_PROFILE's bins: their count; each host atom's bin (-1 outside the
 * group; malloc'd); each bin's mean of the flagged velocity components and
 * its atom count, 4 per bin (summed in tag order, every rank's atoms;
 * malloc'd; collective on several ranks). */
int temp_profile_nbins(const struct temp_state *t);
int *temp_profile_bins(struct gravel *g, const struct temp_state *t);
double *temp_profile_means(struct gravel *g, const struct temp_state *t, const int *bin);
/* Component d of the velocity bias of host atom i: its bin's mean when d is
 * flagged, else 0 (bin, mean: the two above). */
double temp_profile_bias(const struct temp_state *t, const int *bin, const double *mean, int i,
                         int d);
/* The temperature that thermo uses: thermo_modify temp ID, else thermo_temp. */
struct temp_state *temp_thermo(struct gravel *g);
/* compute_modify keywords of a temperature: dynamic/dof (dynamic),
 * extra/dof (extra); argv holds keyword value pairs. */
void temp_modify(struct gravel *g, struct temp_state *t, int argc, char **argv);
/* `compute_modify ID keyword value ...` (commands.def): temp_modify on a
 * temperature compute or on the implicit thermo_temp. */
void cmd_compute_modify(struct gravel *g, int argc, char **argv);

/* The temperature computes (compute temp, temp/sphere): attach a temperature
 * of this kind to c (global scalar and 6-vector), and the compute_style
 * callbacks that serve it. */
struct compute;
void temp_compute_attach(struct gravel *g, struct compute *c, enum temp_kind kind);
void temp_compute_init(struct gravel *g, struct compute *c);
double temp_compute_scalar(struct gravel *g, struct compute *c);
void temp_compute_vector(struct gravel *g, struct compute *c);

#endif
