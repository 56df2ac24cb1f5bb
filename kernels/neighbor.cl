/* neighbor.cl - device neighbor machinery: rebuild check, periodic wrap and
 * atom extent, binning, a chunked prefix scan, a deterministic counting sort
 * by cell (ties ordered by tag), re-ordering of per-atom arrays, the full
 * Verlet list build (rows in partner-tag order), the contacts of the
 * pipeline (kernels/pair_loop.cl) and their history carried across rebuilds.
 *
 * Determinism: counts and scatter use integer atomics, but each cell's
 * segment is then sorted by tag, so the resulting order depends only on the
 * positions and tags, never on thread timing. */

/* Every step, unless the step before ran it (pair_gather, look): the step's
 * opening for every particle (kernels/atom_step.cl). */
/* arguments: KARGS_nbr_check (kernels/kernel_args.h) */
__kernel void nbr_check(KA_KERNEL(nbr_check))
{
    KA_UNPACK(nbr_check);
    const int i = get_global_id(0);
    if (i >= n)
        return;
    struct fused_atom at;
    at.x = vload3(i, x);
    at.xl = POS_LOAD_LO(i);
    at.v = vload3(i, v);
    if (ninit > 0) {
        at.f = vload3(i, f);
#ifdef HAS_ROTATION
        at.om = vload3(i, omega);
        at.tq = vload3(i, torque);
#endif
        at.m = rmass[i];
        at.r = radius[i];
        at.type = type[i];
    }
    at.mask = mask[i];
    atom_step(i, &at, KA_ARGS(atom_step), v, omega, ops, prm POS_LO_ARG);
}

/* Wrap periodic dimensions into [lo, hi) updating image flags (LAMMPS
 * Domain::pbc, one period at most), and write the per-chunk extent
 * ext[6 c ..] = (min x, min y, min z, max x, max y, max z). */
/* arguments: KARGS_nbr_wrap_extent (kernels/kernel_args.h) */
__kernel void nbr_wrap_extent(KA_KERNEL(nbr_wrap_extent))
{
    KA_UNPACK(nbr_wrap_extent);
    const int c = get_global_id(0);
    const int i0 = c * chunk;
    if (c > 0 && i0 >= n)
        return;
    int i1 = i0 + chunk;
    if (i1 > n)
        i1 = n;
    const int per[3] = {px, py, pz};
#ifndef VREMAP
    (void)v;
    (void)mask;
    (void)hrate;
    (void)vgroup;
#endif
    const REAL lo[3] = {lox, loy, loz}, hi[3] = {hix, hiy, hiz};
    REAL mn[3] = {INFINITY, INFINITY, INFINITY}, mx[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = i0; i < i1; i++) {
#ifdef TRICLINIC
        {
            REAL3 xi = vload3(i, x), xl = POS_LOAD_LO(i);
            int3 im = vload3(i, image);
            const int3 im0 = im;
            pbc_wrap_tri(&xi, &xl, &im, (REAL3)(lox, loy, loz), (REAL3)(hix, hiy, hiz), xy, xz,
                         yz);
            vstore3(xi, i, x);
            POS_STORE_LO(xl, i);
            vstore3(im, i, image);
#ifdef VREMAP
            if ((mask[i] & vgroup) && (im.x != im0.x || im.y != im0.y || im.z != im0.z))
                vstore3(vload3(i, v) - image_velocity(im - im0, hrate), i, v);
#endif
            for (int d = 0; d < 3; d++) {
                mn[d] = fmin(mn[d], x[3 * i + d]);
                mx[d] = fmax(mx[d], x[3 * i + d]);
            }
            continue;
        }
#endif
        for (int d = 0; d < 3; d++) {
            REAL xd = x[3 * i + d];
            if (per[d]) {
#ifdef SPLIT_POS
                REAL xld = xlo[3 * i + d];
#else
                REAL xld = 0;
#endif
                int im = image[3 * i + d];
#ifdef VREMAP
                const int im0 = im;
#endif
                pbc_wrap(&xd, &xld, &im, lo[d], hi[d], hi[d] - lo[d]);
                image[3 * i + d] = im;
#ifdef VREMAP /* orthogonal: only the diagonal rates */
                if ((mask[i] & vgroup) && im != im0)
                    v[3 * i + d] -= (im - im0) * hrate[d];
#endif
                x[3 * i + d] = xd;
#ifdef SPLIT_POS
                xlo[3 * i + d] = xld;
#endif
            }
            mn[d] = fmin(mn[d], xd);
            mx[d] = fmax(mx[d], xd);
        }
    }
    for (int d = 0; d < 3; d++) {
        ext[6 * c + d] = mn[d];
        ext[6 * c + 3 + d] = mx[d];
    }
}

/* Cell of each atom; atoms outside a non-periodic face go to the sentinel
 * cell ncell (they are lost). counts[] must be zero on entry. */
