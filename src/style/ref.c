/* ref.c - parsing and wildcard expansion of c_ID / f_ID references (ref.h). */
#include "ref.h"

#include <stdlib.h>
#include <string.h>

#include "compute.h"
#include "error.h"
#include "fix.h"

int ref_parse(const char *ref, char kind, char *id, int *index, int *col)
{
    if (ref[0] != kind || ref[1] != '_')
        return 0;
    const char *s = ref + 2;
    const char *br = strchr(s, '[');
    size_t n = br ? (size_t)(br - s) : strlen(s);
    if (n == 0 || n >= GR_NAMELEN)
        return 0;
    memcpy(id, s, n);
    id[n] = '\0';
    *index = *col = 0;
    for (int k = 0; br; k++) {
        char *end;
        long v = strtol(br + 1, &end, 10);
        if (k == 2 || end == br + 1 || *end != ']' || v < 1 || v > 1000000)
            return 0;
        *(k ? col : index) = (int)v;
        br = end[1] == '[' ? end + 1 : NULL;
        if (!br && end[1] != '\0')
            return 0;
    }
    return 1;
}

/* Parse a decimal >= 1 from s up to `end`; -1 when empty or malformed. */
static long bound(const char *s, const char *end)
{
    if (s == end)
        return 0;
    char *e;
    long v = strtol(s, &e, 10);
    return e == end && v >= 1 && v <= 1000000 ? v : -1;
}

int ref_wildcard(struct gravel *g, const char *ref, int array, char *prefix, int *lo, int *hi,
                 const char *who)
{
    if ((ref[0] != 'c' && ref[0] != 'f') || ref[1] != '_')
        return 0;
    const char *br = strchr(ref, '['), *star = strchr(ref, '*');
    if (!br || !star || star < br)
        return 0;
    size_t n = (size_t)(br - ref);
    const char *close = strchr(br, ']');
    if (n <= 2 || n - 2 >= GR_NAMELEN || !close || close[1] || close < star)
        gr_error(g, "%s: malformed wildcard reference '%.64s' (use c_ID[*], c_ID[N*], c_ID[*M] "
                    "or c_ID[N*M])", who, ref);
    memcpy(prefix, ref, n);
    prefix[n] = '\0';
    long a = bound(br + 1, star), b = bound(star + 1, close);
    if (a < 0 || b < 0)
        gr_error(g, "%s: malformed wildcard reference '%.64s' (use c_ID[*], c_ID[N*], c_ID[*M] "
                    "or c_ID[N*M])", who, ref);
    const char *id = prefix + 2;
    int width;
    const char *what = array ? "global array" : "global vector";
    if (ref[0] == 'c') {
        struct compute *c = compute_get(g, id, who);
        if (array ? c->array_flag : c->vector_flag)
            width = array ? c->size_array_cols : c->size_vector;
        else if (c->peratom_flag && c->size_peratom_cols > 0)
            width = c->size_peratom_cols, what = "per-atom array";
        else if (c->local_flag && c->size_local_cols > 0)
            width = c->size_local_cols, what = "local array";
        else
            gr_error(g, "%s: cannot expand %.64s: compute %s (%s) has no %s", who, ref, id,
                     c->style->name, what);
    } else {
        struct fix *f = fix_find(g, id);
        if (!f)
            gr_error(g, "%s: no fix with ID '%.64s' for %.64s", who, id, ref);
        if (array ? !f->array_flag : !f->vector_flag)
            gr_error(g, "%s: cannot expand %.64s: fix %s (%s) has no %s", who, ref, id,
                     f->style->name, what);
        width = array ? f->size_array_cols : f->size_vector;
    }
    *lo = a ? (int)a : 1;
    *hi = b ? (int)b : width;
    if ((bigint)*hi - *lo >= 100000)
        gr_error(g, "%s: %.64s expands to %d references (at most 100000)", who, ref,
                 *hi - *lo + 1);
    if (*lo > *hi || *hi > width)
        gr_error(g, "%s: %.64s is out of range: %s %s has %d in its %s", who, ref,
                 ref[0] == 'c' ? "compute" : "fix", id, width, what);
    return 1;
}
