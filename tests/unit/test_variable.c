/* test_variable.c - variable styles, LAMMPS redefinition rules, next,
 * -var, format and getenv, reproducible random streams, and the errors of
 * each. */
#include <stdlib.h>

#include "expr.h"
#include "test.h"

#include "error.h"
#include "variable.h"

static int ok(struct gravel *g, const char *text)
{
    return test_script(g, text) == GR_OK;
}

static const char *val(struct gravel *g, const char *name)
{
    const char *v = var_retrieve(g, name);
    return v ? v : "(undefined)";
}

/* Evaluate under a boundary; returns 1 on success. */
static int eval(struct gravel *g, const char *text, double *out)
{
    jmp_buf jb;
    g->err.jmp = &jb;
    g->err.cmd = "test";
    g->err.file = NULL;
    if (setjmp(jb)) {
        g->err.jmp = NULL;
        return 0;
    }
    *out = expr_eval(g, text);
    g->err.jmp = NULL;
    return 1;
}

TEST(styles)
{
    struct gravel *g = test_engine();
    CHECK(ok(g, "variable e equal 1+2*3\nvariable s string hello\nvariable i index a b\n"
                "variable l loop 3\nvariable m loop 5 7\nvariable p loop 8 10 pad\n"));
    CHECK(strcmp(val(g, "e"), "7") == 0);
    CHECK(strcmp(val(g, "s"), "hello") == 0);
    CHECK(strcmp(val(g, "i"), "a") == 0);
    CHECK(strcmp(val(g, "l"), "1") == 0);
    CHECK(strcmp(val(g, "m"), "5") == 0);
    CHECK(strcmp(val(g, "p"), "08") == 0);
    CHECK(var_count(g) == 6);
    /* equal variables use %.15g */
    CHECK(ok(g, "variable t equal 1/3\n"));
    CHECK(strcmp(val(g, "t"), "0.333333333333333") == 0);
    /* equal is evaluated at use: later changes show */
    CHECK(ok(g, "variable a equal 2\nvariable b equal v_a*10\nvariable a equal 5\n"));
    CHECK(strcmp(val(g, "b"), "50") == 0);
    CHECK_NEAR(var_compute_equal(g, "b"), 50, 0);
    /* numeric values of string, index and loop variables */
    CHECK(ok(g, "variable n string 2.5\nvariable f string 2*v_a\n"));
    CHECK_NEAR(var_compute_equal(g, "n"), 2.5, 0);
    CHECK_NEAR(var_compute_equal(g, "f"), 10, 0); /* a formula held in a string */
    CHECK_NEAR(var_compute_equal(g, "m"), 5, 0);
    CHECK(var_retrieve(g, "nothere") == NULL);
    CHECK(!var_exists(g, "nothere") && var_exists(g, "e"));
    /* existence does not evaluate: a formula that fails is still defined */
    CHECK(ok(g, "variable bad equal 1/0\n"));
    CHECK(var_exists(g, "bad"));
    gr_destroy(g);
}

TEST(redefine_rules)
{
    struct gravel *g = test_engine();
    /* index and loop: an existing variable is kept (so -var wins) */
    CHECK(ok(g, "variable i index a b\nvariable i index z\nvariable l loop 4\n"
                "variable l loop 9\n"));
    CHECK(strcmp(val(g, "i"), "a") == 0);
    CHECK(ok(g, "next l\n"));
    CHECK(strcmp(val(g, "l"), "2") == 0);
    /* string and equal are replaced */
    CHECK(ok(g, "variable s string one\nvariable s string two\n"));
    CHECK(strcmp(val(g, "s"), "two") == 0);
    CHECK(ok(g, "variable e equal 1\nvariable e equal 2\n"));
    CHECK(strcmp(val(g, "e"), "2") == 0);
    /* changing the style is an error; delete first */
    CHECK(test_script(g, "variable s equal 3\n") == GR_ERR);
    CHECK(strstr(g->err.msg, "already defined as string-style") != NULL);
    CHECK(strcmp(val(g, "s"), "two") == 0);
    CHECK(ok(g, "variable s delete\nvariable s equal 3\nvariable gone delete\n"));
    CHECK(strcmp(val(g, "s"), "3") == 0);
    gr_destroy(g);
}

TEST(command_line_var)
{
    struct gravel *g = test_engine();
    char *vals[] = {"10", "20"};
    var_set_index(g, "T", 2, vals);
    CHECK(ok(g, "variable T index 99\nprint $T file /dev/null\n"));
    CHECK(strcmp(val(g, "T"), "10") == 0);
    CHECK(ok(g, "next T\n"));
    CHECK(strcmp(val(g, "T"), "20") == 0);
    gr_destroy(g);
}

TEST(next_semantics)
{
    struct gravel *g = test_engine();
    CHECK(ok(g, "variable i index x y\nnext i\n"));
    CHECK(strcmp(val(g, "i"), "y") == 0);
    CHECK(ok(g, "next i\n"));
    CHECK(var_retrieve(g, "i") == NULL); /* exhausted -> deleted */
    /* the exhausted next skips exactly the next jump */
    CHECK(ok(g, "variable j loop 1\nnext j\njump SELF nowhere\nvariable after string yes\n"));
    CHECK(strcmp(val(g, "after"), "yes") == 0);
    /* a huge loop costs nothing until it runs (found by the fuzzer: it used
     * to allocate one slot per value) */
    CHECK(ok(g, "variable big loop 2000000000\nvariable big2 loop 300000000\n"));
    CHECK(strcmp(val(g, "big"), "1") == 0);
    gr_destroy(g);
    CHECK_ERROR("variable s string a\nnext s\n", "variable 's' is string-style; only index "
                "and loop variables have a next value", 2);
    CHECK_ERROR("next nope\n", "variable 'nope' is not defined", 1);
}

