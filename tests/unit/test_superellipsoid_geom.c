/* test_superellipsoid_geom.c - the superellipsoid contact geometry is one
 * source for the host and the device (kernels/superellipsoid_geom.h): the
 * device (PoCL) compiles it and, over 240 pairs of random shapes,
 * blockiness (ellipsoid, n1 = n2, general), orientations and distances,
 * finds the same contact points, normals, overlaps, curvatures and
 * separating box axes as the host. The statuses and box axes must agree
 * exactly and the reals to 1e-12 of their scale; the count of bit-identical
 * reals is printed (the device's pow and cbrt are its own libm's). */
#include <stdint.h>
#include <stdlib.h>

#include "test.h"

#include "engine.h"
#include "kernel_text.h"
#include "ocl.h"
#include "rigid_math.h"
#include "superellipsoid_contact.h"

enum { NCASE = 240, NIN = 36, NOUT = 16 };

/* One case: body i at the origin, body j at distance d along a random
 * direction; in[] = xi R_i shape_i block_i, xj R_j shape_j block_j, form,
 * gaussian (36 doubles). */
static void case_bodies(const double *in, struct sqe_body *bi, struct sqe_body *bj)
{
    struct sqe_body *b[2] = {bi, bj};
    for (int k = 0; k < 2; k++) {
        const double *p = in + 17 * k;
        for (int q = 0; q < 3; q++)
            b[k]->xc[q] = p[q];
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++)
                b[k]->R[r][c] = p[3 + 3 * r + c];
        for (int q = 0; q < 3; q++)
            b[k]->shape[q] = p[12 + q];
        b[k]->block[0] = p[15];
        b[k]->block[1] = p[16];
        b[k]->kind = sqe_kind(b[k]->block);
    }
}

/* The host's evaluation of one case: the same steps as the kernel below. */
static void host_case(const double *in, double *out)
{
    struct sqe_body bi, bj;
    case_bodies(in, &bi, &bj);
    enum sqe_formulation form = in[34] != 0 ? SQE_GEOMETRIC : SQE_ALGEBRAIC;
    double reqi = cbrt(bi.shape[0] * bi.shape[1] * bi.shape[2]);
    double reqj = cbrt(bj.shape[0] * bj.shape[1] * bj.shape[2]);
    double X0[4], nij[3] = {0, 0, 0}, rinv = 1.0 / (reqi + reqj);
    for (int q = 0; q < 3; q++)
        X0[q] = reqj * rinv * bi.xc[q] + reqi * rinv * bj.xc[q];
    X0[3] = reqj / reqi;
    int st = sqe_contact_point(&bi, &bj, X0, nij, form);
    for (int k = 0; k < NOUT; k++)
        out[k] = 0.0;
    out[0] = st;
    out[1] = sqe_obb_separating_axis(&bi, &bj, 0);
    for (int q = 0; q < 4; q++)
        out[2 + q] = X0[q];
    if (st != 0)
        return;
    for (int q = 0; q < 3; q++)
        out[6 + q] = nij[q];
    double nji[3] = {-nij[0], -nij[1], -nij[2]};
    double di = sqe_overlap_distance(&bi, X0, nij), dj = sqe_overlap_distance(&bj, X0, nji);
    double pi[3], pj[3];
    for (int q = 0; q < 3; q++) {
        pi[q] = X0[q] + di * nij[q];
        pj[q] = X0[q] + dj * nji[q];
    }
    out[9] = di;
    out[10] = dj;
    out[11] = sqe_curvature(&bi, pi, 0);
    out[12] = sqe_curvature(&bj, pj, 0);
    out[13] = sqe_curvature(&bi, pi, 1);
    out[14] = sqe_curvature(&bj, pj, 1);
}

