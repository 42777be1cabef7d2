/* Dense LU with partial pivoting, Householder QR and minimum-norm least squares (see linalg.h). */
#include <math.h>
#include <stddef.h>

#include "linalg.h"

int ac_lu(double *a, int n, int *piv) {
    int i, j, k;
    for (k = 0; k < n; k++) {
        int p = k;
        double best = fabs(a[k + k * n]);
        for (i = k + 1; i < n; i++)
            if (fabs(a[i + k * n]) > best) { best = fabs(a[i + k * n]); p = i; }
        piv[k] = p;
        if (!(best > 0.0) || !isfinite(best)) return -1;
        if (p != k)
            for (j = 0; j < n; j++) { double t = a[k + j * n]; a[k + j * n] = a[p + j * n]; a[p + j * n] = t; }
        for (i = k + 1; i < n; i++) a[i + k * n] /= a[k + k * n];
        for (j = k + 1; j < n; j++) {
            double akj = a[k + j * n];
            if (akj != 0.0)
                for (i = k + 1; i < n; i++) a[i + j * n] -= a[i + k * n] * akj;
        }
    }
    return 0;
}

void ac_lu_solve(const double *a, int n, const int *piv, double *b) {
    int i, j;
    for (i = 0; i < n; i++) {
        if (piv[i] != i) { double t = b[i]; b[i] = b[piv[i]]; b[piv[i]] = t; }
    }
    for (j = 0; j < n; j++) {
        double bj = b[j];
        if (bj != 0.0) for (i = j + 1; i < n; i++) b[i] -= a[i + j * n] * bj;
    }
    for (j = n - 1; j >= 0; j--) {
        b[j] /= a[j + j * n];
        for (i = 0; i < j; i++) b[i] -= a[i + j * n] * b[j];
    }
}

int ac_all_finite(const double *v, int n) {
    int i;
    for (i = 0; i < n; i++) if (!isfinite(v[i])) return 0;
    return 1;
}

void ac_qr(double *a, int m, int n, double *tau, int *perm) {
    int i, j, c, k = m < n ? m : n;
    if (perm) for (c = 0; c < n; c++) perm[c] = c;
    for (j = 0; j < k; j++) {
        double tail = 0.0, alpha, beta;
        if (perm) {                               /* the remaining column of largest norm */
            int best = j;
            double most = -1.0;
            for (c = j; c < n; c++) {
                double s = 0.0;
                for (i = j; i < m; i++) s += a[i + c * m] * a[i + c * m];
                if (s > most) { most = s; best = c; }
            }
            if (best != j) {
                int t = perm[j]; perm[j] = perm[best]; perm[best] = t;
                for (i = 0; i < m; i++) {
                    double v = a[i + j * m]; a[i + j * m] = a[i + best * m]; a[i + best * m] = v;
                }
            }
        }
        for (i = j + 1; i < m; i++) tail += a[i + j * m] * a[i + j * m];
        if (tail == 0.0) { tau[j] = 0.0; continue; }      /* nothing below the diagonal */
        alpha = a[j + j * m];
        beta = -copysign(sqrt(alpha * alpha + tail), alpha);
        tau[j] = (beta - alpha) / beta;
        for (i = j + 1; i < m; i++) a[i + j * m] /= alpha - beta;
        a[j + j * m] = beta;
        for (c = j + 1; c < n; c++) {
            double s = a[j + c * m];
            for (i = j + 1; i < m; i++) s += a[i + j * m] * a[i + c * m];
            s *= tau[j];
            a[j + c * m] -= s;
            for (i = j + 1; i < m; i++) a[i + c * m] -= s * a[i + j * m];
        }
    }
}

static void reflect(const double *a, int m, int j, double tau, double *b) {
    double s = b[j];
    int i;
    if (tau == 0.0) return;
    for (i = j + 1; i < m; i++) s += a[i + j * m] * b[i];
    s *= tau;
    b[j] -= s;
    for (i = j + 1; i < m; i++) b[i] -= s * a[i + j * m];
}

void ac_qt_apply(const double *a, int m, int k, const double *tau, double *b) {
    int j;
    for (j = 0; j < k; j++) reflect(a, m, j, tau[j], b);
}

void ac_q_apply(const double *a, int m, int k, const double *tau, double *b) {
    int j;
    for (j = k - 1; j >= 0; j--) reflect(a, m, j, tau[j], b);
}

/* A complete orthogonal decomposition (LAPACK's xGELSY, on Aᵀ): Aᵀ Π = Q R, so Πᵀ A = Rᵀ Qᵀ
 * and, with y the first r entries of Qᵀ x, the r independent rows read Rᵀ_r y = Πᵀ b: a
 * least-squares problem with the m×r matrix Rᵀ_r of full column rank, solved by a second QR;
 * x = Q [y; 0] is the solution of least norm. Orthogonal transformations only: the error is
 * that of the problem's own conditioning, not its square (as with normal equations). */
void ac_min_norm_lstsq(double *at, int n, int m, const double *b, double *x, double rcond,
                       double *work, int *perm) {
    int i, j, r = 0, k = m < n ? m : n;
    double *tau = work, *R = tau + k, *tau2 = R + m * k, *c = tau2 + k;
    ac_qr(at, n, m, tau, perm);
    while (r < k && fabs(at[r + r * n]) > rcond * fabs(at[0])) r++;
    for (j = 0; j < r; j++)
        for (i = 0; i < m; i++) R[i + j * m] = i >= j ? at[j + i * n] : 0.0;
    for (i = 0; i < m; i++) c[i] = b[perm[i]];
    ac_qr(R, m, r, tau2, NULL);
    ac_qt_apply(R, m, r, tau2, c);
    for (j = r - 1; j >= 0; j--) {
        double s = c[j];
        for (i = j + 1; i < r; i++) s -= R[j + i * m] * c[i];
        c[j] = s / R[j + j * m];
    }
    for (i = 0; i < n; i++) x[i] = i < r ? c[i] : 0.0;
    ac_q_apply(at, n, k, tau, x);
}
