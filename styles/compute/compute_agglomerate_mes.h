/* compute_agglomerate_mes.h - the minimum enclosing sphere of a set of
 * spheres (styles/compute/compute_agglomerate_mes.c), for compute agglomerate and
 * its unit tests. */
#ifndef GR_COMPUTE_AGGLOMERATE_MES_H
#define GR_COMPUTE_AGGLOMERATE_MES_H

/* Smallest sphere enclosing n spheres (centres p[3i..3i+2], radii r[i]):
 * centre c[3] and radius *R. Welzl's move-to-front recursion on spheres, the
 * basis sphere of up to 4 support spheres solved in closed form (internally
 * tangent, centre in the affine hull of their centres); a final pass
 * guarantees enclosure (R grows to the farthest surface if round-off or a
 * degenerate basis left a sphere outside). `work` holds n ints. n >= 1.
 * Returns 1 when the Welzl result enclosed everything to 1e-12 relative,
 * 0 when the final pass had to grow R. */
int agg_min_sphere(int n, const double *p, const double *r, double c[3], double *R, int *work);

#endif