static const char *kernel_text =
    "__kernel void sqe_check(__global const double *in, __global double *out, int n)\n"
    "{\n"
    "    int c = get_global_id(0);\n"
    "    if (c >= n)\n"
    "        return;\n"
    "    __global const double *p = in + 36 * c;\n"
    "    __global double *o = out + 16 * c;\n"
    "    struct sqe_body bi, bj;\n"
    "    struct sqe_body *b[2] = {&bi, &bj};\n"
    "    for (int k = 0; k < 2; k++) {\n"
    "        __global const double *s = p + 17 * k;\n"
    "        for (int q = 0; q < 3; q++)\n"
    "            b[k]->xc[q] = s[q];\n"
    "        for (int r = 0; r < 3; r++)\n"
    "            for (int cc = 0; cc < 3; cc++)\n"
    "                b[k]->R[r][cc] = s[3 + 3 * r + cc];\n"
    "        for (int q = 0; q < 3; q++)\n"
    "            b[k]->shape[q] = s[12 + q];\n"
    "        b[k]->block[0] = s[15];\n"
    "        b[k]->block[1] = s[16];\n"
    "        b[k]->kind = sqe_kind(b[k]->block);\n"
    "    }\n"
    "    enum sqe_formulation form = p[34] != 0 ? SQE_GEOMETRIC : SQE_ALGEBRAIC;\n"
    "    double reqi = cbrt(bi.shape[0] * bi.shape[1] * bi.shape[2]);\n"
    "    double reqj = cbrt(bj.shape[0] * bj.shape[1] * bj.shape[2]);\n"
    "    double X0[4], nij[3] = {0, 0, 0}, rinv = 1.0 / (reqi + reqj);\n"
    "    for (int q = 0; q < 3; q++)\n"
    "        X0[q] = reqj * rinv * bi.xc[q] + reqi * rinv * bj.xc[q];\n"
    "    X0[3] = reqj / reqi;\n"
    "    int st = sqe_contact_point(&bi, &bj, X0, nij, form);\n"
    "    for (int k = 0; k < 16; k++)\n"
    "        o[k] = 0.0;\n"
    "    o[0] = st;\n"
    "    o[1] = sqe_obb_separating_axis(&bi, &bj, 0);\n"
    "    for (int q = 0; q < 4; q++)\n"
    "        o[2 + q] = X0[q];\n"
    "    if (st != 0)\n"
    "        return;\n"
    "    for (int q = 0; q < 3; q++)\n"
    "        o[6 + q] = nij[q];\n"
    "    double nji[3] = {-nij[0], -nij[1], -nij[2]};\n"
    "    double di = sqe_overlap_distance(&bi, X0, nij), dj = sqe_overlap_distance(&bj, X0, "
    "nji);\n"
    "    double pi[3], pj[3];\n"
    "    for (int q = 0; q < 3; q++) {\n"
    "        pi[q] = X0[q] + di * nij[q];\n"
    "        pj[q] = X0[q] + dj * nji[q];\n"
    "    }\n"
    "    o[9] = di;\n"
    "    o[10] = dj;\n"
    "    o[11] = sqe_curvature(&bi, pi, 0);\n"
    "    o[12] = sqe_curvature(&bj, pj, 0);\n"
    "    o[13] = sqe_curvature(&bi, pi, 1);\n"
    "    o[14] = sqe_curvature(&bj, pj, 1);\n"
    "}\n";

static uint64_t rng = 88172645463325252ull;
static double urand(void) /* xorshift64, [0, 1) */
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (double)(rng >> 11) * (1.0 / 9007199254740992.0);
}

static void random_body(double *p, const double xc[3])
{
    static const double blocks[][2] = {{2, 2}, {4, 4}, {3, 3}, {3, 5}, {6, 2.5}, {2, 4}};
    double q[4] = {urand() - 0.5, urand() - 0.5, urand() - 0.5, urand() - 0.5}, R[3][3];
    double qn = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    for (int k = 0; k < 4; k++)
        q[k] /= qn;
    rm_quat_to_mat(q, R);
    for (int k = 0; k < 3; k++)
        p[k] = xc[k];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            p[3 + 3 * r + c] = R[r][c];
    for (int k = 0; k < 3; k++)
        p[12 + k] = 0.4 + 0.8 * urand();
    int b = (int)(urand() * 6);
    p[15] = blocks[b][0];
    p[16] = blocks[b][1];
}

