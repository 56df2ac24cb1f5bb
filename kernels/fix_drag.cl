/* fix_drag.cl - Stokes drag F_d = beta (u_f(x) - v), beta = m/tau_p =
 * 3 pi mu d = 6 pi mu r (000 eq. 2.7-2.8), in a uniform flow or the
 * Taylor-Green vortex (000 eq. 6.1-6.3). Host side and the update schemes:
 * styles/fix/fix_drag.c. */

/* The flow and the drag laws: kernels/drag_law.cl */

__kernel void drag_explicit(const int n, const uint groupbit, __global const uint *mask,
                            __global const REAL *x, __global const REAL *v, __global REAL *f,
                            __global const REAL *radius, __global const REAL *rmass,
                            const REAL mu, const int flow, const REAL p0, const REAL p1,
                            const REAL p2)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    (void)rmass;
    const REAL3 uf = drag_flow(vload3(i, x), flow, p0, p1, p2);
    vstore3(drag_explicit_force(vload3(i, f), uf, vload3(i, v), radius[i], mu), i, f);
}

/* Effective drag for one half kick of length h (implicit or exact update):
 * F = f - (replace ? D_old : 0) are the other forces, v' the velocity after
 * the kick, D = m (v' - v)/h - F; f = F + D and D is stored. dstore per atom:
 * D (3 REAL) then u_f(x) (3): the post_force call (replace 0) evaluates the
 * flow and keeps it, the end_of_step call of the same step (replace 1, same
 * position: only velocities change in between) reuses it. */
__kernel void drag_implicit(const int n, const uint groupbit, __global const uint *mask,
                            __global const REAL *x, __global const REAL *v, __global REAL *f,
                            __global const REAL *radius, __global const REAL *rmass,
                            const REAL mu, const int flow, const REAL p0, const REAL p1,
                            const REAL p2, __global REAL *dstore, const int replace,
                            const int exact, const REAL h)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    REAL3 uf;
    if (replace) {
        uf = vload3(2 * i + 1, dstore);
    } else {
        uf = drag_flow(vload3(i, x), flow, p0, p1, p2);
        vstore3(uf, 2 * i + 1, dstore);
    }
    REAL3 F = vload3(i, f);
    if (replace)
        F -= vload3(2 * i, dstore);
    const REAL3 D = drag_half_kick(F, uf, vload3(i, v), rmass[i], radius[i], mu, exact, h);
    vstore3(D, 2 * i, dstore);
    vstore3(F + D, i, f);
}

/* update trapezoidal (000 eq. 3.8-3.9): per step the full backward-Euler
 * velocity v_{n+1} = v_n + dt (u_f(x_n) - v_n + tau F_n/m) / (tau + dt) and the
 * trapezoidal position x_{n+1} = x_n + dt (v_n + v_{n+1})/2, realised through
 * the velocity-Verlet kicks: the opening kick (closing = 0, from x_n, v_n,
 * F_n) lands on v_{n+1/2} = (v_n + v_{n+1})/2, so the drift x += dt v_{n+1/2}
 * is eq. 3.9; the closing kick (closing = 1) adds the same dv again, landing
 * on v_{n+1}. dstore per atom: D (3 REAL) then dv of the opening kick (3). */
__kernel void drag_trapezoid(const int n, const uint groupbit, __global const uint *mask,
                             __global const REAL *x, __global const REAL *v, __global REAL *f,
                             __global const REAL *radius, __global const REAL *rmass,
                             const REAL mu, const int flow, const REAL p0, const REAL p1,
                             const REAL p2, __global REAL *dstore, const int replace,
                             const int closing, const REAL h)
{
    const int i = get_global_id(0);
    if (i >= n || !(mask[i] & groupbit))
        return;
    const REAL m = rmass[i];
    REAL3 F = vload3(i, f);
    if (replace)
        F -= vload3(2 * i, dstore);
    REAL3 dv;
    if (closing) {
        dv = vload3(2 * i + 1, dstore);
    } else {
        const REAL tau = m / ((REAL)6 * (REAL)M_PI * mu * radius[i]);
        const REAL3 uf = drag_flow(vload3(i, x), flow, p0, p1, p2);
        /* half of the full-step change: (target - v) dt / (2 (tau + dt)), h = dt/2 */
        dv = (uf + (tau / m) * F - vload3(i, v)) * (h / (tau + (REAL)2 * h));
        vstore3(dv, 2 * i + 1, dstore);
    }
    const REAL3 D = (m / h) * dv - F;
    vstore3(D, 2 * i, dstore);
    vstore3(F + D, i, f);
}
