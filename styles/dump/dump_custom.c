/* dump_custom.c - `dump ID group custom N file field...`: LAMMPS text dumps.
 *
 * Each snapshot is, as LAMMPS writes it:
 *   ITEM: TIMESTEP / step / ITEM: NUMBER OF ATOMS / n /
 *   ITEM: BOX BOUNDS xx yy zz (boundary flags lo/hi per dimension) /
 *   three "lo hi" lines in %-1.16e (triclinic, as LAMMPS: "BOX BOUNDS xy xz
 *   yz ..." and "lo_bound hi_bound tilt" lines of the bounding box) / ITEM: ATOMS field... / one line per atom,
 * values separated by one space; integers "%d", floats "%g" unless
 * dump_modify format says otherwise (precedence: format N > format int|float
 * > the word of format line, as LAMMPS).
 * Fields: id type x y z xu yu zu ix iy iz vx vy vz fx fy fz radius diameter
 * mass omegax omegay omegaz tqx tqy tqz, xs ys zs (scaled to the box: (x -
 * xlo) / Lx; triclinic: the lamda coordinates), xsu ysu zsu (scaled,
 * unwrapped: xs + ix), xu yu zu unwrapped with the tilted edge vectors, and c_ID / c_ID[N] (a per-atom
 * compute's vector or column N of its array), v_name (an atom-style variable,
 * evaluated at each snapshot). With atom_style ellipsoid superellipsoid:
 * quatw quati quatj quatk (the orientation; 0 for a point particle),
 * shapex shapey shapez (the diameters, twice the semi-axes, as LAMMPS
 * dumps them), angmomx angmomy angmomz. */
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "compute.h"
#include "domain.h"
#include "fix.h"
#include "dump.h"
#include "dump_custom.h"
#include "atom_custom.h"
#include "error.h"
#include "thermo.h"
#include "variable.h"

enum field {
    F_ID, F_TYPE, F_X, F_Y, F_Z, F_XU, F_YU, F_ZU, F_IX, F_IY, F_IZ, F_VX, F_VY, F_VZ, F_FX,
    F_FY, F_FZ, F_RADIUS, F_DIAMETER, F_MASS, F_OMEGAX, F_OMEGAY, F_OMEGAZ, F_TQX, F_TQY, F_TQZ,
    F_XS, F_YS, F_ZS, F_XSU, F_YSU, F_ZSU, F_MOL, F_TEMPERATURE,
    F_HEATFLOW, F_QUATW, F_QUATI, F_QUATJ, F_QUATK, F_SHAPEX, F_SHAPEY, F_SHAPEZ, F_ANGMOMX,
    F_ANGMOMY, F_ANGMOMZ, F_COUNT, F_COMPUTE = -1, F_VARIABLE = -2, F_CUSTOM = -3,
    F_FIX = -4
};

static const char *const field_names[F_COUNT] = {
    "id", "type", "x", "y", "z", "xu", "yu", "zu", "ix", "iy", "iz", "vx", "vy", "vz", "fx",
    "fy", "fz", "radius", "diameter", "mass", "omegax", "omegay", "omegaz", "tqx", "tqy", "tqz",
    "xs", "ys", "zs", "xsu", "ysu", "zsu", "mol", "temperature", "heatflow", "quatw", "quati",
    "quatj", "quatk", "shapex", "shapey", "shapez", "angmomx", "angmomy", "angmomz"};

static int field_is_int(int f)
{
    return f == F_ID || f == F_TYPE || f == F_MOL || f == F_IX || f == F_IY || f == F_IZ;
}

struct column {
    int field;                  /* enum field or F_COMPUTE */
    char name[GR_NAMELEN];      /* as given */
    char fmt[80];               /* resolved at init */
    char cid[GR_NAMELEN];       /* c_ID / c_ID[N]: compute ID and column (0: vector) */
    int index;
    const double *peratom;      /* compute values for the current snapshot */
    int stride;
    double *vals;               /* v_name: the variable's values (owned) */
    struct custom_ref cref;     /* i_name d_name i2_name[k] d2_name[k] (resolved at init) */
    int cint;                   /* ... an integer property */
};

