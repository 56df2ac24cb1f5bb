/* pair_surf_granular.c - `pair_style hybrid LAW args surf/granular` and
 * `pair_coeff P S surf/granular <pair granular's sub-models>` (LAMMPS 4 Jul
 * 2026, GRANSURF): the model between particles of type P and the triangles
 * of surface type S of fix surface/local. A surface sub-style
 * (pair_style.surface): pair.c splits it off the hybrid into
 * g->styles.surf; it never enters the pair loop. The words are checked
 * with pair granular's parser at pair_coeff and kept; fix surface/local
 * makes its mesh wall from them at run start. */
#include <stdlib.h>
#include <string.h>

#include "error.h"
#include "pair.h"
#include "pair_granular.h"
#include "pair_surf_granular.h"

struct sg_words {
    int n;
    char **w;
};

struct surf_tab {
    int nt;
    struct sg_words *m;         /* nt x nt */
};

static void words_free(struct sg_words *m)
{
    for (int k = 0; k < m->n; k++)
        free(m->w[k]);
    free(m->w);
    m->w = NULL;
    m->n = 0;
}

static void destroy(struct pair *p)
{
    struct surf_tab *t = p->data;
    if (t) {
        for (int k = 0; k < t->nt * t->nt; k++)
            words_free(&t->m[k]);
        free(t->m);
    }
    free(t);
    p->data = NULL;
}

static void settings(struct gravel *g, struct pair *p, int argc, char **argv)
{
    (void)p;
    if (argc > 0)
        gr_error(g, "surf/granular takes no pair_style arguments, got '%.64s'", argv[0]);
}

static void set_words(struct gravel *g, struct sg_words *m, int argc, char **argv)
{
    words_free(m);
    m->w = gr_calloc(g, (size_t)argc, sizeof *m->w);
    for (; m->n < argc; m->n++)
        m->w[m->n] = gr_strdup(g, argv[m->n]);
}

static void coeff(struct gravel *g, struct pair *p, int ilo, int ihi, int jlo, int jhi,
                  int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "pair_coeff ... surf/granular expects pair granular's sub-models (e.g. "
                    "hooke 4000 100 tangential linear_history 1000 1 0.5)");
    struct gr_one o;
    memset(&o, 0, sizeof o);
    int used = granular_parse(g, &o, argc, argv, NULL, 0, "pair_coeff surf/granular");
    if (used != argc)
        gr_error(g, "pair_coeff surf/granular: unexpected word '%.64s'", argv[used]);
    if (o.sync) /* LAMMPS's GranularModel keeps the full-step normal for SURFACE contacts */
        gr_error(g, "pair_coeff surf/granular: synchronized_verlet is not supported here (LAMMPS "
                    "computes no half-step normal for a particle-surface contact)");
    int nt = g->atoms.ntypes;
    struct surf_tab *t = p->data;
    if (!t || t->nt != nt) {
        destroy(p);
        t = p->data = gr_calloc(g, 1, sizeof *t);
        t->m = gr_calloc(g, (size_t)nt * nt, sizeof *t->m);
        t->nt = nt;
    }
    for (int i = ilo; i <= ihi; i++)
        for (int j = jlo > i ? jlo : i; j <= jhi; j++) {
            set_words(g, &t->m[(size_t)(i - 1) * nt + (j - 1)], argc, argv);
            set_words(g, &t->m[(size_t)(j - 1) * nt + (i - 1)], argc, argv);
        }
}

int surf_granular_model(const struct gravel *g, int ptype, int stype, char ***words)
{
    const struct pair *p = g->styles.surf;
    const struct surf_tab *t = p ? p->data : NULL;
    if (!t || ptype < 1 || stype < 1 || ptype > t->nt || stype > t->nt)
        return -1;
    const struct sg_words *m = &t->m[(size_t)(ptype - 1) * t->nt + (stype - 1)];
    if (!m->n)
        return -1;
    *words = m->w;
    return m->n;
}

/* never in the pair loop: an empty record */
static void describe(const struct pair *p, struct pair_caps *c)
{
    (void)p;
    (void)c;
}

const struct pair_style pair_style_surf_granular = {
    .name = "surf/granular",
    .settings = settings,
    .coeff = coeff,
    .describe = describe,
    .destroy = destroy,
    .surface = 1,
};
