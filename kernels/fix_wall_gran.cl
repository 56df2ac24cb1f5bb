/* fix_wall_gran.cl - the LAMMPS granular wall models (fix wall/gran, 2021
 * semantics; host side styles/fix/fix_wall_gran.c): the wall stage of the
 * contact pipeline (kernels/wall.cl) with the pair evaluators of
 * pair_gran_hooke.cl, pair_gran_hooke_history.cl and
 * pair_gran_hertz_history.cl, so the wall physics is the pair physics;
 * model granular takes the sub-models of pair_granular.cl with the wall's
 * own layout (run-time: one model per wall, param GRW_*); LIGGGHTS's `model
 * ...` walls take pair_gran.cl's gran_model_eval with a table by (particle
 * type, wall type) of LG_* sets (LG_WALL = 1), its row form with an epsd
 * rolling model (shear, then the spring torque). */

static inline void wall_granular_eval(const struct contact *c, __global const REAL *p, REAL *h,
                                      struct contact_force *out)
{
    const struct gr_layout L = {1 << (int)p[GR_NMODEL], 1 << (int)p[GR_DMODEL],
                                1 << (int)p[GR_TMODEL], 1 << (int)p[GR_RMODEL],
                                1 << (int)p[GR_WMODEL], (int)p[GRW_TANG],
                                (int)p[GRW_HA],         (int)p[GRW_HROLL],
                                (int)p[GRW_HTWIST],     (int)p[GRW_HTOUCH],
                                (int)p[GRW_WIDTH],      1,
                                (int)p[GRW_HDYN],       (int)p[GRW_HMDR]};
    granular_eval_l(c, p, h, out, L);
}

/* accuracy record: pair granular's collision time of the wall's kn
 * (granular_tcol, kernels/pair_granular.cl) */
static inline REAL wall_granular_eval_tcol(const struct contact *c, __global const REAL *p,
                                           const REAL vn)
{
    return granular_tcol(c, p, vn);
}

/* jkr walls (LAMMPS 2021 FixWallGran::pulloff_distance): the reach of a
 * sphere of radius radi, radi + pull-off distance; with p[GRW_JKR2021] by
 * LAMMPS 2021's wall formula, its a^3 = 9 pi coh radi / (4 E) (the wall's
 * own one, not the pair's Reff^2) and the signed pull-off overlap added
 * (it may shrink the reach); else the flat wall's physical pull-off gap,
 * the pair's formula at Reff = radi. E = 3/4 kn (LAMMPS THREEQUARTERS). */
static inline REAL wall_jkr_reach(__global const REAL *p, const REAL radi)
{
    const REAL E = p[GR_KN] * (REAL)0.75, coh = p[GR_COH];
    if (p[GRW_JKR2021] != (REAL)0) {
        const REAL a = cbrt((REAL)9 * (REAL)M_PI * coh * radi / ((REAL)4 * E));
        return radi + (a * a / radi - (REAL)2 * sqrt((REAL)M_PI * coh * a / E));
    }
    return radi - grn_jkr_pulloff(E, coh, radi);
}
#define WALL_REACH_1(p, radi) wall_jkr_reach(p, radi)
#define WALL_HOLD_1(p) ((int)(p)[GRW_HTOUCH])

/* the laws' contact bodies (kernels/contact.cl) */
CONTACT_BODY(gran_hooke_body, gran_hooke_eval, 0, TCOL_OF(gran_hooke_eval))
CONTACT_BODY(gran_hooke_history_body, gran_hooke_history_eval, 0,
             TCOL_OF(gran_hooke_history_eval))
CONTACT_BODY(gran_hertz_history_body, gran_hertz_history_eval, 0,
             TCOL_OF(gran_hertz_history_eval))
CONTACT_BODY(wall_granular_body, wall_granular_eval, 1, TCOL_OF(wall_granular_eval))
CONTACT_BODY(gran_model_body, gran_model_eval, 0, TCOL_OF(gran_model_eval))
CONTACT_BODY(gran_model_row_body, gran_model_eval_row, 1, TCOL_OF(gran_model_eval_row))

/* each model's contact body and its form (1: a history row) */
#define WG_BODY_WG_HOOKE gran_hooke_body
#define WG_BODY_WG_HOOKE_HISTORY gran_hooke_history_body
#define WG_BODY_WG_HERTZ_HISTORY gran_hertz_history_body
#define WG_BODY_WG_GRANULAR wall_granular_body
#define WG_BODY_WG_LIGGGHTS gran_model_body
#define WG_BODY_WG_LIGGGHTS_ROW gran_model_row_body
#define WG_ROW_WG_HOOKE 0
#define WG_ROW_WG_HOOKE_HISTORY 0
#define WG_ROW_WG_HERTZ_HISTORY 0
#define WG_ROW_WG_GRANULAR 1
#define WG_ROW_WG_LIGGGHTS 0
#define WG_ROW_WG_LIGGGHTS_ROW 1

/* every kernel of the table (kernels/wall_gran_kernels.h), without approach:
 * plane and cylinder walls (fix wall/gran), meshes (fix wall/gran ...
 * mesh; no jkr row), region surfaces (fix wall/gran/region) */
#define WG_INSTANCE(name, source, model, jkr)                                                  \
    WG_INSTANCE_##source(name, WG_BODY_##model, WG_ROW_##model, jkr)
#define WG_INSTANCE_WG_WALL(name, body, row, jkr) WALL_KERNEL(name, body, row, 0, jkr)
#define WG_INSTANCE_WG_MESH(name, body, row, jkr) MESH_KERNEL(name, body, row, 0)
#define WG_INSTANCE_WG_REGION(name, body, row, jkr) REGION_KERNEL(name, body, row, jkr)
WALL_GRAN_KERNELS(WG_INSTANCE)
