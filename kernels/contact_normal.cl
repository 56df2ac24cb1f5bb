/* contact_normal.cl - the normal force of the source-document contact laws
 * (linear/restitution, hertz/mindlin), made consistent with the velocity
 * Verlet step so that the integrator never gains energy in a collision.
 *
 * Why: evaluated pointwise, a contact force that starts and ends between two
 * steps gives a restitution that depends on the phase of the steps against
 * the contact (an elastic collision rebounds at up to 1 + (w dt)^2/8), and an
 * explicit dashpot lags by half a step (+3 % restitution at t_col/8). Here
 * the kick of one step is the one that makes the two-body collision exact in
 * energy (elastic part) and in impulse (dashpot), whatever the phase; the
 * dashpot coefficient is then corrected (normal_damping_scale) for the
 * scheme's own restitution error, which is large at low e.
 *
 * Both laws have the shape U(d) = cv^2 P(d)^2 (elastic energy) and
 * H(d) = ch P(d) (dashpot impulse per overlap, H' = eta), with
 * P(d) = d (linear: cv^2 = ke/2, ch = eta) or d^(5/4) (Hertz). With d the
 * overlap at the kick, s its rate over the drift that led here (lagged
 * velocity of the kick-drift-kick step) and S the rate after the kick,
 *   dp = d - dt s,  dn = d + dt S            (two-body overlaps a step away)
 *   F_el = 2 cv^2 P(d) [P(dn+) - P(dp+)] / (dn - dp)
 *   F_d  = ch/dt { [P(d) - P(dp+)] d/(d + dp+) + [P(dn+) - P(d)] d/(d + dn+) }
 *   S    = s - dt (F_el + F_d) / m*           (solved for S; x+ = max(x, 0))
 * F_el conserves E = S^2 + (2/m*) cv^2 P(d+) P(dn+) exactly across a step
 * (a discrete gradient of the segment energy), so an elastic two-body
 * collision returns its incoming normal speed to round-off. Inside the
 * contact F_el = U'(d) + O(dt^2) (linear: exactly ke d). F_d is the dashpot
 * impulse over the overlap change of the two neighbouring drifts, each split
 * between its end points in proportion to their overlaps, so the first and
 * last kick of a contact carry the impulse of the partial step. The residual
 * S - s + dt F/m* grows with S at slope >= 1: the root is unique and
 * bracketed by [s, s - r(s)]. Returns F_el + F_d (repulsive > 0). */

#define NORMAL_LINEAR 0
#define NORMAL_HERTZ 1
/* round-off, and the span under which a divided difference is round-off */
#ifdef USE_DOUBLE
#define NORMAL_EPS DBL_EPSILON
#define NORMAL_TINY 1e-8
#else
#define NORMAL_EPS FLT_EPSILON
#define NORMAL_TINY 3e-4
#endif

static inline REAL normal_shape(const int law, const REAL d)
{
    if (d <= (REAL)0)
        return (REAL)0;
    return law == NORMAL_HERTZ ? d * sqrt(sqrt(d)) : d;
}

/* [P(b) - P(a)] / (b - a), with the derivative at the midpoint when the two
 * overlaps coincide to within sqrt(epsilon) (round-off would dominate). */
static inline REAL normal_shape_slope(const int law, const REAL a, const REAL b)
{
    const REAL span = b - a;
    const REAL scale = fmax(fabs(a), fabs(b));
    if (fabs(span) > (REAL)NORMAL_TINY * scale)
        return (normal_shape(law, b) - normal_shape(law, a)) / span;
    const REAL mid = (REAL)0.5 * (a + b);
    if (mid <= (REAL)0)
        return (REAL)0;
    return law == NORMAL_HERTZ ? (REAL)1.25 * sqrt(sqrt(mid)) : (REAL)1;
}

/* Dashpot coefficient correction g >= 1 (ch -> g ch): why. The scheme above
 * is second order, and its restitution error grows with the damping
 * exponent: ln e_eff - ln e ~ |ln e| (dt/t_col)^2, because both the interior
 * decay and the partial steps at the ends of a contact are off by relative
 * O(dt^2) and the restitution is exp(-(decay rate) t_col). At e = 0.01 that
 * is +8 % at t_col/32 and +140 % at t_col/8 (the per-step damping
 * a = eta dt / m* reaches 1.15). g cancels that error: a polynomial in
 * x2 = k dt^2 / m* and a2 = a^2 (k the contact stiffness dF/dd), fitted to
 * the phase-averaged restitution of two-body collisions of this very scheme
 * (linear law, e = 0.02 .. 0.95, 7 .. 64 steps per collision: g - 1 to 2 %;
 * doc/contact_normal.md). Hertz uses the same terms at the local stiffness
 * and damping of the kick's overlap, with the x and a groups scaled by
 * NORMAL_GX / NORMAL_GA (fitted the same way, e = 0.01 .. 0.8). Without
 * damping g does not enter (e = 1 stays exact); x2 and a2 are held at the
 * edge of the fitted range beyond it (t_col/7 at e = 0.02). */
