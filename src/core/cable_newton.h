/* The cable's small equilibrium systems solved: damped Newton over a handful of unknowns, each
   step through GSL's LU, continuation where Newton alone fails, bracketed roots in one unknown. */
#ifndef ZP_CABLE_NEWTON_H
#define ZP_CABLE_NEWTON_H

#define ZP_CABLE_NEWTON_MAX 6 /* unknowns at most */

/* Fills the residual r[n] and the Jacobian jac[n * n] (row-major, jac[i n + j] = dr_i / dz_j)
   at z; returns nonzero when z lies outside the unknowns' domain or gives non-finite numbers
   (the step is then shortened). */
typedef int (*zp_cable_newton_fn)(const double *z, double *r, double *jac, void *ctx);

/* The root of f in [lo, hi], where f changes sign and is finite, to round-off by GSL's Brent;
   NAN when f does not change sign or the iteration fails. */
double zp_cable_newton_root(double (*f)(double, void *), void *ctx, double lo, double hi);
/* Solves jac x = b (n x n, row-major) through GSL's LU: 0, or -1 when jac is singular. */
int zp_cable_newton_linear(int n, const double *jac, const double *b, double *x);
/* Newton from z (updated in place), each step halved until the residual, scaled by rscale,
   decreases; zscale: the size of each unknown, for the step's size. Returns 0 once the full
   steps have shrunk to round-off, -1 when a step cannot be taken (singular Jacobian, no
   decrease, too many steps): z is then unspecified. */
int zp_cable_newton_solve(int n, zp_cable_newton_fn fn, void *ctx, double *z, const double *zscale,
                          const double *rscale);
/* Follows the solution z of the problem at *lambda = 0 (given exactly) to the problem at
   *lambda = 1, the one fn describes as it reads *lambda: each step solved by
   zp_cable_newton_solve from the last two solutions' secant, a step that fails halved. Returns
   0 with z solving *lambda = 1, or -1 (z unspecified). */
int zp_cable_newton_continue(int n, zp_cable_newton_fn fn, void *ctx, double *lambda, double *z,
                             const double *zscale, const double *rscale);

#endif
