/* test_collision_time.c - the collision-time formulas are one source for
 * the host and the device (kernels/collision_time.h): the device (PoCL)
 * compiles them in double and in single precision and its Hertz collision
 * time, whose fifth root it takes without pow (tcol_root5), agrees with the
 * host's pow over 60 decades of the argument and every residue of the
 * exponent: within 3e-12 in double, 1e-6 in float; zero gives zero. */
#include <stdlib.h>

#include "test.h"

#include "collision_time.h"
#include "engine.h"
#include "kernel_text.h"
#include "ocl.h"

enum { N = 4001 };

static const char *kernel_text =
    "__kernel void root5_check(__global const double *in, __global double *out, int n)\n"
    "{\n"
    "    int c = get_global_id(0);\n"
    "    if (c >= n)\n"
    "        return;\n"
    "    out[2 * c] = (double)tcol_root5((REAL)in[c]);\n"
    "    out[2 * c + 1] = (double)tcol_hertz((REAL)1.5e5, (REAL)0.5, (REAL)0.3, (REAL)in[c]);\n"
    "}\n";

/* Runs the check kernel over x[] in the given precision; 0 without fp64. */
static int device_values(const double *x, double *out, int single)
{
    struct gravel *g = test_engine();
    struct engine *e = eng_get(g);
    if (!e->ocl.fp64) {
        gr_destroy(g);
        return 0;
    }
    const char *names[3] = {"prelude.cl", "collision_time.h", "root5_check.cl"};
    const char *texts[3] = {single ? "#pragma OPENCL EXTENSION cl_khr_fp64 : enable\n"
                                     "#define REAL float\n"
                                   : "#pragma OPENCL EXTENSION cl_khr_fp64 : enable\n"
                                     "#define REAL double\n",
                            kernel_text_of("collision_time.h"), kernel_text};
    CHECK(texts[1] != NULL);
    ocl_build(g, &e->ocl, 3, names, texts, "");
    cl_kernel k = ocl_kernel(g, &e->ocl, "root5_check");
    cl_mem bin = ocl_alloc(g, &e->ocl, N * sizeof(double), "root5 in");
    cl_mem bout = ocl_alloc(g, &e->ocl, 2 * N * sizeof(double), "root5 out");
    OCL_CHECK(g, clEnqueueWriteBuffer(e->ocl.queue, bin, CL_TRUE, 0, N * sizeof(double), x, 0,
                                      NULL, NULL));
    int n = N;
    OCL_CHECK(g, clSetKernelArg(k, 0, sizeof bin, &bin));
    OCL_CHECK(g, clSetKernelArg(k, 1, sizeof bout, &bout));
    OCL_CHECK(g, clSetKernelArg(k, 2, sizeof n, &n));
    size_t gsz = N;
    OCL_CHECK(g, clEnqueueNDRangeKernel(e->ocl.queue, k, 1, NULL, &gsz, NULL, 0, NULL, NULL));
    OCL_CHECK(g, clEnqueueReadBuffer(e->ocl.queue, bout, CL_TRUE, 0, 2 * N * sizeof(double), out,
                                     0, NULL, NULL));
    clReleaseMemObject(bin);
    clReleaseMemObject(bout);
    clReleaseKernel(k);
    gr_destroy(g);
    return 1;
}

TEST(root5_matches_pow)
{
    double *x = malloc(N * sizeof *x), *out = malloc(2 * N * sizeof *out);
    for (int single = 0; single < 2; single++) {
        /* 1e-30 .. 1e30 in steps of 10^0.015 (every exponent residue many times;
         * float's range), and zero */
        for (int c = 0; c < N - 1; c++)
            x[c] = pow(10.0, -30.0 + 0.015 * c);
        x[N - 1] = 0;
        if (!device_values(x, out, single)) {
            printf("  no fp64 device: the device's values were not checked\n");
            break;
        }
        double worst = 0, worst_h = 0;
        for (int c = 0; c < N - 1; c++) {
            worst = fmax(worst, fabs(out[2 * c] / pow(x[c], 0.2) - 1));
            if (x[c] < 1e-6 || x[c] > 1e6) /* speeds: the root's argument stays normal in float */
                continue;
            double h = tcol_hertz(1.5e5, 0.5, 0.3, x[c]);
            worst_h = fmax(worst_h, fabs(out[2 * c + 1] / h - 1));
        }
        double tol = single ? 1e-6 : 3e-12;
        printf("  %s: worst relative difference from pow %.2e (fifth root), %.2e (Hertz "
               "collision time)\n", single ? "float" : "double", worst, worst_h);
        CHECK(worst <= tol);
        CHECK(worst_h <= tol);
        CHECK(out[2 * (N - 1)] == 0);
    }
    free(x);
    free(out);
}

int main(void)
{
    RUN(root5_matches_pow);
    return 0;
}
