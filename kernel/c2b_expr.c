#include "c2b_expr.h"

#include <ctype.h>
#include <matheval.h>
#include <stdlib.h>
#include <string.h>

#define EXPR_MAX_VARS 64

struct c2b_expr {
    void *ev;                      /* libmatheval evaluator */
    int nvar;
    char *names[EXPR_MAX_VARS];    /* variables the evaluator mentions (owned copies) */
    double values[EXPR_MAX_VARS];  /* constant values; u, v, t slots filled per call */
    int iu, iv, it;                /* slots of u, v, t or -1 */
    char *text;
};

static const char *const FUNCTIONS[] = {
    "exp",  "log",   "sqrt",  "sin",   "cos",   "tan",   "cot",   "sec",  "csc",
    "asin", "acos",  "atan",  "acot",  "asec",  "acsc",  "sinh",  "cosh", "tanh",
    "coth", "sech",  "csch",  "asinh", "acosh", "atanh", "acoth", "asech", "acsch",
    "abs",  "step",  "delta", "nandelta", "erf"};

static int is_function(const char *s, size_t len)
{
    for (size_t i = 0; i < sizeof FUNCTIONS / sizeof *FUNCTIONS; i++)
        if (strlen(FUNCTIONS[i]) == len && !strncmp(FUNCTIONS[i], s, len))
            return 1;
    return 0;
}

static int find_constant(const c2b_constants *c, const char *s, size_t len)
{
    if (!c)
        return -1;
    for (int i = 0; i < c->n; i++)
        if (strlen(c->names[i]) == len && !strncmp(c->names[i], s, len))
            return i;
    return -1;
}

/* Check identifiers and parentheses before handing the text to libmatheval. */
static c2b_status scan(const char *text, const c2b_constants *constants, int allowed,
                       c2b_error *err)
{
    int depth = 0;
    for (const char *p = text; *p;) {
        if (*p == '(') {
            depth++;
            p++;
        } else if (*p == ')') {
            if (--depth < 0)
                return c2b_error_set(err, C2B_ERR_SPEC, "unbalanced ')' in '%s'", text);
            p++;
        } else if (isalpha((unsigned char)*p) || *p == '_') {
            const char *s = p;
            while (isalnum((unsigned char)*p) || *p == '_')
                p++;
            size_t len = (size_t)(p - s);
            const char *q = p;
            while (*q == ' ' || *q == '\t')
                q++;
            if (*q == '(') {
                if (!is_function(s, len))
                    return c2b_error_set(err, C2B_ERR_SPEC, "unknown function '%.*s' in '%s'",
                                         (int)len, s, text);
                continue;
            }
            if (len == 1 && (*s == 'u' || *s == 'v' || *s == 't')) {
                int bit = *s == 'u' ? C2B_EXPR_U : *s == 'v' ? C2B_EXPR_V : C2B_EXPR_T;
                if (!(allowed & bit))
                    return c2b_error_set(err, C2B_ERR_SPEC, "variable '%c' is not allowed here",
                                         *s);
                continue;
            }
            if ((len == 2 && !strncmp(s, "pi", 2)) || (len == 1 && *s == 'e'))
                continue;
            if (find_constant(constants, s, len) < 0)
                return c2b_error_set(err, C2B_ERR_SPEC, "unknown identifier '%.*s'", (int)len, s);
        } else if (isdigit((unsigned char)*p) || *p == '.') {
            /* number, with optional exponent: 1.5e-3 */
            while (isdigit((unsigned char)*p) || *p == '.')
                p++;
            if ((*p == 'e' || *p == 'E') &&
                (isdigit((unsigned char)p[1]) ||
                 ((p[1] == '+' || p[1] == '-') && isdigit((unsigned char)p[2])))) {
                p += 2;
                while (isdigit((unsigned char)*p))
                    p++;
            }
        } else if (strchr("+-*/^ \t\n", *p)) {
            p++;
        } else {
            return c2b_error_set(err, C2B_ERR_SPEC, "unexpected character '%c' in '%s'", *p, text);
        }
    }
    if (depth != 0)
        return c2b_error_set(err, C2B_ERR_SPEC, "unbalanced '(' in '%s'", text);
    return C2B_OK;
}

