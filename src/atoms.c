/* atoms.c - growth and bookkeeping of the host-side atom arrays. */
#include "atoms.h"

#include <stdlib.h>
#include <string.h>

#include "error.h"

#define GROW(p, type, per)                                                                     \
    do {                                                                                       \
        p = gr_realloc(g, p, (size_t)cap * (per) * sizeof(type));                              \
        memset(p + (size_t)a->cap * (per), 0, (size_t)(cap - a->cap) * (per) * sizeof(type)); \
    } while (0)

void atoms_reserve(struct gravel *g, int n)
{
    struct atoms *a = &g->atoms;
    if (n <= a->cap)
        return;
    if (n > 200000000)
        gr_error(g, "too many atoms (%d)", n);
    int cap = a->cap ? a->cap : 1024;
    while (cap < n)
        cap = cap < (1 << 29) ? cap * 2 : n;
    GROW(a->tag, int64_t, 1);
    GROW(a->type, int, 1);
    GROW(a->mask, unsigned, 1);
    GROW(a->x, double, 3);
    GROW(a->v, double, 3);
    GROW(a->f, double, 3);
    GROW(a->omega, double, 3);
    GROW(a->torque, double, 3);
    GROW(a->radius, double, 1);
    GROW(a->rmass, double, 1);
    GROW(a->image, int, 3);
    GROW(a->mol, int64_t, 1);
    a->cap = cap;
}

int atoms_add(struct gravel *g, int64_t tag, int type, const double x[3], double radius,
              double rmass)
{
    struct atoms *a = &g->atoms;
    atoms_reserve(g, a->n + 1);
    int i = a->n++;
    if (tag <= 0)
        tag = a->maxtag + 1;
    if (tag > a->maxtag)
        a->maxtag = tag;
    a->tag[i] = tag;
    a->type[i] = type;
    a->mask[i] = 1u;
    for (int k = 0; k < 3; k++) {
        a->x[3 * i + k] = x[k];
        a->v[3 * i + k] = a->f[3 * i + k] = 0;
        a->omega[3 * i + k] = a->torque[3 * i + k] = 0;
        a->image[3 * i + k] = 0;
    }
    a->radius[i] = radius;
    a->rmass[i] = rmass;
    a->mol[i] = 0;
    return i;
}

void atoms_remove(struct gravel *g, int i)
{
    struct atoms *a = &g->atoms;
    int last = --a->n;
    if (i == last)
        return;
    a->tag[i] = a->tag[last];
    a->type[i] = a->type[last];
    a->mask[i] = a->mask[last];
    a->radius[i] = a->radius[last];
    a->rmass[i] = a->rmass[last];
    a->mol[i] = a->mol[last];
    for (int k = 0; k < 3; k++) {
        a->x[3 * i + k] = a->x[3 * last + k];
        a->v[3 * i + k] = a->v[3 * last + k];
        a->f[3 * i + k] = a->f[3 * last + k];
        a->omega[3 * i + k] = a->omega[3 * last + k];
        a->torque[3 * i + k] = a->torque[3 * last + k];
        a->image[3 * i + k] = a->image[3 * last + k];
    }
}

void atoms_set_ntypes(struct gravel *g, int ntypes)
{
    struct atoms *a = &g->atoms;
    if (ntypes < 1 || ntypes > 1000000)
        gr_error(g, "number of atom types must be between 1 and 1000000, got %d", ntypes);
    a->type_mass = gr_realloc(g, a->type_mass, (size_t)(ntypes + 1) * sizeof(double));
    for (int t = a->ntypes + 1; t <= ntypes; t++)
        a->type_mass[t] = 0;
    if (a->ntypes == 0)
        a->type_mass[0] = 0;
    a->ntypes = ntypes;
}

void atoms_free(struct atoms *a)
{
    free(a->tag);
    free(a->type);
    free(a->mask);
    free(a->x);
    free(a->v);
    free(a->f);
    free(a->omega);
    free(a->torque);
    free(a->radius);
    free(a->rmass);
    free(a->image);
    free(a->mol);
    free(a->order);
    free(a->type_mass);
    memset(a, 0, sizeof *a);
}

int atoms_find_tag(const struct atoms *a, int64_t tag)
{
    for (int i = 0; i < a->n; i++)
        if (a->tag[i] == tag)
            return i;
    return -1;
}

static int by_tag_of(const void *pa, const void *pb, void *ctx)
{
    const int64_t *tag = ctx;
    int64_t ta = tag[*(const int *)pa], tb = tag[*(const int *)pb];
    return (ta > tb) - (ta < tb);
}

const int *atoms_tag_order(struct gravel *g)
{
    struct atoms *a = &g->atoms;
    if (a->n + 1 > a->order_cap) {
        a->order = gr_realloc(g, a->order, ((size_t)a->n + 1) * sizeof(int));
        a->order_cap = a->n + 1;
    }
    int n = a->n, *ord = a->order;
    int64_t lo = INT64_MAX, hi = INT64_MIN;
    for (int i = 0; i < n; i++) {
        lo = a->tag[i] < lo ? a->tag[i] : lo;
        hi = a->tag[i] > hi ? a->tag[i] : hi;
    }
    if (n > 0 && hi - lo < (int64_t)n) { /* dense tags: place directly if unique */
        for (int i = 0; i < n; i++)
            ord[i] = -1;
        int unique = 1;
        for (int i = 0; i < n && unique; i++) {
            int *slot = &ord[a->tag[i] - lo];
            unique = *slot < 0;
            *slot = i;
        }
        if (unique)
            return ord;
    }
    for (int i = 0; i < n; i++)
        ord[i] = i;
    qsort_r(ord, (size_t)n, sizeof *ord, by_tag_of, a->tag);
    return ord;
}
