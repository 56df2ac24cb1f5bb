/* atoms.c - growth and bookkeeping of the host-side atom arrays: every
 * per-atom array is handled through the field table (atom_fields.h). */
#include "atoms.h"

#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>

#include "atom_custom.h"
#include "error.h"

/* The arrays are page mappings: page-aligned (a CPU device can use them as
 * its buffers, engine.c) and zero until written, so the capacity beyond the
 * atoms costs address space, not memory. */
static void *field_alloc(struct gravel *g, size_t bytes)
{
    void *p = mmap(NULL, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED)
        gr_error(g, "cannot allocate %zu bytes for the atoms' arrays", bytes);
    return p;
}

static void field_free(void *p, size_t bytes)
{
    if (p)
        munmap(p, bytes);
}

/* Grow one field from a->cap to cap atoms; the new slots are zero. */
#define GROW(name, ctype, dev, width, when, life, sect, what)                                  \
    {                                                                                         \
        size_t old_ = (size_t)a->cap * (width) * sizeof(ctype);                               \
        ctype *p_ = field_alloc(g, (size_t)cap * (width) * sizeof(ctype));                    \
        if (a->name && atoms_holds(a, when)) /* else all zero: left untouched */              \
            memcpy(p_, a->name, old_);                                                        \
        field_free(a->name, old_);                                                            \
        a->name = p_;                                                                         \
    }

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
    ATOM_FIELDS(GROW)
    if (a->cus.slots) {
        size_t w = (size_t)a->cus.slots * sizeof(double);
        double *p = field_alloc(g, (size_t)cap * w);
        if (a->custom)
            memcpy(p, a->custom, (size_t)a->cap * w);
        field_free(a->custom, (size_t)a->cap * w);
        a->custom = p;
    }
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
#define ZERO(name, ctype, dev, width, when, life, sect, what)                                  \
    if (atoms_holds(a, when))                                                                 \
        memset(a->name + (size_t)(width) * i, 0, (width) * sizeof(ctype));
    ATOM_FIELDS(ZERO)
#undef ZERO
    if (a->cus.slots)
        custom_new_atom(a, i); /* zeros, or a property's new-atom values */
    a->tag[i] = tag;
    a->type[i] = type;
    a->mask[i] = 1u;
    for (int k = 0; k < 3; k++)
        a->x[3 * i + k] = x[k];
    a->radius[i] = radius;
    a->rmass[i] = rmass;
    if (a->heat_flag & ATOM_HEAT_T)
        a->temperature[i] = a->temp_default;
    return i;
}

void atoms_copy(struct atoms *a, int from, int to)
{
    if (from == to)
        return;
#define COPY(name, ctype, dev, width, when, life, sect, what)                                  \
    if (atoms_holds(a, when))                                                                 \
        memcpy(a->name + (size_t)(width) * to, a->name + (size_t)(width) * from,              \
               (width) * sizeof(ctype));
    ATOM_FIELDS(COPY)
#undef COPY
    if (a->cus.slots)
        memcpy(a->custom + (size_t)a->cus.slots * to, a->custom + (size_t)a->cus.slots * from,
               (size_t)a->cus.slots * sizeof(double));
}

void atoms_custom_relayout(struct gravel *g, const struct atom_custom *to, const int *from_slot)
{
    struct atoms *a = &g->atoms;
    size_t cap = (size_t)a->cap, nw = (size_t)to->slots, ow = (size_t)a->cus.slots;
    double *p = nw && cap ? field_alloc(g, cap * nw * sizeof(double)) : NULL;
    for (int k = 0; k < to->n && p; k++) {
        int w = to->p[k].cols ? to->p[k].cols : 1, o = from_slot[k];
        if (o < 0)
            continue; /* a new property: zero (the mapping's pages) */
        for (int i = 0; i < a->n; i++)
            memcpy(p + (size_t)i * nw + to->p[k].slot, a->custom + (size_t)i * ow + o,
                   (size_t)w * sizeof(double));
    }
    field_free(a->custom, cap * ow * sizeof(double));
    a->custom = p;
    a->cus = *to;
}

void atoms_remove(struct gravel *g, int i)
{
    struct atoms *a = &g->atoms;
    int last = --a->n;
    atoms_copy(a, last, i);
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

void atoms_free_fields(struct atoms *a)
{
#define FREE(name, ctype, dev, width, when, life, sect, what)                                  \
    field_free(a->name, (size_t)a->cap * (width) * sizeof(ctype));
    ATOM_FIELDS(FREE)
#undef FREE
    field_free(a->custom, (size_t)a->cap * a->cus.slots * sizeof(double));
    a->custom = NULL;
    free(a->order);
    a->order = NULL;
    a->order_cap = 0;
}

void atoms_free(struct atoms *a)
{
#define FREE(name, ctype, dev, width, when, life, sect, what)                                  \
    field_free(a->name, (size_t)a->cap * (width) * sizeof(ctype));
    ATOM_FIELDS(FREE)
#undef FREE
    field_free(a->custom, (size_t)a->cap * a->cus.slots * sizeof(double));
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

void atoms_order_by_tag(const int64_t *tag, int n, int *ord)
{
    int64_t lo = INT64_MAX, hi = INT64_MIN;
    for (int i = 0; i < n; i++) {
        lo = tag[i] < lo ? tag[i] : lo;
        hi = tag[i] > hi ? tag[i] : hi;
    }
    if (n > 0 && hi - lo < (int64_t)n) { /* dense tags: place directly if unique */
        for (int i = 0; i < n; i++)
            ord[i] = -1;
        int unique = 1;
        for (int i = 0; i < n && unique; i++) {
            int *slot = &ord[tag[i] - lo];
            unique = *slot < 0;
            *slot = i;
        }
        if (unique)
            return;
    }
    for (int i = 0; i < n; i++)
        ord[i] = i;
    qsort_r(ord, (size_t)n, sizeof *ord, by_tag_of, (void *)tag);
}

const int *atoms_tag_order(struct gravel *g)
{
    struct atoms *a = &g->atoms;
    if (a->n + 1 > a->order_cap) {
        a->order = gr_realloc(g, a->order, ((size_t)a->n + 1) * sizeof(int));
        a->order_cap = a->n + 1;
    }
    atoms_order_by_tag(a->tag, a->n, a->order);
    return a->order;
}

uint64_t atoms_fingerprint(const struct atoms *a)
{
    uint64_t h = 14695981039346656037ull; /* FNV-1a 64 */
    size_t n = (size_t)a->n;
    const unsigned char *c = (const unsigned char *)&a->n;
    for (size_t k = 0; k < sizeof a->n; k++)
        h = (h ^ c[k]) * 1099511628211ull;
#define HASH_FIELD(name, ctype, dev, width, when, life, sect, what)                            \
    if (sect == FS_ATOMS) {                                                                   \
        c = (const unsigned char *)a->name;                                                   \
        for (size_t k = 0; k < n * (width) * sizeof(ctype); k++)                              \
            h = (h ^ c[k]) * 1099511628211ull;                                                \
    }
    ATOM_FIELDS(HASH_FIELD)
#undef HASH_FIELD
    return h;
}
