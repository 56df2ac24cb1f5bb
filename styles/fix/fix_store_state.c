/* fix_store_state.c - `fix ID group store/state N input ... [com yes|no]`:
 * per-atom values kept as they were, as LAMMPS's fix store/state: the
 * atom attributes (atom_attr.h's names and the custom properties i_name,
 * d_name) are stored when the fix is defined, the computes', fixes' and
 * atom-style variables' inputs (c_ID, c_ID[I], f_ID, f_ID[I], v_name;
 * c_ID[*] expands) at the setup of the first run after that; with N > 0
 * everything again at the end of every step that is a multiple of N. `com
 * yes` subtracts the group's centre of mass (unwrapped, group.h) from the
 * unwrapped positions xu yu zu (LAMMPS's: not from x y z). Output: a per-atom vector (one input) or
 * array, 0 for atoms outside the group; values kept by atom ID, so they
 * follow the atoms through gravel's re-sorts, and in restart files. On MPI
 * ranks every rank stores every atom's values (taken on the ranks' atoms
 * gathered, as fix ave/atom's samples), so an atom finds them on any rank. */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atom_attr.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "group.h"
#include "par.h"
#include "peratom_input.h"
#include "ref.h"
#include "thermo.h"

#define WHO "fix store/state"

struct store_state {
    int nevery, com, first;     /* first: the first run's setup is still to come */
    int n;
    struct peratom_input *in;
    double *val;                /* [cap * n] by atom ID */
    int64_t cap;
    double *out;                /* peratom_values, host order */
};

static void destroy(struct fix *f)
{
    struct store_state *s = f->data;
    if (s) {
        free(s->in);
        free(s->val);
        free(s->out);
    }
    free(s);
}

static void reserve(struct gravel *g, struct store_state *s, int64_t t)
{
    if (t < s->cap)
        return;
    int64_t cap = s->cap ? s->cap : 64;
    while (cap <= t)
        cap *= 2;
    s->val = gr_realloc(g, s->val, (size_t)cap * s->n * sizeof *s->val);
    memset(s->val + (size_t)s->cap * s->n, 0, (size_t)(cap - s->cap) * s->n * sizeof *s->val);
    s->cap = cap;
}

/* Store the attribute inputs (attrs), the compute/fix/variable ones (cfv),
 * on the host atoms now. */
static void store(struct gravel *g, struct fix *f, int attrs, int cfv)
{
    struct store_state *s = f->data;
    const struct atoms *a = &g->atoms;
    double cm[3] = {0, 0, 0};
    if (s->com)
        group_xcm(g, f->igroup, group_mass(g, f->igroup), cm);
    for (int i = 0; i < a->n; i++)
        reserve(g, s, a->tag[i]);
    for (int j = 0; j < s->n; j++) {
        const struct peratom_input *in = &s->in[j];
        int isattr = in->kind == 'a' || in->kind == 'p';
        if (isattr ? !attrs : !cfv)
            continue;
        int stride, d = -1;
        double *owned;
        const double *p = peratom_input_values(g, in, &stride, &owned, WHO);
        if (s->com && in->kind == 'a') { /* xu yu zu: from the centre of mass */
            static const char *const pos[] = {"xu", "yu", "zu"};
            for (int k = 0; k < 3; k++)
                if (in->index == atom_attr_find(pos[k]))
                    d = k;
        }
        for (int i = 0; i < a->n; i++)
            s->val[(size_t)a->tag[i] * s->n + j] =
                (a->mask[i] & f->groupbit) ? p[(size_t)i * stride] - (d >= 0 ? cm[d] : 0.0) : 0.0;
        free(owned);
    }
}

