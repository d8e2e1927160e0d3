/* The hottest serial N_Vector operations, compiled with the project's optimisation.
   Design note: Debian's libsundials-cvode 6.4.1 is built without optimisation (its
   N_VLinearSum_Serial keeps every local on the stack), and on our 10-component systems those
   vector operations took ~36% of a run's instructions. SUNDIALS' N_Vector is an operations
   table meant to be supplied by the user; replacing these five entries is cheaper than
   building SUNDIALS ourselves. The results differ from the stock ones only in rounding
   (a x + b y instead of special cases such as a (x + y)). */
#include "nvec_fast.h"

#include <math.h>

static void lin_sum(sunrealtype a, N_Vector x, sunrealtype b, N_Vector y, N_Vector z) {
    sunindextype n = NV_LENGTH_S(x);
    const sunrealtype *xd = NV_DATA_S(x), *yd = NV_DATA_S(y);
    sunrealtype *zd = NV_DATA_S(z);
    for (sunindextype i = 0; i < n; i++) {
        zd[i] = a * xd[i] + b * yd[i];
    }
}

static void scale(sunrealtype c, N_Vector x, N_Vector z) {
    sunindextype n = NV_LENGTH_S(x);
    const sunrealtype *xd = NV_DATA_S(x);
    sunrealtype *zd = NV_DATA_S(z);
    for (sunindextype i = 0; i < n; i++) {
        zd[i] = c * xd[i];
    }
}

static sunrealtype wrms_norm(N_Vector x, N_Vector w) {
    sunindextype n = NV_LENGTH_S(x);
    const sunrealtype *xd = NV_DATA_S(x), *wd = NV_DATA_S(w);
    sunrealtype sum = 0;
    for (sunindextype i = 0; i < n; i++) {
        sunrealtype p = xd[i] * wd[i];
        sum += p * p;
    }
    return sqrt(sum / n);
}

/* z = sum_j c_j X_j; z may be X_0: each element is read before it is written */
static int lin_comb(int nv, sunrealtype *c, N_Vector *X, N_Vector z) {
    sunindextype n = NV_LENGTH_S(z);
    sunrealtype *zd = NV_DATA_S(z);
    for (sunindextype i = 0; i < n; i++) {
        sunrealtype s = 0;
        for (int j = 0; j < nv; j++) {
            s += c[j] * NV_DATA_S(X[j])[i];
        }
        zd[i] = s;
    }
    return 0;
}

/* Z_j = a_j x + Y_j; Z_j may be Y_j */
static int scale_add_multi(int nv, sunrealtype *a, N_Vector x, N_Vector *Y, N_Vector *Z) {
    sunindextype n = NV_LENGTH_S(x);
    const sunrealtype *xd = NV_DATA_S(x);
    for (int j = 0; j < nv; j++) {
        const sunrealtype *yd = NV_DATA_S(Y[j]);
        sunrealtype *zd = NV_DATA_S(Z[j]);
        for (sunindextype i = 0; i < n; i++) {
            zd[i] = a[j] * xd[i] + yd[i];
        }
    }
    return 0;
}

void zp_nvec_fast_install(N_Vector v) {
    v->ops->nvlinearsum = lin_sum;
    v->ops->nvscale = scale;
    v->ops->nvwrmsnorm = wrms_norm;
    v->ops->nvlinearcombination = lin_comb;
    v->ops->nvscaleaddmulti = scale_add_multi;
}
