/* dump_custom_vtk.c - `dump ID group custom/vtk N file.vtk field ...`:
 * LIGGGHTS's particle VTK dump (LIGGGHTS-PUBLIC 3.8 DumpCustomVTK with the
 * legacy .vtk extension), written by gravel's own code as legacy VTK 3.0
 * POLYDATA that every VTK and ParaView reads.
 *
 * Arrays as LIGGGHTS names and orders them (its DumpParticle field map): the
 * points are always x y z (listed or not); then, in this order and each once
 * however often listed: id, mol, type (int), mass, ix iy iz -> "i" (3 ints),
 * vx vy vz -> "v", fx fy fz -> "f", radius, diameter, omegax omegay omegaz
 * -> "omega", tqx tqy tqz -> "tq" (doubles), then fix heat/gran's
 * f_Temp[0], f_heatFlux[0] and f_heatSource[0] (LIGGGHTS's per-atom Temp,
 * heatFlux and heatSource: the atoms' temperature, heat flow and heat
 * source, under those names). A triple becomes a 3-component
 * array only when all three are listed; otherwise each is its own scalar
 * array under its keyword. One VERTICES cell per particle; dataset field
 * data TIME and CYCLE. Beside each snapshot, as LIGGGHTS, the box as a
 * RECTILINEAR_GRID in "<before *>boundingBox_<step><after *>" (without '*':
 * "<name>_boundingBox.vtk"). Other per-atom computes, fixes and variables,
 * scaled/unwrapped coordinates and LIGGGHTS's SPH/superquadric fields are
 * refused, as are the XML extensions (.vtu .vtp .pvtu .pvtp need the VTK
 * library). `dump_modify binary yes`: big-endian binary blocks. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "dump.h"
#include "error.h"
#include "outfile.h"

enum { C_ID, C_MOL, C_TYPE, C_MASS, C_IX, C_IY, C_IZ, C_VX, C_VY, C_VZ, C_FX, C_FY, C_FZ,
       C_RADIUS, C_DIAMETER, C_OMEGAX, C_OMEGAY, C_OMEGAZ, C_TQX, C_TQY, C_TQZ, C_TEMP,
       C_HEATFLUX, C_HEATSOURCE, C_COUNT };

static const char *const names[C_COUNT] = {
    "id", "mol", "type", "mass", "ix", "iy", "iz", "vx", "vy", "vz", "fx", "fy", "fz",
    "radius", "diameter", "omegax", "omegay", "omegaz", "tqx", "tqy", "tqz", "f_Temp[0]",
    "f_heatFlux[0]", "f_heatSource[0]"};

struct cvtk {
    int on[C_COUNT];
    double *buf;
    int cap;
};

static void create(struct gravel *g, struct dump *d, int argc, char **argv)
{
    dump_vtk_check_name(g, d);
    if (argc < 1)
        gr_error(g, "dump custom/vtk: no fields after the file name");
    struct cvtk *c = gr_calloc(g, 1, sizeof *c);
    d->data = c;
    for (int i = 0; i < argc; i++) {
        const char *s = argv[i];
        if (!strcmp(s, "x") || !strcmp(s, "y") || !strcmp(s, "z"))
            continue; /* always the points */
        int k;
        for (k = 0; k < C_COUNT && strcmp(s, names[k]); k++)
            ;
        if (k == C_COUNT)
            gr_error(g, "dump custom/vtk: field '%.64s' is not supported (supported: id mol type "
                        "mass x y z ix iy iz vx vy vz fx fy fz radius diameter omegax omegay "
                        "omegaz tqx tqy tqz, and f_Temp[0] f_heatFlux[0] f_heatSource[0] with fix "
                        "heat/gran)", s);
        if (k >= C_TEMP && !(g->atoms.heat_flag & ATOM_HEAT_T))
            gr_error(g, "dump custom/vtk: %s needs the atoms' temperature (define fix heat/gran "
                        "first)", s);
        c->on[k] = 1;
    }
}

static void destroy(struct dump *d)
{
    struct cvtk *c = d->data;
    if (c)
        free(c->buf);
    free(c);
    d->data = NULL;
}

