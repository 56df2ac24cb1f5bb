/* test.h - a minimal unit-test harness. Each TEST runs under RUN(), which
 * prints "PASS name" or "FAIL name"; tests/run.sh counts those lines. Failed
 * CHECKs print their location and expression first. */
#ifndef GR_TEST_H
#define GR_TEST_H

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "gravel.h"
#include "input.h"

static int t_failed_checks;

#define CHECK(cond)                                                                  \
    do {                                                                             \
        if (!(cond)) {                                                               \
            printf("  check failed %s:%d: %s\n", __FILE__, __LINE__, #cond);         \
            t_failed_checks++;                                                       \
        }                                                                            \
    } while (0)

#define CHECK_NEAR(a, b, tol)                                                        \
    do {                                                                             \
        double a_ = (a), b_ = (b);                                                   \
        if (!(fabs(a_ - b_) <= (tol))) {                                             \
            printf("  check failed %s:%d: %s = %.17g, expected %.17g (tol %g)\n",    \
                   __FILE__, __LINE__, #a, a_, b_, (double)(tol));                   \
            t_failed_checks++;                                                       \
        }                                                                            \
    } while (0)

#define TEST(name) static void name(void)
#define RUN(name)                                                                    \
    do {                                                                             \
        int before_ = t_failed_checks;                                               \
        name();                                                                      \
        printf("%s %s\n", t_failed_checks == before_ ? "PASS" : "FAIL", #name);      \
        fflush(stdout);                                                              \
    } while (0)

/* A quiet engine for tests: no screen, no log. */
static inline struct gravel *test_engine(void)
{
    struct gravel *g = gr_create();
    g->screen = NULL;
    return g;
}

/* Run script text; returns GR_OK/GR_ERR/GR_QUIT. The message is in g->err.msg. */
static inline int test_script(struct gravel *g, const char *text)
{
    return inp_string(g, text, "test.in");
}

/* Expect `text` to fail with a message containing `what` at script line `line`. */
#define CHECK_ERROR(text, what, line)                                                \
    do {                                                                             \
        struct gravel *ge_ = test_engine();                                          \
        int rc_ = test_script(ge_, text);                                            \
        char where_[64];                                                             \
        snprintf(where_, sizeof where_, "(test.in:%d)", (line));                     \
        if (rc_ != GR_ERR || !strstr(ge_->err.msg, what) || !strstr(ge_->err.msg, where_)) { \
            printf("  check failed %s:%d: expected error '%s' %s, got rc %d '%s'\n", \
                   __FILE__, __LINE__, what, where_, rc_, ge_->err.msg);             \
            t_failed_checks++;                                                       \
        }                                                                            \
        gr_destroy(ge_);                                                             \
    } while (0)

#endif