__kernel void nbr_bin(const int n, __global const REAL *x, const int nx, const int ny,
                      const int nz, const REAL lox, const REAL loy, const REAL loz,
                      const REAL hix, const REAL hiy, const REAL hiz, const REAL sx,
                      const REAL sy, const REAL sz, const REAL xy, const REAL xz,
                      const REAL yz, __global int *cellof, __global int *counts)
{
    const int i = get_global_id(0);
    if (i >= n)
        return;
    const REAL3 xi = vload3(i, x);
    int c;
#ifdef TRICLINIC
    const REAL3 u = box_u(xi - (REAL3)(lox, loy, loz), hiy - loy, hiz - loz, xy, xz, yz);
    const int out = !box_inside(u, (REAL3)(hix - lox, hiy - loy, hiz - loz));
#else
    const REAL3 u = xi - (REAL3)(lox, loy, loz);
    const int out = !(xi.x >= lox && xi.x < hix && xi.y >= loy && xi.y < hiy && xi.z >= loz &&
                      xi.z < hiz);
    (void)xy;
    (void)xz;
    (void)yz;
#endif
    if (out) {
        c = nx * ny * nz;
    } else {
        int cx = (int)(u.x * sx), cy = (int)(u.y * sy);
        int cz = (int)(u.z * sz);
        cx = clamp(cx, 0, nx - 1);
        cy = clamp(cy, 0, ny - 1);
        cz = clamp(cz, 0, nz - 1);
        c = (cz * ny + cy) * nx + cx;
    }
    cellof[i] = c;
    atomic_inc(&counts[c]);
}

/* The exclusive scan of m ints in one launch of one work-item (the serial
 * device, where a launch costs more than the loop): out[m] = the total. */
__kernel void scan_serial(const int m, __global const int *in, __global int *out)
{
    if (get_global_id(0) != 0)
        return;
    int acc = 0;
    for (int i = 0; i < m; i++) {
        const int s = in[i];
        out[i] = acc;
        acc += s;
    }
    out[m] = acc;
}

/* Chunked exclusive scan, three launches: partial sums per chunk, a serial
 * scan of the chunk sums, then each chunk scans itself from its offset.
 * start[m] receives the total. */
__kernel void scan_partial(const int m, const int chunk, __global const int *in,
                           __global int *sums)
{
    const int p = get_global_id(0);
    const int i0 = p * chunk;
    if (p > 0 && i0 >= m)
        return;
    int i1 = i0 + chunk;
    if (i1 > m)
        i1 = m;
    int s = 0;
    for (int i = i0; i < i1; i++)
        s += in[i];
    sums[p] = s;
}

__kernel void scan_top(const int nchunk, __global int *sums)
{
    if (get_global_id(0) != 0)
        return;
    int acc = 0;
    for (int p = 0; p < nchunk; p++) {
        const int s = sums[p];
        sums[p] = acc;
        acc += s;
    }
    sums[nchunk] = acc;
}

__kernel void scan_final(const int m, const int chunk, const int nchunk,
                         __global const int *in, __global const int *sums,
                         __global int *out)
{
    const int p = get_global_id(0);
    if (p >= nchunk)
        return;
    const int i0 = p * chunk;
    int i1 = i0 + chunk;
    if (i1 > m)
        i1 = m;
    int acc = sums[p];
    for (int i = i0; i < i1; i++) {
        out[i] = acc;
        acc += in[i];
    }
    if (p == nchunk - 1)
        out[m] = sums[nchunk];
}

/* perm[start[c] + k] = i for the atoms of cell c (in arbitrary order). */
__kernel void nbr_scatter(const int n, __global const int *cellof, __global const int *start,
                          __global int *cursor, __global int *perm)
{
    const int i = get_global_id(0);
    if (i >= n)
        return;
    const int c = cellof[i];
    perm[start[c] + atomic_inc(&cursor[c])] = i;
}

/* Order each cell's segment by tag: the deterministic part of the sort. */
__kernel void nbr_cellsort(const int ncell, __global const int *start, __global int *perm,
                           __global const long *tag)
{
    const int c = get_global_id(0);
    if (c >= ncell)
        return;
    const int s = start[c], e = start[c + 1];
    for (int a = s + 1; a < e; a++) {
        const int pa = perm[a];
        const long ta = tag[pa];
        int b = a - 1;
        while (b >= s && tag[perm[b]] > ta) {
            perm[b + 1] = perm[b];
            b--;
        }
        perm[b + 1] = pa;
    }
}

/* Gather one per-atom array of `words` 32-bit words per atom into its new
 * order, dst[i] = src[perm[i]] (the re-sort goes array by array through one
 * scratch buffer). */
__kernel void nbr_reorder_words(const int n, const int words, __global const int *perm,
                                __global const uint *src, __global uint *dst)
{
    const int i = get_global_id(0);
    if (i >= n)
        return;
    const size_t o = (size_t)perm[i] * words, d = (size_t)i * words;
    for (int k = 0; k < words; k++)
        dst[d + k] = src[o + k];
}

