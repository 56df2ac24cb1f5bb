/* param_layout.h - the packed per-type-pair parameter layouts of the pair
 * styles: one definition read by the host (each style's pack(), the tests)
 * and by the kernels (the engine prepends this file to every program), so
 * the two sides cannot disagree. Plain enums: valid C and OpenCL C. Each
 * style packs REAL[<STYLE>_NPARAM] per type pair (I, J), I the type of the
 * contact's owner i, J of its partner j. */
#ifndef GR_PARAM_LAYOUT_H
#define GR_PARAM_LAYOUT_H

/* gran/hooke, gran/hooke/history, gran/hertz/history and fix wall/gran:
 * stiffnesses, dampings, friction coefficient, limit_damping (0/1). */
enum gran_param { GRAN_KN, GRAN_KT, GRAN_GAMMAN, GRAN_GAMMAT, GRAN_XMU, GRAN_LIMIT,
                  GRAN_NPARAM };

/* linear/restitution: ke kf mu, then eta = ceta sqrt(m*) and
 * t_col = ctcol sqrt(m*), torque on/off (0/1). */
enum lr_param { LR_KE, LR_KF, LR_MU, LR_CETA, LR_CTCOL, LR_TORQUE, LR_NPARAM };

/* hertz/mindlin: kn = 4/3 E*, kt (8 G*, or 8 G with tangential thesis), damping
 * factor, friction and rolling-friction coefficients, tangential model (0 Mindlin
 * history, 1 003's one-step displacement) (styles/pair/pair_hertz_mindlin.c). */
enum hm_param { HM_KN, HM_KT, HM_CDAMP, HM_MU, HM_MUR, HM_TTHESIS, HM_NPARAM };

/* cohesion: kc, then the effect radius a + b r of each side (i, j). */
enum coh_param { COH_KC, COH_AI, COH_BI, COH_AJ, COH_BJ, COH_NPARAM };

/* granular (styles/pair/pair_granular.c, kernels/pair_granular.cl): the sub-model
 * of each category (GR_N_*, GR_D_*, GR_T_*, GR_R_*, GR_W_* as REAL), limit_damping
 * (0/1), then LAMMPS's coefficients after its conversions and mixing:
 * normal kn (4/3 E* for the material models), damping (tsuji, coeff_restitution:
 * the factor from the restitution coefficient), cohesion; tangential kt, damping ratio, mu;
 * rolling kr, gr, mu_r; twisting kw, gw, mu_w; the dynamic friction coefficient
 * of the /static tangential models (mu above is their static one);
 * 1 where the pair follows LAMMPS 29Sep2021 (-compat lammps2021: dmt's
 * Coulomb load, marshall's twist stiffness), 0 for today's LAMMPS; the heat
 * model (GR_H_*) and its coefficient; 1 where the pair has LAMMPS's
 * synchronized_verlet (the half-step normal, kernels/pair_granular.cl; 0 on
 * walls); the mdr damping type (1: eta_n0 times the contact's damping scale,
 * 2: eta_n0 alone; GR_DAMP holds eta_n0). */
enum gr_param { GR_NMODEL, GR_DMODEL, GR_TMODEL, GR_RMODEL, GR_WMODEL, GR_LIMIT,
                GR_KN, GR_DAMP, GR_COH, GR_KT, GR_GT, GR_MU, GR_KR, GR_GR, GR_MUR,
                GR_KW, GR_GW, GR_MUW, GR_MUD, GR_2021, GR_HMODEL, GR_HK, GR_SYNC,
                GR_MDR_DTYPE, GR_NPARAM };
/* LAMMPS's numbering of the sub-models (pair_granular.cpp); mdr last (today's
 * LAMMPS GranSubModNormalMDR with GranSubModDampingMDR, only together) */
enum gr_normal { GR_N_HOOKE, GR_N_HERTZ, GR_N_HERTZ_MATERIAL, GR_N_DMT, GR_N_JKR, GR_N_MDR };
enum gr_damping { GR_D_VELOCITY, GR_D_MASS_VELOCITY, GR_D_VISCOELASTIC, GR_D_TSUJI,
                  GR_D_COEFF_RESTITUTION /* LAMMPS 2024 */, GR_D_MDR };

