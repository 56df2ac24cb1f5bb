/* settings.c - simple global settings: units, dimension, atom_style, timestep,
 * neighbor, neigh_modify and mass. Each validates its arguments the way LAMMPS
 * does and stores the result in struct gravel. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "atoms.h"
#include "domain.h"
#include "error.h"
#include "gravel.h"


/* units lj|si|cgs: only defaults differ (gr_unit_defaults: timestep, skin,
 * thermo normalization); gravel converts nothing. */
void cmd_units(struct gravel *g, int argc, char **argv)
{
    (void)argc;
    if (strcmp(argv[0], "lj") == 0)
        g->dom.units = UNITS_LJ;
    else if (strcmp(argv[0], "si") == 0)
        g->dom.units = UNITS_SI;
    else if (strcmp(argv[0], "cgs") == 0)
        g->dom.units = UNITS_CGS;
    else if (!strcmp(argv[0], "real") || !strcmp(argv[0], "metal") ||
             !strcmp(argv[0], "electron") || !strcmp(argv[0], "micro") ||
             !strcmp(argv[0], "nano"))
        gr_error(g, "units '%s' is not supported: use lj, si or cgs", argv[0]);
    else
        gr_error(g, "unknown units '%.32s': expected lj, si or cgs", argv[0]);
    gr_unit_defaults(g);
    g->dt_set = 0;
}

/* soft_particles|hard_particles yes|no (LIGGGHTS): lift the youngsModulus
 * sanity limits of pair gran's material models (styles/pair/pair_gran.c) */
static int yes_no(struct gravel *g, const char *cmd, const char *v)
{
    if (strcmp(v, "yes") && strcmp(v, "no"))
        gr_error(g, "%s expects 'yes' or 'no'", cmd);
    return v[0] == 'y';
}

void cmd_soft_particles(struct gravel *g, int argc, char **argv)
{
    (void)argc;
    g->atoms.allow_soft = yes_no(g, "soft_particles", argv[0]);
}

void cmd_hard_particles(struct gravel *g, int argc, char **argv)
{
    (void)argc;
    g->atoms.allow_hard = yes_no(g, "hard_particles", argv[0]);
}

void cmd_dimension(struct gravel *g, int argc, char **argv)
{
    (void)argc;
    int d = arg_int(g, argv[0], "dimension");
    if (d != 2 && d != 3)
        gr_error(g, "dimension must be 2 or 3, got %d", d);
    if (g->dom.box_exists)
        gr_error(g, "dimension must be set before the simulation box is created");
    g->dom.dimension = d;
}

/* atom_style sphere [0|1]: the optional LAMMPS radvary flag is accepted.
 * atom_style hybrid sphere molecular (either order): spheres with molecule IDs
 * as part of the style (LAMMPS's molecular sub-style; no bonds in granular
 * decks: a molecule template with bonds is refused where it is read).
 * atom_style granular is LIGGGHTS's name for sphere (no flag), with
 * LIGGGHTS's thermo kinetic energy. atom_style tri and a hybrid's tri
 * sub-style (LAMMPS 4 Jul 2026: the triangle particles of fix
 * surface/local) are sphere here: gravel's local triangles are mesh walls,
 * not atoms. */
