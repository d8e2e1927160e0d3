/* Expressions in x: a recursive-descent parser of docs/scene-file.md's grammar, exact derivatives
   by the textbook rules, and simplification (constants folded, x+0, x*1, x^1, ... dropped, equal
   subtrees shared) done by the node constructors, so every tree is built simplified. */
#include "expr.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const func_names[ZP_EX_COUNT] = {
    [ZP_EX_SQRT] = "sqrt", [ZP_EX_EXP] = "exp",   [ZP_EX_LOG] = "log",
    [ZP_EX_SIN] = "sin",   [ZP_EX_COS] = "cos",   [ZP_EX_TAN] = "tan",
    [ZP_EX_SINH] = "sinh", [ZP_EX_COSH] = "cosh", [ZP_EX_TANH] = "tanh"};

const char *zp_expr_func_name(zp_ex_op op) {
    return func_names[op];
}

static int is_func(zp_ex_op op) {
    return op >= ZP_EX_SQRT;
}

static double apply(zp_ex_op op, double a, double b) {
    switch (op) {
    case ZP_EX_NEG:
        return -a;
    case ZP_EX_ADD:
        return a + b;
    case ZP_EX_SUB:
        return a - b;
    case ZP_EX_MUL:
        return a * b;
    case ZP_EX_DIV:
        return a / b;
    case ZP_EX_POW:
        return pow(a, b);
    case ZP_EX_SQRT:
        return sqrt(a);
    case ZP_EX_EXP:
        return exp(a);
    case ZP_EX_LOG:
        return log(a);
    case ZP_EX_SIN:
        return sin(a);
    case ZP_EX_COS:
        return cos(a);
    case ZP_EX_TAN:
        return tan(a);
    case ZP_EX_SINH:
        return sinh(a);
    case ZP_EX_COSH:
        return cosh(a);
    case ZP_EX_TANH:
        return tanh(a);
    default:
        return NAN; /* leaves have no operation */
    }
}

/* the node (op, a, b, value), reusing an equal one: -1 when out of memory (or an operand is) */
static int intern(zp_expr *e, zp_ex_op op, int a, int b, double value) {
    if ((op != ZP_EX_NUM && op != ZP_EX_X && a < 0) ||
        (op >= ZP_EX_ADD && op <= ZP_EX_POW && b < 0)) {
        return -1;
    }
    for (int i = 0; i < e->n; i++) {
        const zp_ex_node *p = &e->node[i];
        if (p->op == op && p->a == a && p->b == b &&
            (op != ZP_EX_NUM || memcmp(&p->value, &value, sizeof value) == 0)) {
            return i;
        }
    }
    if (e->n == e->cap) {
        int cap = e->cap ? 2 * e->cap : 64;
        zp_ex_node *grown = realloc(e->node, sizeof *grown * cap);
        if (!grown) {
            return -1;
        }
        e->node = grown;
        e->cap = cap;
    }
    e->node[e->n] = (zp_ex_node){op, a, b, value};
    return e->n++;
}

static int num(zp_expr *e, double v) {
    return intern(e, ZP_EX_NUM, -1, -1, v);
}

static int is_num(const zp_expr *e, int i, double v) {
    return i >= 0 && e->node[i].op == ZP_EX_NUM && e->node[i].value == v;
}

/* op applied to a (and b), simplified */
static int make(zp_expr *e, zp_ex_op op, int a, int b) {
    if (a < 0 || (op >= ZP_EX_ADD && op <= ZP_EX_POW && b < 0)) {
        return -1;
    }
    const zp_ex_node *na = &e->node[a], *nb = b >= 0 ? &e->node[b] : NULL;
    if (na->op == ZP_EX_NUM && (!nb || nb->op == ZP_EX_NUM)) {
        return num(e, apply(op, na->value, nb ? nb->value : 0));
    }
    switch (op) {
    case ZP_EX_NEG:
        return na->op == ZP_EX_NEG ? na->a : intern(e, op, a, -1, 0);
    case ZP_EX_ADD:
        return is_num(e, a, 0) ? b : is_num(e, b, 0) ? a : intern(e, op, a, b, 0);
    case ZP_EX_SUB:
        return is_num(e, b, 0)   ? a
               : is_num(e, a, 0) ? make(e, ZP_EX_NEG, b, -1)
                                 : intern(e, op, a, b, 0);
    case ZP_EX_MUL:
        if (is_num(e, a, 0) || is_num(e, b, 0)) {
            return num(e, 0);
        }
        if (is_num(e, a, 1) || is_num(e, b, 1)) {
            return is_num(e, a, 1) ? b : a;
        }
        if (is_num(e, a, -1) || is_num(e, b, -1)) {
            return make(e, ZP_EX_NEG, is_num(e, a, -1) ? b : a, -1);
        }
        return intern(e, op, a, b, 0);
    case ZP_EX_DIV:
        return is_num(e, a, 0) ? num(e, 0) : is_num(e, b, 1) ? a : intern(e, op, a, b, 0);
    case ZP_EX_POW:
        return is_num(e, b, 1) ? a : is_num(e, b, 0) ? num(e, 1) : intern(e, op, a, b, 0);
    default:
        return intern(e, op, a, -1, 0);
    }
}