/* Stencil range of one dimension: the 3 neighboring cells (wrapped when
 * periodic, clipped otherwise), or every cell once when there are fewer
 * than 3 (no cell is visited twice). Returns the count; cells in out[]. */
static inline int stencil(const int c, const int nc, const int periodic, int out[3])
{
    int k = 0;
    if (nc < 3) {
        for (int d = 0; d < nc; d++)
            out[k++] = d;
        return k;
    }
    for (int d = -1; d <= 1; d++) {
        int cc = c + d;
        if (cc < 0 || cc >= nc) {
            if (!periodic)
                continue;
            cc = cc < 0 ? cc + nc : cc - nc;
        }
        out[k++] = cc;
    }
    return k;
}

/* The x-stencil of `stencil` as ranges of cells lo[e] .. hi[e] (cells are
 * numbered x fastest, so each range is one contiguous run of the sorted
 * atoms in every (y, z) row): one range, or two when a periodic stencil
 * wraps. The same cells as stencil(c, nc, periodic), each once. Returns the
 * number of ranges. */
static inline int stencil_x(const int c, const int nc, const int periodic, int lo[2], int hi[2])
{
    if (nc < 3) {
        lo[0] = 0;
        hi[0] = nc - 1;
        return 1;
    }
    if (periodic && c == 0) {
        lo[0] = 0;
        hi[0] = 1;
        lo[1] = hi[1] = nc - 1;
        return 2;
    }
    if (periodic && c == nc - 1) {
        lo[0] = nc - 2;
        hi[0] = nc - 1;
        lo[1] = hi[1] = 0;
        return 2;
    }
    lo[0] = max(c - 1, 0);
    hi[0] = min(c + 1, nc - 1);
    return 1;
}

/* The pair test of every list build: j is a neighbor of i when
 * |x_i - x_j| < radi + radj + skin (LAMMPS size lists; with cohesion the
 * effect surfaces; with PAIR_TYPECUT at least typecut[ti][tj] + skin, the
 * type pair's cut-off of a potential), j != i, and the pair is not excluded (type table, group
 * bit pairs). Both list styles (bin, multi) accept exactly these pairs. */
static inline int nbr_accept(const int i, const REAL3 xi, const REAL radi, const int ti,
                             const uint mi, const int j, __global const REAL *x,
                             __global const REAL *radius, __global const int *type,
                             __global const uint *mask, const REAL Lx, const REAL Ly,
                             const REAL Lz, const REAL xy, const REAL xz, const REAL yz,
                             const REAL skin, const int ntypes,
                             __global const int *excl_type, const int nexg,
                             __global const uint *excl_group, __global const long *mol,
                             __global const REAL *typecut)
{
    if (j == i)
        return 0;
    REAL3 del = xi - vload3(j, x);
    MINIMG3(del);
    const REAL rsq = del.x * del.x + del.y * del.y + del.z * del.z;
    const REAL radsum = radi + radius[j];
#if defined(PAIR_TYPECUT) /* a potential (pair colloid): its type pair's cut-off */
    const REAL cut = fmax(fmax(radsum, (REAL)COH_REACH_A + (REAL)COH_REACH_B * radsum),
                          typecut[(ti - 1) * ntypes + type[j] - 1]) + skin;
#elif defined(HAS_COHESION) /* cohesion: the list reaches the effect surfaces */
    const REAL cut = fmax(radsum, (REAL)COH_REACH_A + (REAL)COH_REACH_B * radsum) + skin;
#else
    const REAL cut = radsum + skin;
#endif
    if (rsq >= cut * cut)
        return 0;
    if (excl_type[(ti - 1) * ntypes + type[j] - 1])
        return 0;
    const uint mj = mask[j];
    for (int q = 0; q < nexg; q++) {
        const uint g1 = excl_group[3 * q], g2 = excl_group[3 * q + 1];
        const uint kind = excl_group[3 * q + 2];
        if (kind == 0) {
            if (((mi & g1) && (mj & g2)) || ((mi & g2) && (mj & g1)))
                return 0;
        } else if ((mi & g1) && (mj & g1) && ((mol[i] == mol[j]) == (kind == 1))) {
            return 0; /* molecule/intra (same ID, 0 included) or molecule/inter */
        }
    }
    return 1;
}

/* Insert partner j into row (cnt entries, capacity maxn) in ascending tag
 * order; a full row only counts. The row's content and order depend on the
 * set of partners only, never on the order in which they were found. */
static inline void nbr_row_insert(__global int *row, int *cnt, int *own, const int maxn,
                                  __global const long *tag, const int j, const long tagi)
{
    const long tj = tag[j];
    if (*cnt < maxn) {
        int p = *cnt;
        while (p > 0 && tag[row[p - 1]] > tj) {
            row[p] = row[p - 1];
            p--;
        }
        row[p] = j;
    }
    *own += tj > tagi;
    (*cnt)++;
}

