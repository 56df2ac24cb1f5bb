/* fix.c - the fix registry (FIX rows of styles/styles.def) and the `fix` and
 * `unfix` commands. Fix order is definition order, as in LAMMPS: a fix
 * redefined with the same ID keeps its place. */
#include "fix.h"
#include "fix_property_atom.h"

#include <setjmp.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "error.h"
#include "ref.h"

#define PAIR(k, i)
#define COMPUTE(k, i)
#define DUMP(k, i)
#define REGION(k, i)
#define FIX(k, i) extern const struct fix_style fix_style_##i;
#include "styles.def"
#undef FIX
#define FIX(k, i) &fix_style_##i,
static const struct fix_style *const fix_styles[] = {
#include "styles.def"
    NULL};
#undef FIX
#undef PAIR
#undef COMPUTE
#undef DUMP
#undef REGION

struct fix *fix_find(struct gravel *g, const char *id)
{
    for (int i = 0; i < g->styles.nfix; i++)
        if (!strcmp(g->styles.fix[i]->id, id))
            return g->styles.fix[i];
    return NULL;
}

int fix_parse_ref(const char *ref, char *id, int *index, int *col)
{
    return ref_parse(ref, 'f', id, index, col);
}

struct fix *fix_ref_check(struct gravel *g, const char *ref, const char *who)
{
    char id[GR_NAMELEN];
    int index, col;
    if (!fix_parse_ref(ref, id, &index, &col))
        gr_error(g, "%s: invalid fix reference '%.64s' (use f_ID, f_ID[I] or f_ID[I][J], I, "
                    "J >= 1)", who, ref);
    struct fix *f = fix_find(g, id);
    if (!f)
        gr_error(g, "%s: no fix with ID '%.64s' for %.64s", who, id, ref);
    if (col > 0) {
        if (!f->array_flag)
            gr_error(g, "%s: fix %s (%s) does not produce a global array", who, id,
                     f->style->name);
        if (col > f->size_array_cols)
            gr_error(g, "%s: %.64s is out of range: fix %s has %d columns", who, ref, id,
                     f->size_array_cols);
    } else if (index == 0) {
        if (!f->scalar_flag)
            gr_error(g, "%s: fix %s (%s) does not compute a global scalar", who, id,
                     f->style->name);
    } else {
        if (!f->vector_flag)
            gr_error(g, "%s: fix %s (%s) does not produce a global vector%s", who, id,
                     f->style->name, f->array_flag ? " (it has an array: f_ID[I][J])" : "");
        if (index > f->size_vector && !f->rows_variable)
            gr_error(g, "%s: %.64s is out of range: fix %s has %d values", who, ref, id,
                     f->size_vector);
    }
    return f;
}

struct fix *fix_peratom_check(struct gravel *g, const char *ref, const char *who)
{
    char id[GR_NAMELEN];
    int index, col;
    if (!fix_parse_ref(ref, id, &index, &col) || col > 0)
        gr_error(g, "%s: invalid per-atom fix reference '%.64s' (use f_ID or f_ID[N], N >= 1)",
                 who, ref);
    struct fix *f = fix_find(g, id);
    if (!f)
        gr_error(g, "%s: no fix with ID '%.64s' for %.64s", who, id, ref);
    if (!f->peratom_flag || !f->style->peratom_values)
        gr_error(g, "%s: fix %s (%s) does not calculate per-atom values", who, id,
                 f->style->name);
    if (index == 0 && f->size_peratom_cols > 0)
        gr_error(g, "%s: fix %s (%s) calculates a per-atom array: name a column, f_%s[N]", who,
                 id, f->style->name, id);
    if (index > 0 && f->size_peratom_cols == 0)
        gr_error(g, "%s: fix %s (%s) calculates a per-atom vector: f_%s, no index", who, id,
                 f->style->name, id);
    if (index > f->size_peratom_cols)
        gr_error(g, "%s: %.64s is out of range: fix %s's per-atom array has %d columns", who,
                 ref, id, f->size_peratom_cols);
    return f;
}

