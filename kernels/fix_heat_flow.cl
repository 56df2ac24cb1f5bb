/* fix_heat_flow.cl - LAMMPS's fix heat/flow (2023, fix_heat_flow.cpp
 * final_integrate): explicit Euler on each atom's temperature,
 *   T += (Q + S) dt / (m cp)
 * in LIGGGHTS's order of operations (FixScalarTransportEquation: (flux +
 * source) dt / (rmass capacity); with S = 0 the same bits as LAMMPS's dt Q /
 * (cp m)), S the atom's heat source (fix heat/gran's heatSource, else 0),
 * Q the heat flow into the atom of the step (W; the contacts' conduction,
 * kernels/gran_heat.cl), m its mass, cp the specific heat of its type
 * (packed per type on the host: the constant style repeats one value). */

__kernel void heat_flow_final(const int n, const uint groupbit, __global const uint *mask,
                              __global const int *type, __global const REAL *rmass,
                              __global const REAL *heatflow, __global const REAL *source,
                              __global REAL *temperature, __global const REAL *cp, const REAL dt)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    temperature[i] += (heatflow[i] + source[i]) * dt / (rmass[i] * cp[type[i] - 1]);
}
