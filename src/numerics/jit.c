/* zp_jit_compile: a zp_expr pool to machine code with libgccjit, one straight-line function
   per group of expressions, every node computed once into a local. */
#include "jit.h"

#include <dlfcn.h>
#include <errno.h>
#include <libgccjit.h>
#include <limits.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* Design note: each node becomes one assignment to a local in the pool's order (operands come
   first), so subtrees shared between f, f' and f'' are computed once; the functions are GCC
   builtins, so GCC may merge sin and cos of one argument. Floating-point contraction is off,
   as in the rest of the build: the code does exactly the operations of zp_expr_eval, with
   the C library's functions, as libmatheval does. */

/* libgccjit is opened on the first compile, not linked: loading its 30 MB costs every command
   tens of milliseconds at start, and a machine without it falls back to the interpreter */
#define ZP_JIT_API(X)                                                                              \
    X(gcc_jit_block_add_assignment)                                                                \
    X(gcc_jit_block_end_with_void_return)                                                          \
    X(gcc_jit_context_acquire)                                                                     \
    X(gcc_jit_context_add_command_line_option)                                                     \
    X(gcc_jit_context_compile)                                                                     \
    X(gcc_jit_context_compile_to_file)                                                             \
    X(gcc_jit_context_get_builtin_function)                                                        \
    X(gcc_jit_context_get_first_error)                                                             \
    X(gcc_jit_context_get_type)                                                                    \
    X(gcc_jit_context_new_array_access)                                                            \
    X(gcc_jit_context_new_binary_op)                                                               \
    X(gcc_jit_context_new_call)                                                                    \
    X(gcc_jit_context_new_function)                                                                \
    X(gcc_jit_context_new_global)                                                                  \
    X(gcc_jit_context_new_param)                                                                   \
    X(gcc_jit_context_new_rvalue_from_double)                                                      \
    X(gcc_jit_context_new_rvalue_from_int)                                                         \
    X(gcc_jit_context_new_string_literal)                                                          \
    X(gcc_jit_context_new_unary_op)                                                                \
    X(gcc_jit_context_release)                                                                     \
    X(gcc_jit_context_set_bool_option)                                                             \
    X(gcc_jit_context_set_bool_print_errors_to_stderr)                                             \
    X(gcc_jit_context_set_bool_use_external_driver)                                                \
    X(gcc_jit_context_set_int_option)                                                              \
    X(gcc_jit_function_new_block)                                                                  \
    X(gcc_jit_function_new_local)                                                                  \
    X(gcc_jit_global_set_initializer_rvalue)                                                       \
    X(gcc_jit_lvalue_as_rvalue)                                                                    \
    X(gcc_jit_param_as_rvalue)                                                                     \
    X(gcc_jit_result_get_code)                                                                     \
    X(gcc_jit_result_release)                                                                      \
    X(gcc_jit_type_get_pointer)
static struct jit_api {
#define ZP_JIT_SLOT(f) __typeof__(f) *f;
    ZP_JIT_API(ZP_JIT_SLOT)
} api;
#define J(f) (api.f)

/* the library's functions into api, once per process (callers hold the course's lock, and
   every thread stores the same values); 0 on success, else why in err */
static int open_api(char *err, size_t errlen) {
    static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
    static int state; /* 0 not tried, 1 open, -1 failed */
    pthread_mutex_lock(&lock);
    if (state == 0) {
        void *lib = dlopen("libgccjit.so.0", RTLD_NOW | RTLD_LOCAL);
        state = lib ? 1 : -1;
#define ZP_JIT_LOAD(f)                                                                             \
    if (state == 1) {                                                                              \
        void *sym = dlsym(lib, #f);                                                                \
        memcpy(&api.f, &sym, sizeof sym);                                                          \
        state = sym ? 1 : -1;                                                                      \
    }
        ZP_JIT_API(ZP_JIT_LOAD)
    }
    int ok = state == 1;
    pthread_mutex_unlock(&lock);
    if (!ok) {
        snprintf(err, errlen, "libgccjit.so.0 (Debian package libgccjit0) cannot be loaded");
    }
    return ok ? 0 : -1;
}

struct zp_jit {
    gcc_jit_result *result; /* owned: code compiled in memory, or */
    void *dl;               /* owned: the cache file loaded */
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
        return J(gcc_jit_context_new_rvalue_from_double)(g->ctx, g->dbl, p->value);
    case ZP_EX_X:
        return J(gcc_jit_param_as_rvalue)(x);
    case ZP_EX_NEG:
        return J(gcc_jit_context_new_unary_op)(g->ctx, NULL, GCC_JIT_UNARY_OP_MINUS, g->dbl,
                                               g->val[p->a]);
    case ZP_EX_ADD:
    case ZP_EX_SUB:
    case ZP_EX_MUL:
    case ZP_EX_DIV:
        return J(gcc_jit_context_new_binary_op)(g->ctx, NULL, bin[p->op], g->dbl, g->val[p->a],
                                                g->val[p->b]);
    case ZP_EX_POW: {
        gcc_jit_rvalue *args[2] = {g->val[p->a], g->val[p->b]};
        return J(gcc_jit_context_new_call)(g->ctx, NULL, g->builtin[ZP_EX_POW], 2, args);
    }
    default:
        return J(gcc_jit_context_new_call)(g->ctx, NULL, g->builtin[p->op], 1, &g->val[p->a]);
    }
}

