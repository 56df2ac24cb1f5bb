/* test_expr.c - the expression evaluator: every operator with its LAMMPS
 * precedence and associativity, every function, constants, group functions
 * and per-atom values on host atoms, thermo keywords, and each error. */
#include <stdlib.h>

#include "expr.h"
#include "test.h"

#include "atoms.h"
#include "error.h"
#include "variable.h"

static struct gravel *G;

/* Evaluate under a boundary; returns 1 on success. */
static int eval(const char *text, double *out)
{
    jmp_buf jb;
    G->err.jmp = &jb;
    G->err.cmd = "test";
    G->err.file = NULL;
    if (setjmp(jb)) {
        G->err.jmp = NULL;
        return 0;
    }
    *out = expr_eval(G, text);
    G->err.jmp = NULL;
    return 1;
}

#define CHECK_EXPR(text, want)                                                       \
    do {                                                                             \
        double v_ = NAN, w_ = (want);                                                \
        int ok_ = eval(text, &v_);                                                   \
        if (!ok_ || !(fabs(v_ - w_) <= 1e-12 * fmax(1.0, fabs(w_)))) {               \
            printf("  check failed %s:%d: %s = %.17g (%s), expected %.17g\n",        \
                   __FILE__, __LINE__, text, v_, ok_ ? "ok" : G->err.msg,            \
                   w_);                                                              \
            t_failed_checks++;                                                       \
        }                                                                            \
    } while (0)

#define CHECK_EXPR_ERROR(text, what)                                                 \
    do {                                                                             \
        double v_;                                                                   \
        if (eval(text, &v_) || !strstr(G->err.msg, what)) {                          \
            printf("  check failed %s:%d: %s: expected error '%s', got '%s'\n",      \
                   __FILE__, __LINE__, text, what, G->err.msg);                      \
            t_failed_checks++;                                                       \
        }                                                                            \
    } while (0)

TEST(operators)
{
    CHECK_EXPR("1+2", 3);
    CHECK_EXPR("7-10", -3);
    CHECK_EXPR("6*7", 42);
    CHECK_EXPR("7/2", 3.5);
    CHECK_EXPR("2^10", 1024);
    CHECK_EXPR("7%3", 1);
    CHECK_EXPR("-7%3", -1);      /* fmod, as LAMMPS */
    CHECK_EXPR("-3", -3);
    CHECK_EXPR("--3", 3);
    CHECK_EXPR("!0", 1);
    CHECK_EXPR("!5", 0);
    CHECK_EXPR("2==2", 1);
    CHECK_EXPR("2==3", 0);
    CHECK_EXPR("2!=3", 1);
    CHECK_EXPR("2<3", 1);
    CHECK_EXPR("3<3", 0);
    CHECK_EXPR("3<=3", 1);
    CHECK_EXPR("4>3", 1);
    CHECK_EXPR("3>=4", 0);
    CHECK_EXPR("1&&0", 0);
    CHECK_EXPR("1&&2", 1);
    CHECK_EXPR("0||0", 0);
    CHECK_EXPR("0||3", 1);
    CHECK_EXPR("1|^1", 0);
    CHECK_EXPR("1|^0", 1);
    CHECK_EXPR("0|^0", 0);
    /* precedence and associativity as LAMMPS */
    CHECK_EXPR("1+2*3", 7);
    CHECK_EXPR("(1+2)*3", 9);
    CHECK_EXPR("2*3^2", 18);
    CHECK_EXPR("-2^2", 4);       /* unary binds tighter than ^ */
    CHECK_EXPR("2^-2", 0.25);
    CHECK_EXPR("2^3^2", 64);     /* left-associative */
    CHECK_EXPR("8/4/2", 1);
    CHECK_EXPR("10-4-3", 3);
    CHECK_EXPR("1+1==2", 1);
    CHECK_EXPR("1<2==1", 1);
    CHECK_EXPR("0&&1||1", 1);
    CHECK_EXPR("1||0&&0", 1);
    CHECK_EXPR("!1+1", 1);       /* (!1)+1 */
    CHECK_EXPR("0^0", 1);
    CHECK_EXPR("5^0", 1);
    CHECK_EXPR(" ( 1 + 2 ) * ( 3 - 1 ) ", 6);
    CHECK_EXPR("1.5e3+2E-1+.5", 1500.7);
    CHECK_EXPR("1e+2", 100);
}

