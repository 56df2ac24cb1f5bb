/* fix_add_heat.cl - today's LAMMPS's fix add/heat (GRANULAR): heat added to
 * each atom's heat flow of the step (after the contacts' sum, in fix
 * order): style 0 (constant) Q += v, 1 (linear) Q += k (v - T), 2 (quartic)
 * Q += k (v^4 - T^4); v the value, or with peratom the atom's vatom[i]
 * (an atom-style variable); overwrite: Q = 0 first. */

__kernel void add_heat_post_force(const int n, const uint groupbit, __global const uint *mask,
                                  __global REAL *heatflow, __global const REAL *temperature,
                                  const int style, const REAL value, const REAL prefactor,
                                  __global const REAL *vatom, const int peratom,
                                  const int overwrite)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    const REAL v = peratom ? vatom[i] : value;
    REAL q = overwrite ? (REAL)0 : heatflow[i];
    if (style == 0)
        q += v;
    else if (style == 1)
        q += prefactor * (v - temperature[i]);
    else
        q += prefactor * (pow(v, (REAL)4) - pow(temperature[i], (REAL)4));
    heatflow[i] = q;
}
