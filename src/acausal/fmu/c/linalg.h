/* Dense linear algebra of the runtime, column-major a[i + j*m] (m rows): meant for the small and
 * medium models FMUs are made of (tens to a few hundred unknowns). */
#ifndef AC_LINALG_H
#define AC_LINALG_H

int ac_lu(double *a, int n, int *piv);                  /* in place; -1 if singular */
void ac_lu_solve(const double *a, int n, const int *piv, double *b);
int ac_all_finite(const double *v, int n);

/* Householder QR of the m×n matrix a in place, a Π = Q R: R in the upper triangle, the
 * reflectors H_j = I − tau_j v_j v_jᵀ (v_j = [0…0, 1, a[j+1.., j]]) below it, min(m, n) of
 * them. perm (n ints) chooses column pivoting: the remaining column of largest norm first,
 * perm[j] the original index of column j, so that |R_jj| decrease and show the rank; NULL:
 * no pivoting. */
void ac_qr(double *a, int m, int n, double *tau, int *perm);
/* b (length m) <- Qᵀ b, resp. Q b, with the k reflectors of ac_qr */
void ac_qt_apply(const double *a, int m, int k, const double *tau, double *b);
void ac_q_apply(const double *a, int m, int k, const double *tau, double *b);
/* x (length n) = A⁺ b, the minimum-norm least-squares solution of A x = b, for the m×n matrix
 * A given transposed (at: n×m, destroyed); rank-truncated where |R_jj| <= rcond·|R_00| in the
 * pivoted QR of Aᵀ. work: m·min(m, n) + 2·min(m, n) + m doubles; perm: m ints. */
void ac_min_norm_lstsq(double *at, int n, int m, const double *b, double *x, double rcond,
                       double *work, int *perm);

#endif