/* The mdr block of a pair granular contact's history row (at GR_H_MDR):
 * LAMMPS's 27 entries of GranSubModNormalMDR (side 0 is the contact seen from
 * its higher-tag atom, side 1 from its lower-tag atom; the contact's owner is
 * the lower tag, so side 1 is the owner's), then the normal force of the
 * step (MH_FN: the two sides' mean, penalty applied) and the mean contact
 * area (MH_AC_AVG, compute pair/local p13), which fix granular/mdr
 * computes on the host before the forces (styles/fix/fix_granular_mdr.c) and
 * the kernel reads. */
enum mdr_hist { MH_DELTA_MAX, MH_DELTAP_0, MH_DELTAP_1, MH_DELTA_0, MH_DELTA_1, MH_DELTAO_0,
                MH_DELTAO_1, MH_DELTA_MDR_0, MH_DELTA_MDR_1, MH_DELTA_BULK_0, MH_DELTA_BULK_1,
                MH_DELTAMAX_MDR_0, MH_DELTAMAX_MDR_1, MH_YFLAG_0, MH_YFLAG_1, MH_DELTAY_0,
                MH_DELTAY_1, MH_CA_0, MH_CA_1, MH_AADH_0, MH_AADH_1, MH_AC_0, MH_AC_1,
                MH_EPS_BAR_0, MH_EPS_BAR_1, MH_PENALTY, MH_DAMP_SCALE, MH_FN, MH_AC_AVG, MH_N };
enum gr_tangential { GR_T_NOHISTORY, GR_T_HISTORY, GR_T_MINDLIN, GR_T_MINDLIN_RESCALE,
                     GR_T_MINDLIN_FORCE, GR_T_MINDLIN_RESCALE_FORCE,
                     GR_T_HISTORY_STATIC, GR_T_MINDLIN_STATIC /* today's LAMMPS */,
                     GR_T_HISTORY_CLASSIC, GR_T_MINDLIN_CLASSIC /* LAMMPS 2023+ */ };
enum gr_twist { GR_W_NONE, GR_W_SDS, GR_W_MARSHALL };
enum gr_roll { GR_R_NONE, GR_R_SDS };
/* heat conduction (LAMMPS 2023 GranSubModHeat*; kernels/gran_heat.cl): GR_HK is
 * the conductivity (radius) or the heat transfer coefficient (area) */
enum gr_heat { GR_H_NONE, GR_H_AREA, GR_H_RADIUS };

/* The kernel's part of an mdr wall contact's history (at GRW_HMDR): the
 * normal force and damping scale fix granular/mdr computed for the step;
 * the contact's mdr state (enum mdr_hist) is the host's (the wall rows of
 * the kernels hold WALL_HMAX REAL). */
enum mdrw_hist { MHW_FN, MHW_DAMP_SCALE, MHW_N };
/* fix wall/gran granular: the GR_* set, then the history layout of its one
 * model (kernels/fix_wall_gran.cl): tangential history on (0/1), offsets of
 * the contact radius (mindlin_rescale), rolling displacement, twist angle
 * and JKR touch flag (-1: absent), as LAMMPS 2021 sizes a wall's history;
 * then 1 when a jkr wall reaches as LAMMPS 2021's (-compat lammps2021); the
 * offset of the static/dynamic flag of the /static tangential models (-1);
 * the offset of the mdr wall block (enum mdrw_hist; -1: not mdr). */
enum grw_param { GRW_TANG = GR_NPARAM, GRW_HA, GRW_HROLL, GRW_HTWIST, GRW_HTOUCH, GRW_WIDTH,
                 GRW_JKR2021, GRW_HDYN, GRW_HMDR, GRW_NPARAM };

/* colloid (styles/pair/pair_colloid.c, kernels/pair_colloid.cl): LAMMPS's form
 * (COL_SS small-small LJ, COL_SL colloid-small, COL_LL colloid-colloid as
 * REAL), cutsq, the Hamaker constant A, sigma^3, sigma^6, the radii a1 (of
 * the I type) and a2 (a2 alone: the colloid's radius in COL_SL), LJ
 * prefactors 48 eps s^12, 24 eps s^6, 4 eps s^12, 4 eps s^6 (eps = A/144),
 * and the energy offset (pair_modify shift yes). */
enum col_param { COL_FORM, COL_CUTSQ, COL_A12, COL_SIGMA3, COL_SIGMA6, COL_A1, COL_A2,
                 COL_LJ1, COL_LJ2, COL_LJ3, COL_LJ4, COL_OFFSET, COL_NPARAM };
enum col_form { COL_SS, COL_SL, COL_LL };