static int mul(zp_expr *e, int a, int b) {
    return make(e, ZP_EX_MUL, a, b);
}
static int fn(zp_expr *e, zp_ex_op op, int a) {
    return make(e, op, a, -1);
}

/* d/dx of node i, given its operands' derivatives da, db */
static int deriv_node(zp_expr *e, int i, int da, int db) {
    zp_ex_node nd = e->node[i];
    int a = nd.a, b = nd.b;
    switch (nd.op) {
    case ZP_EX_NUM:
        return num(e, 0);
    case ZP_EX_X:
        return num(e, 1);
    case ZP_EX_NEG:
        return make(e, ZP_EX_NEG, da, -1);
    case ZP_EX_ADD:
    case ZP_EX_SUB:
        return make(e, nd.op, da, db);
    case ZP_EX_MUL:
        return make(e, ZP_EX_ADD, mul(e, da, b), mul(e, a, db));
    case ZP_EX_DIV:
        if (e->node[b].op == ZP_EX_NUM) {
            return make(e, ZP_EX_DIV, da, b);
        }
        return make(e, ZP_EX_DIV, make(e, ZP_EX_SUB, mul(e, da, b), mul(e, a, db)), mul(e, b, b));
    case ZP_EX_POW:
        if (e->node[b].op == ZP_EX_NUM) { /* c a^(c-1) a' */
            double c = e->node[b].value;
            return mul(e, mul(e, b, make(e, ZP_EX_POW, a, num(e, c - 1))), da);
        }
        if (e->node[a].op == ZP_EX_NUM) { /* a^b log(a) b' */
            return mul(e, mul(e, i, fn(e, ZP_EX_LOG, a)), db);
        }
        /* a^b (b' log a + b a' / a) */
        return mul(e, i,
                   make(e, ZP_EX_ADD, mul(e, db, fn(e, ZP_EX_LOG, a)),
                        make(e, ZP_EX_DIV, mul(e, b, da), a)));
    case ZP_EX_SQRT:
        return make(e, ZP_EX_DIV, da, mul(e, num(e, 2), i));
    case ZP_EX_EXP:
        return mul(e, i, da);
    case ZP_EX_LOG:
        return make(e, ZP_EX_DIV, da, a);
    case ZP_EX_SIN:
        return mul(e, fn(e, ZP_EX_COS, a), da);
    case ZP_EX_COS:
        return make(e, ZP_EX_NEG, mul(e, fn(e, ZP_EX_SIN, a), da), -1);
    case ZP_EX_TAN: {
        int c = fn(e, ZP_EX_COS, a);
        return make(e, ZP_EX_DIV, da, mul(e, c, c));
    }
    case ZP_EX_SINH:
        return mul(e, fn(e, ZP_EX_COSH, a), da);
    case ZP_EX_COSH:
        return mul(e, fn(e, ZP_EX_SINH, a), da);
    case ZP_EX_TANH: { /* 1/cosh^2 rather than 1 - tanh^2, which cancels for large |a| */
        int c = fn(e, ZP_EX_COSH, a);
        return make(e, ZP_EX_DIV, da, mul(e, c, c));
    }
    default:
        return -1;
    }
}

int zp_expr_deriv(zp_expr *e, int root) {
    if (root < 0) {
        return -1;
    }
    /* operands precede their nodes: one pass in node order differentiates the whole tree */
    int n = root + 1, *d = malloc(sizeof *d * n);
    if (!d) {
        return -1;
    }
    /* d[i] = 1 marks the nodes under root; the pool holds other expressions too */
    memset(d, 0, sizeof *d * n);
    d[root] = 1;
    for (int i = root; i >= 0; i--) {
        const zp_ex_node *p = &e->node[i];
        if (d[i] && p->a >= 0) {
            d[p->a] = 1;
        }
        if (d[i] && p->b >= 0) {
            d[p->b] = 1;
        }
    }
    for (int i = 0; i < n; i++) {
        const zp_ex_node *p = &e->node[i];
        if (!d[i]) {
            d[i] = -1;
            continue;
        }
        int da = p->a >= 0 ? d[p->a] : -1, db = p->b >= 0 ? d[p->b] : -1;
        int has_a = p->op != ZP_EX_NUM && p->op != ZP_EX_X,
            has_b = p->op >= ZP_EX_ADD && !is_func(p->op);
        d[i] = (has_a && da < 0) || (has_b && db < 0) ? -1 : deriv_node(e, i, da, db);
    }
    int r = d[root];
    free(d);
    return r;
}

