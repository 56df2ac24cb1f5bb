/* coeff_check.c - range checks of physical coefficients (coeff_check.h). */
#include "coeff_check.h"

#include <math.h>
#include <stdio.h>

#include "args.h"
#include "error.h"

/* One row per range: bounds, which are open, and the words of the error. */
static const struct {
    double lo, hi;
    int lo_open, hi_open;
    const char *words;
} ranges[] = {
    [CR_FINITE] = {-INFINITY, INFINITY, 1, 1, "a finite number"},
    [CR_POSITIVE] = {0, INFINITY, 1, 1, "positive"},
    [CR_NONNEG] = {0, INFINITY, 0, 1, "non-negative (>= 0)"},
    [CR_POISSON] = {-1, 0.5, 1, 0, "in (-1, 0.5]"},
    [CR_RESTITUTION] = {0, 1, 1, 0, "in (0, 1]"},
    [CR_UNIT] = {0, 1, 0, 0, "in [0, 1]"},
};

static int inside(double v, double lo, int lo_open, double hi, int hi_open)
{
    if (!isfinite(v))
        return 0;
    if (lo_open ? !(v > lo) : !(v >= lo))
        return 0;
    return hi_open ? v < hi : v <= hi;
}

static _Noreturn void fail(struct gravel *g, const char *who, const char *name, double v,
                           const char *words)
{
    if (who)
        gr_error(g, "%s: %s must be %s, got %.10g", who, name, words, v);
    gr_error(g, "%s must be %s, got %.10g", name, words, v);
}

double coeff_check(struct gravel *g, const char *who, const char *name, double v,
                   enum coeff_range range)
{
    if (!inside(v, ranges[range].lo, ranges[range].lo_open, ranges[range].hi,
                ranges[range].hi_open))
        fail(g, who, name, v, ranges[range].words);
    return v;
}

double coeff_upto(struct gravel *g, const char *who, const char *name, double v, double hi)
{
    if (!inside(v, 0, 0, hi, 0)) {
        char words[64];
        snprintf(words, sizeof words, "between 0 and %g", hi);
        fail(g, who, name, v, words);
    }
    return v;
}

double coeff_arg(struct gravel *g, const char *who, const char *s, const char *name,
                 enum coeff_range range)
{
    return coeff_check(g, who, name, arg_double(g, s, name), range);
}