/* gran (LIGGGHTS `pair_style gran model ...`, styles/pair/pair_gran.c,
 * kernels/pair_gran.cl), per type pair, from the fix property/global
 * materials: the normal model (LG_N_*), Y* and G* (material mixing), beta
 * = ln e / sqrt(ln^2 e + pi^2), ln e, characteristicVelocity; the stiffness
 * models' kn kt gamman gammat; switches absolute_damping, tangential_damping,
 * limitForce, ktToKnUser (0/1); tangential history (1) or no_history (0) and
 * coefficientFriction; cohesion (LG_C_*) and cohesionEnergyDensity; rolling
 * friction (LG_R_*), coefficientRollingFriction, torsionTorque (0/1); 1 for
 * the wall's set (fix wall/gran model ...: reff = radi, lever radi - delta/2,
 * the wall's contact area); hooke/hysteresis's coefficientMaxElasticStiffness,
 * coefficientAdhesionStiffness, coefficientPlasticityDepth; fix heat/gran's
 * conduction (LG_H_*: none on walls and without the fix), its conductance
 * factor 4 k_i k_j / (k_i + k_j) (thermalConductivity; 0 if one k < 1e-6)
 * and the area of contact_area constant; the epsd rolling models'
 * coefficientRollingViscousDamping (epsd, epsd3; 0 for epsd2), the
 * prefactor of kr (2.25 for epsd, rollingStiffness for epsd3) and of the
 * rolling inertia (1.4 in 3d, 1.5 in 2d); thornton_ning's surfaceEnergy (of the
 * pair) and coefficientYieldRatio (of type I: the contact's first particle,
 * a wall's atom); luding's LoadingStiffness (in LG_KN), UnloadingStiffness,
 * coefficientAdhesionStiffness and coefficientPlasticityDepth (as
 * hooke/hysteresis's, in LG_K2MAX LG_KC LG_PHIF) and pullOffForce (LG_FADH). */
enum lg_param { LG_NMODEL, LG_YEFF, LG_GEFF, LG_BETA, LG_LOGE, LG_CHARV, LG_KN, LG_KT, LG_GN,
                LG_GT, LG_ABSDAMP, LG_TDAMP, LG_LIMIT, LG_KTTOKN, LG_TMODEL, LG_MU, LG_COH,
                LG_CED, LG_ROLL, LG_RMU, LG_TORSION, LG_WALL, LG_K2MAX, LG_KC, LG_PHIF,
                LG_HEAT, LG_HC, LG_HAREA, LG_RVISC, LG_RSTIFF, LG_RINERTIA, LG_GSURF,
                LG_YRATIO, LG_FADH, LG_NPARAM };
enum lg_normal { LG_N_HERTZ, LG_N_HOOKE, LG_N_HERTZ_STIFFNESS, LG_N_HOOKE_STIFFNESS,
                 LG_N_HOOKE_HYSTERESIS, LG_N_THORNTON_NING, LG_N_LUDING };
/* The normal model's history REAL, first in a contact's history row:
 * hooke/hysteresis and luding the largest overlap; thornton_ning its state
 * (enum lg_tn_hist) */
#define LG_NORMAL_HIST(nm)                                                                     \
    ((nm) == LG_N_HOOKE_HYSTERESIS || (nm) == LG_N_LUDING ? 1 : (nm) == LG_N_THORNTON_NING ? 7 : 0)
/* thornton_ning's history: LIGGGHTS's ten values, its four flags in one
 * REAL (LG_TN_* bits) */
enum lg_tn_hist { LG_TN_FLAGS, LG_TN_DELTA_OLD, LG_TN_DELTA_MAX, LG_TN_FORCE_OLD,
                  LG_TN_FORCE_MAX, LG_TN_DETACH_DELTA, LG_TN_DETACH_FORCE };
enum lg_tn_flag { LG_TN_VIRGIN = 1, LG_TN_ADHESION = 2, LG_TN_DETACHING = 4,
                  LG_TN_YIELDING = 8 };
enum lg_cohesion { LG_C_NONE, LG_C_SJKR, LG_C_SJKR2 };
/* the epsd models (elastic-plastic spring-dashpot) keep their spring torque
 * in 3 more history REAL: every model from LG_R_EPSD on has them */
enum lg_rolling { LG_R_NONE, LG_R_CDT, LG_R_EPSD, LG_R_EPSD2, LG_R_EPSD3 };
enum lg_heat { LG_H_NONE, LG_H_OVERLAP, LG_H_PROJECTION, LG_H_CONSTANT };

#endif