struct custom {
    int n;
    struct column *col;
    struct dump_formats fmt;
};

static void custom_destroy(struct dump *d)
{
    struct custom *c = d->data;
    if (!c)
        return;
    for (int i = 0; i < c->n; i++)
        free(c->col[i].vals);
    free(c->col);
    dump_formats_free(&c->fmt);
    free(c);
    d->data = NULL;
}

static void custom_create(struct gravel *g, struct dump *d, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "dump custom needs at least one field after the file name");
    struct custom *c = gr_calloc(g, 1, sizeof *c);
    d->data = c;
    c->col = gr_calloc(g, (size_t)argc, sizeof *c->col);
    c->fmt.col = gr_calloc(g, (size_t)argc, sizeof *c->fmt.col);
    c->fmt.n = argc;
    c->n = argc;
    for (int i = 0; i < argc; i++) {
        struct column *col = &c->col[i];
        const char *s = argv[i];
        if (strlen(s) >= GR_NAMELEN)
            gr_error(g, "dump custom field '%.64s...' is too long", s);
        snprintf(col->name, sizeof col->name, "%s", s);
        col->field = F_COMPUTE;
        for (int f = 0; f < F_COUNT; f++)
            if (strcmp(s, field_names[f]) == 0)
                col->field = f;
        if (col->field == F_MOL && !g->atoms.molecule_flag)
            gr_error(g, "dumping an atom property (mol) that isn't allocated (fix property/atom "
                        "mol)");
        if (col->field == F_TEMPERATURE && !(g->atoms.heat_flag & ATOM_HEAT_T))
            gr_error(g, "dumping an atom property (temperature) that isn't allocated (fix "
                        "property/atom temperature)");
        if (col->field == F_HEATFLOW && !(g->atoms.heat_flag & ATOM_HEAT_Q))
            gr_error(g, "dumping an atom property (heatflow) that isn't allocated (fix "
                        "property/atom heatflow)");
        if (col->field >= F_QUATW && col->field <= F_ANGMOMZ && !g->atoms.ellipsoid_flag)
            gr_error(g, "dumping an atom property (%s) that isn't allocated (atom_style "
                        "ellipsoid superellipsoid)", s);
        if (col->field != F_COMPUTE)
            continue;
        if (strncmp(s, "c_", 2) == 0 && compute_parse_ref(s, col->cid, &col->index))
            continue;
        if (strncmp(s, "v_", 2) == 0 && s[2]) {
            col->field = F_VARIABLE;
            continue;
        }
        if (custom_ref_parse(g, s, "dump custom", &col->cref, NULL)) {
            col->field = F_CUSTOM;
            col->cint = g->atoms.cus.p[col->cref.idx].isint;
            continue;
        }
        if (strncmp(s, "f_", 2) == 0 && s[2]) { /* a fix's per-atom output: checked at init */
            col->field = F_FIX;
            continue;
        }
        gr_error(g, "unknown dump custom field '%s' (id type x y z xu yu zu ix iy iz vx vy vz "
                    "fx fy fz radius diameter mass omegax omegay omegaz tqx tqy tqz xs ys zs xsu ysu zsu mol "
                    "temperature heatflow quatw quati quatj quatk shapex shapey shapez angmomx "
                    "angmomy angmomz i_name d_name i2_name[k] d2_name[k] c_ID c_ID[N] f_ID f_ID[N] v_name)", s);
    }
}

static void set_str(struct gravel *g, char **dst, const char *s)
{
    char *n = gr_strdup(g, s);
    free(*dst);
    *dst = n;
}

void dump_formats_free(struct dump_formats *fm)
{
    free(fm->line);
    free(fm->fint);
    free(fm->ffloat);
    fm->line = fm->fint = fm->ffloat = NULL;
    if (fm->col)
        for (int k = 0; k < fm->n; k++)
            free(fm->col[k]);
    free(fm->col);
    fm->col = NULL;
}

