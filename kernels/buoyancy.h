/* buoyancy.h - LIGGGHTS's fix buoyancy law (fix_buoyancy.cpp), written once:
 * the volume of a sphere of radius r at coordinate xd below a fluid surface at
 * `level` along the gravity axis, dir the sign of gravity along that axis.
 * Plain C valid as C11 and OpenCL C: styles/fix/fix_buoyancy.c includes it
 * (the fix's global vector) and the engine prepends it to the programs of
 * runs with the fix (kernels/fix_buoyancy.cl). On the host BUOY_REAL is
 * double; in a program the build's REAL.
 *
 * h = (xd - level) dir, the depth of the centre below the surface: above by
 * more than r nothing; below by more than r the whole sphere; else the
 * immersed cap (or the sphere less the dry cap), h_cap (3 a^2 + h_cap^2)
 * pi/6 with a^2 = 2 r h_cap - h_cap^2, in LIGGGHTS's order of operations. */
#ifndef GR_BUOYANCY_H
#define GR_BUOYANCY_H

#ifdef __OPENCL_VERSION__
#define BUOY_REAL REAL
#else
#include <math.h>
#define BUOY_REAL double
#endif

static inline BUOY_REAL buoyancy_volume(const BUOY_REAL xd, const BUOY_REAL level,
                                        const BUOY_REAL dir, const BUOY_REAL r)
{
    const BUOY_REAL c = (BUOY_REAL)4. * (BUOY_REAL)M_PI / (BUOY_REAL)3.;
    const BUOY_REAL pi6 = (BUOY_REAL)M_PI / (BUOY_REAL)6.;
    BUOY_REAL h = (xd - level) * dir;
    const BUOY_REAL hmag = fabs(h);
    if (hmag > r && h < 0)
        return 0;
    if (hmag > r && h > 0)
        return c * r * r * r;
    if (h > 0) { /* the larger part immersed */
        h = r - h;
        const BUOY_REAL a = sqrt((BUOY_REAL)2. * r * h - h * h);
        const BUOY_REAL seg = h * pi6 * ((BUOY_REAL)3. * a * a + h * h);
        return c * r * r * r - seg;
    }
    h = r + h; /* the smaller part: r - |h| */
    const BUOY_REAL a = sqrt((BUOY_REAL)2. * r * h - h * h);
    return h * pi6 * ((BUOY_REAL)3. * a * a + h * h);
}

#endif