/* function `name`: out[k] = expression roots[k], k < nout */
static void build_function(gen *g, const zp_expr *e, const char *name, int nout, const int *roots,
                           char *used) {
    gcc_jit_type *void_t = J(gcc_jit_context_get_type)(g->ctx, GCC_JIT_TYPE_VOID);
    gcc_jit_param *prm[2] = {
        J(gcc_jit_context_new_param)(g->ctx, NULL, g->dbl, "x"),
        J(gcc_jit_context_new_param)(g->ctx, NULL, J(gcc_jit_type_get_pointer)(g->dbl), "out")};
    gcc_jit_function *f = J(gcc_jit_context_new_function)(g->ctx, NULL, GCC_JIT_FUNCTION_EXPORTED,
                                                          void_t, name, 2, prm, 0);
    gcc_jit_block *blk = J(gcc_jit_function_new_block)(f, NULL);
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
            gcc_jit_lvalue *t = J(gcc_jit_function_new_local)(f, NULL, g->dbl, local);
            J(gcc_jit_block_add_assignment)(blk, NULL, t, v);
            v = J(gcc_jit_lvalue_as_rvalue)(t);
        }
        g->val[i] = v;
    }
    gcc_jit_type *int_t = J(gcc_jit_context_get_type)(g->ctx, GCC_JIT_TYPE_INT);
    for (int k = 0; k < nout; k++) {
        gcc_jit_lvalue *slot = J(gcc_jit_context_new_array_access)(
            g->ctx, NULL, J(gcc_jit_param_as_rvalue)(prm[1]),
            J(gcc_jit_context_new_rvalue_from_int)(g->ctx, int_t, k));
        J(gcc_jit_block_add_assignment)(blk, NULL, slot, g->val[roots[k]]);
    }
    J(gcc_jit_block_end_with_void_return)(blk, NULL);
}

static void set_options(gcc_jit_context *ctx) {
    /* -O1 already does the work of straight-line code (CSE, scheduling) and compiles in a
       fraction of -O2's time, which every command pays once per scene */
    J(gcc_jit_context_set_int_option)(ctx, GCC_JIT_INT_OPTION_OPTIMIZATION_LEVEL, 1);
    J(gcc_jit_context_add_command_line_option)(ctx, "-ffp-contract=off");
    J(gcc_jit_context_set_bool_option)(ctx, GCC_JIT_BOOL_OPTION_DEBUGINFO, 0);
    /* the driver in its own process: the embedded one exits the program when it cannot run
       the assembler (no binutils, or no PATH), where a failed compile must fall back */
    J(gcc_jit_context_set_bool_use_external_driver)(ctx, 1);
    /* a failure is reported once, by the caller's notice */
    J(gcc_jit_context_set_bool_print_errors_to_stderr)(ctx, 0);
}

/* The on-disk cache: every command pays the compile (tens of ms, mostly the assembler and
   linker run as processes) only the first time a scene's course is seen. The file is named by
   one hash of everything the code is made from (nodes, roots, this generator's version) and
   holds a second, checked after loading. */
#define ZP_JIT_GENERATOR 1 /* raise when the generated code changes for the same pool */

static unsigned long long fnv(unsigned long long h, const void *data, size_t len) {
    const unsigned char *b = data;
    for (size_t i = 0; i < len; i++) {
        h = (h ^ b[i]) * 1099511628211ULL;
    }
    return h;
}

