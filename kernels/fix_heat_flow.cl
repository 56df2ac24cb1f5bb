/* fix_heat_flow.cl - LAMMPS's fix heat/flow (2023, fix_heat_flow.cpp
 * final_integrate): explicit Euler on each atom's temperature,
 *   T += dt Q / (m cp)
 * Q the heat flow into the atom of the step (W; the contacts' conduction,
 * kernels/gran_heat.cl), m its mass, cp the specific heat of its type
 * (packed per type on the host: the constant style repeats one value). */

__kernel void heat_flow_final(const int n, const uint groupbit, __global const uint *mask,
                              __global const int *type, __global const REAL *rmass,
                              __global const REAL *heatflow, __global REAL *temperature,
                              __global const REAL *cp, const REAL dt)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    temperature[i] += dt * heatflow[i] / (cp[type[i] - 1] * rmass[i]);
}
