/* common.cl - types shared by every kernel. REAL is float or double (-D REAL=...). */
#ifndef REAL
#define REAL double
#endif
#if defined(USE_DOUBLE)
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
#endif