int dump_formats_modify(struct gravel *g, struct dump_formats *fm, const struct dump_columns *dc,
                        int argc, char **argv, int i, int apply)
{
    char buf[96];
    const char *bad;
    if (strcmp(argv[i], "format") != 0)
        return 0;
    arg_need(g, argc, i, 1, "format");
    const char *what = argv[i + 1];
    if (strcmp(what, "none") == 0) {
        if (!apply)
            return 2;
        free(fm->line);
        free(fm->fint);
        free(fm->ffloat);
        fm->line = fm->fint = fm->ffloat = NULL;
        for (int k = 0; k < fm->n; k++) {
            free(fm->col[k]);
            fm->col[k] = NULL;
        }
        return 2;
    }
    if (strchr(what, '%')) { /* LIGGGHTS's (and LAMMPS's before 2016) `format "..."`: a line */
        if (strlen(what) > 4000)
            gr_error(g, "format line is too long");
        if (apply)
            set_str(g, &fm->line, what);
        return 2;
    }
    arg_need(g, argc, i, 2, "format");
    const char *f = argv[i + 2];
    if (strcmp(what, "line") == 0) {
        if (strlen(f) > 4000)
            gr_error(g, "format line is too long");
        if (apply)
            set_str(g, &fm->line, f);
    } else if (strcmp(what, "int") == 0) {
        if ((bad = output_format_fix(f, 1, buf)))
            gr_error(g, "format int '%.64s' %s", f, bad);
        if (apply)
            set_str(g, &fm->fint, f);
    } else if (strcmp(what, "float") == 0) {
        if ((bad = output_format_fix(f, 0, buf)))
            gr_error(g, "format float '%.64s' %s", f, bad);
        if (apply)
            set_str(g, &fm->ffloat, f);
    } else if (arg_is_number(what)) {
        int k = arg_int(g, what, "format column");
        if (k < 1 || k > fm->n)
            gr_error(g, "format column %d is outside 1..%d (the dump's %s)", k, fm->n, dc->noun);
        if ((bad = output_format_fix(f, dc->is_int(dc->ctx, k - 1), buf)))
            gr_error(g, "format '%.64s' for column %d (%s) %s", f, k, dc->name(dc->ctx, k - 1),
                     bad);
        if (apply)
            set_str(g, &fm->col[k - 1], f);
    } else {
        gr_error(g, "format must be followed by line, int, float, none, a column number or "
                    "(LIGGGHTS) the line's format string, got '%.64s'", what);
    }
    return 3;
}

void dump_box_header(struct gravel *g, FILE *fp, const char *what, long long count)
{
    const struct domain *dom = &g->dom;
    fprintf(fp, "ITEM: TIMESTEP\n%lld\nITEM: NUMBER OF %s\n%lld\nITEM: BOX BOUNDS%s",
            (long long)g->step, what, count, dom->triclinic ? " xy xz yz" : "");
    for (int k = 0; k < 3; k++)
        fprintf(fp, " %c%c", dom->bnd[k][0], dom->bnd[k][1]);
    fprintf(fp, "\n");
    if (dom->triclinic) { /* LAMMPS: the bounding box, each line with one tilt */
        double blo[3], bhi[3], tilt[3] = {dom->xy, dom->xz, dom->yz};
        domain_bbox(g, blo, bhi);
        for (int k = 0; k < 3; k++)
            fprintf(fp, "%-1.16e %-1.16e %-1.16e\n", blo[k], bhi[k], tilt[k]);
    } else {
        for (int k = 0; k < 3; k++)
            fprintf(fp, "%-1.16e %-1.16e\n", dom->lo[k], dom->hi[k]);
    }
}

static int col_is_int(const struct column *col)
{
    return col->field == F_CUSTOM ? col->cint : col->field >= 0 && field_is_int(col->field);
}

static int custom_is_int(const void *ctx, int k)
{
    return col_is_int(&((const struct custom *)ctx)->col[k]);
}

static const char *custom_name(const void *ctx, int k)
{
    return ((const struct custom *)ctx)->col[k].name;
}