void cmd_atom_style(struct gravel *g, int argc, char **argv)
{
    g->atoms.ellipsoid_flag = 0;
    snprintf(g->atoms.style, sizeof g->atoms.style, "%s", argv[0]);
    if (!strcmp(argv[0], "hybrid")) {
        int sphere = 0, molecular = 0, tri = 0;
        for (int i = 1; i < argc; i++) {
            if (!strcmp(argv[i], "sphere") && !sphere)
                sphere = 1;
            else if (!strcmp(argv[i], "molecular") && !molecular)
                molecular = 1;
            else if (!strcmp(argv[i], "tri") && !tri)
                tri = 1;
            else
                gr_error(g, "hybrid sub-style '%.32s' is not supported (gravel "
                            "has hybrid sphere molecular and hybrid sphere tri)", argv[i]);
        }
        if (!sphere || !(molecular || tri))
            gr_error(g, "hybrid needs the sub-styles sphere and molecular (or tri)");
        if (!molecular) { /* hybrid sphere tri: spheres */
            g->atoms.style_molecular = 0;
            g->atoms.molecule_flag = 0;
            return;
        }
        g->atoms.style_molecular = 1;
        g->atoms.molecule_flag = 1;
        return;
    }
    if (g->atoms.style_molecular) { /* a later atom_style replaces hybrid */
        g->atoms.style_molecular = 0;
        g->atoms.molecule_flag = 0;
    }
    /* LIGGGHTS's thermo `ke` is 1/2 sum m v^2 of the atoms of the step, also just
     * after an insertion into an empty box (its thermo temperature counts 3 N
     * degrees of freedom at each evaluation; LAMMPS's counts 3 N - 3 at the run's
     * setup): a granular deck gets thermo_temp dynamic/dof yes, extra/dof 0. */
    int granular = !strcmp(argv[0], "granular");
    g->thermo.temp.dynamic = granular;
    g->thermo.temp.extra_set = granular;
    g->thermo.temp.extra_dof = 0;
    if (!strcmp(argv[0], "ellipsoid")) {
        /* LAMMPS 30 Mar 2026: atom_style ellipsoid superellipsoid, the
         * bonus_super record (shape, blockiness, quaternion, inertia) with a
         * bounding radius and angular momentum (atom_fields.h) */
        if (argc != 2 || strcmp(argv[1], "superellipsoid") != 0)
            gr_error(g, "atom_style ellipsoid is supported with its superellipsoid flag only "
                        "(atom_style ellipsoid superellipsoid): gravel has no pair style for "
                        "plain ellipsoids");
        g->atoms.ellipsoid_flag = 1;
        return;
    }
    if (granular) {
        if (argc > 1)
            gr_error(g, "atom_style granular takes no arguments, got '%.32s'", argv[1]);
        return;
    }
    if (!strcmp(argv[0], "tri")) {
        if (argc > 1)
            gr_error(g, "atom_style tri takes no arguments, got '%.32s'", argv[1]);
        return;
    }
    if (strcmp(argv[0], "sphere") != 0)
        gr_error(g, "atom_style '%.32s' is not supported: gravel has atom_style sphere (LIGGGHTS: "
                    "granular), tri (as sphere), hybrid sphere molecular and ellipsoid "
                    "superellipsoid",
                 argv[0]);
    if (argc > 2)
        gr_error(g, "atom_style sphere takes at most one flag (0 or 1)");
    if (argc == 2)
        arg_int_range(g, argv[1], 0, 1, "atom_style sphere radvary flag");
}

void cmd_timestep(struct gravel *g, int argc, char **argv)
{
    (void)argc;
    g->dt = arg_positive(g, argv[0], "timestep");
    g->dt_set = 1;
}

/* neighbor skin bin|multi */
void cmd_neighbor(struct gravel *g, int argc, char **argv)
{
    (void)argc;
    double skin = arg_nonneg(g, argv[0], "skin");
    if (strcmp(argv[1], "nsq") == 0 || strcmp(argv[1], "multi/old") == 0)
        gr_error(g, "neighbor style '%s' is not supported: use bin or multi", argv[1]);
    int style = 0;
    if (strcmp(argv[1], "bin") == 0)
        style = NEIGH_BIN;
    else if (strcmp(argv[1], "multi") == 0)
        style = NEIGH_MULTI;
    else
        gr_error(g, "unknown neighbor style '%.32s': expected bin or multi", argv[1]);
    g->neigh.skin = skin;
    g->neigh.style = style;
}

/* neigh_modify collection/interval N cut1 ... cutN: upper bounds of the
 * particle diameter (LAMMPS' atom cut-off of granular styles), ascending. */
static int collection_interval(struct gravel *g, struct neigh_settings *ns, int argc,
                               char **argv, int i)
{
    if (ns->style != NEIGH_MULTI)
        gr_error(g, "collection/interval needs neighbor style multi");
    arg_need(g, argc, i, 1, "collection/interval");
    int n = arg_int_range(g, argv[i + 1], 1, GR_MAXCOLL, "number of collections");
    arg_need(g, argc, i, 1 + n, "collection/interval");
    for (int k = 0; k < n; k++) {
        ns->coll_cut[k] = arg_positive(g, argv[i + 2 + k], "collection/interval cut-off");
        if (k > 0 && ns->coll_cut[k - 1] >= ns->coll_cut[k])
            gr_error(g, "collection/interval cut-offs must increase: %g then %g",
                     ns->coll_cut[k - 1], ns->coll_cut[k]);
    }
    ns->ncoll = n;
    ns->coll_interval = 1;
    return i + 1 + n;
}

/* neigh_modify collection/type N types1 ... typesN: each a comma list of
 * type ranges (1*3,5); every type in exactly one collection. */
