/* par_hist.c - contact history by tag pair (par_hist.h). */
#include "par_hist.h"

#include <stdlib.h>
#include <string.h>

#include "error.h"

static uint64_t mix(int64_t a, int64_t b)
{
    uint64_t h = (uint64_t)a * 0x9E3779B97F4A7C15ull ^ (uint64_t)b * 0xC2B2AE3D27D4EB4Full;
    return h ^ (h >> 29);
}

void par_hist_free(struct par_hist *h)
{
    if (!h)
        return;
    free(h->key);
    free(h->val);
    free(h);
}

struct par_hist *par_hist_new(struct gravel *g, size_t n, size_t vb)
{
    struct par_hist *h = gr_calloc(g, 1, sizeof *h);
    h->cap = 64;
    while (h->cap < 2 * n + 16)
        h->cap *= 2;
    h->vb = vb;
    h->key = gr_calloc(g, 2 * h->cap, sizeof *h->key);
    h->val = gr_malloc(g, h->cap * vb + 1);
    return h;
}

/* slot of (a, b): its own or the empty one where it goes */
static size_t hist_slot(const struct par_hist *h, int64_t a, int64_t b)
{
    size_t s = mix(a, b) & (h->cap - 1);
    while (h->key[2 * s] && (h->key[2 * s] != a || h->key[2 * s + 1] != b))
        s = (s + 1) & (h->cap - 1);
    return s;
}

/* Insert (first copy wins: every copy holds the same bits). */
void par_hist_put(struct gravel *g, struct par_hist **hp, int64_t a, int64_t b,
                     const void *val)
{
    struct par_hist *h = *hp;
    if (2 * (h->n + 1) > h->cap) {
        struct par_hist *w = par_hist_new(g, h->n + 1, h->vb);
        for (size_t s = 0; s < h->cap; s++)
            if (h->key[2 * s])
                par_hist_put(g, &w, h->key[2 * s], h->key[2 * s + 1], h->val + s * h->vb);
        par_hist_free(h);
        *hp = h = w;
    }
    size_t s = hist_slot(h, a, b);
    if (h->key[2 * s])
        return;
    h->key[2 * s] = a;
    h->key[2 * s + 1] = b;
    memcpy(h->val + s * h->vb, val, h->vb);
    h->n++;
}

const void *par_hist_get(const struct par_hist *h, int64_t a, int64_t b)
{
    size_t s = hist_slot(h, a, b);
    return h->key[2 * s] ? h->val + s * h->vb : NULL;
}

size_t par_hist_entry_bytes(const struct par_hist *h) { return 2 * sizeof(int64_t) + h->vb; }

void par_hist_entry_pack(const struct par_hist *h, size_t s, unsigned char *out)
{
    memcpy(out, h->key + 2 * s, 2 * sizeof(int64_t));
    memcpy(out + 2 * sizeof(int64_t), h->val + s * h->vb, h->vb);
}

void par_hist_entries_put(struct gravel *g, struct par_hist **h, const unsigned char *in,
                        size_t bytes)
{
    size_t eb = par_hist_entry_bytes(*h);
    for (size_t o = 0; o + eb <= bytes; o += eb) {
        int64_t k[2];
        memcpy(k, in + o, sizeof k);
        par_hist_put(g, h, k[0], k[1], in + o + sizeof k);
    }
}