static int custom_modify(struct gravel *g, struct dump *d, int argc, char **argv, int i,
                         int apply)
{
    struct custom *c = d->data;
    const struct dump_columns dc = {c, custom_is_int, custom_name, "fields"};
    return dump_formats_modify(g, &c->fmt, &dc, argc, argv, i, apply);
}

static void custom_init(struct gravel *g, struct dump *d)
{
    struct custom *c = d->data;
    char line[4100] = "";
    char *save = NULL, *word = NULL;
    if (c->fmt.line) {
        snprintf(line, sizeof line, "%s", c->fmt.line);
        word = strtok_r(line, " \t", &save);
    }
    for (int i = 0; i < c->n; i++) {
        struct column *col = &c->col[i];
        if (col->field == F_COMPUTE)
            compute_peratom_check(g, col->cid, col->index, "dump custom");
        if (col->field == F_VARIABLE)
            var_check_atom(g, col->name + 2, "dump custom");
        if (col->field == F_FIX) { /* LAMMPS DumpCustom::init: current on the dump's steps */
            struct fix *fx = fix_peratom_check(g, col->name, "dump custom");
            if (!d->every_var && d->every % fx->peratom_freq)
                gr_error(g, "dump custom %s: dump every %d and fix %s (%s, per-atom output "
                            "every %d steps) are not computed at compatible times", d->id,
                         d->every, fx->id, fx->style->name, fx->peratom_freq);
        }
        if (col->field == F_CUSTOM) { /* the property may have moved (or gone: unfix) */
            custom_ref_parse(g, col->name, "dump custom", &col->cref, NULL);
            col->cint = g->atoms.cus.p[col->cref.idx].isint;
        }
        int isint = col_is_int(col);
        const char *f = NULL, *src = NULL;
        if (c->fmt.col[i]) {
            f = c->fmt.col[i];
            src = "format N";
        } else if (isint && c->fmt.fint) {
            f = c->fmt.fint;
            src = "format int";
        } else if (!isint && c->fmt.ffloat) {
            f = c->fmt.ffloat;
            src = "format float";
        } else if (c->fmt.line) {
            if (!word)
                gr_error(g, "dump %s: dump_modify format line has fewer words than the %d "
                            "fields", d->id, c->n);
            f = word;
            src = "format line";
        }
        if (f) {
            const char *bad = output_format_fix(f, isint, col->fmt);
            if (bad)
                gr_error(g, "dump %s: %s '%.64s' for field %s %s", d->id, src, f, col->name,
                         bad);
        } else {
            snprintf(col->fmt, sizeof col->fmt, "%s", isint ? "%lld" : "%g");
        }
        if (word)
            word = strtok_r(NULL, " \t", &save);
    }
}

