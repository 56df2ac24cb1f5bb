/* peratom_input.c - per-atom inputs of the fixes that read the atoms
 * (peratom_input.h). */
#include "peratom_input.h"

#include <stdlib.h>
#include <string.h>

#include "atom_attr.h"
#include "atom_custom.h"
#include "compute.h"
#include "error.h"
#include "fix.h"
#include "ref.h"
#include "variable.h"

static const char *const xvf[] = {"x", "y", "z", "vx", "vy", "vz", "fx", "fy", "fz", NULL};

void peratom_input_parse(struct gravel *g, const char *word, enum peratom_attrs attrs,
                         struct peratom_input *in, const char *usage, const char *who)
{
    memset(in, 0, sizeof *in);
    snprintf(in->word, sizeof in->word, "%s", word);
    int allowed = attrs == PERATOM_ALL;
    for (int k = 0; xvf[k] && !allowed; k++)
        allowed = !strcmp(word, xvf[k]);
    int a = atom_attr_find(word);
    if (a >= 0 && allowed) {
        atom_attr_check(g, a, word, who);
        in->kind = 'a';
        in->index = a;
        return;
    }
    struct custom_ref ref;
    if (attrs == PERATOM_ALL && (!strncmp(word, "i_", 2) || !strncmp(word, "d_", 2)) &&
        custom_ref_parse(g, word, who, &ref, NULL)) {
        in->kind = 'p';
        return;
    }
    int col;
    if (!strchr("cfv", word[0]) || !ref_parse(word, word[0], in->id, &in->index, &col) || col ||
        (word[0] == 'v' && in->index))
        gr_error(g, "%s: invalid value '%.64s' (%s)", who, word, usage);
    in->kind = word[0];
}

void peratom_input_check(struct gravel *g, const struct peratom_input *in, const char *who,
                         const char *id)
{
    struct custom_ref ref;
    if (in->kind == 'c')
        compute_peratom_check(g, in->id, in->index, who);
    else if (in->kind == 'f')
        fix_peratom_check(g, in->word, who);
    else if (in->kind == 'v' && (!var_exists(g, in->id) || !var_is_atom(g, in->id)))
        gr_error(g, "%s %s: variable '%s' %s", who, id, in->id,
                 var_exists(g, in->id) ? "is not atom-style" : "does not exist");
    else if (in->kind == 'p') /* the property may have gone (unfix) */
        custom_ref_parse(g, in->word, who, &ref, NULL);
}

const double *peratom_input_values(struct gravel *g, const struct peratom_input *in, int *stride,
                                   double **owned, const char *who)
{
    const struct atoms *a = &g->atoms;
    *owned = NULL;
    *stride = 1;
    if (in->kind == 'v')
        return *owned = var_atom_values(g, in->id);
    if (in->kind == 'c')
        return compute_peratom_ref(g, compute_get(g, in->id, who), in->index, stride, who);
    if (in->kind == 'f')
        return fix_peratom_ref(g, in->word, stride, who);
    double *v = gr_malloc(g, (size_t)(a->n > 0 ? a->n : 1) * sizeof *v);
    struct custom_ref ref;
    if (in->kind == 'p')
        custom_ref_parse(g, in->word, who, &ref, NULL);
    for (int i = 0; i < a->n; i++)
        v[i] = in->kind == 'p' ? custom_get(a, ref, i) : atom_attr_value(g, in->index, i);
    return *owned = v;
}