static int modify(struct gravel *g, struct dump *d, int argc, char **argv, int i, int apply)
{
    const int used = dump_vtk_binary(g, d, argc, argv, i, apply);
    if (used)
        return used;
    if (!strcmp(argv[i], "label")) { /* LIGGGHTS: the title line */
        arg_need(g, argc, i, 1, "label");
        return 2;
    }
    return 0;
}

/* Value c (C_*) of atom i. */
static double value(const struct gravel *g, int c, int i)
{
    const struct atoms *a = &g->atoms;
    switch (c) {
    case C_ID: return (double)a->tag[i];
    case C_MOL: return a->mol ? (double)a->mol[i] : 0.0;
    case C_TYPE: return a->type[i];
    case C_MASS: return a->rmass[i];
    case C_IX: case C_IY: case C_IZ: return a->image[3 * i + c - C_IX];
    case C_VX: case C_VY: case C_VZ: return a->v[3 * i + c - C_VX];
    case C_FX: case C_FY: case C_FZ: return a->f[3 * i + c - C_FX];
    case C_RADIUS: return a->radius[i];
    case C_DIAMETER: return 2.0 * a->radius[i];
    case C_OMEGAX: case C_OMEGAY: case C_OMEGAZ:
        return a->omega ? a->omega[3 * i + c - C_OMEGAX] : 0.0;
    case C_TEMP: return a->temperature[i];
    case C_HEATFLUX: return a->heatflow[i];
    case C_HEATSOURCE: return a->heatsource[i];
    default: return a->torque ? a->torque[3 * i + c - C_TQX] : 0.0;
    }
}

static int is_int(int c)
{
    return c == C_ID || c == C_MOL || c == C_TYPE || (c >= C_IX && c <= C_IZ);
}

/* One array: comp values per atom from fields c0 .. c0 + comp - 1. */
static void array(struct gravel *g, struct dump *d, FILE *fp, const char *name, int c0,
                  int comp, const int *idx, int n)
{
    struct cvtk *c = d->data;
    int integer = is_int(c0);
    fprintf(fp, "%s %d %d %s\n", name, comp, n, integer ? "int" : "double");
    if (d->binary) {
        if ((size_t)c->cap < (size_t)comp * n) {
            c->cap = comp * n;
            c->buf = gr_realloc(g, c->buf, (size_t)c->cap * sizeof(double));
        }
        if (integer) {
            int32_t *b = (int32_t *)c->buf;
            for (int k = 0; k < n; k++)
                for (int j = 0; j < comp; j++)
                    b[comp * k + j] = (int32_t)value(g, c0 + j, idx[k]);
            dump_write_be_int32(fp, b, (size_t)comp * n);
        } else {
            for (int k = 0; k < n; k++)
                for (int j = 0; j < comp; j++)
                    c->buf[comp * k + j] = value(g, c0 + j, idx[k]);
            dump_write_be_doubles(fp, c->buf, (size_t)comp * n);
        }
        fputc('\n', fp);
        return;
    }
    for (int k = 0; k < n; k++)
        for (int j = 0; j < comp; j++)
            fprintf(fp, integer ? "%.0f%c" : "%.17g%c", value(g, c0 + j, idx[k]),
                    j == comp - 1 ? '\n' : ' ');
}

/* The box beside the snapshot (LIGGGHTS's boundingBox file). */
static void write_box(struct gravel *g, struct dump *d)
{
    const char *star = strchr(d->file, '*');
    char path[1200], num[40];
    snprintf(num, sizeof num, "%0*lld", d->pad, (long long)g->step);
    if (star)
        snprintf(path, sizeof path, "%.*sboundingBox_%s%s", (int)(star - d->file), d->file, num,
                 star + 1);
    else {
        const char *dot = strrchr(d->file, '.');
        snprintf(path, sizeof path, "%.*s_boundingBox%s", (int)(dot - d->file), d->file, dot);
    }
    struct ofile o;
    memset(&o, 0, sizeof o);
    int e = of_open(&o, path, ".tmp", OF_TRUNC);
    if (e)
        gr_error(g, "dump custom/vtk: cannot write %s: %s", path, strerror(e));
    FILE *fp = o.fp;
    fprintf(fp, "# vtk DataFile Version 3.0\ngravel dump %s box step %lld\nASCII\n"
                "DATASET RECTILINEAR_GRID\nDIMENSIONS 2 2 2\n", d->id, (long long)g->step);
    for (int k = 0; k < 3; k++)
        fprintf(fp, "%c_COORDINATES 2 double\n%.17g %.17g\n", 'X' + k, g->dom.lo[k],
                g->dom.hi[k]);
    if ((e = of_commit(&o, 0)) != 0)
        gr_error(g, "dump custom/vtk: cannot write %s: %s", path, strerror(e));
}