double zp_expr_eval(const zp_expr *e, int root, double x) {
    const zp_ex_node *p = &e->node[root];
    switch (p->op) {
    case ZP_EX_NUM:
        return p->value;
    case ZP_EX_X:
        return x;
    default:
        return apply(p->op, zp_expr_eval(e, p->a, x), p->b >= 0 ? zp_expr_eval(e, p->b, x) : 0);
    }
}

void zp_expr_free(zp_expr *e) {
    free(e->node);
    memset(e, 0, sizeof *e);
}

/* the parser: one token of lookahead over the text */
typedef struct parser {
    zp_expr *e;
    const char *p;
    char *err;
    size_t errlen;
    int failed;
} parser;

static int fail_at(parser *ps, const char *what) {
    if (!ps->failed) {
        snprintf(ps->err, ps->errlen, "%s at `%.20s`", what, *ps->p ? ps->p : "end");
    }
    ps->failed = 1;
    return -1;
}

static char peek(parser *ps) {
    while (isspace((unsigned char)*ps->p)) {
        ps->p++;
    }
    return *ps->p;
}

static int parse_sum(parser *ps);

static int parse_primary(parser *ps) {
    char c = peek(ps);
    if (isdigit((unsigned char)c) || c == '.') {
        char *end;
        double v = strtod(ps->p, &end);
        if (end == ps->p) {
            return fail_at(ps, "bad number");
        }
        ps->p = end;
        return num(ps->e, v);
    }
    if (c == '(') {
        ps->p++;
        int r = parse_sum(ps);
        if (peek(ps) != ')') {
            return fail_at(ps, "expected `)`");
        }
        ps->p++;
        return r;
    }
    const char *s = ps->p;
    while (isalnum((unsigned char)*ps->p) || *ps->p == '_') {
        ps->p++;
    }
    size_t len = (size_t)(ps->p - s);
    if (len == 1 && *s == 'x') {
        return intern(ps->e, ZP_EX_X, -1, -1, 0);
    }
    for (int op = ZP_EX_SQRT; op < ZP_EX_COUNT && len > 0; op++) {
        if (strlen(func_names[op]) == len && !strncmp(func_names[op], s, len)) {
            if (peek(ps) != '(') {
                return fail_at(ps, "expected `(` after a function name");
            }
            return fn(ps->e, (zp_ex_op)op, parse_primary(ps));
        }
    }
    ps->p = s;
    return fail_at(ps, "expected a number, x, a function or `(`");
}

/* a^b with b a signed operand (chained ^ is refused: its reading is ambiguous) */
static int parse_power(parser *ps) {
    int a = parse_primary(ps);
    if (peek(ps) != '^') {
        return a;
    }
    ps->p++;
    int neg = 0;
    for (char c; (c = peek(ps)) == '-' || c == '+'; ps->p++) {
        neg ^= c == '-';
    }
    int b = parse_primary(ps);
    if (peek(ps) == '^') {
        return fail_at(ps, "chained `^`");
    }
    return make(ps->e, ZP_EX_POW, a, neg ? make(ps->e, ZP_EX_NEG, b, -1) : b);
}

static int parse_unary(parser *ps) {
    char c = peek(ps);
    if (c == '-' || c == '+') {
        ps->p++;
        int a = parse_unary(ps);
        return c == '-' ? make(ps->e, ZP_EX_NEG, a, -1) : a;
    }
    return parse_power(ps);
}

static int parse_product(parser *ps) {
    int a = parse_unary(ps);
    for (char c; (c = peek(ps)) == '*' || c == '/';) {
        ps->p++;
        a = make(ps->e, c == '*' ? ZP_EX_MUL : ZP_EX_DIV, a, parse_unary(ps));
    }
    return a;
}

static int parse_sum(parser *ps) {
    int a = parse_product(ps);
    for (char c; (c = peek(ps)) == '+' || c == '-';) {
        ps->p++;
        a = make(ps->e, c == '+' ? ZP_EX_ADD : ZP_EX_SUB, a, parse_product(ps));
    }
    return a;
}

int zp_expr_parse(zp_expr *e, const char *text, char *err, size_t errlen) {
    parser ps = {e, text, err, errlen, 0};
    int r = parse_sum(&ps);
    if (!ps.failed && peek(&ps) != '\0') {
        return fail_at(&ps, "unexpected text");
    }
    if (r < 0 && !ps.failed) {
        snprintf(err, errlen, "out of memory");
    }
    return ps.failed ? -1 : r;
}