#define NORMAL_GX_HERTZ 0.806457
#define NORMAL_GA_HERTZ 1.184070
static inline REAL normal_damping_scale(const int law, const REAL cv2, const REAL ch,
                                        const REAL d, const REAL meff, const REAL dt)
{
    REAL k, eta, gx = (REAL)1, ga = (REAL)1;
    if (law == NORMAL_HERTZ) {
        const REAL q = sqrt(d);
        k = (REAL)3.75 * cv2 * q;             /* d/dd (2.5 cv2 d^1.5) */
        eta = (REAL)1.25 * ch * sqrt(q);      /* d/dd (ch d^1.25) */
        gx = (REAL)NORMAL_GX_HERTZ;
        ga = (REAL)NORMAL_GA_HERTZ;
    } else {
        k = (REAL)2 * cv2;
        eta = ch;
    }
    const REAL x = fmin(k * dt * dt / meff, (REAL)0.52);
    const REAL a = eta * dt / meff;
    const REAL b = fmin(a * a, (REAL)1.3);
    const REAL px = x * ((REAL)0.28736528 + x * ((REAL)-0.09076945 + x * (REAL)0.45881879));
    const REAL pa = b * ((REAL)-0.04055182 + x * ((REAL)0.01504070 + x * (REAL)-0.20586836)
                         + b * ((REAL)-0.00516588 + x * (REAL)0.06496180 + b * (REAL)-0.00648897));
    return (REAL)1 + gx * px + ga * pa;
}

/* F(S) of the header for an after-kick overlap rate S; pd = P(d) and jl, the
 * share of the past drift's dashpot impulse, do not depend on S. */
static inline REAL normal_force_at(const int law, const REAL cv2, const REAL ch, const REAL d,
                                   const REAL pd, const REAL dp, const REAL jl, const REAL dt,
                                   const REAL S)
{
    const REAL dn = d + dt * S;
    const REAL dnp = fmax(dn, (REAL)0);
    const REAL fel = (REAL)2 * cv2 * pd * normal_shape_slope(law, dp, dn);
    const REAL jr = (normal_shape(law, dnp) - pd) * (d / (d + dnp));
    return fel + ch * (jl + jr) / dt;
}

/* A bound on the round-off of normal_force_at(S) beyond that of its
 * arguments: the differences of the shapes of nearly equal overlaps lose
 * digits in proportion to the largest shape over the difference (the
 * Hertz elastic slope; the dashpot's P(dn) - P(d) for both laws), so near a
 * root whose overlaps differ little (a resting contact: dn ~ dp ~ d) r can
 * not get below it however S is chosen. */
static inline REAL normal_residual_noise(const int law, const REAL cv2, const REAL ch,
                                         const REAL d, const REAL pd, const REAL dp,
                                         const REAL dt, const REAL S)
{
    const REAL dn = d + dt * S;
    const REAL pm = normal_shape(law, fmax(fmax(d, dn), dp));
    REAL el = (REAL)0;
    if (law == NORMAL_HERTZ) {
        const REAL span = fabs(dn - dp);
        if (span > (REAL)NORMAL_TINY * fmax(fabs(dn), fabs(dp)))
            el = (REAL)2 * cv2 * pd / span;
    }
    return (REAL)8 * NORMAL_EPS * pm * (el + fabs(ch) / dt);
}

/* The linear law with the overlap positive a drift before and after the kick
 * (dp > 0, dn > 0): there F_el = ke d and jr = dt S d / (2 d + dt S), so
 * r(S) (2 d + dt S) is the quadratic dt S^2 + (2 d + c0 dt + A) S + 2 d c0
 * with c0 = k (ke d + ch jl / dt) - s and A = k ch d. r rises with S where
 * dn > 0, so at most one root lies there: returns 1 and that root in *S
 * (the cancellation-free pair of roots q / dt, 2 d c0 / q), else 0 (the
 * contact ends within the drift: the caller iterates). */
static inline int normal_linear_inside(const REAL cv2, const REAL ch, const REAL d, const REAL s,
                                       const REAL jl, const REAL k, const REAL dt, REAL *S)
{
    const REAL c0 = k * ((REAL)2 * cv2 * d + ch * jl / dt) - s;
    const REAL B = (REAL)2 * d + c0 * dt + k * ch * d;
    const REAL disc = B * B - (REAL)8 * dt * d * c0;
    if (!(disc >= (REAL)0))
        return 0;
    const REAL q = (REAL)-0.5 * (B + copysign(sqrt(disc), B));
    if (q == (REAL)0)
        return 0;
    const REAL s1 = q / dt, s2 = (REAL)2 * d * c0 / q;
    *S = d + dt * s1 > (REAL)0 ? s1 : s2;
    return d + dt * *S > (REAL)0;
}

