/* par_sum.c - sums over every rank's atoms in one process's order, and the
 * collectives of insertion on several ranks (par_sum.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "comm.h"
#include "error.h"
#include "par.h"
#include "par_sum.h"

/* ---- sums in tag order ------------------------------------------------------------ */

void par_sum_add(struct gravel *g, struct par_sum *s, int64_t key, double v)
{
    if (!par_on(g)) {
        s->acc += v;
        return;
    }
    if (s->n == s->cap) {
        s->cap = s->cap ? 2 * s->cap : 1024;
        s->key = gr_realloc(g, s->key, (size_t)s->cap * sizeof *s->key);
        s->v = gr_realloc(g, s->v, (size_t)s->cap * sizeof *s->v);
    }
    s->key[s->n] = key;
    s->v[s->n++] = v;
}

double par_sum_total(struct gravel *g, struct par_sum *s)
{
    double t = s->acc;
    if (par_on(g))
        t = comm_sum_in_key_order(s->n, s->key, s->v);
    free(s->key);
    free(s->v);
    memset(s, 0, sizeof *s);
    return t;
}

/* ---- insertion on several ranks (fix pour) ---------------------------------------- */

int par_owns(struct gravel *g, const double x[3])
{
    return !par_on(g) || decomp_owner(g, &g->par->dc, x) == comm_rank();
}

int par_gather_rows(struct gravel *g, double **rows, int n, int width)
{
    if (!par_on(g))
        return n;
    double *all = NULL;
    size_t w = (size_t)width * sizeof(double);
    size_t bytes = comm_allgatherv(*rows, (size_t)n * w, (void **)&all);
    if (bytes == (size_t)-1)
        gr_error(g, "out of memory gathering the atoms of every rank");
    free(*rows);
    *rows = all;
    return (int)(bytes / w);
}

int64_t par_max_atom_tag(struct gravel *g)
{
    int64_t m = 0;
    for (int i = 0; i < g->atoms.n; i++)
        m = g->atoms.tag[i] > m ? g->atoms.tag[i] : m;
    return par_max_tag(g, m);
}

int64_t par_max_tag(struct gravel *g, int64_t mine)
{
    if (!par_on(g))
        return mine;
    int64_t *all = NULL, m = mine;
    size_t bytes = comm_allgatherv(&mine, sizeof mine, (void **)&all);
    if (bytes == (size_t)-1)
        gr_error(g, "out of memory gathering the ranks' largest atom IDs");
    for (size_t r = 0; r < bytes / sizeof mine; r++)
        m = all[r] > m ? all[r] : m;
    free(all);
    return m;
}