TEST(format_and_getenv)
{
    struct gravel *g = test_engine();
    setenv("GRAVEL_TEST_ENV", "from-env", 1);
    CHECK(ok(g, "variable x equal 2/3\nvariable f format x %.3f\nvariable g format x "
                "\"%10.2e\"\nvariable h getenv GRAVEL_TEST_ENV\nvariable u getenv "
                "GRAVEL_TEST_UNSET_XYZ\n"));
    CHECK(strcmp(val(g, "f"), "0.667") == 0);
    CHECK(strcmp(val(g, "g"), "  6.67e-01") == 0);
    CHECK(strcmp(val(g, "h"), "from-env") == 0);
    CHECK(strcmp(val(g, "u"), "") == 0);
    CHECK_NEAR(var_compute_equal(g, "f"), 2.0 / 3.0, 1e-15);
    gr_destroy(g);
    CHECK_ERROR("variable f format x %d\n", "invalid format '%d'", 1);
    CHECK_ERROR("variable f format x %s\n", "invalid format '%s'", 1);
    CHECK_ERROR("variable f format x \"%f %f\"\n", "invalid format", 1);
    CHECK_ERROR("variable f format x %n\n", "invalid format", 1);
    CHECK_ERROR("variable f format x %99999f\n", "invalid format", 1);
    CHECK_ERROR("variable f format x\n", "expected: variable f format EQUAL_VARIABLE FORMAT", 1);
    CHECK_ERROR("variable f format x %f\nprint ${f}\n", "variable 'x' is not defined", 2);
    CHECK(expr_format_ok("v=%-+#012.5g%%"));
    CHECK(!expr_format_ok("%%"));
}

TEST(definition_errors)
{
    CHECK_ERROR("variable x bogus 1\n", "unknown variable style 'bogus'", 1);
    CHECK_ERROR("variable 'a b' string 1\n", "may contain only letters, digits and '_'", 1);
    CHECK_ERROR("variable x equal 1 + 2\n", "takes exactly one value, got 3", 1);
    CHECK_ERROR("variable x string\n", "takes exactly one value, got 0", 1);
    CHECK_ERROR("variable x index\n", "needs at least one value", 1);
    CHECK_ERROR("variable x loop 0\n", "loop count N must be between 1 and 2000000000", 1);
    CHECK_ERROR("variable x loop 5 3\n", "smaller than start", 1);
    CHECK_ERROR("variable x loop 1.5\n", "expected an integer for loop count N", 1);
    CHECK_ERROR("variable x loop 1 2 3\n", "variable x loop N [pad]", 1);
    CHECK_ERROR("variable x delete now\n", "takes no further arguments", 1);
    CHECK_ERROR("variable a equal v_b\nvariable b equal v_a+1\nprint ${a}\n",
                "in a cycle?", 3);
    CHECK_ERROR("variable e getenv 'A B'\n", "may contain only letters", 1);
}

TEST(random_reproducible)
{
    struct gravel *g1 = test_engine(), *g2 = test_engine();
    double a, b, sum = 0, sum2 = 0, lo = 1e9, hi = -1e9;
    int same = 1, n = 4000;
    double first;
    CHECK(eval(g1, "random(2,5,12345)", &first));
    CHECK(eval(g2, "random(2,5,12345)", &b));
    CHECK(first == b);
    for (int i = 0; i < n; i++) {
        CHECK(eval(g1, "random(2,5,12345)", &a));
        CHECK(eval(g2, "random(2,5,12345)", &b));
        same &= a == b;
        sum += a;
        lo = a < lo ? a : lo;
        hi = a > hi ? a : hi;
    }
    CHECK(same);
    CHECK(lo >= 2 && hi <= 5 && hi - lo > 2.9);
    CHECK_NEAR(sum / n, 3.5, 0.06); /* sd of the mean = 3/sqrt(12 n) = 0.014 */
    /* a different seed gives a different stream */
    CHECK(eval(g1, "random(2,5,777)", &a));
    CHECK(a != first);
    sum = 0;
    for (int i = 0; i < n; i++) {
        CHECK(eval(g1, "normal(10,2,99)", &a));
        sum += a;
        sum2 += a * a;
    }
    double mean = sum / n, sd = sqrt(sum2 / n - mean * mean);
    CHECK_NEAR(mean, 10, 0.15);  /* 4.7 sigma */
    CHECK_NEAR(sd, 2, 0.1);
    CHECK(!eval(g1, "random(1,2,0)", &a));
    CHECK(strstr(g1->err.msg, "seed must be a positive integer") != NULL);
    CHECK(!eval(g1, "random(3,2,5)", &a));
    CHECK(!eval(g1, "normal(0,-1,5)", &a));
    CHECK(!eval(g1, "random(1,2,1.5)", &a));
    gr_destroy(g1);
    gr_destroy(g2);
}

int main(void)
{
    RUN(styles);
    RUN(redefine_rules);
    RUN(command_line_var);
    RUN(next_semantics);
    RUN(format_and_getenv);
    RUN(definition_errors);
    RUN(random_reproducible);
    return 0;
}
