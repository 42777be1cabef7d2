/* Dense linear algebra of the runtime, column-major a[i + j*n]: meant for the small and
 * medium models FMUs are made of (tens to a few hundred unknowns). */
#ifndef AC_LINALG_H
#define AC_LINALG_H

int ac_lu(double *a, int n, int *piv);                  /* in place; -1 if singular */
void ac_lu_solve(const double *a, int n, const int *piv, double *b);
int ac_all_finite(const double *v, int n);

#endif