TEST(functions)
{
    CHECK_EXPR("sqrt(16)", 4);
    CHECK_EXPR("exp(1)", exp(1));
    CHECK_EXPR("ln(10)", log(10));
    CHECK_EXPR("log(1000)", 3);
    CHECK_EXPR("abs(-2.5)", 2.5);
    CHECK_EXPR("sin(PI/2)", 1);
    CHECK_EXPR("cos(PI)", -1);
    CHECK_EXPR("tan(PI/4)", tan(M_PI / 4));
    CHECK_EXPR("asin(1)", M_PI / 2);
    CHECK_EXPR("acos(0)", M_PI / 2);
    CHECK_EXPR("atan(1)", M_PI / 4);
    CHECK_EXPR("atan2(1,-1)", 3 * M_PI / 4);
    CHECK_EXPR("ceil(1.2)", 2);
    CHECK_EXPR("ceil(-1.2)", -1);
    CHECK_EXPR("floor(-1.2)", -2);
    CHECK_EXPR("round(2.5)", 3);
    CHECK_EXPR("round(-2.5)", -2);  /* LAMMPS rounds halves up */
    CHECK_EXPR("round(2.4)", 2);
    CHECK_EXPR("sqrt(abs(-9))+floor(sqrt(2)*10)", 17);
    CHECK_EXPR("PI", M_PI);
    CHECK_EXPR("yes+on+true", 3);
    CHECK_EXPR("no+off+false", 0);
}

TEST(errors)
{
    CHECK_EXPR_ERROR("1/0", "division by zero in expression '1/0'");
    CHECK_EXPR_ERROR("1%0", "modulo by zero");
    CHECK_EXPR_ERROR("0^-1", "0 raised to a negative power");
    CHECK_EXPR_ERROR("sqrt(-1)", "sqrt() of a negative value");
    CHECK_EXPR_ERROR("ln(0)", "ln() of a zero or negative value");
    CHECK_EXPR_ERROR("log(-1)", "log() of a zero or negative value");
    CHECK_EXPR_ERROR("asin(2)", "asin() of 2, outside [-1, 1]");
    CHECK_EXPR_ERROR("acos(-1.5)", "outside [-1, 1]");
    CHECK_EXPR_ERROR("foo(1)", "unknown function 'foo()'");
    CHECK_EXPR_ERROR("sqrt(1,2)", "sqrt() takes 1 argument, got 2");
    CHECK_EXPR_ERROR("atan2(1)", "atan2() takes 2 arguments, got 1");
    CHECK_EXPR_ERROR("random()", "random() takes 3 arguments, got 0");
    CHECK_EXPR_ERROR("blah", "unknown name 'blah'");
    CHECK_EXPR_ERROR("x", "'x' needs an atom ID: x[ID]");
    CHECK_EXPR_ERROR("(1+2", "missing ')'");
    CHECK_EXPR_ERROR("1+", "unexpected end");
    CHECK_EXPR_ERROR("1 2", "unexpected '2' after a complete value");
    CHECK_EXPR_ERROR("", "empty expression");
    CHECK_EXPR_ERROR("   ", "empty expression");
    CHECK_EXPR_ERROR("1=2", "unexpected '=2'");
    CHECK_EXPR_ERROR("1|2", "unexpected '|2'");
    CHECK_EXPR_ERROR("1&2", "unexpected '&2'");
    CHECK_EXPR_ERROR("1 ** 2", "unexpected character '*'");
    CHECK_EXPR_ERROR(".", "a lone '.'");
    CHECK_EXPR_ERROR("@", "unexpected character '@'");
    CHECK_EXPR_ERROR("\x01", "unexpected byte 0x01");
    CHECK_EXPR_ERROR("v_undefined", "variable 'undefined' is not defined");
    CHECK_EXPR_ERROR("c_nothing", "unknown compute 'c_nothing'");
    CHECK_EXPR_ERROR("f_fix[2]", "unknown fix 'f_fix[2]'");
    CHECK_EXPR_ERROR("c_x[1", "missing ']'");
    CHECK_EXPR_ERROR("v_a[1]", "vector variables");
    /* deep nesting is an error, not a stack overflow */
    char deep[2100];
    memset(deep, '(', 1000);
    deep[1000] = '1';
    memset(deep + 1001, ')', 1000);
    deep[2001] = '\0';
    CHECK_EXPR_ERROR(deep, "nesting deeper than 200 levels");
    memset(deep, '-', 2000);
    strcpy(deep + 2000, "1");
    CHECK_EXPR_ERROR(deep, "nesting deeper than 200 levels");
    /* but 100 levels work */
    memset(deep, '(', 100);
    deep[100] = '7';
    memset(deep + 101, ')', 100);
    deep[201] = '\0';
    CHECK_EXPR(deep, 7);
    /* a very long flat expression works */
    size_t n = 200000;
    char *flat = malloc(2 * n + 2);
    for (size_t i = 0; i < n; i++) {
        flat[2 * i] = '1';
        flat[2 * i + 1] = '+';
    }
    flat[2 * n] = '1';
    flat[2 * n + 1] = '\0';
    CHECK_EXPR(flat, (double)n + 1);
    free(flat);
    /* overflow to inf is allowed and printed, not an error */
    CHECK_EXPR("1e308*10 > 1e308", 1);
}

