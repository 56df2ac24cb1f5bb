/* random.c - RanPark and RanMars as LAMMPS implements them (see random.h).
 * Every operation is in the order LAMMPS performs it, in the same types
 * (int state, double results), so the streams agree to the last bit. */
#include "random.h"

#include <math.h>
#include <string.h>

/* Park-Miller constants: a, m = 2^31 - 1, 1/m, and Schrage's q = m / a,
 * r = m % a, which keep a * seed within 32 bits. */
#define PARK_A 16807
#define PARK_M 2147483647
#define PARK_Q 127773
#define PARK_R 2836

void rng_park_init(struct rng_park *r, int seed)
{
    r->seed = seed;
    r->save = 0;
    r->second = 0;
}

double rng_park_uniform(struct rng_park *r)
{
    int k = r->seed / PARK_Q;
    r->seed = PARK_A * (r->seed - k * PARK_Q) - PARK_R * k;
    if (r->seed < 0)
        r->seed += PARK_M;
    return (1.0 / PARK_M) * r->seed;
}

double rng_park_gaussian(struct rng_park *r)
{
    if (r->save) {
        r->save = 0;
        return r->second;
    }
    double v1, v2, rsq;
    do {
        v1 = 2.0 * rng_park_uniform(r) - 1.0;
        v2 = 2.0 * rng_park_uniform(r) - 1.0;
        rsq = v1 * v1 + v2 * v2;
    } while (rsq >= 1.0 || rsq == 0.0);
    double fac = sqrt(-2.0 * log(rsq) / rsq);
    r->second = v1 * fac;
    r->save = 1;
    return v2 * fac;
}

/* One step of Jenkins' one-at-a-time hash. LAMMPS feeds the bytes through a
 * plain `char`, which is signed on the x86-64 and most other ABIs LAMMPS is
 * built for: bytes >= 0x80 enter sign-extended. We do the same explicitly so
 * the result does not depend on this compiler's char signedness. */
static uint32_t oaat(uint32_t h, unsigned char byte)
{
    h += (uint32_t)(int32_t)(signed char)byte;
    h += h << 10;
    h ^= h >> 6;
    return h;
}

void rng_park_reset_coord(struct rng_park *r, int seed, const double coord[3])
{
    unsigned char b[sizeof(int) + 3 * sizeof(double)];
    memcpy(b, &seed, sizeof(int));
    memcpy(b + sizeof(int), coord, 3 * sizeof(double));
    uint32_t h = 0;
    for (size_t i = 0; i < sizeof b; i++)
        h = oaat(h, b[i]);
    h += h << 3;
    h ^= h >> 11;
    h += h << 15;
    /* LAMMPS keeps 27 bits (mask 0x7ffffff, though its comment says 31):
     * reproduce the mask, not the comment. Seed 0 would stall gaussian(). */
    r->seed = (int)(h & 0x7ffffffu);
    if (!r->seed)
        r->seed = 1;
    for (int i = 0; i < 5; i++)
        rng_park_uniform(r);
    r->save = 0;
}

void rng_mars_init(struct rng_mars *r, int seed)
{
    memset(r, 0, sizeof *r);
    int ij = (seed - 1) / 30082;
    int kl = (seed - 1) - 30082 * ij;
    int i = (ij / 177) % 177 + 2;
    int j = ij % 177 + 2;
    int k = (kl / 169) % 178 + 1;
    int l = kl % 169;
    for (int ii = 1; ii <= 97; ii++) {
        double s = 0.0, t = 0.5;
        for (int jj = 1; jj <= 24; jj++) {
            int m = ((i * j) % 179) * k % 179;
            i = j;
            j = k;
            k = m;
            l = (53 * l + 1) % 169;
            if ((l * m) % 64 >= 32)
                s += t;
            t *= 0.5;
        }
        r->u[ii] = s;
    }
    r->c = 362436.0 / 16777216.0;
    r->cd = 7654321.0 / 16777216.0;
    r->cm = 16777213.0 / 16777216.0;
    r->i97 = 97;
    r->j97 = 33;
    rng_mars_uniform(r);
}

double rng_mars_uniform(struct rng_mars *r)
{
    double uni = r->u[r->i97] - r->u[r->j97];
    if (uni < 0.0)
        uni += 1.0;
    r->u[r->i97] = uni;
    if (--r->i97 == 0)
        r->i97 = 97;
    if (--r->j97 == 0)
        r->j97 = 97;
    r->c -= r->cd;
    if (r->c < 0.0)
        r->c += r->cm;
    uni -= r->c;
    if (uni < 0.0)
        uni += 1.0;
    return uni;
}

double rng_mars_gaussian(struct rng_mars *r)
{
    if (r->save) {
        r->save = 0;
        return r->second;
    }
    double v1, v2, rsq;
    do {
        v1 = 2.0 * rng_mars_uniform(r) - 1.0;
        v2 = 2.0 * rng_mars_uniform(r) - 1.0;
        rsq = v1 * v1 + v2 * v2;
    } while (rsq >= 1.0 || rsq == 0.0);
    double fac = sqrt(-2.0 * log(rsq) / rsq);
    r->second = v1 * fac;
    r->save = 1;
    return v2 * fac;
}

/* LAMMPS's iterative selection: each pass flips unmarked items to marked
 * (too few marked) or marked to unmarked (too many) with probability
 * thresh = missing / candidates, clamped to [0.01, 0.99], walking the
 * candidates as a linked list in index order; after a pass every visited
 * item is appended to the list of its new state. Ends when exactly ntarget
 * are marked. The caller guarantees 0 <= ntarget <= n. */
void rng_mars_select_subset(struct rng_mars *r, int64_t ntarget, int n, int *mark, int *next)
{
    int64_t active[2] = {n, 0};
    int first[2] = {0, -1};
    for (int i = 0; i < n; i++) {
        mark[i] = 0;
        next[i] = i + 1;
    }
    if (n > 0)
        next[n - 1] = -1;
    int64_t nmark = 0;
    while (nmark != ntarget) {
        int mode = ntarget - nmark > 0 ? 0 : 1; /* 0 add, 1 subtract */
        double thresh = mode == 0 ? 1.0 * (double)(ntarget - nmark) / (double)active[0]
                                  : 1.0 * (double)(nmark - ntarget) / (double)active[1];
        thresh = thresh > 0.01 ? thresh : 0.01;
        thresh = thresh < 0.99 ? thresh : 0.99;
        int newvalue = mode == 0 ? 1 : 0;
        int nact[2] = {0, 0}, nfirst[2] = {-1, -1}, nlast[2] = {-1, -1};
        int index = first[mode];
        int64_t nflip = 0;
        while (n > 0 && index >= 0) {
            if (rng_mars_uniform(r) < thresh) {
                mark[index] = newvalue;
                nflip++;
            }
            int old = index;
            index = next[index];
            int w = mark[old];
            nact[w]++;
            if (nfirst[w] < 0)
                nfirst[w] = old;
            if (nlast[w] >= 0)
                next[nlast[w]] = old;
            nlast[w] = old;
            next[old] = -1;
            /* LAMMPS updates the live sets inside the walk; the list it
             * walks is `next`, already relinked, so only these change */
            active[0] = nact[0];
            active[1] = nact[1];
            first[0] = nfirst[0];
            first[1] = nfirst[1];
        }
        nmark += mode == 0 ? nflip : -nflip;
    }
}

double rng_park_draw(void *park)
{
    return rng_park_uniform(park);
}

double rng_mars_draw(void *mars)
{
    return rng_mars_uniform(mars);
}
