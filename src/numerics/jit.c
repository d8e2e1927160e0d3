/* zp_jit_compile: a zp_expr pool to machine code with libgccjit, one straight-line function
   per group of expressions, every node computed once into a local. */
#include "jit.h"

#include <libgccjit.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Design note: each node becomes one assignment to a local in the pool's order (operands come
   first), so subtrees shared between f, f' and f'' are computed once; the functions are GCC
   builtins, so GCC may merge sin and cos of one argument. Floating-point contraction is off,
   as in the rest of the build: the code does exactly the operations of zp_expr_eval, with
   the C library's functions, as libmatheval does. */

struct zp_jit {
    gcc_jit_result *result; /* owned */
    int nfn;
    zp_jit_fn fn[]; /* nfn */
};

typedef struct gen {
    gcc_jit_context *ctx;
    gcc_jit_type *dbl;
    gcc_jit_function *builtin[ZP_EX_COUNT];
    gcc_jit_rvalue **val; /* per node, in the function being built */
} gen;

static gcc_jit_rvalue *node_value(gen *g, const zp_ex_node *p, gcc_jit_param *x) {
    static const enum gcc_jit_binary_op bin[ZP_EX_COUNT] = {[ZP_EX_ADD] = GCC_JIT_BINARY_OP_PLUS,
                                                            [ZP_EX_SUB] = GCC_JIT_BINARY_OP_MINUS,
                                                            [ZP_EX_MUL] = GCC_JIT_BINARY_OP_MULT,
                                                            [ZP_EX_DIV] = GCC_JIT_BINARY_OP_DIVIDE};
    switch (p->op) {
    case ZP_EX_NUM:
        return gcc_jit_context_new_rvalue_from_double(g->ctx, g->dbl, p->value);
    case ZP_EX_X:
        return gcc_jit_param_as_rvalue(x);
    case ZP_EX_NEG:
        return gcc_jit_context_new_unary_op(g->ctx, NULL, GCC_JIT_UNARY_OP_MINUS, g->dbl,
                                            g->val[p->a]);
    case ZP_EX_ADD:
    case ZP_EX_SUB:
    case ZP_EX_MUL:
    case ZP_EX_DIV:
        return gcc_jit_context_new_binary_op(g->ctx, NULL, bin[p->op], g->dbl, g->val[p->a],
                                             g->val[p->b]);
    case ZP_EX_POW: {
        gcc_jit_rvalue *args[2] = {g->val[p->a], g->val[p->b]};
        return gcc_jit_context_new_call(g->ctx, NULL, g->builtin[ZP_EX_POW], 2, args);
    }
    default:
        return gcc_jit_context_new_call(g->ctx, NULL, g->builtin[p->op], 1, &g->val[p->a]);
    }
}

/* function `name`: out[k] = expression roots[k], k < nout */
static void build_function(gen *g, const zp_expr *e, const char *name, int nout, const int *roots,
                           char *used) {
    gcc_jit_type *void_t = gcc_jit_context_get_type(g->ctx, GCC_JIT_TYPE_VOID);
    gcc_jit_param *prm[2] = {
        gcc_jit_context_new_param(g->ctx, NULL, g->dbl, "x"),
        gcc_jit_context_new_param(g->ctx, NULL, gcc_jit_type_get_pointer(g->dbl), "out")};
    gcc_jit_function *f = gcc_jit_context_new_function(g->ctx, NULL, GCC_JIT_FUNCTION_EXPORTED,
                                                       void_t, name, 2, prm, 0);
    gcc_jit_block *blk = gcc_jit_function_new_block(f, NULL);
    /* the nodes these roots need: operands precede their nodes */
    int top = 0;
    memset(used, 0, (size_t)e->n);
    for (int k = 0; k < nout; k++) {
        used[roots[k]] = 1;
        top = roots[k] > top ? roots[k] : top;
    }
    for (int i = top; i >= 0; i--) {
        if (used[i] && e->node[i].a >= 0) {
            used[e->node[i].a] = 1;
        }
        if (used[i] && e->node[i].b >= 0) {
            used[e->node[i].b] = 1;
        }
    }
    for (int i = 0; i <= top; i++) {
        if (!used[i]) {
            continue;
        }
        gcc_jit_rvalue *v = node_value(g, &e->node[i], prm[0]);
        if (e->node[i].op != ZP_EX_NUM && e->node[i].op != ZP_EX_X) {
            char local[24];
            snprintf(local, sizeof local, "t%d", i);
            gcc_jit_lvalue *t = gcc_jit_function_new_local(f, NULL, g->dbl, local);
            gcc_jit_block_add_assignment(blk, NULL, t, v);
            v = gcc_jit_lvalue_as_rvalue(t);
        }
        g->val[i] = v;
    }
    gcc_jit_type *int_t = gcc_jit_context_get_type(g->ctx, GCC_JIT_TYPE_INT);
    for (int k = 0; k < nout; k++) {
        gcc_jit_lvalue *slot =
            gcc_jit_context_new_array_access(g->ctx, NULL, gcc_jit_param_as_rvalue(prm[1]),
                                             gcc_jit_context_new_rvalue_from_int(g->ctx, int_t, k));
        gcc_jit_block_add_assignment(blk, NULL, slot, g->val[roots[k]]);
    }
    gcc_jit_block_end_with_void_return(blk, NULL);
}

