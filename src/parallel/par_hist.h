/* par_hist.h - contact history by tag pair, the form in which it moves
 * between ranks (par.c): open addressing over (lower tag, higher tag), each
 * with the device's raw history bytes (bit-exact on any rank). */
#ifndef GR_PAR_HIST_H
#define GR_PAR_HIST_H

#include <stddef.h>
#include <stdint.h>

#include "state.h"

struct par_hist {
    size_t cap, n, vb;      /* slots (a power of 2), used, value bytes */
    int64_t *key;           /* 2 per slot; key[2s] = 0: empty */
    unsigned char *val;
};

/* A table for about n entries of vb value bytes; released by par_hist_free. */
struct par_hist *par_hist_new(struct gravel *g, size_t n, size_t vb);
void par_hist_free(struct par_hist *h);
/* Insert (a, b) (first copy wins: every copy holds the same bits); grows *hp. */
void par_hist_put(struct gravel *g, struct par_hist **hp, int64_t a, int64_t b,
                  const void *val);
/* The value bytes of (a, b), or NULL. */
const void *par_hist_get(const struct par_hist *h, int64_t a, int64_t b);
/* Entries as sent between ranks: two tags, then the value bytes. */
size_t par_hist_entry_bytes(const struct par_hist *h);
void par_hist_entry_pack(const struct par_hist *h, size_t slot, unsigned char *out);
void par_hist_entries_put(struct gravel *g, struct par_hist **h, const unsigned char *in,
                          size_t bytes);

#endif