static int collection_type(struct gravel *g, struct neigh_settings *ns, int argc, char **argv,
                           int i)
{
    if (ns->style != NEIGH_MULTI)
        gr_error(g, "collection/type needs neighbor style multi");
    if (!g->dom.box_exists)
        gr_error(g, "collection/type needs the box (atom types) to exist");
    arg_need(g, argc, i, 1, "collection/type");
    int n = arg_int_range(g, argv[i + 1], 1, GR_MAXCOLL, "number of collections");
    arg_need(g, argc, i, 1 + n, "collection/type");
    int nt = g->atoms.ntypes;
    char *seen = gr_calloc(g, (size_t)nt + 1, 1);
    ns->ncoll_range = 0;
    for (int k = 0; k < n; k++) {
        char buf[256];
        snprintf(buf, sizeof buf, "%s", argv[i + 2 + k]);
        for (char *w = buf, *next; w; w = next) {
            next = strchr(w, ',');
            if (next)
                *next++ = 0;
            int lo, hi;
            arg_type_range(g, w, nt, &lo, &hi);
            for (int t = lo; t <= hi; t++) {
                if (seen[t]) {
                    free(seen);
                    gr_error(g, "type %d is in more than one collection of collection/type", t);
                }
                seen[t] = 1;
            }
            if (ns->ncoll_range >= GR_MAXCOLL_RANGE) {
                free(seen);
                gr_error(g, "too many type ranges in collection/type (at most %d)",
                         GR_MAXCOLL_RANGE);
            }
            int *r = ns->coll_range[ns->ncoll_range++];
            r[0] = lo;
            r[1] = hi;
            r[2] = k;
        }
    }
    for (int t = 1; t <= nt; t++)
        if (!seen[t]) {
            free(seen);
            gr_error(g, "type %d is in no collection of collection/type", t);
        }
    free(seen);
    ns->ncoll = n;
    ns->coll_interval = 0;
    return i + 1 + n;
}

/* An exclusion is an unordered pair: one already in the list (either order)
 * is not added again, so re-issuing the same neigh_modify after read_restart
 * (which restores the exclusions) leaves the settings as they were. */
static void add_exclusion(struct gravel *g, int pairs[16][2], int *n, int a, int b)
{
    for (int k = 0; k < *n; k++)
        if ((pairs[k][0] == a && pairs[k][1] == b) || (pairs[k][0] == b && pairs[k][1] == a))
            return;
    if (*n >= 16)
        gr_error(g, "too many neigh_modify exclusions (at most 16 of each kind)");
    pairs[*n][0] = a;
    pairs[*n][1] = b;
    (*n)++;
}