/* FNV-1a over the pool (field by field: a node has padding), roots and versions, from h */
static unsigned long long pool_hash(unsigned long long h, const zp_expr *e, int nfn, int nout,
                                    const int *roots) {
    int head[3] = {ZP_JIT_GENERATOR, nfn, nout};
    h = fnv(h, head, sizeof head);
    h = fnv(h, roots, sizeof *roots * (size_t)nfn * nout);
    for (int i = 0; i < e->n; i++) {
        const zp_ex_node *p = &e->node[i];
        int ops[3] = {(int)p->op, p->a, p->b};
        h = fnv(fnv(h, ops, sizeof ops), &p->value, sizeof p->value);
    }
    return h;
}

/* 1 when path is a real (not linked) file of the given type, owned by this user and writable
   by nobody else: loading code runs its constructors, so a cache anyone else could plant a file
   in is not used */
static int private_to_us(const char *path, mode_t type) {
    struct stat st;
    return lstat(path, &st) == 0 && (st.st_mode & S_IFMT) == type && st.st_uid == geteuid() &&
           (st.st_mode & (S_IWGRP | S_IWOTH)) == 0;
}

/* the cache file for this pool in path (empty when there is no cache directory), and the
   check value in key */
static void cache_names(const zp_expr *e, int nfn, int nout, const int *roots, char *path,
                        size_t pathlen, char *key, size_t keylen) {
    unsigned long long h1 = pool_hash(14695981039346656037ULL, e, nfn, nout, roots);
    unsigned long long h2 = pool_hash(h1 ^ 0x9e3779b97f4a7c15ULL, e, nfn, nout, roots);
    snprintf(key, keylen, "%016llx%016llx", h1, h2);
    const char *xdg = getenv("XDG_CACHE_HOME"), *home = getenv("HOME");
    char dir[PATH_MAX - 64]; /* room for the file name */
    path[0] = '\0';
    if (xdg && *xdg) {
        snprintf(dir, sizeof dir, "%s/zipopt", xdg);
    } else if (home && *home) {
        snprintf(dir, sizeof dir, "%s/.cache/zipopt", home);
    } else {
        return;
    }
    /* the parent may be missing too (a fresh $HOME): make both levels */
    char parent[sizeof dir];
    snprintf(parent, sizeof parent, "%s", dir);
    char *slash = strrchr(parent, '/');
    if (slash) {
        *slash = '\0';
        mkdir(parent, 0700);
    }
    if ((mkdir(dir, 0700) == 0 || errno == EEXIST) && private_to_us(dir, S_IFDIR)) {
        snprintf(path, pathlen, "%s/course-%016llx.so", dir, h1);
    }
}

/* the nfn functions from handle (a loaded file or a compile result) through get */
static int resolve(zp_jit *j, int nfn, void *(*get)(void *, const char *), void *handle) {
    for (int i = 0; i < nfn; i++) {
        char name[32];
        snprintf(name, sizeof name, "zp_expr_fn%d", i);
        /* the one cast from object to function pointer that a JIT needs (POSIX allows it) */
        void *code = get(handle, name);
        memcpy(&j->fn[i], &code, sizeof code);
        if (!code) {
            return -1;
        }
    }
    j->nfn = nfn;
    return 0;
}

static void *result_get(void *r, const char *name) {
    return J(gcc_jit_result_get_code)(r, name);
}

/* a loaded cache file whose key matches; 0 on success */
static int load_cached(zp_jit *j, const char *path, const char *key, int nfn) {
    void *dl = path[0] && private_to_us(path, S_IFREG) ? dlopen(path, RTLD_NOW | RTLD_LOCAL)
                                                        : NULL;
    const char *const *stored = dl ? dlsym(dl, "zp_expr_key") : NULL;
    if (!stored || strcmp(*stored, key) || resolve(j, nfn, dlsym, dl)) {
        if (dl) {
            dlclose(dl);
        }
        return -1;
    }
    j->dl = dl;
    return 0;
}

/* the pool's functions, and the key as an exported string, in g's context */
static int generate(gen *g, const zp_expr *e, int nfn, int nout, const int *roots,
                    const char *key) {
    char *used = malloc((size_t)e->n + 1);
    if (!used) {
        return -1;
    }
    for (int i = 0; i < nfn; i++) {
        char name[32];
        snprintf(name, sizeof name, "zp_expr_fn%d", i);
        build_function(g, e, name, nout, roots + (size_t)i * nout, used);
    }
    free(used);
    gcc_jit_type *str = J(gcc_jit_context_get_type)(g->ctx, GCC_JIT_TYPE_CONST_CHAR_PTR);
    gcc_jit_lvalue *k =
        J(gcc_jit_context_new_global)(g->ctx, NULL, GCC_JIT_GLOBAL_EXPORTED, str, "zp_expr_key");
    J(gcc_jit_global_set_initializer_rvalue)(k, J(gcc_jit_context_new_string_literal)(g->ctx, key));
    return 0;
}