static void custom_write(struct gravel *g, struct dump *d, FILE *fp, const int *idx, int n)
{
    struct custom *c = d->data;
    const struct atoms *a = &g->atoms;
    const struct domain *dom = &g->dom;
    custom_init(g, d); /* formats may have changed since run setup (tests, dump_modify) */
    for (int i = 0; i < c->n; i++)
        if (c->col[i].field == F_COMPUTE)
            c->col[i].peratom = compute_peratom_ref(g, compute_find(g, c->col[i].cid),
                                                    c->col[i].index, &c->col[i].stride,
                                                    "dump custom");
    for (int i = 0; i < c->n; i++) {
        struct column *col = &c->col[i];
        if (col->field == F_FIX) {
            col->peratom = fix_peratom_ref(g, col->name, &col->stride, "dump custom");
            continue;
        }
        if (col->field != F_VARIABLE)
            continue;
        double *v = realloc(col->vals, ((size_t)a->n + 1) * sizeof *v);
        if (!v)
            gr_error(g, "out of memory");
        col->vals = v;
        var_compute_atom(g, col->name + 2, v);
        col->peratom = v;
        col->stride = 1;
    }

    double prd[3];
    for (int k = 0; k < 3; k++)
        prd[k] = dom->hi[k] - dom->lo[k];
    dump_box_header(g, fp, "ATOMS", n);
    fprintf(fp, "ITEM: ATOMS");
    for (int i = 0; i < c->n; i++)
        fprintf(fp, " %s", c->col[i].name);
    fprintf(fp, "\n");

    for (int k = 0; k < n; k++) {
        int j = idx[k];
        for (int i = 0; i < c->n; i++) {
            const struct column *col = &c->col[i];
            long long iv = 0;
            double v = 0.0;
            switch (col->field) {
            case F_ID: iv = a->tag[j]; break;
            case F_MOL: iv = a->mol[j]; break;
            case F_TYPE: iv = a->type[j]; break;
            case F_TEMPERATURE: v = a->temperature[j]; break;
            case F_HEATFLOW: v = a->heatflow[j]; break;
            case F_QUATW: case F_QUATI: case F_QUATJ: case F_QUATK:
                v = a->quat[4 * j + col->field - F_QUATW];
                break;
            case F_SHAPEX: case F_SHAPEY: case F_SHAPEZ:
                v = 2.0 * a->shape[3 * j + col->field - F_SHAPEX];
                break;
            case F_ANGMOMX: case F_ANGMOMY: case F_ANGMOMZ:
                v = a->angmom[3 * j + col->field - F_ANGMOMX];
                break;
            case F_X: case F_Y: case F_Z: v = a->x[3 * j + col->field - F_X]; break;
            case F_XU: case F_YU: case F_ZU: {
                int dim = col->field - F_XU;
                if (dom->triclinic) {
                    double u[3];
                    domain_unmap(g, a->x + 3 * j, a->image + 3 * j, u);
                    v = u[dim];
                } else {
                    v = a->x[3 * j + dim] + a->image[3 * j + dim] * prd[dim];
                }
                break;
            }
            case F_XS: case F_YS: case F_ZS:
            case F_XSU: case F_YSU: case F_ZSU: {
                int su = col->field >= F_XSU, dim = col->field - (su ? F_XSU : F_XS);
                if (dom->triclinic) { /* LAMMPS: the lamda coordinate */
                    double lam[3];
                    domain_x2lamda(g, a->x + 3 * j, lam);
                    v = lam[dim];
                } else {
                    v = (a->x[3 * j + dim] - dom->lo[dim]) / prd[dim];
                }
                if (su)
                    v += a->image[3 * j + dim];
                break;
            }
            case F_IX: case F_IY: case F_IZ: iv = a->image[3 * j + col->field - F_IX]; break;
            case F_VX: case F_VY: case F_VZ: v = a->v[3 * j + col->field - F_VX]; break;
            case F_FX: case F_FY: case F_FZ: v = a->f[3 * j + col->field - F_FX]; break;
            case F_RADIUS: v = a->radius[j]; break;
            case F_DIAMETER: v = 2.0 * a->radius[j]; break;
            case F_MASS: v = a->rmass[j]; break;
            case F_OMEGAX: case F_OMEGAY: case F_OMEGAZ:
                v = a->omega[3 * j + col->field - F_OMEGAX];
                break;
            case F_TQX: case F_TQY: case F_TQZ: v = a->torque[3 * j + col->field - F_TQX]; break;
            case F_CUSTOM:
                v = custom_get(a, col->cref, j);
                iv = (long long)v;
                break;
            default: v = col->peratom[(size_t)j * col->stride]; break;
            }
            if (i)
                fputc(' ', fp);
            if (col_is_int(col))
                fprintf(fp, col->fmt, iv);
            else
                fprintf(fp, col->fmt, v);
        }
        fputc('\n', fp);
    }
}

int dump_custom_has_field(const struct dump *d, const char *name)
{
    const struct custom *c = d->data;
    for (int i = 0; c && i < c->n; i++)
        if (strcmp(c->col[i].name, name) == 0)
            return 1;
    return 0;
}

const struct dump_style dump_style_custom = {
    .name = "custom",
    .append = 1,
    .create = custom_create,
    .modify = custom_modify,
    .init = custom_init,
    .write = custom_write,
    .destroy = custom_destroy,
};