/* store() during a run: on every rank's atoms gathered (several ranks) */
static void store_in_run(struct gravel *g, struct fix *f, int attrs, int cfv)
{
    run_sync_host(g);
    thermo_pre_take(g); /* several ranks: the keywords a gathered pass cannot take */
    par_gather_begin(g);
    store(g, f, attrs, cfv);
    par_gather_end(g);
    thermo_pre_clear(g);
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 2)
        gr_error(g, WHO " needs N and at least one input");
    struct store_state *s = gr_calloc(g, 1, sizeof *s);
    f->data = s;
    s->nevery = arg_int(g, argv[0], WHO " N");
    if (s->nevery < 0)
        gr_error(g, WHO ": N must be >= 0, got %d", s->nevery);
    int i = 1;
    for (; i < argc && strcmp(argv[i], "com"); i++) {
        char prefix[GR_NAMELEN + 2];
        int lo, hi;
        int wild = ref_wildcard(g, argv[i], 1, prefix, &lo, &hi, WHO);
        for (int k = wild ? lo : 0; k <= (wild ? hi : 0); k++) {
            char word[GR_NAMELEN + 24];
            if (wild)
                snprintf(word, sizeof word, "%s[%d]", prefix, k);
            else
                snprintf(word, sizeof word, "%s", argv[i]);
            s->in = gr_realloc(g, s->in, (size_t)(s->n + 1) * sizeof *s->in);
            peratom_input_parse(g, word, PERATOM_ALL, &s->in[s->n++],
                                "an atom attribute, i_name, d_name, c_ID, c_ID[I], f_ID, "
                                "f_ID[I], v_name", WHO);
        }
    }
    if (!s->n)
        gr_error(g, WHO " needs at least one input");
    for (; i < argc; i += 2) {
        arg_need(g, argc, i, 1, "com");
        s->com = arg_yesno(g, argv[i + 1], WHO " com");
        if (i + 2 < argc && strcmp(argv[i + 2], "com"))
            gr_error(g, WHO ": unknown keyword '%.64s' (com)", argv[i + 2]);
    }
    f->hooks = s->nevery ? HOOK_END_OF_STEP : 0;
    f->peratom_flag = 1;
    f->size_peratom_cols = s->n == 1 ? 0 : s->n;
    s->first = 1;
    store(g, f, 1, 0); /* the attributes now, as LAMMPS's constructor */
}

static void init(struct gravel *g, struct fix *f)
{
    struct store_state *s = f->data;
    for (int j = 0; j < s->n; j++)
        peratom_input_check(g, &s->in[j], WHO, f->id);
}

/* the first run after the fix: the compute, fix and variable inputs */
static void setup(struct gravel *g, struct fix *f)
{
    struct store_state *s = f->data;
    if (!s->first)
        return;
    s->first = 0;
    store_in_run(g, f, 0, 1);
}

static void end_of_step(struct gravel *g, struct fix *f)
{
    struct store_state *s = f->data;
    if (g->step % s->nevery)
        return;
    store_in_run(g, f, 1, 1);
}

static const double *peratom_values(struct gravel *g, struct fix *f)
{
    struct store_state *s = f->data;
    const struct atoms *a = &g->atoms;
    s->out = gr_realloc(g, s->out, (size_t)(a->n > 0 ? a->n : 1) * s->n * sizeof *s->out);
    for (int i = 0; i < a->n; i++)
        for (int j = 0; j < s->n; j++)
            s->out[(size_t)i * s->n + j] =
                a->tag[i] < s->cap ? s->val[(size_t)a->tag[i] * s->n + j] : 0.0;
    return s->out;
}

/* restart: the inputs' count, then (ID, values) of every ID the table holds */
static size_t write_restart(struct gravel *g, struct fix *f, unsigned char *buf, size_t cap)
{
    (void)g;
    const struct store_state *s = f->data;
    int64_t head[2] = {s->n, s->cap};
    size_t need = sizeof head + (size_t)s->cap * s->n * sizeof(double);
    if (!buf || cap < need)
        return need;
    memcpy(buf, head, sizeof head);
    if (s->cap)
        memcpy(buf + sizeof head, s->val, (size_t)s->cap * s->n * sizeof(double));
    return need;
}

static void read_restart(struct gravel *g, struct fix *f, const unsigned char *buf, size_t len)
{
    struct store_state *s = f->data;
    int64_t head[2];
    if (len < sizeof head)
        gr_error(g, "fix %s: restart state of %zu bytes is too short", f->id, len);
    memcpy(head, buf, sizeof head);
    if (head[0] != s->n || head[1] < 0 ||
        len != sizeof head + (size_t)head[1] * s->n * sizeof(double))
        gr_error(g, "fix %s: restart state of %zu bytes holds %lld inputs, the fix has %d",
                 f->id, len, (long long)head[0], s->n);
    free(s->val);
    s->val = NULL;
    s->cap = 0;
    if (head[1])
        reserve(g, s, head[1] - 1);
    memcpy(s->val, buf + sizeof head, (size_t)head[1] * s->n * sizeof(double));
    /* as LAMMPS: the first run's setup still takes the compute, fix and
     * variable inputs again */
}

const struct fix_style fix_style_store_state = {
    .name = "store/state",
    .create = create,
    .init = init,
    .setup = setup,
    .end_of_step = end_of_step,
    .destroy = destroy,
    .peratom_values = peratom_values,
    .write_restart = write_restart,
    .read_restart = read_restart,
};