static void write(struct gravel *g, struct dump *d, FILE *fp, const int *idx, int n)
{
    struct cvtk *c = d->data;
    const struct atoms *a = &g->atoms;
    int bin = d->binary;
    if (g->dom.triclinic)
        gr_error(g, "dump custom/vtk: triclinic boxes are not supported (LIGGGHTS writes a "
                    "hexahedron grid for the box)");
    for (int k = 0; c->on[C_ID] && k < n; k++)
        if (a->tag[idx[k]] > INT32_MAX)
            gr_error(g, "dump custom/vtk: atom ID %lld does not fit LIGGGHTS's int id array "
                        "(use dump vtk, which writes 64-bit IDs)", (long long)a->tag[idx[k]]);
    char title[GR_NAMELEN + 96];
    snprintf(title, sizeof title, "gravel dump %s step %lld time %.17g", d->id,
             (long long)g->step, g->time);
    dump_vtk_polydata_head(g, d, fp, title);
    fprintf(fp, "POINTS %d double\n", n);
    if (bin) {
        if (c->cap < 3 * n) {
            c->cap = 3 * n;
            c->buf = gr_realloc(g, c->buf, (size_t)c->cap * sizeof(double));
        }
        for (int k = 0; k < n; k++)
            memcpy(c->buf + 3 * k, a->x + 3 * idx[k], 3 * sizeof(double));
        dump_write_be_doubles(fp, c->buf, 3 * (size_t)n);
        fputc('\n', fp);
    } else {
        for (int k = 0; k < n; k++)
            fprintf(fp, "%.17g %.17g %.17g\n", a->x[3 * idx[k]], a->x[3 * idx[k] + 1],
                    a->x[3 * idx[k] + 2]);
    }
    fprintf(fp, "VERTICES %d %d\n", n, 2 * n);
    for (int k = 0; k < n; k++) {
        if (bin) {
            int32_t v[2] = {1, k};
            dump_write_be_int32(fp, v, 2);
        } else {
            fprintf(fp, "1 %d\n", k);
        }
    }
    if (bin)
        fputc('\n', fp);
    write_box(g, d);
    if (n == 0)
        return; /* VTK's reader rejects empty attribute arrays */
    /* the arrays, in LIGGGHTS's order */
    int narr = 0;
    for (int k = 0; k < C_COUNT; k++) {
        int triple = (k == C_IX || k == C_VX || k == C_FX || k == C_OMEGAX || k == C_TQX) &&
                     c->on[k] && c->on[k + 1] && c->on[k + 2];
        if (triple) {
            narr++;
            k += 2;
        } else if (c->on[k]) {
            narr++;
        }
    }
    fprintf(fp, "POINT_DATA %d\nFIELD FieldData %d\n", n, narr);
    for (int k = 0; k < C_COUNT; k++) {
        int triple = (k == C_IX || k == C_VX || k == C_FX || k == C_OMEGAX || k == C_TQX) &&
                     c->on[k] && c->on[k + 1] && c->on[k + 2];
        if (triple) {
            char nm[16];
            snprintf(nm, sizeof nm, "%.*s", (int)(strchr(names[k], 'x') - names[k]), names[k]);
            array(g, d, fp, nm, k, 3, idx, n);
            k += 2;
        } else if (c->on[k]) {
            array(g, d, fp, names[k], k, 1, idx, n);
        }
    }
}

const struct dump_style dump_style_custom_vtk = {
    .name = "custom/vtk",
    .append = 0,
    .create = create,
    .modify = modify,
    .write = write,
    .destroy = destroy,
};