/* Normal force magnitude along n for overlap d > 0 closing at rate s over
 * the last drift (s = -vr.n), reduced mass meff, time step dt. */
static inline REAL contact_normal_force(const int law, const REAL cv2, REAL ch,
                                        const REAL d, const REAL s, const REAL meff,
                                        const REAL dt)
{
    if (!(d > (REAL)0)) /* touching to round-off: r rounded up to radsum */
        return (REAL)0;
    if (ch != (REAL)0)
        ch *= normal_damping_scale(law, cv2, ch, d, meff, dt);
    const REAL pd = normal_shape(law, d);
    const REAL dp = d - dt * s;
    const REAL dpp = fmax(dp, (REAL)0);
    const REAL jl = (pd - normal_shape(law, dpp)) * (d / (d + dpp));
    const REAL k = dt / meff;
    REAL Sq;
    if (law == NORMAL_LINEAR && dp > (REAL)0 && normal_linear_inside(cv2, ch, d, s, jl, k, dt, &Sq))
        return (s - Sq) / k;
    /* bracket [lo, hi] with r(lo) <= 0 <= r(hi), r(S) = S - s + k F(S) */
    const REAL f0 = normal_force_at(law, cv2, ch, d, pd, dp, jl, dt, s);
    const REAL r0 = k * f0;
    if (r0 == (REAL)0)
        return f0;
    REAL lo = s, hi = s, rlo = r0, rhi = r0;
    const REAL s1 = s - r0;
    const REAL r1 = s1 - s + k * normal_force_at(law, cv2, ch, d, pd, dp, jl, dt, s1);
    if (r0 > (REAL)0) {
        lo = s1;
        rlo = r1;
    } else {
        hi = s1;
        rhi = r1;
    }
    /* Anderson-Bjorck regula falsi: r is monotone with slope >= 1 and nearly
     * linear, so |S - root| <= |r(S)|: converged when r (or the bracket) is
     * at the round-off of the rates involved, or when r is within its own
     * round-off (normal_residual_noise) */
    const REAL tol = (REAL)4 * NORMAL_EPS * (fabs(s) + fabs(r0));
    REAL S = rlo >= (REAL)0 ? lo : hi;
    int side = 0;
    for (int it = 0; it < 60 && rlo < (REAL)0 && rhi > (REAL)0; it++) {
        S = (lo * rhi - hi * rlo) / (rhi - rlo);
        if (!(S > lo && S < hi))
            S = (REAL)0.5 * (lo + hi);
        const REAL rs = S - s + k * normal_force_at(law, cv2, ch, d, pd, dp, jl, dt, S);
        if (fabs(rs) <= tol + k * normal_residual_noise(law, cv2, ch, d, pd, dp, dt, S) ||
            hi - lo <= tol)
            break;
        if (rs < (REAL)0) {
            if (side == -1) {
                const REAL m = (REAL)1 - rs / rlo;
                rhi *= m > (REAL)0 ? m : (REAL)0.5;
            }
            lo = S;
            rlo = rs;
            side = -1;
        } else {
            if (side == 1) {
                const REAL m = (REAL)1 - rs / rhi;
                rlo *= m > (REAL)0 ? m : (REAL)0.5;
            }
            hi = S;
            rhi = rs;
            side = 1;
        }
    }
    return (s - S) / k;
}

