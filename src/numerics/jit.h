/* Native code for expressions in x through libgccjit: several functions, each computing a few
   expressions of one zp_expr pool, in one compile. The result is read-only: any thread may
   call its functions. */
#ifndef ZP_JIT_H
#define ZP_JIT_H

#include <stddef.h>

#include "expr.h"

/* out[k] = the k-th expression of the function at x */
typedef void (*zp_jit_fn)(double x, double *out);
typedef struct zp_jit zp_jit;

/* Compiles nfn functions; function i computes the nout expressions with roots
   roots[i * nout + k] in e. NULL with why in err when libgccjit fails. */
zp_jit *zp_jit_compile(const zp_expr *e, int nfn, int nout, const int *roots, char *err,
                       size_t errlen);
zp_jit_fn zp_jit_get(const zp_jit *j, int i);
void zp_jit_free(zp_jit *j);

#endif
