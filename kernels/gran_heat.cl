/* gran_heat.cl - the heat conduction sub-models of pair granular and fix
 * wall/gran granular (LAMMPS 2023+, gran_sub_mod_heat.cpp): the heat
 * flowing into particle i through a contact of radius a with a partner
 * (particle or wall) at temperature tj, i being at ti:
 *   area    q = h pi a^2 (tj - ti)   h the heat transfer coefficient
 *   radius  q = 2 k a (tj - ti)      k the conductivity
 *   none    q = 0
 * a is the normal model's contact radius (sqrt(delta R*), JKR's own).
 * Antisymmetric: the partner receives exactly -q (kernels/pair_loop.cl).
 * Units: energy / time. Included by kernels/pair_granular.cl. */

static inline REAL gran_heat(const int model, const REAL k, const REAL a, const REAL ti,
                             const REAL tj)
{
    if (model == GR_H_AREA)
        return k * (REAL)M_PI * a * a * (tj - ti);
    if (model == GR_H_RADIUS)
        return (REAL)2.0 * k * a * (tj - ti);
    return 0;
}
