/* fix_setforce.cl - fix setforce, addforce and aveforce (LAMMPS
 * fix_setforce.cpp, fix_addforce.cpp, fix_aveforce.cpp): for each atom of
 * the group (mask & groupbit), its force before the fix into orig (3 REAL
 * per atom, zero for the others: the fix's global vector sums it on the
 * host in tag order), then each component whose bit of `on` is set becomes
 * (add 0) or gains (add 1) the value: (vx, vy, vz) for every atom, or with
 * per the atom's own row of val (the atom-style variables' values). */

__kernel void force_set_add(const int n, const uint groupbit, __global const uint *mask,
                            __global REAL *f, __global REAL *orig, const int on, const int add,
                            const REAL vx, const REAL vy, const REAL vz, const int per,
                            __global const REAL *val)
{
    const int i = get_global_id(0);
    if (i >= n)
        return;
    if (!(mask[i] & groupbit)) {
        vstore3((REAL3)(0), i, orig);
        return;
    }
    const REAL3 v = per ? vload3(i, val) : (REAL3)(vx, vy, vz);
    REAL3 fi = vload3(i, f);
    vstore3(fi, i, orig);
    if (on & 1)
        fi.x = add ? fi.x + v.x : v.x;
    if (on & 2)
        fi.y = add ? fi.y + v.y : v.y;
    if (on & 4)
        fi.z = add ? fi.z + v.z : v.z;
    vstore3(fi, i, f);
}