const double *fix_peratom_ref(struct gravel *g, const char *ref, int *stride, const char *who)
{
    char id[GR_NAMELEN];
    int index, col;
    struct fix *f = fix_peratom_check(g, ref, who);
    fix_parse_ref(ref, id, &index, &col);
    const double *v = f->style->peratom_values(g, f);
    *stride = f->size_peratom_cols > 0 ? f->size_peratom_cols : 1;
    return v + (index > 0 ? index - 1 : 0);
}

int fix_output_extensive(const struct fix *f, int index, int col)
{
    if (col > 0)
        return f->extarray;
    if (index == 0)
        return f->extscalar;
    return f->extvector >= 0 ? f->extvector : f->extlist[index - 1];
}

double fix_output(struct gravel *g, struct fix *f, int index, int col, long long norm,
                  const char *who)
{
    double v;
    if (col > 0) {
        if (index > f->size_array_rows && !f->rows_variable)
            gr_error(g, "%s: f_%s[%d][%d] is out of range: fix %s has %d rows now", who, f->id,
                     index, col, f->id, f->size_array_rows);
        v = f->style->array(g, f, index, col);
    } else {
        v = index ? f->style->vector(g, f, index) : f->style->scalar(g, f);
    }
    if (norm > 0 && fix_output_extensive(f, index, col))
        v /= (double)norm;
    return v;
}

struct fix *fix_find_acceleration(struct gravel *g)
{
    for (int i = 0; i < g->styles.nfix; i++)
        if (g->styles.fix[i]->style->acceleration)
            return g->styles.fix[i];
    return NULL;
}

unsigned fix_frozen_groupbit(struct gravel *g)
{
    for (int i = 0; i < g->styles.nfix; i++)
        if (g->styles.fix[i]->style->flags & FIX_FROZEN)
            return g->styles.fix[i]->groupbit;
    return 0;
}

int fix_all_conserving(const struct gravel *g)
{
    for (int i = 0; i < g->styles.nfix; i++)
        if (!(g->styles.fix[i]->style->flags & FIX_CONSERVING))
            return 0;
    return 1;
}

struct fix *fix_find_style(struct gravel *g, const char *style)
{
    for (int i = 0; i < g->styles.nfix; i++)
        if (!strcmp(g->styles.fix[i]->style->name, style))
            return g->styles.fix[i];
    return NULL;
}

unsigned fix_needs_all(struct gravel *g)
{
    unsigned u = 0;
    for (int i = 0; i < g->styles.nfix; i++)
        u |= g->styles.fix[i]->needs;
    return u;
}

static void fix_delete(struct fix *f)
{
    if (!f)
        return;
    if (f->style && f->style->destroy)
        f->style->destroy(f);
    else
        free(f->data);
    if (f->peratom)
        clReleaseMemObject(f->peratom);
    if (f->peratom_tmp)
        clReleaseMemObject(f->peratom_tmp);
    free(f);
}

void fix_free_all(struct gravel *g)
{
    for (int i = 0; i < g->styles.nfix; i++)
        fix_delete(g->styles.fix[i]);
    free(g->styles.fix);
    g->styles.fix = NULL;
    g->styles.nfix = g->styles.nfix_cap = 0;
}

static int valid_id(const char *s)
{
    if (!*s || strlen(s) >= GR_NAMELEN)
        return 0;
    for (; *s; s++)
        if (!(*s == '_' || (*s >= '0' && *s <= '9') || (*s >= 'a' && *s <= 'z') ||
              (*s >= 'A' && *s <= 'Z')))
            return 0;
    return 1;
}

/* fix ID group style args... */
int fix_style_known(const char *name)
{
    for (int i = 0; fix_styles[i]; i++)
        if (!strcmp(fix_styles[i]->name, name))
            return 1;
    return 0;
}