/* nbr_row_insert into a row held in private memory with its partners' tags
 * (rows of at most NBR_PRIV partners): the same row, without a global load
 * of a tag per comparison and a global store per shift. */
#define NBR_PRIV 64
static inline void nbr_row_insert_priv(int *prow, long *ptag, int *cnt, int *own, const int maxn,
                                       const long tj, const int j, const long tagi)
{
    if (*cnt < maxn) {
        int p = *cnt;
        while (p > 0 && ptag[p - 1] > tj) {
            prow[p] = prow[p - 1];
            ptag[p] = ptag[p - 1];
            p--;
        }
        prow[p] = j;
        ptag[p] = tj;
    }
    *own += tj > tagi;
    (*cnt)++;
}

/* Full Verlet list with skin, each row in ascending partner tag (pairs of
 * nbr_accept). nown[i] counts the partners of higher tag: the contacts i
 * owns, the last nown[i] entries of its row. Cells list their atoms in
 * cellatoms (or, after a re-sort, are contiguous index ranges: sorted = 1).
 * Slots beyond maxn are counted but not written: flags[2] receives the
 * largest count of a row that overflows (zero when none does) so the host
 * can grow and rebuild. */
__kernel void nbr_build(const int n, __global const REAL *x, __global const REAL *radius,
                        __global const int *type, __global const uint *mask,
                        __global const long *tag, __global const int *start,
                        __global const int *cellatoms, const int sorted, const int nx,
                        const int ny, const int nz, const int px, const int py, const int pz,
                        const REAL lox, const REAL loy, const REAL loz, const REAL sx,
                        const REAL sy, const REAL sz, const REAL Lx, const REAL Ly,
                        const REAL Lz, const REAL xy, const REAL xz, const REAL yz,
                        const REAL skin, const int maxn, __global int *nlist,
                        __global int *ncount, __global int *nown, __global int *flags,
                        const int ntypes, __global const int *excl_type, const int nexg,
                        __global const uint *excl_group, __global const long *mol,
                        __global const REAL *typecut)
{
    const int i = get_global_id(0);
    if (i >= n)
        return;
    const REAL3 xi = vload3(i, x);
    const REAL radi = radius[i];
    const int ti = type[i];
    const uint mi = mask[i];
    const long tagi = tag[i];
    const REAL3 u = box_u(xi - (REAL3)(lox, loy, loz), Ly, Lz, xy, xz, yz);
    int cx = clamp((int)(u.x * sx), 0, nx - 1);
    int cy = clamp((int)(u.y * sy), 0, ny - 1);
    int cz = clamp((int)(u.z * sz), 0, nz - 1);
    int sys[3], szs[3], xl[2], xh[2];
    const int nxr = stencil_x(cx, nx, px, xl, xh);
    const int nsy = stencil(cy, ny, py, sys);
    const int nsz = stencil(cz, nz, pz, szs);
    __global int *row = nlist + (size_t)i * maxn;
    int cnt = 0, own = 0;
    const int priv = maxn <= NBR_PRIV;
    int prow[NBR_PRIV];
    long ptag[NBR_PRIV];
    for (int a = 0; a < nsz; a++)
        for (int b = 0; b < nsy; b++) {
            const int rowbase = (szs[a] * ny + sys[b]) * nx;
            for (int e = 0; e < nxr; e++) {
                const int s = start[rowbase + xl[e]], t = start[rowbase + xh[e] + 1];
                for (int jj = s; jj < t; jj++) {
                    const int j = sorted ? jj : cellatoms[jj];
                    if (!nbr_accept(i, xi, radi, ti, mi, j, x, radius, type, mask, Lx, Ly, Lz,
                                    xy, xz, yz, skin, ntypes, excl_type, nexg, excl_group, mol,
                                    typecut))
                        continue;
                    if (priv)
                        nbr_row_insert_priv(prow, ptag, &cnt, &own, maxn, tag[j], j, tagi);
                    else
                        nbr_row_insert(row, &cnt, &own, maxn, tag, j, tagi);
                }
            }
        }
    if (priv)
        for (int k = 0; k < cnt && k < maxn; k++)
            row[k] = prow[k];
    ncount[i] = cnt < maxn ? cnt : maxn;
    nown[i] = own;
    if (cnt > maxn) /* only an overflow is read; an atomic per atom bounces a cache line */
        atomic_max(&flags[2], cnt);
}

/* ---- neighbor multi: one cell grid per collection ------------------------
 * Collection c has its own grid (mgrid[4c ..] = nx, ny, nz, first global
 * cell; minv[3c ..] = cells per unit length); the grids are numbered one
 * after another, so one counting sort orders the atoms by collection, then
 * by cell. An atom of collection a looks for partners of collection b in
 * the cells of b's grid within cutab[a ncoll + b] (a bound of the pair
 * cut-off of any a-b pair, skin included), then applies the same pair test
 * as style bin: the same pairs, in the same (tag) order. */