TEST(device_matches_host)
{
    double *in = calloc(NCASE * NIN, sizeof(double));
    double *host = calloc(NCASE * NOUT, sizeof(double)), *dev = calloc(NCASE * NOUT, 8);
    for (int c = 0; c < NCASE; c++) {
        double *p = in + NIN * c, zero[3] = {0, 0, 0};
        random_body(p, zero);
        double dir[3] = {urand() - 0.5, urand() - 0.5, urand() - 0.5};
        double dn = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
        double tmp[17], xj[3];
        random_body(tmp, zero);
        /* centre distance between 0.5 and 1.3 of the summed mean semi-axes */
        double reach = (p[12] + p[13] + p[14] + tmp[12] + tmp[13] + tmp[14]) / 3.0;
        double d = reach * (0.5 + 0.8 * urand());
        for (int k = 0; k < 3; k++)
            xj[k] = dir[k] / dn * d;
        for (int k = 0; k < 3; k++)
            tmp[k] = xj[k];
        memcpy(p + 17, tmp, sizeof tmp);
        p[34] = c % 2; /* algebraic, geometric */
        host_case(p, host + NOUT * c);
    }
    struct gravel *g = test_engine();
    struct engine *e = eng_get(g);
    const char *names[3] = {"sqe_pragmas.cl", "superellipsoid_geom.h", "sqe_check.cl"};
    const char *texts[3] = {"#pragma OPENCL EXTENSION cl_khr_fp64 : enable\n"
                            "#pragma OPENCL FP_CONTRACT OFF\n",
                            kernel_text_of("superellipsoid_geom.h"), kernel_text};
    CHECK(texts[1] != NULL);
    if (!texts[1] || !e->ocl.fp64) {
        printf("  no superellipsoid_geom.h embedded or no fp64 device\n");
        gr_destroy(g);
        return;
    }
    ocl_build(g, &e->ocl, 3, names, texts, "");
    cl_kernel k = ocl_kernel(g, &e->ocl, "sqe_check");
    cl_mem bin = ocl_alloc(g, &e->ocl, NCASE * NIN * sizeof(double), "sqe in");
    cl_mem bout = ocl_alloc(g, &e->ocl, NCASE * NOUT * sizeof(double), "sqe out");
    OCL_CHECK(g, clEnqueueWriteBuffer(e->ocl.queue, bin, CL_TRUE, 0,
                                      NCASE * NIN * sizeof(double), in, 0, NULL, NULL));
    int n = NCASE;
    OCL_CHECK(g, clSetKernelArg(k, 0, sizeof bin, &bin));
    OCL_CHECK(g, clSetKernelArg(k, 1, sizeof bout, &bout));
    OCL_CHECK(g, clSetKernelArg(k, 2, sizeof n, &n));
    size_t gsz = NCASE;
    OCL_CHECK(g, clEnqueueNDRangeKernel(e->ocl.queue, k, 1, NULL, &gsz, NULL, 0, NULL, NULL));
    OCL_CHECK(g, clEnqueueReadBuffer(e->ocl.queue, bout, CL_TRUE, 0,
                                     NCASE * NOUT * sizeof(double), dev, 0, NULL, NULL));
    clReleaseMemObject(bin);
    clReleaseMemObject(bout);
    clReleaseKernel(k);
    int status_diff = 0, axis_diff = 0, touching = 0, separated = 0, nreal = 0, same = 0;
    double worst = 0.0;
    for (int c = 0; c < NCASE; c++) {
        const double *h = host + NOUT * c, *d = dev + NOUT * c;
        status_diff += h[0] != d[0];
        axis_diff += h[1] != d[1];
        touching += h[0] == 0;
        separated += h[0] == 1;
        for (int q = 2; q < 15; q++) {
            double scale = fmax(1.0, fabs(h[q]));
            worst = fmax(worst, fabs(h[q] - d[q]) / scale);
            nreal++;
            same += memcmp(h + q, d + q, sizeof(double)) == 0;
        }
    }
    printf("  %d pairs: %d touching, %d separated; statuses differ %d, box axes differ %d; "
           "reals: worst difference %.2e of the scale, %d of %d bit-identical\n",
           NCASE, touching, separated, status_diff, axis_diff, worst, same, nreal);
    CHECK(touching >= NCASE / 5 && separated >= NCASE / 5);
    CHECK(status_diff == 0 && axis_diff == 0);
    CHECK(worst <= 1e-12);
    gr_destroy(g);
    free(in);
    free(host);
    free(dev);
}

int main(void)
{
    RUN(device_matches_host);
    return 0;
}