/* Four atoms in a periodic 10^3 box; group "top" (bit 1) holds tags 3 and 4. */
static void make_atoms(void)
{
    struct gravel *g = G;
    g->dom.box_exists = 1;
    for (int d = 0; d < 3; d++) {
        g->dom.lo[d] = 0;
        g->dom.hi[d] = 10;
    }
    atoms_set_ntypes(g, 2);
    double xs[4][3] = {{1, 1, 1}, {3, 1, 1}, {5, 5, 9}, {7, 5, 8}};
    double m[4] = {1, 1, 2, 4};
    for (int i = 0; i < 4; i++) {
        int k = atoms_add(g, 0, 1 + i / 2, xs[i], 0.5 + 0.1 * i, m[i]);
        g->atoms.v[3 * k] = i + 1.0;
        g->atoms.v[3 * k + 2] = -2.0 * i;
        g->atoms.f[3 * k + 1] = 10.0 * i;
    }
    g->groups.used[1] = 1;
    strcpy(g->groups.name[1], "top");
    g->groups.n = 2;
    g->atoms.mask[2] |= 2u;
    g->atoms.mask[3] |= 2u;
}

TEST(group_functions)
{
    make_atoms();
    CHECK_EXPR("count(all)", 4);
    CHECK_EXPR("count(top)", 2);
    CHECK_EXPR("mass(all)", 8);
    CHECK_EXPR("mass(top)", 6);
    CHECK_EXPR("xcm(all,x)", (1 + 3 + 10 + 28) / 8.0);
    CHECK_EXPR("xcm(top,z)", (18 + 32) / 6.0);
    CHECK_EXPR("vcm(all,x)", (1 + 2 + 6 + 16) / 8.0);
    CHECK_EXPR("vcm(top,z)", (2 * -4.0 + 4 * -6.0) / 6.0);
    CHECK_EXPR("bound(all,xmin)", 1);
    CHECK_EXPR("bound(all,xmax)", 7);
    CHECK_EXPR("bound(top,zmin)", 8);
    CHECK_EXPR("bound( top , zmax )", 9);
    /* image flags unwrap positions for xcm: atom 4 one box to the right */
    G->atoms.image[3 * 3 + 0] = 1;
    CHECK_EXPR("xcm(top,x)", (2 * 5 + 4 * 17) / 6.0);
    G->atoms.image[3 * 3 + 0] = 0;
    /* empty group */
    G->groups.used[2] = 1;
    strcpy(G->groups.name[2], "empty");
    CHECK_EXPR("count(empty)", 0);
    CHECK_EXPR("xcm(empty,y)", 0);
    CHECK_EXPR("bound(empty,xmin)", 1e20);
    CHECK_EXPR_ERROR("count(nogroup)", "unknown group 'nogroup'");
    CHECK_EXPR_ERROR("xcm(all)", "xcm() takes 2 arguments, got 1");
    CHECK_EXPR_ERROR("xcm(all,w)", "expected x, y or z, got 'w'");
    CHECK_EXPR_ERROR("bound(all,xmid)", "bound() direction must be");
    CHECK_EXPR_ERROR("count(all", "missing ')'");
    CHECK_EXPR_ERROR("count()", "count() takes 1 argument, got 0");
}

TEST(atom_values)
{
    CHECK_EXPR("x[2]", 3);
    CHECK_EXPR("y[3]+z[3]", 14);
    CHECK_EXPR("vx[4]", 4);
    CHECK_EXPR("vy[4]", 0);
    CHECK_EXPR("vz[3]", -4);
    CHECK_EXPR("fx[2]+fy[2]+fz[2]", 10);
    CHECK_EXPR("radius[3]", 0.7);
    CHECK_EXPR("mass[4]", 4);
    CHECK_EXPR("type[3]", 2);
    CHECK_EXPR("id[1]", 1);
    CHECK_EXPR("x[1+1]*2", 6);  /* the ID may be an expression */
    CHECK_EXPR_ERROR("x[99]", "atom ID 99 in x[] does not exist");
    CHECK_EXPR_ERROR("x[1.5]", "needs a positive integer atom ID, got 1.5");
    CHECK_EXPR_ERROR("x[0]", "needs a positive integer atom ID");
    CHECK_EXPR_ERROR("x[1", "missing ']'");
    /* per-type mass when rmass is unset */
    G->atoms.rmass[0] = 0;
    G->atoms.type_mass[1] = 3.5;
    CHECK_EXPR("mass[1]", 3.5);
}

TEST(variables_and_thermo)
{
    CHECK(test_script(G, "variable a equal 3\nvariable b equal v_a^2+count(all)\n"
                         "variable s string 1+1\nvariable i index 7 8\n") == GR_OK);
    CHECK_EXPR("v_b", 13);
    CHECK_EXPR("v_s*10", 20);
    CHECK_EXPR("v_i", 7);
    G->step = 1234;
    CHECK_EXPR("step", 1234);
    CHECK_EXPR("atoms", 4);
    CHECK_EXPR("step/2+atoms", 621);
}

int main(void)
{
    G = test_engine();
    RUN(operators);
    RUN(functions);
    RUN(errors);
    RUN(group_functions);
    RUN(atom_values);
    RUN(variables_and_thermo);
    gr_destroy(G);
    return 0;
}