void cmd_fix(struct gravel *g, int argc, char **argv)
{
    if (!valid_id(argv[0]))
        gr_error(g, "fix ID '%.64s' must be letters, digits and underscores (at most %d)",
                 argv[0], GR_NAMELEN - 1);
    int igroup = arg_group(g, argv[1]);
    const struct fix_style *st = NULL;
    for (int i = 0; fix_styles[i]; i++)
        if (!strcmp(fix_styles[i]->name, argv[2]))
            st = fix_styles[i];
    if (!st) {
        char known[512] = "";
        for (int i = 0; fix_styles[i]; i++) {
            strncat(known, i ? ", " : "", sizeof known - strlen(known) - 1);
            strncat(known, fix_styles[i]->name, sizeof known - strlen(known) - 1);
        }
        gr_error(g, "unknown fix style '%.64s' (known: %s)", argv[2], known);
    }
    /* LAMMPS: fix property/atom may precede the box; every other fix needs it */
    if (!g->dom.box_exists && strcmp(st->name, "property/atom"))
        gr_error(g, "fix %s needs a simulation box: use create_box or read_data first",
                 st->name);
    struct fix *old = fix_find(g, argv[0]);
    if (old && strcmp(old->style->name, st->name))
        gr_error(g, "fix %s already exists with style %s; unfix it before redefining it as %s",
                 argv[0], old->style->name, st->name);
    struct fix *f = gr_calloc(g, 1, sizeof *f);
    snprintf(f->id, sizeof f->id, "%s", argv[0]);
    f->style = st;
    f->igroup = igroup;
    f->groupbit = 1u << igroup;
    f->scalar_flag = st->scalar != NULL;
    f->vector_flag = st->vector != NULL;
    f->size_vector = st->size_vector;
    f->extscalar = f->extvector = f->extarray = 1;
    f->global_freq = 1;
    f->peratom_freq = 1;
    /* restart.c: a fix re-specified identically after read_restart continues exactly */
    f->arghash = 1469598103934665603ull;
    for (int a = 1; a < argc; a++)
        for (const char *c = argv[a];; c++) {
            f->arghash = (f->arghash ^ (unsigned char)*c) * 1099511628211ull;
            if (!*c)
                break;
        }
    /* create sees f registered (slot at the end); if it raises, f is taken
     * out and freed and the fix list is as before the command (an old fix
     * of the same ID stays in force) */
    if (g->styles.nfix == g->styles.nfix_cap) {
        int cap = g->styles.nfix_cap ? 2 * g->styles.nfix_cap : 8;
        struct fix **nf = realloc(g->styles.fix, (size_t)cap * sizeof *nf);
        if (!nf) {
            free(f);
            gr_error(g, "out of memory");
        }
        g->styles.fix = nf;
        g->styles.nfix_cap = cap;
    }
    g->styles.fix[g->styles.nfix++] = f;
    jmp_buf *outer = g->err.jmp, here;
    g->err.jmp = &here;
    if (setjmp(here)) {
        g->err.jmp = outer;
        for (int i = g->styles.nfix - 1; i >= 0; i--)
            if (g->styles.fix[i] == f) {
                memmove(&g->styles.fix[i], &g->styles.fix[i + 1],
                        (size_t)(g->styles.nfix - i - 1) * sizeof *g->styles.fix);
                g->styles.nfix--;
                break;
            }
        fix_delete(f);
        if (outer)
            longjmp(*outer, 1);
        gr_report_error(g);
        exit(1);
    }
    st->create(g, f, argc - 3, argv + 3);
    g->err.jmp = outer;
    if (old) {
        /* replace in place, keeping the original position: f leaves its slot
         * at the end and takes old's; exactly one fix has the ID */
        int fi = -1, oi = -1;
        for (int i = 0; i < g->styles.nfix; i++) {
            if (g->styles.fix[i] == f)
                fi = i;
            if (g->styles.fix[i] == old)
                oi = i;
        }
        if (fi >= 0 && oi >= 0) {
            memmove(&g->styles.fix[fi], &g->styles.fix[fi + 1],
                    (size_t)(g->styles.nfix - fi - 1) * sizeof *g->styles.fix);
            g->styles.nfix--;
            if (oi > fi)
                oi--;
            g->styles.fix[oi] = f;
            fix_delete(old);
        }
    }
}

