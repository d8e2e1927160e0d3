/* zp_jit_compile: a zp_expr pool to machine code with libgccjit, one straight-line function
   per group of expressions, every node computed once into a local. */
#include "jit.h"

#include <dlfcn.h>
#include <fcntl.h>
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
    int fd;                 /* owned: that file, open while it is loaded, -1 if none; dlopen
                               knows it by its /proc/self/fd name, and glibc returns a loaded
                               object of the same name, so the number is not reused before */
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

/* Design note: the cache is used through descriptors only. Checking a path and then using it
   by name lets whoever can rename a folder above it swap the folder in between (a planted
   library loaded, or a file elsewhere overwritten), so the folder is opened once, its owner
   and mode are checked on the descriptor, and every later step (compile target, rename,
   remove, load) goes through that descriptor: openat/renameat/unlinkat, and /proc/self/fd
   paths for libgccjit and dlopen, which take only names. */

/* 1 when st is of the given type, owned by this user and writable by nobody else: loading
   code runs its constructors, so a cache anyone else could plant a file in is not used */
static int private_to_us(const struct stat *st, mode_t type) {
    return (st->st_mode & S_IFMT) == type && st->st_uid == geteuid() &&
           (st->st_mode & (S_IWGRP | S_IWOTH)) == 0;
}

/* the folder name in parent (a descriptor), never through a link, created (0700) when
   missing only when parent is this user's own: no folder is made in another user's tree.
   Its descriptor (owned), or -1. */
static int open_folder(int parent, const char *name) {
    struct stat st;
    if (fstat(parent, &st) == 0 && st.st_uid == geteuid()) {
        mkdirat(parent, name, 0700);
    }
    return openat(parent, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
}

/* the cache folder, opened and checked: $XDG_CACHE_HOME/zipopt or $HOME/.cache/zipopt (a
   relative XDG_CACHE_HOME is ignored, as the XDG spec says); its descriptor (owned) or -1
   when there is none to use */
static int open_cache_dir(void) {
    const char *xdg = getenv("XDG_CACHE_HOME"), *home = getenv("HOME");
    char base[PATH_MAX];
    if (xdg && xdg[0] == '/') {
        snprintf(base, sizeof base, "%s", xdg);
    } else if (home && home[0] == '/') {
        snprintf(base, sizeof base, "%s/.cache", home);
    } else {
        return -1;
    }
    /* the base's parent as the user named it (links followed), then names below it alone */
    size_t len = strlen(base);
    while (len > 1 && base[len - 1] == '/') {
        base[--len] = '\0';
    }
    char *slash = strrchr(base, '/');
    if (!slash || !slash[1]) {
        return -1;
    }
    *slash = '\0';
    int parent = open(base[0] ? base : "/", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    int top = parent < 0 ? -1 : open_folder(parent, slash + 1);
    int dir = top < 0 ? -1 : open_folder(top, "zipopt");
    struct stat st;
    if (dir >= 0 && (fstat(dir, &st) || !private_to_us(&st, S_IFDIR))) {
        close(dir);
        dir = -1;
    }
    if (top >= 0) {
        close(top);
    }
    if (parent >= 0) {
        close(parent);
    }
    return dir;
}

/* the cache file's name for this pool, and the check value in key */
static void cache_names(const zp_expr *e, int nfn, int nout, const int *roots, char *name,
                        size_t namelen, char *key, size_t keylen) {
    unsigned long long h1 = pool_hash(14695981039346656037ULL, e, nfn, nout, roots);
    unsigned long long h2 = pool_hash(h1 ^ 0x9e3779b97f4a7c15ULL, e, nfn, nout, roots);
    snprintf(key, keylen, "%016llx%016llx", h1, h2);
    snprintf(name, namelen, "course-%016llx.so", h1);
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

/* the file name in the cache folder dir, loaded when it is a private regular file (checked
   on the descriptor dlopen then reads) whose key matches; 0 on success */
static int load_cached(zp_jit *j, int dir, const char *name, const char *key, int nfn) {
    int fd = dir < 0 ? -1 : openat(dir, name, O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    struct stat st;
    void *dl = NULL;
    if (fd >= 0 && fstat(fd, &st) == 0 && private_to_us(&st, S_IFREG)) {
        char self[64];
        snprintf(self, sizeof self, "/proc/self/fd/%d", fd);
        dl = dlopen(self, RTLD_NOW | RTLD_LOCAL);
    }
    const char *const *stored = dl ? dlsym(dl, "zp_expr_key") : NULL;
    if (!stored || strcmp(*stored, key) || resolve(j, nfn, dlsym, dl)) {
        if (dl) {
            dlclose(dl);
        }
        if (fd >= 0) {
            close(fd);
        }
        return -1;
    }
    j->dl = dl;
    j->fd = fd;
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

/* compiles into the cache file (written aside under a fresh name in the folder dir, then
   renamed: concurrent commands never see half a file) and loads it; else compiles in memory */
static int compile(zp_jit *j, gen *g, int dir, const char *name, const char *key, int nfn,
                   char *err, size_t errlen) {
    unsigned char r[8];
    if (dir >= 0 && getentropy(r, sizeof r) == 0) {
        char tmp[96], target[160];
        snprintf(tmp, sizeof tmp, ".%s.%02x%02x%02x%02x%02x%02x%02x%02x.tmp", name, r[0], r[1],
                 r[2], r[3], r[4], r[5], r[6], r[7]);
        snprintf(target, sizeof target, "/proc/self/fd/%d/%s", dir, tmp);
        J(gcc_jit_context_compile_to_file)(g->ctx, GCC_JIT_OUTPUT_KIND_DYNAMIC_LIBRARY, target);
        int ok = !J(gcc_jit_context_get_first_error)(g->ctx) &&
                 renameat(dir, tmp, dir, name) == 0 && load_cached(j, dir, name, key, nfn) == 0;
        unlinkat(dir, tmp, 0);
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
    j->fd = -1;
    char name[64], key[40];
    cache_names(e, nfn, nout, roots, name, sizeof name, key, sizeof key);
    int dir = open_cache_dir();
    int cached = load_cached(j, dir, name, key, nfn) == 0;
    if (cached || open_api(err, errlen)) {
        if (dir >= 0) {
            close(dir);
        }
        if (!cached) {
            free(j);
            j = NULL;
        }
        return j;
    }
    gen g = {.val = calloc((size_t)e->n + 1, sizeof *g.val), .ctx = J(gcc_jit_context_acquire)()};
    int bad = !g.val || !g.ctx;
    if (bad) {
        snprintf(err, errlen, "out of memory");
    } else {
        set_options(g.ctx);
        declare_functions(&g);
        bad = generate(&g, e, nfn, nout, roots, key) ||
              compile(j, &g, dir, name, key, nfn, err, errlen);
    }
    if (dir >= 0) {
        close(dir);
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
    if (j->fd >= 0) {
        close(j->fd);
    }
    free(j);
}