/* Collection of an atom: type2coll[type - 1], or with ninterval cut-offs
 * (collection/interval) the first whose upper diameter is >= 2 radius;
 * -1 when none is. */
static inline int nbr_collection(const int ti, const REAL radi, const int ninterval,
                                 __global const REAL *collcut, __global const int *type2coll)
{
    if (ninterval == 0)
        return type2coll[ti - 1];
    const REAL d = 2 * radi;
    for (int k = 0; k < ninterval; k++)
        if (collcut[k] >= d)
            return k;
    return -1;
}

/* Cells of one dimension within [u - cut, u + cut] (u from the box's lower
 * face, s cells per unit length): up to 2 index ranges lo..hi (2 when a
 * periodic range wraps), or every cell once when the range covers them
 * all. Returns the number of ranges. */
static inline int span(const REAL u, const REAL cut, const REAL s, const int nc,
                       const int periodic, int lo[2], int hi[2])
{
    int a = (int)floor((u - cut) * s), b = (int)floor((u + cut) * s);
    if (b - a + 1 >= nc) {
        lo[0] = 0;
        hi[0] = nc - 1;
        return 1;
    }
    if (!periodic) {
        a = max(a, 0);
        b = min(b, nc - 1);
        if (a > b)
            return 0;
        lo[0] = a;
        hi[0] = b;
        return 1;
    }
    if (a < 0) {
        lo[0] = a + nc;
        hi[0] = nc - 1;
        lo[1] = 0;
        hi[1] = b;
        return 2;
    }
    if (b >= nc) {
        lo[0] = a;
        hi[0] = nc - 1;
        lo[1] = 0;
        hi[1] = b - nc;
        return 2;
    }
    lo[0] = a;
    hi[0] = b;
    return 1;
}

/* Global cell of each atom (its collection's grid); atoms outside a
 * non-periodic face go to the sentinel cell ncell (lost). An atom in no
 * collection sets flags[1] = min(flags[1], its index). counts[] must be
 * zero on entry. */
__kernel void nbr_bin_multi(const int n, __global const REAL *x, __global const REAL *radius,
                            __global const int *type, const int ninterval,
                            __global const REAL *collcut, __global const int *type2coll,
                            __global const int *mgrid, __global const REAL *minv,
                            const int ncell, const REAL lox, const REAL loy, const REAL loz,
                            const REAL hix, const REAL hiy, const REAL hiz, const REAL xy,
                            const REAL xz, const REAL yz, __global int *cellof,
                            __global int *counts, __global int *flags)
{
    const int i = get_global_id(0);
    if (i >= n)
        return;
    const REAL3 xi = vload3(i, x);
    const int col = nbr_collection(type[i], radius[i], ninterval, collcut, type2coll);
    const REAL3 u = box_u(xi - (REAL3)(lox, loy, loz), hiy - loy, hiz - loz, xy, xz, yz);
    int c = ncell;
    if (col < 0) {
        atomic_min(&flags[1], i);
    } else if (
#ifdef TRICLINIC
        box_inside(u, (REAL3)(hix - lox, hiy - loy, hiz - loz))
#else
        xi.x >= lox && xi.x < hix && xi.y >= loy && xi.y < hiy && xi.z >= loz && xi.z < hiz
#endif
    ) {
        const int nx = mgrid[4 * col], ny = mgrid[4 * col + 1], nz = mgrid[4 * col + 2];
        const int cx = clamp((int)(u.x * minv[3 * col]), 0, nx - 1);
        const int cy = clamp((int)(u.y * minv[3 * col + 1]), 0, ny - 1);
        const int cz = clamp((int)(u.z * minv[3 * col + 2]), 0, nz - 1);
        c = mgrid[4 * col + 3] + (cz * ny + cy) * nx + cx;
    }
    cellof[i] = c;
    atomic_inc(&counts[c]);
}

/* Append partner j to row (unsorted; nbr_row_sort orders it); a full row
 * only counts. */
static inline void nbr_row_append(__global int *row, int *cnt, int *own, const int maxn,
                                  __global const long *tag, const int j, const long tagi)
{
    if (*cnt < maxn)
        row[*cnt] = j;
    *own += tag[j] > tagi;
    (*cnt)++;
}

/* Order a row by partner tag: Shell sort (Ciura's gaps, then insertion),
 * O(k^1.3) for the long rows of large spheres where insertion on append
 * is O(k^2). Tags are unique, so the order is the one of nbr_row_insert. */
static inline void nbr_row_sort(__global int *row, const int cnt, __global const long *tag)
{
    const int gaps[8] = {701, 301, 132, 57, 23, 10, 4, 1};
    for (int q = 0; q < 8; q++) {
        const int gap = gaps[q];
        for (int a = gap; a < cnt; a++) {
            const int ja = row[a];
            const long ta = tag[ja];
            int b = a;
            while (b >= gap && tag[row[b - gap]] > ta) {
                row[b] = row[b - gap];
                b -= gap;
            }
            row[b] = ja;
        }
    }
}