/* unfix ID */
void cmd_unfix(struct gravel *g, int argc, char **argv)
{
    (void)argc;
    for (int i = 0; i < g->styles.nfix; i++)
        if (!strcmp(g->styles.fix[i]->id, argv[0])) {
            if (g->styles.fix[i]->style->unfix)
                g->styles.fix[i]->style->unfix(g, g->styles.fix[i]);
            property_atom_release(g, g->styles.fix[i]); /* its properties go with it */
            fix_delete(g->styles.fix[i]);
            memmove(&g->styles.fix[i], &g->styles.fix[i + 1],
                    (size_t)(g->styles.nfix - i - 1) * sizeof *g->styles.fix);
            g->styles.nfix--;
            return;
        }
    gr_error(g, "could not find fix ID '%.64s' to delete", argv[0]);
}

void fix_check_time_reset(struct gravel *g)
{
    for (int i = 0; i < g->styles.nfix; i++)
        if (g->styles.fix[i]->time_depend)
            gr_error(g, "cannot reset timestep with a time-dependent fix defined (fix %s %s)",
                     g->styles.fix[i]->id, g->styles.fix[i]->style->name);
}

void fix_reset_step(struct gravel *g, bigint shift)
{
    for (int i = 0; i < g->styles.nfix; i++)
        if (g->styles.fix[i]->style->reset_step)
            g->styles.fix[i]->style->reset_step(g, g->styles.fix[i], shift);
}

double fix_energy_sum(struct gravel *g)
{
    double e = 0.0;
    for (int i = 0; i < g->styles.nfix; i++) {
        struct fix *f = g->styles.fix[i];
        if (f->energy && f->style->scalar)
            e += f->style->scalar(g, f);
    }
    return e;
}

double fix_ecouple_sum(struct gravel *g)
{
    double e = 0.0;
    for (int i = 0; i < g->styles.nfix; i++) {
        struct fix *f = g->styles.fix[i];
        if (f->style->ecouple && f->style->scalar)
            e += f->style->scalar(g, f);
    }
    return e;
}

/* fix_modify ID keyword value ... (LAMMPS fix_modify). energy yes on a
 * fix with a global energy (fix gravity) adds its scalar to the thermo pe
 * and etotal, as LAMMPS; on other fixes, like virial yes and respa levels,
 * it is accepted with a warning and changes nothing (no fix contributes a
 * virial in gravel). A style's own keywords (fix surface/global's move)
 * go to its modify_param first. */
void cmd_fix_modify(struct gravel *g, int argc, char **argv)
{
    struct fix *f = fix_find(g, argv[0]);
    if (!f)
        gr_error(g, "unknown fix ID '%.64s'", argv[0]);
    for (int i = 1; i < argc; i++) {
        const char *k = argv[i];
        int used = f->style->modify_param ? f->style->modify_param(g, f, argc - i, argv + i) : 0;
        if (used) {
            i += used - 1;
            continue;
        }
        arg_need(g, argc, i, 1, k);
        const char *v = argv[++i];
        if (!strcmp(k, "energy") && f->style->energy_global && f->style->scalar) {
            f->energy = arg_yesno(g, v, k); /* its scalar joins the thermo pe */
        } else if (!strcmp(k, "energy") || !strcmp(k, "virial")) {
            if (arg_yesno(g, v, k))
                gr_warn(g, "fix %s: %s yes has no effect (gravel's thermo output has no "
                           "fix %s contributions)", f->id, k, k);
        } else if (!strcmp(k, "respa")) {
            arg_int_range(g, v, 0, 1 << 20, "respa level");
            gr_warn(g, "fix %s: respa ignored: gravel has only run_style verlet", f->id);
        } else if (!strcmp(k, "dynamic/dof") || !strcmp(k, "bodyforces") ||
                   !strcmp(k, "temp") || !strcmp(k, "press")) {
            gr_error(g, "fix %s: keyword '%s' does not apply to fix %s in gravel", f->id, k,
                     f->style->name);
        } else {
            gr_error(g, "unknown keyword '%.64s' (expected energy, virial or respa)", k);
        }
    }
}
