/* atom_origin.c - atoms' origins by atom ID (atom_origin.h). */
#include "atom_origin.h"

#include <stdlib.h>
#include <string.h>

#include "device.h"
#include "domain.h"
#include "error.h"

void atom_origin_take(struct gravel *g, struct atom_origin *o, unsigned groupbit)
{
    const struct atoms *a = &g->atoms;
    for (int k = 0; k < a->n; k++) {
        if (!(a->mask[k] & groupbit))
            continue;
        tag_ref_reserve(g, &o->x0, a->tag[k]);
        domain_unmap(g, a->x + 3 * k, a->image + 3 * k, o->x0.v + 3 * a->tag[k]);
        o->x0.have[a->tag[k]] = 1;
    }
    o->stale = 1;
}

void atom_origin_setup(struct gravel *g, struct atom_origin *o, unsigned groupbit,
                       const char *who, const char *id)
{
    const struct atoms *a = &g->atoms;
    for (int k = 0; k < a->n; k++)
        if ((a->mask[k] & groupbit) && (a->tag[k] >= o->x0.cap || !o->x0.have[a->tag[k]]))
            gr_error(g, "%s %s: atom %lld is in its group but was not when the fix was defined: "
                        "it has no origin", who, id, (long long)a->tag[k]);
    o->stale = 1;
}

void atom_origin_device(struct gravel *g, struct atom_origin *o)
{
    if (!o->stale)
        return;
    struct engine *e = g->eng;
    o->ntab = o->x0.cap;
    size_t nv = 3 * (size_t)(o->ntab > 0 ? o->ntab : 1);
    double *hi = gr_calloc(g, nv, sizeof *hi), *lo = gr_calloc(g, nv, sizeof *lo);
    for (int64_t t = 0; t < o->ntab; t++)
        for (int d = 0; d < 3; d++) {
            double u = o->x0.v[3 * t + d] - e->origin[d];
            hi[3 * t + d] = e->single ? (double)(float)u : u;
            lo[3 * t + d] = u - hi[3 * t + d];
        }
    for (int k = 0; k < 2; k++) {
        cl_mem *b = k ? &o->tablo : &o->tab;
        if (*b)
            clReleaseMemObject(*b);
        *b = eng_alloc(g, nv * e->rsz, "atom origins");
        eng_write_reals(g, *b, nv, k ? lo : hi);
    }
    free(hi);
    free(lo);
    o->stale = 0;
}

const double *atom_origin_values(struct gravel *g, const struct atom_origin *o,
                                 unsigned groupbit, double **out)
{
    const struct atoms *a = &g->atoms;
    *out = gr_realloc(g, *out, 3 * (size_t)(a->n > 0 ? a->n : 1) * sizeof **out);
    for (int i = 0; i < a->n; i++) {
        int64_t t = a->tag[i];
        int have = (a->mask[i] & groupbit) && t < o->x0.cap && o->x0.have[t];
        for (int d = 0; d < 3; d++)
            (*out)[3 * i + d] = have ? o->x0.v[3 * t + d] : 0.0;
    }
    return *out;
}

#define ROW (sizeof(int64_t) + 3 * sizeof(double))

size_t atom_origin_write(const struct atom_origin *o, unsigned char *buf, size_t cap)
{
    int64_t count = 0;
    for (int64_t t = 0; t < o->x0.cap; t++)
        count += o->x0.have[t];
    size_t need = sizeof count + (size_t)count * ROW;
    if (!buf || cap < need)
        return need;
    memcpy(buf, &count, sizeof count);
    unsigned char *p = buf + sizeof count;
    for (int64_t t = 0; t < o->x0.cap; t++) {
        if (!o->x0.have[t])
            continue;
        memcpy(p, &t, sizeof t);
        memcpy(p + sizeof t, o->x0.v + 3 * t, 3 * sizeof(double));
        p += ROW;
    }
    return need;
}

void atom_origin_read(struct gravel *g, struct atom_origin *o, const unsigned char *buf,
                      size_t len, const char *id)
{
    int64_t count;
    if (len < sizeof count)
        gr_error(g, "fix %s: restart state of %zu bytes is too short", id, len);
    memcpy(&count, buf, sizeof count);
    if (count < 0 || len != sizeof count + (size_t)count * ROW)
        gr_error(g, "fix %s: restart state of %zu bytes does not hold %lld origins", id, len,
                 (long long)count);
    tag_ref_free(&o->x0);
    const unsigned char *p = buf + sizeof count;
    for (int64_t k = 0; k < count; k++, p += ROW) {
        int64_t t;
        memcpy(&t, p, sizeof t);
        if (t < 0)
            gr_error(g, "fix %s: restart state holds atom ID %lld", id, (long long)t);
        tag_ref_reserve(g, &o->x0, t);
        memcpy(o->x0.v + 3 * t, p + sizeof t, 3 * sizeof(double));
        o->x0.have[t] = 1;
    }
    o->stale = 1;
}

void atom_origin_free(struct atom_origin *o)
{
    tag_ref_free(&o->x0);
    if (o->tab)
        clReleaseMemObject(o->tab);
    if (o->tablo)
        clReleaseMemObject(o->tablo);
    memset(o, 0, sizeof *o);
}