/* The full list of style multi: rows, counts and flags as nbr_build (rows
 * appended, then sorted by partner tag). */
__kernel void nbr_build_multi(const int n, __global const REAL *x, __global const REAL *radius,
                              __global const int *type, __global const uint *mask,
                              __global const long *tag, __global const int *start,
                              __global const int *cellatoms, const int sorted, const int ncoll,
                              const int ninterval, __global const REAL *collcut,
                              __global const int *type2coll, __global const int *mgrid,
                              __global const REAL *minv, __global const REAL *cutab,
                              const int px, const int py, const int pz, const REAL lox,
                              const REAL loy, const REAL loz, const REAL Lx, const REAL Ly,
                              const REAL Lz, const REAL xy, const REAL xz, const REAL yz,
                              const REAL skin, const int maxn,
                              __global int *nlist, __global int *ncount, __global int *nown,
                              __global int *flags, const int ntypes,
                              __global const int *excl_type, const int nexg,
                              __global const uint *excl_group, __global const long *mol,
                              __global const REAL *typecut)
{
    const int i = get_global_id(0);
    if (i >= n)
        return;
    const REAL3 xi = vload3(i, x);
    const REAL radi = radius[i];
    const int ti = type[i];
    const uint mi = mask[i];
    const long tagi = tag[i];
    const int ca = nbr_collection(ti, radi, ninterval, collcut, type2coll);
    const REAL3 u = box_u(xi - (REAL3)(lox, loy, loz), Ly, Lz, xy, xz, yz);
    const REAL3 uf = box_ufac(Ly, Lz, xy, xz, yz);
    __global int *row = nlist + (size_t)i * maxn;
    int cnt = 0, own = 0;
    for (int cb = 0; cb < ncoll && ca >= 0; cb++) {
        const REAL cut = cutab[ca * ncoll + cb];
        const int nx = mgrid[4 * cb], ny = mgrid[4 * cb + 1], nz = mgrid[4 * cb + 2];
        const int base = mgrid[4 * cb + 3];
        int xl[2], xh[2], yl[2], yh[2], zl[2], zh[2];
        const int nxr = span(u.x, cut * uf.x, minv[3 * cb], nx, px, xl, xh);
        const int nyr = span(u.y, cut * uf.y, minv[3 * cb + 1], ny, py, yl, yh);
        const int nzr = span(u.z, cut * uf.z, minv[3 * cb + 2], nz, pz, zl, zh);
        for (int a = 0; a < nzr; a++)
            for (int cz = zl[a]; cz <= zh[a]; cz++)
                for (int b = 0; b < nyr; b++)
                    for (int cy = yl[b]; cy <= yh[b]; cy++) {
                        const int rowbase = base + (cz * ny + cy) * nx;
                        for (int e = 0; e < nxr; e++) {
                            const int s = start[rowbase + xl[e]], t = start[rowbase + xh[e] + 1];
                            for (int jj = s; jj < t; jj++) {
                                const int j = sorted ? jj : cellatoms[jj];
                                if (nbr_accept(i, xi, radi, ti, mi, j, x, radius, type, mask,
                                               Lx, Ly, Lz, xy, xz, yz, skin, ntypes,
                                               excl_type, nexg, excl_group, mol, typecut))
                                    nbr_row_append(row, &cnt, &own, maxn, tag, j, tagi);
                            }
                        }
                    }
    }
    if (cnt <= maxn) /* an overflowing row is built again, larger */
        nbr_row_sort(row, cnt, tag);
    ncount[i] = cnt < maxn ? cnt : maxn;
    nown[i] = own;
    if (cnt > maxn) /* only an overflow is read; an atomic per atom bounces a cache line */
        atomic_max(&flags[2], cnt);
}

/* Contacts from the rows: i owns contacts coff[i] .. coff[i] + nown[i] - 1
 * (its last nown[i] row entries, in order), ci/cj name the two atoms. Row
 * slot k < ncount[i] - nown[i] of i (a partner of lower tag, which owns
 * the contact) has its contact in pcon[ioff[i] - coff[i] + k] (found in
 * the owner's row by binary search on the tag). A pair missing from its
 * partner's row sets flags[3] (an inconsistent list). */
