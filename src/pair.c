/* pair.c - the pair registry (PAIR rows of styles/styles.def) and the
 * `pair_style` and `pair_coeff` commands. */
#include "pair.h"

#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "error.h"

#define FIX(k, i)
#define COMPUTE(k, i)
#define DUMP(k, i)
#define REGION(k, i)
#define PAIR(k, i) extern const struct pair_style pair_style_##i;
#include "styles.def"
#undef PAIR
#define PAIR(k, i) &pair_style_##i,
static const struct pair_style *const pair_styles[] = {
#include "styles.def"
    NULL};
#undef PAIR
#undef FIX
#undef COMPUTE
#undef DUMP
#undef REGION

void pair_free(struct gravel *g)
{
    free(g->styles.pair);
    g->styles.pair = NULL;
}

const struct pair_style *pair_style_find(const char *name)
{
    for (int i = 0; pair_styles[i]; i++)
        if (!strcmp(pair_styles[i]->name, name))
            return pair_styles[i];
    return NULL;
}

/* pair_style style args... */
void cmd_pair_style(struct gravel *g, int argc, char **argv)
{
    const struct pair_style *st = NULL;
    for (int i = 0; pair_styles[i]; i++)
        if (!strcmp(pair_styles[i]->name, argv[0]))
            st = pair_styles[i];
    if (!st && !strcmp(argv[0], "none")) {
        if (argc > 1)
            gr_error(g, "pair_style none takes no arguments");
        pair_free(g);
        return;
    }
    if (!st) {
        char known[512] = "";
        for (int i = 0; pair_styles[i]; i++) {
            strncat(known, i ? ", " : "", sizeof known - strlen(known) - 1);
            strncat(known, pair_styles[i]->name, sizeof known - strlen(known) - 1);
        }
        gr_error(g, "unknown pair style '%.64s' (known: %s, none)", argv[0], known);
    }
    struct pair tmp;
    memset(&tmp, 0, sizeof tmp);
    tmp.style = st;
    st->settings(g, &tmp, argc - 1, argv + 1);
    /* LAMMPS: redefining the same style keeps the coefficients */
    if (g->styles.pair && g->styles.pair->style == st)
        tmp.coeff_set = g->styles.pair->coeff_set;
    if (!g->styles.pair)
        g->styles.pair = gr_calloc(g, 1, sizeof *g->styles.pair);
    *g->styles.pair = tmp;
}

/* pair_coeff * *  (granular styles take no per-type coefficients) */
void cmd_pair_coeff(struct gravel *g, int argc, char **argv)
{
    if (!g->styles.pair)
        gr_error(g, "pair_coeff command before pair_style is defined");
    int ilo, ihi, jlo, jhi;
    arg_type_range(g, argv[0], g->atoms.ntypes, &ilo, &ihi);
    arg_type_range(g, argv[1], g->atoms.ntypes, &jlo, &jhi);
    if (argc > 2)
        gr_error(g, "pair style %s takes no coefficients after the two types, got '%.64s'",
                 g->styles.pair->style->name, argv[2]);
    if (ilo != 1 || jlo != 1 || ihi != g->atoms.ntypes || jhi != g->atoms.ntypes)
        gr_error(g, "pair style %s requires pair_coeff * * (all type pairs share the "
                    "pair_style coefficients)", g->styles.pair->style->name);
    g->styles.pair->coeff_set = 1;
}
