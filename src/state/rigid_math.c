/* rigid_math.c - rotation arithmetic of rigid bodies (rigid_math.h). The
 * operations follow LAMMPS's MathExtra term by term (same products, same
 * order) so rounding matches. */
#include "rigid_math.h"

#include <float.h>
#include <math.h>

static void qnormalize(double q[4])
{
    double norm = 1.0 / sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    q[0] *= norm;
    q[1] *= norm;
    q[2] *= norm;
    q[3] *= norm;
}

int rm_jacobi3(const double m[3][3], double eval[3], double evec[3][3])
{
    double a[3][3], v[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            a[i][j] = m[i][j];
    int ok = 0;
    for (int sweep = 0; sweep < 50; sweep++) {
        double off = fabs(a[0][1]) + fabs(a[0][2]) + fabs(a[1][2]);
        if (off == 0.0) {
            ok = 1;
            break;
        }
        for (int p = 0; p < 2; p++)
            for (int q = p + 1; q < 3; q++) {
                if (a[p][q] == 0.0)
                    continue;
                double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                double t = (theta >= 0 ? 1.0 : -1.0) / (fabs(theta) + sqrt(theta * theta + 1.0));
                double c = 1.0 / sqrt(t * t + 1.0), s = t * c;
                for (int k = 0; k < 3; k++) { /* a = J^T a J */
                    double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; k++) {
                    double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; k++) {
                    double vkp = v[k][p], vkq = v[k][q];
                    v[k][p] = c * vkp - s * vkq;
                    v[k][q] = s * vkp + c * vkq;
                }
            }
    }
    if (!ok) {
        double off = fabs(a[0][1]) + fabs(a[0][2]) + fabs(a[1][2]);
        double diag = fabs(a[0][0]) + fabs(a[1][1]) + fabs(a[2][2]);
        ok = off <= 1e-15 * diag;
    }
    int idx[3] = {0, 1, 2};
    for (int i = 0; i < 2; i++) /* decreasing eigenvalues */
        for (int j = i + 1; j < 3; j++)
            if (a[idx[j]][idx[j]] > a[idx[i]][idx[i]]) {
                int t = idx[i];
                idx[i] = idx[j];
                idx[j] = t;
            }
    for (int c = 0; c < 3; c++) {
        eval[c] = a[idx[c]][idx[c]];
        for (int r = 0; r < 3; r++)
            evec[r][c] = v[r][idx[c]];
    }
    return ok ? 0 : 1;
}

int rm_principal(const double t[6], int dim2, double inertia[3], double ex[3], double ey[3],
                 double ez[3], double q[4])
{
    double tensor[3][3], ev[3][3];
    tensor[0][0] = t[0];
    tensor[1][1] = t[1];
    tensor[2][2] = t[2];
    tensor[1][2] = tensor[2][1] = t[3];
    tensor[0][2] = tensor[2][0] = t[4];
    tensor[0][1] = tensor[1][0] = t[5];
    if (rm_jacobi3(tensor, inertia, ev))
        return 1;
    for (int k = 0; k < 3; k++) {
        ex[k] = ev[k][0];
        ey[k] = ev[k][1];
        ez[k] = ev[k][2];
    }
    if (dim2 && (fabs(ez[0]) > 1e-7 || fabs(ez[1]) > 1e-7)) {
        /* 2d: the axis along z last, so the quaternion is a rotation about z */
        int iz = fabs(ex[2]) > fabs(ey[2]) ? 0 : 1;
        double *a = iz == 0 ? ex : ey, tmp;
        tmp = inertia[iz], inertia[iz] = inertia[2], inertia[2] = tmp;
        for (int k = 0; k < 3; k++)
            tmp = a[k], a[k] = ez[k], ez[k] = tmp;
    }
    double max = inertia[0] > inertia[1] ? inertia[0] : inertia[1];
    max = max > inertia[2] ? max : inertia[2];
    for (int k = 0; k < 3; k++)
        if (inertia[k] < 1.0e-7 * max)
            inertia[k] = 0.0;
    double cross[3] = {ex[1] * ey[2] - ex[2] * ey[1], ex[2] * ey[0] - ex[0] * ey[2],
                       ex[0] * ey[1] - ex[1] * ey[0]};
    if (cross[0] * ez[0] + cross[1] * ez[1] + cross[2] * ez[2] < 0.0)
        for (int k = 0; k < 3; k++)
            ez[k] = -ez[k];
    rm_exyz_to_q(ex, ey, ez, q);
    return 0;
}

void rm_exyz_to_q(const double ex[3], const double ey[3], const double ez[3], double q[4])
{
    double q0sq = 0.25 * (ex[0] + ey[1] + ez[2] + 1.0);
    double q1sq = q0sq - 0.5 * (ey[1] + ez[2]);
    double q2sq = q0sq - 0.5 * (ex[0] + ez[2]);
    double q3sq = q0sq - 0.5 * (ex[0] + ey[1]);
    if (q0sq >= 0.25) {
        q[0] = sqrt(q0sq);
        q[1] = (ey[2] - ez[1]) / (4.0 * q[0]);
        q[2] = (ez[0] - ex[2]) / (4.0 * q[0]);
        q[3] = (ex[1] - ey[0]) / (4.0 * q[0]);
    } else if (q1sq >= 0.25) {
        q[1] = sqrt(q1sq);
        q[0] = (ey[2] - ez[1]) / (4.0 * q[1]);
        q[2] = (ey[0] + ex[1]) / (4.0 * q[1]);
        q[3] = (ex[2] + ez[0]) / (4.0 * q[1]);
    } else if (q2sq >= 0.25) {
        q[2] = sqrt(q2sq);
        q[0] = (ez[0] - ex[2]) / (4.0 * q[2]);
        q[1] = (ey[0] + ex[1]) / (4.0 * q[2]);
        q[3] = (ez[1] + ey[2]) / (4.0 * q[2]);
    } else {
        q[3] = sqrt(q3sq);
        q[0] = (ex[1] - ey[0]) / (4.0 * q[3]);
        q[1] = (ez[0] + ex[2]) / (4.0 * q[3]);
        q[2] = (ez[1] + ey[2]) / (4.0 * q[3]);
    }
    qnormalize(q);
}

void rm_q_to_exyz(const double q[4], double ex[3], double ey[3], double ez[3])
{
    ex[0] = q[0] * q[0] + q[1] * q[1] - q[2] * q[2] - q[3] * q[3];
    ex[1] = 2.0 * (q[1] * q[2] + q[0] * q[3]);
    ex[2] = 2.0 * (q[1] * q[3] - q[0] * q[2]);
    ey[0] = 2.0 * (q[1] * q[2] - q[0] * q[3]);
    ey[1] = q[0] * q[0] - q[1] * q[1] + q[2] * q[2] - q[3] * q[3];
    ey[2] = 2.0 * (q[2] * q[3] + q[0] * q[1]);
    ez[0] = 2.0 * (q[1] * q[3] + q[0] * q[2]);
    ez[1] = 2.0 * (q[2] * q[3] - q[0] * q[1]);
    ez[2] = q[0] * q[0] - q[1] * q[1] - q[2] * q[2] + q[3] * q[3];
}

void rm_quat_to_mat(const double q[4], double m[3][3])
{
    double w2 = q[0] * q[0], i2 = q[1] * q[1], j2 = q[2] * q[2], k2 = q[3] * q[3];
    double twoij = 2.0 * q[1] * q[2], twoik = 2.0 * q[1] * q[3], twojk = 2.0 * q[2] * q[3];
    double twoiw = 2.0 * q[1] * q[0], twojw = 2.0 * q[2] * q[0], twokw = 2.0 * q[3] * q[0];
    m[0][0] = w2 + i2 - j2 - k2;
    m[0][1] = twoij - twokw;
    m[0][2] = twojw + twoik;
    m[1][0] = twoij + twokw;
    m[1][1] = w2 - i2 + j2 - k2;
    m[1][2] = twojk - twoiw;
    m[2][0] = twoik - twojw;
    m[2][1] = twojk + twoiw;
    m[2][2] = w2 - i2 - j2 + k2;
}

void rm_axisangle_to_quat(const double v[3], double angle, double q[4])
{
    double halfa = 0.5 * angle, sina = sin(halfa);
    q[0] = cos(halfa);
    q[1] = v[0] * sina;
    q[2] = v[1] * sina;
    q[3] = v[2] * sina;
}

void rm_quatquat(const double a[4], const double b[4], double c[4])
{
    c[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    c[1] = a[0] * b[1] + b[0] * a[1] + a[2] * b[3] - a[3] * b[2];
    c[2] = a[0] * b[2] + b[0] * a[2] + a[3] * b[1] - a[1] * b[3];
    c[3] = a[0] * b[3] + b[0] * a[3] + a[1] * b[2] - a[2] * b[1];
}

void rm_matvec(const double ex[3], const double ey[3], const double ez[3], const double v[3],
               double out[3])
{
    out[0] = ex[0] * v[0] + ey[0] * v[1] + ez[0] * v[2];
    out[1] = ex[1] * v[0] + ey[1] * v[1] + ez[1] * v[2];
    out[2] = ex[2] * v[0] + ey[2] * v[1] + ez[2] * v[2];
}

void rm_transpose_matvec(const double ex[3], const double ey[3], const double ez[3],
                         const double v[3], double out[3])
{
    out[0] = ex[0] * v[0] + ex[1] * v[1] + ex[2] * v[2];
    out[1] = ey[0] * v[0] + ey[1] * v[1] + ey[2] * v[2];
    out[2] = ez[0] * v[0] + ez[1] * v[1] + ez[2] * v[2];
}

void rm_angmom_to_omega(const double m[3], const double ex[3], const double ey[3],
                        const double ez[3], const double idiag[3], double w[3])
{
    double wb[3];
    wb[0] = idiag[0] == 0.0 ? 0.0 : (m[0] * ex[0] + m[1] * ex[1] + m[2] * ex[2]) / idiag[0];
    wb[1] = idiag[1] == 0.0 ? 0.0 : (m[0] * ey[0] + m[1] * ey[1] + m[2] * ey[2]) / idiag[1];
    wb[2] = idiag[2] == 0.0 ? 0.0 : (m[0] * ez[0] + m[1] * ez[1] + m[2] * ez[2]) / idiag[2];
    w[0] = wb[0] * ex[0] + wb[1] * ey[0] + wb[2] * ez[0];
    w[1] = wb[0] * ex[1] + wb[1] * ey[1] + wb[2] * ez[1];
    w[2] = wb[0] * ex[2] + wb[1] * ey[2] + wb[2] * ez[2];
}

/* c = (0, a) * b */
static void vecquat(const double a[3], const double b[4], double c[4])
{
    c[0] = -a[0] * b[1] - a[1] * b[2] - a[2] * b[3];
    c[1] = b[0] * a[0] + a[1] * b[3] - a[2] * b[2];
    c[2] = b[0] * a[1] + a[2] * b[1] - a[0] * b[3];
    c[3] = b[0] * a[2] + a[0] * b[2] - a[1] * b[1];
}

/* omega from angular momentum m and quaternion q (LAMMPS mq_to_omega) */
static void mq_to_omega(const double m[3], const double q[4], const double moments[3],
                        double w[3])
{
    double rot[3][3], wb[3];
    rm_quat_to_mat(q, rot);
    for (int i = 0; i < 3; i++)
        wb[i] = rot[0][i] * m[0] + rot[1][i] * m[1] + rot[2][i] * m[2];
    for (int i = 0; i < 3; i++)
        wb[i] = moments[i] == 0.0 ? 0.0 : wb[i] / moments[i];
    for (int i = 0; i < 3; i++)
        w[i] = rot[i][0] * wb[0] + rot[i][1] * wb[1] + rot[i][2] * wb[2];
}

void rm_richardson(double q[4], const double m[3], double w[3], const double moments[3],
                   double dtq)
{
    double wq[4], qfull[4], qhalf[4];
    vecquat(w, q, wq);
    for (int k = 0; k < 4; k++)
        qfull[k] = q[k] + dtq * wq[k];
    qnormalize(qfull);
    for (int k = 0; k < 4; k++)
        qhalf[k] = q[k] + 0.5 * dtq * wq[k];
    qnormalize(qhalf);
    mq_to_omega(m, qhalf, moments, w);
    vecquat(w, qhalf, wq);
    for (int k = 0; k < 4; k++)
        qhalf[k] += 0.5 * dtq * wq[k];
    qnormalize(qhalf);
    for (int k = 0; k < 4; k++)
        q[k] = 2.0 * qhalf[k] - qfull[k];
    qnormalize(q);
}

int rm_unit_axis(const double a[3], double u[3])
{
    if (!isfinite(a[0]) || !isfinite(a[1]) || !isfinite(a[2]))
        return -1;
    double m = fmax(fabs(a[0]), fmax(fabs(a[1]), fabs(a[2])));
    if (!(m > 0))
        return -1;
    double l2 = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
    if (isfinite(l2) && l2 >= DBL_MIN) {
        double len = sqrt(l2);
        for (int k = 0; k < 3; k++)
            u[k] = a[k] / len;
        return 0;
    }
    double b[3] = {a[0] / m, a[1] / m, a[2] / m};
    double len = sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    for (int k = 0; k < 3; k++)
        u[k] = b[k] / len;
    return 0;
}