__kernel void nbr_contacts(const int n, const int maxn, __global const int *nlist,
                           __global const int *ncount, __global const int *nown,
                           __global const int *coff, __global const int *ioff,
                           __global const long *tag, __global int *ci, __global int *cj,
                           __global int *pcon, __global int *flags)
{
    const int i = get_global_id(0);
    if (i >= n)
        return;
    const int cnt = ncount[i], first = cnt - nown[i];
    const size_t row = (size_t)i * maxn;
    const long tagi = tag[i];
    for (int k = 0; k < cnt; k++) {
        const int j = nlist[row + k];
        if (k >= first) {
            const int c = coff[i] + k - first;
            ci[c] = i;
            cj[c] = j;
            continue;
        }
        const size_t rowj = (size_t)j * maxn;
        int lo = ncount[j] - nown[j], hi = ncount[j] - 1, at = -1;
        while (lo <= hi) {
            const int mid = (lo + hi) / 2;
            const long tm = tag[nlist[rowj + mid]];
            if (tm == tagi) {
                at = mid;
                break;
            }
            if (tm < tagi)
                lo = mid + 1;
            else
                hi = mid - 1;
        }
        if (at < 0) {
            atomic_or(&flags[3], 1);
            continue;
        }
        pcon[ioff[i] - coff[i] + k] = coff[j] + at - (ncount[j] - nown[j]);
    }
}

/* History carried across a rebuild: invperm[perm[i]] = i (old index -> new,
 * -1 for lost atoms: fill first), then every old contact's partner is
 * renamed into the new order, and each new contact (owned by the same atom
 * as before: the lower tag) takes the history of the old contact of its
 * owner with the same partner, or zero. The previous partners and
 * histories are parked in the force buffer during the rebuild (src/engine/neighbor.c:
 * histories from its start, partners from int offset `at`). */
__kernel void nbr_invperm(const int n, __global const int *perm, __global int *invperm)
{
    const int i = get_global_id(0);
    if (i < n)
        invperm[perm[i]] = i;
}

__kernel void hist_rename(const int nold, __global const int *invperm, __global int *parked,
                          const int at)
{
    const int c = get_global_id(0);
    if (c < nold)
        parked[at + c] = invperm[parked[at + c]];
}

#ifdef LMP2021
/* -compat lammps2021: LAMMPS 29Sep2021's neighbor bins (NBinStandard, one
 * process, style bin, atoms in tag order), as src/engine/neighbor.c sets them up. */
struct lmp_grid {
    REAL3 lo, hi, inv;
    int3 n;
    REAL cutsq; /* its cutneighmax squared */
};

/* The bin of one coordinate (coord2bin): bins of 1/inv from lo, n of them
 * inside [lo, hi), images beyond on the same grid */
static inline int lmp_bin(const REAL v, const REAL lo, const REAL hi, const REAL inv, const int n)
{
    if (v >= hi)
        return (int)((v - hi) * inv) + n;
    if (v >= lo)
        return min((int)((v - lo) * inv), n - 1);
    return (int)((v - lo) * inv) - 1;
}

static inline int3 lmp_bin3(const REAL3 v, const struct lmp_grid *G)
{
    return (int3)(lmp_bin(v.x, G->lo.x, G->hi.x, G->inv.x, G->n.x),
                  lmp_bin(v.y, G->lo.y, G->hi.y, G->inv.y, G->n.y),
                  lmp_bin(v.z, G->lo.z, G->hi.z, G->inv.z, G->n.z));
}

/* Closest approach of two bins `d` apart in one dimension (bin_distance) */
static inline REAL lmp_gap(const int d, const REAL inv)
{
    return d > 0 ? (REAL)(d - 1) / inv : d < 0 ? (REAL)(d + 1) / inv : (REAL)0;
}

/* The pair a-b as LAMMPS lists it, a = xa, b = xb, del = xa - xb after
 * minimum image: b's image next to a is its ghost. *in_list: a's stencil (or
 * b's) holds the other's bin, gap below cutneighmax (a pair LAMMPS's list
 * misses where a jkr pull-off made that cut-off short); returns whether the
 * atom with the lower tag owns it: the stencil holds the bins above in
 * (z, y, x) order; in one bin a partner later in the bin's list (the larger
 * index: tag order) or a periodic image above in (z, y, x). */
static inline int lmp_pair(const REAL3 xa, const REAL3 xb, const REAL3 del,
                           const struct lmp_grid *G, const int lower, int *in_list)
{
    const REAL3 shift = (xa - xb) - del;
    const int image = shift.x != 0 || shift.y != 0 || shift.z != 0;
    const REAL3 xi = xb + shift;
    const int3 ba = lmp_bin3(xa, G), bb = lmp_bin3(xi, G), d = bb - ba;
    const REAL gx = lmp_gap(d.x, G->inv.x), gy = lmp_gap(d.y, G->inv.y),
               gz = lmp_gap(d.z, G->inv.z);
    *in_list = gx * gx + gy * gy + gz * gz < G->cutsq;
    int a_owns;
    if (d.z != 0)
        a_owns = d.z > 0;
    else if (d.y != 0)
        a_owns = d.y > 0;
    else if (d.x != 0)
        a_owns = d.x > 0;
    else if (!image)
        a_owns = lower;
    else
        a_owns = xi.z > xa.z || (xi.z == xa.z && (xi.y > xa.y || (xi.y == xa.y && xi.x >= xa.x)));
    return a_owns == lower;
}
#endif

