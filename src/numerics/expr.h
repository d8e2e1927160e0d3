/* Expressions in x (docs/scene-file.md [course] grammar) as a shared tree with exact symbolic
   derivatives, simplified as they are built: the input of the course compiler. */
#ifndef ZP_EXPR_H
#define ZP_EXPR_H

#include <stddef.h>

typedef enum {
    ZP_EX_NUM,
    ZP_EX_X,
    ZP_EX_NEG,
    ZP_EX_ADD,
    ZP_EX_SUB,
    ZP_EX_MUL,
    ZP_EX_DIV,
    ZP_EX_POW,
    ZP_EX_SQRT, /* the functions, one argument each, from here on */
    ZP_EX_EXP,
    ZP_EX_LOG,
    ZP_EX_SIN,
    ZP_EX_COS,
    ZP_EX_TAN,
    ZP_EX_SINH,
    ZP_EX_COSH,
    ZP_EX_TANH,
    ZP_EX_COUNT
} zp_ex_op;

/* One node; its operands are earlier nodes of the same zp_expr, so the node order is an
   evaluation order. */
typedef struct zp_ex_node {
    zp_ex_op op;
    int a, b;     /* operand nodes (b: binary operators only), -1 when unused */
    double value; /* ZP_EX_NUM only */
} zp_ex_node;

/* A pool of nodes, shared by every expression built in it: equal subtrees are stored once. */
typedef struct zp_expr {
    zp_ex_node *node; /* owned, n used of cap */
    int n, cap;
} zp_expr;

/* Parses text into e; returns the root node, or -1 with what is wrong in err. */
int zp_expr_parse(zp_expr *e, const char *text, char *err, size_t errlen);
/* d/dx of the expression at root, built in e; its root, or -1 when out of memory. */
int zp_expr_deriv(zp_expr *e, int root);
/* The expression at root evaluated at x (the operations the compiled code does). */
double zp_expr_eval(const zp_expr *e, int root, double x);
void zp_expr_free(zp_expr *e);
/* The C library function of a function node (ZP_EX_SQRT..ZP_EX_TANH), e.g. "sinh". */
const char *zp_expr_func_name(zp_ex_op op);

#endif
