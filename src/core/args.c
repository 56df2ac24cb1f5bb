/* args.c - argument parsing with errors that name the argument. */
#include "args.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "error.h"

int arg_is_number(const char *s)
{
    if (!s || !*s)
        return 0;
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    /* ERANGE with a finite result is an underflow: a denormal such as
     * 4.9e-324 (or 0) is a number; an overflow gives inf and is rejected */
    return end != s && *end == '\0' && isfinite(v) && (errno == 0 || errno == ERANGE);
}

double arg_double(struct gravel *g, const char *s, const char *what)
{
    if (!arg_is_number(s))
        gr_error(g, "expected a number for %s, got '%.64s'", what, s ? s : "");
    return strtod(s, NULL);
}

double arg_positive(struct gravel *g, const char *s, const char *what)
{
    double v = arg_double(g, s, what);
    if (!(v > 0))
        gr_error(g, "%s must be positive, got %.64s", what, s);
    return v;
}

double arg_nonneg(struct gravel *g, const char *s, const char *what)
{
    double v = arg_double(g, s, what);
    if (!(v >= 0))
        gr_error(g, "%s must not be negative, got %.64s", what, s);
    return v;
}

bigint arg_bigint(struct gravel *g, const char *s, const char *what)
{
    if (!s || !*s)
        gr_error(g, "expected an integer for %s, got ''", what);
    char *end;
    errno = 0;
    long long v = strtoll(s, &end, 10);
    if (*end != '\0' || errno != 0)
        gr_error(g, "expected an integer for %s, got '%.64s'", what, s);
    return (bigint)v;
}

int arg_int(struct gravel *g, const char *s, const char *what)
{
    bigint v = arg_bigint(g, s, what);
    if (v < INT_MIN || v > INT_MAX)
        gr_error(g, "%s is out of range: %.64s", what, s);
    return (int)v;
}

int arg_int_range(struct gravel *g, const char *s, int lo, int hi, const char *what)
{
    int v = arg_int(g, s, what);
    if (v < lo || v > hi)
        gr_error(g, "%s must be between %d and %d, got %d", what, lo, hi, v);
    return v;
}

int arg_yesno(struct gravel *g, const char *s, const char *what)
{
    if (strcmp(s, "yes") == 0)
        return 1;
    if (strcmp(s, "no") == 0)
        return 0;
    gr_error(g, "expected yes or no for %s, got '%.64s'", what, s);
}

void arg_range(struct gravel *g, const char *s, int n, int *lo, int *hi, const char *what)
{
    const char *star = strchr(s, '*');
    if (!star) {
        *lo = *hi = arg_int(g, s, what);
    } else {
        char buf[64];
        size_t k = (size_t)(star - s);
        if (k >= sizeof buf || strlen(star + 1) >= sizeof buf)
            gr_error(g, "invalid %s range '%.64s'", what, s);
        memcpy(buf, s, k);
        buf[k] = '\0';
        *lo = k ? arg_int(g, buf, what) : 1;
        *hi = star[1] ? arg_int(g, star + 1, what) : n;
    }
    if (*lo < 1 || *hi > n || *lo > *hi)
        gr_error(g, "%s range '%.64s' is outside 1..%d", what, s, n);
}

void arg_type_range(struct gravel *g, const char *s, int ntypes, int *lo, int *hi)
{
    arg_range(g, s, ntypes, lo, hi, "atom type");
}

int arg_axis(struct gravel *g, const char *s, const char *what)
{
    if (s[0] && !s[1] && s[0] >= 'x' && s[0] <= 'z')
        return s[0] - 'x';
    gr_error(g, "%s must be x, y or z, got '%.32s'", what, s);
}

int arg_group(struct gravel *g, const char *name)
{
    for (int i = 0; i < GR_MAXGROUP; i++)
        if (g->groups.used[i] && strcmp(g->groups.name[i], name) == 0)
            return i;
    gr_error(g, "unknown group '%.64s'", name);
}

void arg_need(struct gravel *g, int argc, int i, int need, const char *keyword)
{
    if (i + need >= argc)
        gr_error(g, "keyword '%s' needs %d value%s", keyword, need, need == 1 ? "" : "s");
}