__kernel void hist_transfer(const int ncontact, __global const int *ci, __global const int *cj,
                            __global const int *perm, const int permuted,
                            __global const int *old_coff, __global const int *parked,
                            const int at, __global const REAL *old_shear,
                            __global REAL *shear, __global const REAL *x,
                            __global const REAL *radius, const REAL Lx, const REAL Ly,
                            const REAL Lz, const REAL xy, const REAL xz, const REAL yz,
                            __global const long *tag, const REAL blox,
                            const REAL bloy, const REAL bloz, const REAL bhix, const REAL bhiy,
                            const REAL bhiz, const REAL binvx, const REAL binvy,
                            const REAL binvz, const int nbx, const int nby, const int nbz,
                            const REAL lmp_cutsq POS_LO_PARAM)
{
    /* ncontact < 0: -ncontact contacts and no previous ones (first build) */
    const int have_old = ncontact > 0, nc = have_old ? ncontact : -ncontact;
    __global const int *old_cj = parked + at;
    const int c = get_global_id(0);
    if (c >= nc)
        return;
    const int io = have_old && permuted ? perm[ci[c]] : ci[c], j = cj[c];
    /* LAMMPS (fix neigh/history): a pair that overlaps at the rebuild keeps
     * its history; with a jkr term (pair granular, beyond contact) every
     * listed partner does: apart, it holds zeros unless its contact holds
     * beyond touch */
    REAL3 del = vload3(ci[c], x) - vload3(j, x);
    MINIMG3(del);
#if defined(HAS_COHESION) && defined(GRN_HAS_JKR) /* LAMMPS's beyond_contact */
    int keep = 1;
    (void)radius;
#else
    /* the pair kernel's own test on the same positions (with their low parts
     * in single precision), so that a rebuild drops exactly the histories
     * that kernel zeroes at this step, whatever the schedule */
    int keep = contact_pair_overlaps(del, POS_LOAD_LO(ci[c]) - POS_LOAD_LO(j), radius[ci[c]],
                                     radius[j]);
#endif
#ifdef LMP2021
    struct lmp_grid G;
    G.lo = (REAL3)(blox, bloy, bloz);
    G.hi = (REAL3)(bhix, bhiy, bhiz);
    G.inv = (REAL3)(binvx, binvy, binvz);
    G.n = (int3)(nbx, nby, nbz);
    G.cutsq = lmp_cutsq;
    int listed;
    const int lower_owns = lmp_pair(vload3(ci[c], x), vload3(j, x), del, &G,
                                    tag[ci[c]] < tag[j], &listed);
    keep = keep && listed;
    (void)lower_owns;
#else
    (void)tag;
#endif
    int from = -1;
    for (int o = have_old ? old_coff[io] : 0, e = have_old ? old_coff[io + 1] : 0; keep && o < e;
         o++)
        if (old_cj[o] == j) {
            from = o;
            break;
        }
    for (int q = 0; q < HIST_N; q++)
        shear[(size_t)c * HIST_N + q] = from >= 0 ? old_shear[(size_t)from * HIST_N + q] : (REAL)0;
#ifdef HIST_OWNER /* LAMMPS's owner flips negate these symmetric slots */
    {
        __global REAL *row = shear + (size_t)c * HIST_N;
        const REAL was = row[HIST_OWNER], now = lower_owns ? (REAL)1 : (REAL)-1;
        if (was * now < 0)
            for (int q = HIST_FLIP_LO; q < HIST_FLIP_LO + HIST_FLIP_N; q++)
                row[q] = -row[q];
        row[HIST_OWNER] = now;
    }
#endif
}

/* Per-chunk largest overlap (radsum - r) / min(radi, radj) over the list. */
__kernel void nbr_overlap(const int n, const int chunk, __global const REAL *x,
                          __global const REAL *radius, __global const int *nlist,
                          __global const int *ncount, const int maxn, const REAL Lx,
                          const REAL Ly, const REAL Lz, const REAL xy, const REAL xz,
                          const REAL yz, __global REAL *out)
{
    const int c = get_global_id(0);
    const int i0 = c * chunk;
    if (c > 0 && i0 >= n)
        return;
    int i1 = i0 + chunk;
    if (i1 > n)
        i1 = n;
    REAL best = 0;
    for (int i = i0; i < i1; i++) {
        const REAL3 xi = vload3(i, x);
        const REAL radi = radius[i];
        for (int k = 0; k < ncount[i]; k++) {
            const int j = nlist[(size_t)i * maxn + k];
            REAL3 del = xi - vload3(j, x);
            MINIMG3(del);
            const REAL r = sqrt(del.x * del.x + del.y * del.y + del.z * del.z);
            const REAL radj = radius[j];
            const REAL ov = (radi + radj - r) / fmin(radi, radj);
            best = fmax(best, ov);
        }
    }
    out[c] = best;
}