/* Fill the variable table of a new evaluator. */
static c2b_status bind(c2b_expr *x, const c2b_constants *constants, c2b_error *err)
{
    char **names;
    int cnt;
    evaluator_get_variables(x->ev, &names, &cnt);
    if (cnt > EXPR_MAX_VARS)
        return c2b_error_set(err, C2B_ERR_LIMIT, "expression uses more than %d names",
                             EXPR_MAX_VARS);
    x->nvar = cnt;
    x->iu = x->iv = x->it = -1;
    for (int i = 0; i < cnt; i++) {
        x->names[i] = malloc(strlen(names[i]) + 1);
        if (!x->names[i])
            return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
        strcpy(x->names[i], names[i]);
        x->values[i] = 0.0;
        if (!strcmp(names[i], "u"))
            x->iu = i;
        else if (!strcmp(names[i], "v"))
            x->iv = i;
        else if (!strcmp(names[i], "t"))
            x->it = i;
        else {
            int k = find_constant(constants, names[i], strlen(names[i]));
            if (k < 0)
                return c2b_error_set(err, C2B_ERR_SPEC, "unknown identifier '%s'", names[i]);
            x->values[i] = constants->values[k];
        }
    }
    return C2B_OK;
}

void c2b_expr_destroy(c2b_expr *e)
{
    if (!e)
        return;
    if (e->ev)
        evaluator_destroy(e->ev);
    for (int i = 0; i < e->nvar; i++)
        free(e->names[i]);
    free(e->text);
    free(e);
}

c2b_status c2b_expr_create(const char *text, const c2b_constants *constants, int allowed,
                           c2b_expr **out, c2b_error *err)
{
    if (!text || !out)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_expr_create: NULL argument");
    *out = NULL;
    const char *p = text;
    while (*p == ' ' || *p == '\t')
        p++;
    if (!*p)
        return c2b_error_set(err, C2B_ERR_SPEC, "empty expression");
    c2b_status st = scan(text, constants, allowed, err);
    if (st)
        return st;
    c2b_expr *x = calloc(1, sizeof *x);
    if (!x)
        return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
    x->text = malloc(strlen(text) + 1);
    if (!x->text) {
        free(x);
        return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
    }
    strcpy(x->text, text);
    x->ev = evaluator_create(x->text);
    if (!x->ev) {
        c2b_expr_destroy(x);
        return c2b_error_set(err, C2B_ERR_SPEC, "cannot parse expression '%s'", text);
    }
    /* Constants are folded in by value: substitute only the ones used. */
    c2b_constants none = {0, NULL, NULL};
    st = bind(x, constants ? constants : &none, err);
    if (st) {
        c2b_expr_destroy(x);
        return st;
    }
    *out = x;
    return C2B_OK;
}

c2b_status c2b_expr_derivative(const c2b_expr *e, char var, int k, c2b_expr **out,
                               c2b_error *err)
{
    if (!e || !out || (var != 'u' && var != 'v' && var != 't') || k < 0 || k > 6)
        return c2b_error_set(err, C2B_ERR_ARG, "c2b_expr_derivative: invalid arguments");
    *out = NULL;
    char vn[2] = {var, 0};
    void *ev = evaluator_create(e->text);
    for (int i = 0; i < k && ev; i++) {
        void *d = evaluator_derivative(ev, vn);
        evaluator_destroy(ev);
        ev = d;
    }
    if (!ev)
        return c2b_error_set(err, C2B_ERR_NOMEM, "cannot differentiate '%s'", e->text);
    c2b_expr *x = calloc(1, sizeof *x);
    if (!x) {
        evaluator_destroy(ev);
        return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
    }
    x->ev = ev;
    const char *s = evaluator_get_string(ev);
    x->text = malloc(strlen(s) + 1);
    if (!x->text) {
        c2b_expr_destroy(x);
        return c2b_error_set(err, C2B_ERR_NOMEM, "out of memory");
    }
    strcpy(x->text, s);
    /* The derivative mentions a subset of the original names: copy their values. */
    const char *cn[EXPR_MAX_VARS];
    double cv[EXPR_MAX_VARS];
    int nc = 0;
    for (int i = 0; i < e->nvar; i++)
        if (i != e->iu && i != e->iv && i != e->it) {
            cn[nc] = e->names[i];
            cv[nc++] = e->values[i];
        }
    c2b_constants cs = {nc, cn, cv};
    c2b_status st = bind(x, &cs, err);
    if (st) {
        c2b_expr_destroy(x);
        return st;
    }
    *out = x;
    return C2B_OK;
}

double c2b_expr_eval(const c2b_expr *e, double u, double v, double t)
{
    c2b_expr *x = (c2b_expr *)e; /* the values table is scratch space */
    if (x->iu >= 0)
        x->values[x->iu] = u;
    if (x->iv >= 0)
        x->values[x->iv] = v;
    if (x->it >= 0)
        x->values[x->it] = t;
    return evaluator_evaluate(x->ev, x->nvar, x->names, x->values);
}

int c2b_expr_depends(const c2b_expr *e, char var)
{
    return var == 'u' ? e->iu >= 0 : var == 'v' ? e->iv >= 0 : var == 't' ? e->it >= 0 : 0;
}

const char *c2b_expr_text(const c2b_expr *e) { return e->text; }
