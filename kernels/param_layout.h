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

/* hertz/mindlin: kn = 4/3 E*, kt = 8 G*, damping factor, friction and
 * rolling-friction coefficients (styles/pair_hertz_mindlin.c). */
enum hm_param { HM_KN, HM_KT, HM_CDAMP, HM_MU, HM_MUR, HM_NPARAM };

/* cohesion: kc, then the effect radius a + b r of each side (i, j). */
enum coh_param { COH_KC, COH_AI, COH_BI, COH_AJ, COH_BJ, COH_NPARAM };

#endif