static void set_options(gcc_jit_context *ctx) {
    /* -O1 already does the work of straight-line code (CSE, scheduling) and compiles in a
       fraction of -O2's time, which every command pays once per scene */
    gcc_jit_context_set_int_option(ctx, GCC_JIT_INT_OPTION_OPTIMIZATION_LEVEL, 1);
    gcc_jit_context_add_command_line_option(ctx, "-ffp-contract=off");
    gcc_jit_context_set_bool_option(ctx, GCC_JIT_BOOL_OPTION_DEBUGINFO, 0);
}

zp_jit *zp_jit_compile(const zp_expr *e, int nfn, int nout, const int *roots, char *err,
                       size_t errlen) {
    zp_jit *j = calloc(1, sizeof *j + sizeof j->fn[0] * (size_t)nfn);
    gen g = {.val = calloc((size_t)e->n + 1, sizeof *g.val)};
    char *used = malloc((size_t)e->n + 1);
    g.ctx = gcc_jit_context_acquire();
    if (!j || !g.val || !used || !g.ctx) {
        snprintf(err, errlen, "out of memory");
        goto fail;
    }
    set_options(g.ctx);
    g.dbl = gcc_jit_context_get_type(g.ctx, GCC_JIT_TYPE_DOUBLE);
    /* pow is the library's, not the builtin: GCC would turn pow(u, 2) into u * u, which
       differs from the interpreter's pow in the last bit at some u */
    gcc_jit_param *pw[2] = {gcc_jit_context_new_param(g.ctx, NULL, g.dbl, "a"),
                            gcc_jit_context_new_param(g.ctx, NULL, g.dbl, "b")};
    g.builtin[ZP_EX_POW] = gcc_jit_context_new_function(g.ctx, NULL, GCC_JIT_FUNCTION_IMPORTED,
                                                        g.dbl, "pow", 2, pw, 0);
    for (int op = ZP_EX_SQRT; op < ZP_EX_COUNT; op++) {
        char name[32];
        snprintf(name, sizeof name, "__builtin_%s", zp_expr_func_name((zp_ex_op)op));
        g.builtin[op] = gcc_jit_context_get_builtin_function(g.ctx, name);
    }
    for (int i = 0; i < nfn; i++) {
        char name[32];
        snprintf(name, sizeof name, "zp_expr_fn%d", i);
        build_function(&g, e, name, nout, roots + (size_t)i * nout, used);
    }
    j->result = gcc_jit_context_compile(g.ctx);
    if (!j->result) {
        const char *why = gcc_jit_context_get_first_error(g.ctx);
        snprintf(err, errlen, "libgccjit: %s", why ? why : "compile failed");
        goto fail;
    }
    j->nfn = nfn;
    for (int i = 0; i < nfn; i++) {
        char name[32];
        snprintf(name, sizeof name, "zp_expr_fn%d", i);
        /* the one cast from object to function pointer that a JIT needs (POSIX allows it) */
        void *code = gcc_jit_result_get_code(j->result, name);
        memcpy(&j->fn[i], &code, sizeof code);
        if (!j->fn[i]) {
            snprintf(err, errlen, "libgccjit: no code for %s", name);
            goto fail;
        }
    }
    gcc_jit_context_release(g.ctx);
    free(g.val);
    free(used);
    return j;
fail:
    if (g.ctx) {
        gcc_jit_context_release(g.ctx);
    }
    free(g.val);
    free(used);
    zp_jit_free(j);
    return NULL;
}

zp_jit_fn zp_jit_get(const zp_jit *j, int i) {
    return j->fn[i];
}

void zp_jit_free(zp_jit *j) {
    if (!j) {
        return;
    }
    if (j->result) {
        gcc_jit_result_release(j->result);
    }
    free(j);
}