/* ---- linear law: the two-body collision integrated exactly ----
 *
 * With the pre-contact kick below (c->approach: the caller evaluates pairs
 * that one drift at their rate brings into or out of contact), the linear
 * spring-dashpot m* d'' = -ke d - eta d' (d > 0) has a closed-form solution,
 * and each kick sets the rate S of the next drift so that the overlaps at
 * the kicks are the exact ones. Why: below e = 0.1 at t_col/8 one drift of
 * free flight overshoots the deepest overlap the collision ever reaches, and
 * no history-free kick made after that can return the right restitution
 * (doc/contact_normal.md); the kick one step earlier can. With
 * a = eta / (2 m*), w = pi / t_col (so ke / m* = a^2 + w^2), b = a / w,
 * W = w dt and G(th) = exp(-b th) sin th (the unit collision: d(t) = u0
 * G(w t) / w from first touch, exit rate -e u0 at th = pi), d the overlap at
 * the kick and s its rate over the last drift (dp = d - dt s):
 *   apart, closing, d + dt s > 0 (pre-contact): contact starts tau0 = -d/s
 *     into the drift; S makes the next overlap s G(W - w tau0) / w, or, when
 *     the whole contact fits in the drift, S = -e s;
 *   d > 0 >= dp (first kick in contact, after a pre-contact kick): dp = -u0
 *     tau0 and d = u0 G(W - w tau0) / w; their ratio fixes tau0 (one root,
 *     Newton from the free-flight value, monotone for a concave G) and u0;
 *     S makes the next overlap u0 G(2W - w tau0) / w;
 *   d > 0, dp > 0 (inside): the exact two-step recurrence of the ODE,
 *     d_next = 2 E cos W d - E^2 dp (E = exp(-a dt)), written without
 *     cancellation; its force is q m* d / dt^2 + (1 - E^2) m* s / dt,
 *     q = (1 - E)^2 + 4 E sin^2(W/2); the last kick of a contact continues
 *     on the solution's negative lobe;
 *   apart, dp > 0 (first kick after the contact ended inside the drift):
 *     S = the solution's rate where it crossed zero, from dp and d.
 * At setup (the run's first force, applied as a half kick, with s the
 * current velocity) the pre-contact kick is doubled so that the first drift
 * still runs at S, and no contact has just ended.
 * So an isolated two-body collision rebounds at e to round-off, whatever
 * dt and the phase, e = 1 included. Without c->approach (mesh walls,
 * hybrid/overlay) the first kick in contact would misread a free-flight
 * state, so those contacts keep contact_normal_force (NORMAL_LINEAR). */
static inline REAL normal_arc(const REAL b, const REAL th)
{
    return exp(-b * th) * sin(th);
}

static inline REAL contact_normal_linear(const REAL eta, const REAL tcol, const REAL d,
                                         const REAL s, const REAL meff, const REAL dt,
                                         const REAL scale, const int setup)
{
    const REAL pi = (REAL)M_PI;
    const REAL a = eta / ((REAL)2 * meff), w = pi / tcol, b = a / w, W = w * dt;
    /* in contact: d > tol. A contact that ends at a kick (d = 0 but for the
     * round-off of the overlaps of bodies of size scale) ends there, and the
     * next kick, whose reconstructed dp is as small, does not end it again.
     * (Single precision: an overlap below 1e-6 scale carries no force.) */
    const REAL tol = (REAL)8 * NORMAL_EPS * scale;
    REAL S;
    if (!(d > tol)) {
        if (s > (REAL)0 && d + dt * s > (REAL)0) {          /* pre-contact */
            const REAL ph = W + w * d / s;
            S = ph >= pi ? -exp(-b * pi) * s : (s * normal_arc(b, ph) / w - d) / dt;
            if (setup) /* the run's first kick is a half kick, s the free-flight rate */
                return (REAL)2 * meff * (s - S) / dt;
        } else if (!setup && s < (REAL)0 && d - dt * s > tol) { /* ended in the drift */
            const REAL sn = sin(W);
            if (!(sn > (REAL)0)) /* dt >= t_col: no solution through both overlaps */
                return (REAL)0;
            const REAL B = (d * cos(W) - exp(-a * dt) * (d - dt * s)) / sn;
            S = -w * hypot(d, B) * exp(-b * atan2(d, -B));
        } else {
            return (REAL)0;
        }
        return meff * (s - S) / dt;
    }
    const REAL q = dt * s - d; /* -dp */
    if (q >= (REAL)0) {        /* first kick in contact */
        /* h(p) = q G(W - p) - d p = 0 for p = w tau0 in [0, W q / (d + q)] */
        REAL lo = (REAL)0, hi = W * q / (d + q), p = hi;
        for (int it = 0; it < 40; it++) {
            const REAL t = W - p, ex = exp(-b * t), sn = sin(t);
            const REAL h = q * ex * sn - d * p;
            if (h > (REAL)0)
                lo = p;
            else
                hi = p;
            const REAL hd = -q * ex * (cos(t) - b * sn) - d;
            REAL pn = hd < (REAL)0 ? p - h / hd : (REAL)0.5 * (lo + hi);
            if (!(pn >= lo && pn <= hi))
                pn = (REAL)0.5 * (lo + hi);
            const int done = fabs(pn - p) <= (REAL)4 * NORMAL_EPS * W;
            p = pn;
            if (done)
                break;
        }
        const REAL u0 = dt * s * w / (normal_arc(b, W - p) + p);
        S = (u0 * normal_arc(b, (REAL)2 * W - p) / w - d) / dt;
        return meff * (s - S) / dt;
    }
    const REAL em1 = expm1(-a * dt), E = (REAL)1 + em1, sh = sin((REAL)0.5 * W);
    return meff * ((em1 * em1 + (REAL)4 * E * sh * sh) * d - em1 * ((REAL)2 + em1) * dt * s) /
           (dt * dt);
}
