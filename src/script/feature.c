/* feature.c - the feature functions of variables, as LAMMPS's Info class
 * answers them: is_active(category,name) (the style or setting in use),
 * is_defined(category,ID), is_available(category,name) (what gravel can
 * run), is_file(name), is_os(regex). gravel has no accelerator packages,
 * no minimizer, no bonds and no long-range solver: those categories answer
 * as LAMMPS's would without them. is_defined of a group, region or
 * variable is answered by the expression parser (src/script/expr.c), whose
 * modules own them: this file stays outside the variable language's knot. */
#include <regex.h>
#include <stdio.h>
#include <string.h>
#include <sys/utsname.h>

#include "command.h"
#include "compute.h"
#include "dump.h"
#include "feature.h"
#include "fix.h"
#include "pair.h"
#include "par.h"

int feature_is_function(const char *fn)
{
    static const char *const fns[] = {"is_active", "is_defined", "is_available", "is_file",
                                      "is_os", NULL};
    for (int k = 0; fns[k]; k++)
        if (!strcmp(fn, fns[k]))
            return 1;
    return 0;
}

static int fail(char *err, size_t errlen, const char *fmt, const char *a, const char *b)
{
    snprintf(err, errlen, fmt, a, b);
    return -1;
}

/* is_active: the style in use in a category, or a setting of it */
static int is_active(struct gravel *g, const char *cat, const char *name, char *err, size_t len)
{
    if (!strcmp(cat, "package")) {
        static const char *const pk[] = {"cuda", "gpu", "intel", "kokkos", "omp", NULL};
        for (int k = 0; pk[k]; k++)
            if (!strcmp(name, pk[k]))
                return 0;
        return fail(err, len, "is_active(): unknown name '%.40s' for category %s", name, cat);
    }
    if (!strcmp(cat, "newton")) { /* LAMMPS's defaults: on (gravel ignores the command) */
        if (!strcmp(name, "pair") || !strcmp(name, "bond") || !strcmp(name, "any"))
            return 1;
        return fail(err, len, "is_active(): unknown name '%.40s' for category %s", name, cat);
    }
    if (!strcmp(cat, "pair")) {
        static const char *const set[] = {"single", "respa", "manybody", "tail", "shift", NULL};
        int k = 0;
        while (set[k] && strcmp(name, set[k]))
            k++;
        if (!set[k])
            return fail(err, len, "is_active(): unknown name '%.40s' for category %s", name,
                        cat);
        if (!g->styles.pair)
            return 0;
        return k == 0 ? 1 : k == 4 ? g->styles.pair->shift != 0 : 0;
    }
    const char *style;
    if (!strcmp(cat, "comm_style"))
        style = par_state(g)->dc.tiled ? "tiled" : "brick";
    else if (!strcmp(cat, "run_style"))
        style = "verlet";
    else if (!strcmp(cat, "min_style"))
        style = "cg";
    else if (!strcmp(cat, "atom_style"))
        style = g->atoms.style[0] ? g->atoms.style : "sphere";
    else if (!strcmp(cat, "pair_style"))
        style = g->styles.pair ? g->styles.pair->style->name : "none";
    else if (!strcmp(cat, "bond_style") || !strcmp(cat, "angle_style") ||
             !strcmp(cat, "dihedral_style") || !strcmp(cat, "improper_style") ||
             !strcmp(cat, "kspace_style"))
        style = "none";
    else
        return fail(err, len, "is_active(): unknown category '%.40s'%s", cat, "");
    return strcmp(style, name) == 0;
}

static int is_defined(struct gravel *g, const char *cat, const char *id, char *err, size_t len)
{
    if (!strcmp(cat, "compute")) /* LAMMPS defines thermo's three computes at start */
        return compute_find(g, id) != NULL || !strcmp(id, "thermo_temp") ||
               !strcmp(id, "thermo_press") || !strcmp(id, "thermo_pe");
    if (!strcmp(cat, "dump"))
        return dump_find(g, id) != NULL;
    if (!strcmp(cat, "fix"))
        return fix_find(g, id) != NULL;
    return fail(err, len, "is_defined(): unknown category '%.40s'%s", cat, "");
}

static int is_available(const char *cat, const char *name, char *err, size_t len)
{
    if (!strcmp(cat, "command"))
        return cmd_find(name) != NULL;
    if (!strcmp(cat, "compute"))
        return compute_style_known(name);
    if (!strcmp(cat, "fix"))
        return fix_style_known(name);
    if (!strcmp(cat, "pair_style"))
        return pair_style_find(name) != NULL;
    if (!strcmp(cat, "feature")) /* gravel reads and writes plain files, no images */
        return 0;
    return fail(err, len, "is_available(): unknown category '%.40s'%s", cat, "");
}

/* is_os: the regex against "sysname release", as LAMMPS's platform string */
static int is_os(const char *pattern, char *err, size_t len)
{
    struct utsname u;
    char os[2 * sizeof u.sysname + 2] = "";
    if (uname(&u) == 0)
        snprintf(os, sizeof os, "%s %s", u.sysname, u.release);
    regex_t re;
    if (regcomp(&re, pattern, REG_EXTENDED | REG_NOSUB) != 0)
        return fail(err, len, "is_os(): invalid regular expression '%.40s'%s", pattern, "");
    const int match = regexec(&re, os, 0, NULL, 0) == 0;
    regfree(&re);
    return match;
}

int feature_value(struct gravel *g, const char *fn, int n, char args[][GR_NAMELEN], char *err,
                  size_t errlen)
{
    const int want = !strcmp(fn, "is_file") || !strcmp(fn, "is_os") ? 1 : 2;
    if (n != want) {
        snprintf(err, errlen, "%s() takes %d argument%s, got %d", fn, want, want == 1 ? "" : "s",
                 n);
        return -1;
    }
    if (!strcmp(fn, "is_active"))
        return is_active(g, args[0], args[1], err, errlen);
    if (!strcmp(fn, "is_defined"))
        return is_defined(g, args[0], args[1], err, errlen);
    if (!strcmp(fn, "is_available"))
        return is_available(args[0], args[1], err, errlen);
    if (!strcmp(fn, "is_os"))
        return is_os(args[0], err, errlen);
    FILE *f = fopen(args[0], "r"); /* is_file: LAMMPS opens it for reading */
    if (f)
        fclose(f);
    return f != NULL;
}