void cmd_neigh_modify(struct gravel *g, int argc, char **argv)
{
    struct neigh_settings ns = g->neigh;
    for (int i = 0; i < argc; i++) {
        const char *kw = argv[i];
        if (!strcmp(kw, "every")) {
            arg_need(g, argc, i, 1, kw);
            ns.every = arg_int_range(g, argv[++i], 1, 1 << 30, "every");
        } else if (!strcmp(kw, "delay")) {
            arg_need(g, argc, i, 1, kw);
            ns.delay = arg_int_range(g, argv[++i], 0, 1 << 30, "delay");
        } else if (!strcmp(kw, "check")) {
            arg_need(g, argc, i, 1, kw);
            ns.check = arg_yesno(g, argv[++i], "check");
        } else if (!strcmp(kw, "once")) {
            arg_need(g, argc, i, 1, kw);
            ns.once = arg_yesno(g, argv[++i], "once");
        } else if (!strcmp(kw, "one")) {
            arg_need(g, argc, i, 1, kw);
            ns.one = arg_int_range(g, argv[++i], 1, 1 << 24, "one");
        } else if (!strcmp(kw, "page")) {
            arg_need(g, argc, i, 1, kw);
            ns.page = arg_int_range(g, argv[++i], 1, 1 << 30, "page");
        } else if (!strcmp(kw, "exclude")) {
            arg_need(g, argc, i, 1, kw);
            const char *how = argv[++i];
            if (!strcmp(how, "none")) {
                ns.nexclude = ns.nexclude_type = ns.nexclude_mol = 0;
            } else if (!strcmp(how, "type")) {
                arg_need(g, argc, i, 2, "exclude type");
                if (!g->dom.box_exists)
                    gr_error(g, "exclude type needs the box (atom types) to exist");
                int a = arg_int_range(g, argv[i + 1], 1, g->atoms.ntypes, "exclude type");
                int b = arg_int_range(g, argv[i + 2], 1, g->atoms.ntypes, "exclude type");
                add_exclusion(g, ns.exclude_type, &ns.nexclude_type, a, b);
                i += 2;
            } else if (!strcmp(how, "group")) {
                arg_need(g, argc, i, 2, "exclude group");
                int a = arg_group(g, argv[i + 1]);
                int b = arg_group(g, argv[i + 2]);
                add_exclusion(g, ns.exclude_group, &ns.nexclude, a, b);
                i += 2;
            } else if (!strcmp(how, "molecule/intra") || !strcmp(how, "molecule/inter") ||
                       !strcmp(how, "molecule")) {
                /* LAMMPS: exclude pairs of atoms both in the group with the same
                 * (intra; `molecule` is its old name) or different (inter) IDs */
                arg_need(g, argc, i, 1, how);
                if (!g->atoms.molecule_flag)
                    gr_error(g, "neigh_modify exclude %s requires atom attribute molecule (fix "
                                "property/atom mol)", how);
                int a = arg_group(g, argv[i + 1]), intra = strcmp(how, "molecule/inter") != 0;
                int k;
                for (k = 0; k < ns.nexclude_mol; k++)
                    if (ns.exclude_mol[k][0] == a && ns.exclude_mol[k][1] == intra)
                        break;
                if (k == ns.nexclude_mol) {
                    if (ns.nexclude_mol >= 16)
                        gr_error(g, "too many neigh_modify exclusions (at most 16 of each kind)");
                    ns.exclude_mol[k][0] = a;
                    ns.exclude_mol[k][1] = intra;
                    ns.nexclude_mol++;
                }
                i += 1;
            } else {
                gr_error(g, "unsupported exclude style '%.32s': expected type, group, "
                            "molecule/intra, molecule/inter or none", how);
            }
        } else if (!strcmp(kw, "collection/interval")) {
            i = collection_interval(g, &ns, argc, argv, i);
        } else if (!strcmp(kw, "collection/type")) {
            i = collection_type(g, &ns, argc, argv, i);
        } else {
            gr_error(g, "unknown keyword '%.32s'", kw);
        }
    }
    if (ns.page < 10 * ns.one)
        gr_error(g, "page (%d) must be at least 10 x one (%d)", ns.page, ns.one);
    if (ns.delay > 0 && ns.delay % ns.every != 0)
        gr_error(g, "delay (%d) must be 0 or a multiple of every (%d)", ns.delay, ns.every);
    g->neigh = ns;
}

/* atom_modify sort Nfreq binsize: re-sort the atoms by cell at the first
 * rebuild Nfreq or more steps after the last (0 = never; the binsize is
 * accepted, cells are the neighbor cells). Other LAMMPS keywords (id, map,
 * first) only tune LAMMPS' memory layout: accepted with one warning. */
void cmd_atom_modify(struct gravel *g, int argc, char **argv)
{
    bigint every = g->neigh.sort_every;
    int other = 0;
    for (int i = 0; i < argc; i++) {
        const char *kw = argv[i];
        if (!strcmp(kw, "sort")) {
            arg_need(g, argc, i, 2, kw);
            every = arg_bigint(g, argv[i + 1], "sort frequency");
            if (every < 0)
                gr_error(g, "sort frequency must be >= 0, got %lld", (long long)every);
            (void)arg_nonneg(g, argv[i + 2], "sort bin size");
            i += 2;
        } else if (!strcmp(kw, "id") || !strcmp(kw, "map") || !strcmp(kw, "first")) {
            arg_need(g, argc, i, 1, kw);
            i++;
            other = 1;
        } else {
            gr_error(g, "unknown keyword '%.32s' (expected sort, id, map or first)", kw);
        }
    }
    g->neigh.sort_every = every;
    if (other)
        gr_warn(g, "keywords id, map and first only tune LAMMPS' memory layout: ignored");
}

/* mass I value: per-type mass (I may be a range). atom_style sphere keeps a
 * per-atom mass from diameter and density; the per-type value is stored
 * (written to data files' Masses section) but does not change atom masses. */
void cmd_mass(struct gravel *g, int argc, char **argv)
{
    (void)argc;
    int lo, hi;
    arg_type_range(g, argv[0], g->atoms.ntypes, &lo, &hi);
    double m = arg_positive(g, argv[1], "mass");
    for (int t = lo; t <= hi; t++)
        g->atoms.type_mass[t] = m;
}