static void declare_functions(gen *g) {
    g->dbl = J(gcc_jit_context_get_type)(g->ctx, GCC_JIT_TYPE_DOUBLE);
    /* pow is the library's, not the builtin: GCC would turn pow(u, 2) into u * u, which
       differs from the interpreter's pow in the last bit at some u */
    gcc_jit_param *pw[2] = {J(gcc_jit_context_new_param)(g->ctx, NULL, g->dbl, "a"),
                            J(gcc_jit_context_new_param)(g->ctx, NULL, g->dbl, "b")};
    g->builtin[ZP_EX_POW] = J(gcc_jit_context_new_function)(g->ctx, NULL, GCC_JIT_FUNCTION_IMPORTED,
                                                            g->dbl, "pow", 2, pw, 0);
    for (int op = ZP_EX_SQRT; op < ZP_EX_COUNT; op++) {
        char name[32];
        snprintf(name, sizeof name, "__builtin_%s", zp_expr_func_name((zp_ex_op)op));
        g->builtin[op] = J(gcc_jit_context_get_builtin_function)(g->ctx, name);
    }
}

/* compiles into the cache file (written aside, then renamed: concurrent commands never see
   half a file) and loads it; else compiles in memory */
static int compile(zp_jit *j, gen *g, const char *path, const char *key, int nfn, char *err,
                   size_t errlen) {
    if (path[0]) {
        char tmp[PATH_MAX + 32];
        snprintf(tmp, sizeof tmp, "%s.%ld.tmp", path, (long)getpid());
        J(gcc_jit_context_compile_to_file)(g->ctx, GCC_JIT_OUTPUT_KIND_DYNAMIC_LIBRARY, tmp);
        int ok = !J(gcc_jit_context_get_first_error)(g->ctx) && rename(tmp, path) == 0 &&
                 load_cached(j, path, key, nfn) == 0;
        remove(tmp);
        if (ok) {
            return 0;
        }
    }
    if (!J(gcc_jit_context_get_first_error)(g->ctx)) {
        j->result = J(gcc_jit_context_compile)(g->ctx);
    }
    if (!j->result || resolve(j, nfn, result_get, j->result)) {
        const char *why = J(gcc_jit_context_get_first_error)(g->ctx);
        snprintf(err, errlen, "libgccjit: %s", why ? why : "compile failed");
        return -1;
    }
    return 0;
}

zp_jit *zp_jit_compile(const zp_expr *e, int nfn, int nout, const int *roots, char *err,
                       size_t errlen) {
    zp_jit *j = calloc(1, sizeof *j + sizeof j->fn[0] * (size_t)nfn);
    if (!j) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    char path[PATH_MAX], key[40];
    cache_names(e, nfn, nout, roots, path, sizeof path, key, sizeof key);
    if (load_cached(j, path, key, nfn) == 0) {
        return j;
    }
    if (open_api(err, errlen)) {
        free(j);
        return NULL;
    }
    gen g = {.val = calloc((size_t)e->n + 1, sizeof *g.val), .ctx = J(gcc_jit_context_acquire)()};
    int bad = !g.val || !g.ctx;
    if (bad) {
        snprintf(err, errlen, "out of memory");
    } else {
        set_options(g.ctx);
        declare_functions(&g);
        bad = generate(&g, e, nfn, nout, roots, key) || compile(j, &g, path, key, nfn, err, errlen);
    }
    if (g.ctx) {
        J(gcc_jit_context_release)(g.ctx);
    }
    free(g.val);
    if (bad) {
        zp_jit_free(j);
        return NULL;
    }
    return j;
}

zp_jit_fn zp_jit_get(const zp_jit *j, int i) {
    return j->fn[i];
}

void zp_jit_free(zp_jit *j) {
    if (!j) {
        return;
    }
    if (j->result) {
        J(gcc_jit_result_release)(j->result);
    }
    if (j->dl) {
        dlclose(j->dl);
    }
    free(j);
}
