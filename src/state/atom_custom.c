/* atom_custom.c - the custom per-atom properties' names, shapes and layout
 * (atom_custom.h); their storage grows and moves with the atoms (atoms.c). */
#include "atom_custom.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atoms.h"
#include "error.h"

int custom_find_in(const struct atom_custom *c, const char *name)
{
    for (int k = 0; k < c->n; k++)
        if (!strcmp(c->p[k].name, name))
            return k;
    return -1;
}

int custom_find(const struct atoms *a, const char *name) { return custom_find_in(&a->cus, name); }

int custom_name_ok(const char *name)
{
    if (!*name || strlen(name) >= GR_CUSTOMLEN)
        return 0;
    for (const char *c = name; *c; c++)
        if (!isalnum((unsigned char)*c) && *c != '_')
            return 0;
    return 1;
}

const char *custom_prefixed(const struct atoms *a, int k, char *buf)
{
    const struct custom_prop *p = &a->cus.p[k];
    snprintf(buf, GR_CUSTOMLEN + 4, "%s%s_%s", p->isint ? "i" : "d", p->cols ? "2" : "", p->name);
    return buf;
}

int custom_ref_parse(struct gravel *g, const char *word, const char *who, struct custom_ref *ref,
                     int *whole_array)
{
    int isint, arr;
    if ((word[0] == 'i' || word[0] == 'd') && word[1] == '_')
        arr = 0;
    else if ((word[0] == 'i' || word[0] == 'd') && word[1] == '2' && word[2] == '_')
        arr = 1;
    else
        return 0;
    isint = word[0] == 'i';
    const char *nm = word + (arr ? 3 : 2);
    char name[GR_CUSTOMLEN];
    const char *br = strchr(nm, '[');
    size_t len = br ? (size_t)(br - nm) : strlen(nm);
    if (len == 0 || len >= sizeof name)
        gr_error(g, "%s: invalid custom property name '%.80s'", who, word);
    memcpy(name, nm, len);
    name[len] = '\0';
    int col = 0;
    if (br) {
        char *end;
        long c = strtol(br + 1, &end, 10);
        if (end == br + 1 || *end != ']' || end[1] != '\0')
            gr_error(g, "%s: invalid column in '%.80s' (expected %s2_%s[k])", who, word,
                     isint ? "i" : "d", name);
        if (!arr)
            gr_error(g, "%s: '%.80s': %s_%s is a vector, it takes no [k] (i2_ d2_ arrays do)",
                     who, word, isint ? "i" : "d", name);
        col = (int)c;
    }
    const struct atoms *a = &g->atoms;
    int k = custom_find(a, name);
    if (k < 0)
        gr_error(g, "%s: custom property %.80s does not exist (define it with fix property/atom "
                    "%.80s)", who, word, word);
    const struct custom_prop *p = &a->cus.p[k];
    char have[GR_CUSTOMLEN + 4];
    if (p->isint != isint || (p->cols != 0) != arr)
        gr_error(g, "%s: custom property %s is %s, not %.80s", who, name,
                 custom_prefixed(a, k, have), word);
    if (arr && !br) {
        if (!whole_array)
            gr_error(g, "%s: %.80s is an array: name a column, %.80s[k] with k in 1..%d", who,
                     word, word, p->cols);
        *whole_array = 1;
    } else if (arr && (col < 1 || col > p->cols)) {
        gr_error(g, "%s: column %d of %s is outside 1..%d", who, col,
                 custom_prefixed(a, k, have), p->cols);
    }
    if (whole_array && !(arr && !br))
        *whole_array = 0;
    ref->idx = k;
    ref->col = arr && br ? col - 1 : 0;
    return 1;
}

double custom_check_value(struct gravel *g, const struct atoms *a, int k, double v,
                          const char *what)
{
    const struct custom_prop *p = &a->cus.p[k];
    if (!isfinite(v))
        gr_error(g, "%s: value %g for custom property %s is not finite", what, v, p->name);
    if (p->isint && (v != floor(v) || v < -2147483648.0 || v > 2147483647.0))
        gr_error(g, "%s: value %.17g for integer property i%s_%s is not an integer", what, v,
                 p->cols ? "2" : "", p->name);
    return v;
}

