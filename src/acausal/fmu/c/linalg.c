/* Dense LU with partial pivoting (see linalg.h). */
#include <math.h>

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