/* Lay out `to` (slots in order) and move the values: prop k from from[k]. */
static void relayout(struct gravel *g, struct atom_custom *to, int *from)
{
    int s = 0;
    for (int k = 0; k < to->n; k++) {
        to->p[k].slot = s;
        s += custom_width(&to->p[k]);
    }
    to->slots = s;
    atoms_custom_relayout(g, to, from);
}

void custom_define(struct gravel *g, const char *fix, int n, const struct custom_def *defs)
{
    const struct atoms *a = &g->atoms;
    struct atom_custom to = {0};
    int from[GR_MAXCUSTOM];
    /* what stays: other fixes' properties, and this fix's listed ones */
    for (int k = 0; k < a->cus.n; k++) {
        const struct custom_prop *p = &a->cus.p[k];
        int mine = !strcmp(p->fix, fix), listed = -1;
        for (int d = 0; d < n; d++)
            if (!strcmp(defs[d].name, p->name))
                listed = d;
        if (listed >= 0 && !mine && !p->restored)
            gr_error(g, "fix property/atom %s name %s already exists (fix %s)",
                     defs[listed].cols ? "array" : "vector", p->name, p->fix);
        if (listed >= 0 || (mine && listed < 0))
            continue; /* redefined below, replaced, or dropped by this fix */
        from[to.n] = p->slot;
        to.p[to.n++] = *p;
    }
    for (int d = 0; d < n; d++) {
        int k = custom_find(a, defs[d].name), keep = -1;
        if (k >= 0 && !strcmp(a->cus.p[k].fix, fix) && a->cus.p[k].isint == defs[d].isint &&
            a->cus.p[k].cols == defs[d].cols)
            keep = a->cus.p[k].slot;
        if (to.n == GR_MAXCUSTOM)
            gr_error(g, "fix property/atom: more than %d custom properties", GR_MAXCUSTOM);
        struct custom_prop *p = &to.p[to.n];
        memset(p, 0, sizeof *p);
        snprintf(p->name, sizeof p->name, "%s", defs[d].name);
        snprintf(p->fix, sizeof p->fix, "%s", fix);
        p->isint = defs[d].isint;
        p->cols = defs[d].cols;
        for (int c = 0; defs[d].def && c < custom_width(p) && c < GR_CUSTOM_DEFS; c++)
            p->def[c] = defs[d].def[c];
        from[to.n++] = keep;
    }
    relayout(g, &to, from);
    /* a property new to the atoms starts at its new-atom values (LIGGGHTS) */
    struct atoms *at = &g->atoms;
    for (int d = 0; d < n; d++) {
        const int k = custom_find(at, defs[d].name);
        if (!defs[d].def || from[k] >= 0)
            continue;
        const struct custom_prop *p = &at->cus.p[k];
        const int w = custom_width(p) < GR_CUSTOM_DEFS ? custom_width(p) : GR_CUSTOM_DEFS;
        for (int i = 0; i < at->n; i++)
            memcpy(at->custom + (size_t)i * at->cus.slots + p->slot, p->def,
                   (size_t)w * sizeof(double));
    }
}

void custom_new_atom(struct atoms *a, int i)
{
    double *rec = a->custom + (size_t)a->cus.slots * i;
    memset(rec, 0, (size_t)a->cus.slots * sizeof(double));
    for (int k = 0; k < a->cus.n; k++) {
        const struct custom_prop *p = &a->cus.p[k];
        const int w = custom_width(p) < GR_CUSTOM_DEFS ? custom_width(p) : GR_CUSTOM_DEFS;
        memcpy(rec + p->slot, p->def, (size_t)w * sizeof(double));
    }
}

void custom_remove_fix(struct gravel *g, const char *fix)
{
    const struct atoms *a = &g->atoms;
    struct atom_custom to = {0};
    int from[GR_MAXCUSTOM], gone = 0;
    for (int k = 0; k < a->cus.n; k++) {
        if (!strcmp(a->cus.p[k].fix, fix) && !a->cus.p[k].restored) {
            gone++;
            continue;
        }
        from[to.n] = a->cus.p[k].slot;
        to.p[to.n++] = a->cus.p[k];
    }
    if (gone)
        relayout(g, &to, from);
}
