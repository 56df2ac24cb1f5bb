/* thermo.c - the thermo table: `thermo`, `thermo_style`, `thermo_modify`,
 * the header and value lines in LAMMPS 2021's layout, and thermo keyword
 * values for expressions (thermo_keyword_value).
 *
 * Layout (LAMMPS 2021 Thermo): the header is the column names each followed
 * by one space; a line is each value formatted and followed by one space.
 * Default formats: integers "%8d" (steps, atoms), floats "%12.8g"; in multi
 * mode a banner line "---------------- Step %8d ----- CPU = %11.4f (sec)
 * ----------------" and "%-8s = %14.4f " fields, three per line.
 * Format precedence per column: `format N` > `format int|float` >
 * the word of `format line` > default, as LAMMPS 2021. */
#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "atoms.h"
#include "args.h"
#include "comm.h"
#include "compute.h"
#include "engine.h"
#include "error.h"
#include "fix.h"
#include "pair_energy.h"
#include "par.h"
#include "par_sum.h"
#include "pressure.h"
#include "temperature.h"
#include "thermo.h"
#include "variable.h"
#include "wall_clock.h"

enum vtype { V_BIGINT, V_FLOAT };
enum kw_id {
    KW_STEP, KW_ELAPSED, KW_ELAPLONG, KW_DT, KW_TIME, KW_CPU, KW_TPCPU, KW_SPCPU, KW_ATOMS, KW_KE, KW_PE,
    KW_ETOTAL, KW_VOL, KW_LX, KW_LY, KW_LZ, KW_XLO, KW_XHI, KW_YLO, KW_YHI, KW_ZLO, KW_ZHI,
    KW_TEMP, KW_EPAIR, KW_EMOL, KW_CPUREMAIN, KW_PRESS,
    KW_PXX, KW_PYY, KW_PZZ, KW_PXY, KW_PXZ, KW_PYZ, KW_XY, KW_XZ, KW_YZ,
    KW_CELLA, KW_CELLB, KW_CELLC, KW_CELLALPHA, KW_CELLBETA, KW_CELLGAMMA, KW_DENSITY,
    KW_EVDWL, KW_ECOUL, KW_ELONG, KW_ETAIL, KW_EBOND, KW_EANGLE, KW_EDIHED, KW_EIMP,
    KW_ENTHALPY, KW_FMAX, KW_FNORM, KW_NBUILD, KW_NDANGER, KW_XLAT, KW_YLAT, KW_ZLAT,
    KW_ECOUPLE, KW_ECONSERVE,
    KW_THERMO_TEMP, /* c_thermo_temp without a compute of that ID: no keyword name */
    /* c_thermo_temp[1..6]: its kinetic tensor (no keyword names) */
    KW_THERMO_TEMP_V, KW_THERMO_TEMP_V2, KW_THERMO_TEMP_V3, KW_THERMO_TEMP_V4, KW_THERMO_TEMP_V5,
    KW_THERMO_TEMP_V6,
    KW_COUNT
};
#define KIND_COMPUTE (-1)
#define KIND_VARIABLE (-2)
#define KIND_FIX (-3)

int thermo_shows_fix_vector(const struct gravel *g, const char *id)
{
    size_t n = strlen(id);
    for (int i = 0; i < g->thermo.ncol; i++) {
        const char *c = g->thermo.col[i];
        if (!strncmp(c, "f_", 2) && !strncmp(c + 2, id, n) && c[2 + n] == '[')
            return 1;
    }
    return 0;
}

static int norm_flag(struct gravel *g);

/* f_ID, f_ID[I], f_ID[I][J]: extensive fix outputs are divided by the atom
 * count under thermo_modify norm yes, as LAMMPS does. */
static double fix_ref_value(struct gravel *g, const char *ref)
{
    char id[GR_NAMELEN];
    int index, col;
    struct fix *f = fix_ref_check(g, ref, "thermo_style");
    fix_parse_ref(ref, id, &index, &col);
    return fix_output(g, f, index, col, norm_flag(g) ? par_natoms(g) : 0, "thermo_style");
}

static const struct {
    const char *name, *header;
    enum vtype type;
} keywords[KW_COUNT] = {
    [KW_STEP] = {"step", "Step", V_BIGINT},     [KW_ELAPSED] = {"elapsed", "Elapsed", V_BIGINT},
    [KW_ELAPLONG] = {"elaplong", "Elaplong", V_BIGINT},
    [KW_DT] = {"dt", "Dt", V_FLOAT},            [KW_TIME] = {"time", "Time", V_FLOAT},
    [KW_CPU] = {"cpu", "CPU", V_FLOAT},         [KW_TPCPU] = {"tpcpu", "T/CPU", V_FLOAT},
    [KW_SPCPU] = {"spcpu", "S/CPU", V_FLOAT},   [KW_ATOMS] = {"atoms", "Atoms", V_BIGINT},
    [KW_KE] = {"ke", "KinEng", V_FLOAT},        [KW_PE] = {"pe", "PotEng", V_FLOAT},
    [KW_ETOTAL] = {"etotal", "TotEng", V_FLOAT}, [KW_VOL] = {"vol", "Volume", V_FLOAT},
    [KW_LX] = {"lx", "Lx", V_FLOAT},            [KW_LY] = {"ly", "Ly", V_FLOAT},
    [KW_LZ] = {"lz", "Lz", V_FLOAT},            [KW_XLO] = {"xlo", "Xlo", V_FLOAT},
    [KW_XHI] = {"xhi", "Xhi", V_FLOAT},         [KW_YLO] = {"ylo", "Ylo", V_FLOAT},
    [KW_YHI] = {"yhi", "Yhi", V_FLOAT},         [KW_ZLO] = {"zlo", "Zlo", V_FLOAT},
    [KW_ZHI] = {"zhi", "Zhi", V_FLOAT},         [KW_TEMP] = {"temp", "Temp", V_FLOAT},
    [KW_EPAIR] = {"epair", "E_pair", V_FLOAT},  [KW_EMOL] = {"emol", "E_mol", V_FLOAT},
    [KW_CPUREMAIN] = {"cpuremain", "CPULeft", V_FLOAT}, [KW_PRESS] = {"press", "Press", V_FLOAT},
    [KW_PXX] = {"pxx", "Pxx", V_FLOAT},         [KW_PYY] = {"pyy", "Pyy", V_FLOAT},
    [KW_PZZ] = {"pzz", "Pzz", V_FLOAT},         [KW_PXY] = {"pxy", "Pxy", V_FLOAT},
    [KW_PXZ] = {"pxz", "Pxz", V_FLOAT},         [KW_PYZ] = {"pyz", "Pyz", V_FLOAT},
    [KW_XY] = {"xy", "Xy", V_FLOAT},            [KW_XZ] = {"xz", "Xz", V_FLOAT},
    [KW_YZ] = {"yz", "Yz", V_FLOAT},
    [KW_CELLA] = {"cella", "Cella", V_FLOAT},   [KW_CELLB] = {"cellb", "Cellb", V_FLOAT},
    [KW_CELLC] = {"cellc", "Cellc", V_FLOAT},
    [KW_CELLALPHA] = {"cellalpha", "CellAlpha", V_FLOAT},
    [KW_CELLBETA] = {"cellbeta", "CellBeta", V_FLOAT},
    [KW_CELLGAMMA] = {"cellgamma", "CellGamma", V_FLOAT},
    [KW_DENSITY] = {"density", "Density", V_FLOAT},
    [KW_EVDWL] = {"evdwl", "E_vdwl", V_FLOAT},
    [KW_ECOUL] = {"ecoul", "E_coul", V_FLOAT},
    [KW_ELONG] = {"elong", "E_long", V_FLOAT},
    [KW_ETAIL] = {"etail", "E_tail", V_FLOAT},
    [KW_EBOND] = {"ebond", "E_bond", V_FLOAT},
    [KW_EANGLE] = {"eangle", "E_angle", V_FLOAT},
    [KW_EDIHED] = {"edihed", "E_dihed", V_FLOAT},
    [KW_EIMP] = {"eimp", "E_impro", V_FLOAT},
    [KW_ENTHALPY] = {"enthalpy", "Enthalpy", V_FLOAT},
    [KW_FMAX] = {"fmax", "Fmax", V_FLOAT},
    [KW_FNORM] = {"fnorm", "Fnorm", V_FLOAT},
    [KW_NBUILD] = {"nbuild", "Nbuild", V_BIGINT},
    [KW_NDANGER] = {"ndanger", "Ndanger", V_BIGINT},
    [KW_XLAT] = {"xlat", "Xlat", V_FLOAT},
    [KW_YLAT] = {"ylat", "Ylat", V_FLOAT},
    [KW_ZLAT] = {"zlat", "Zlat", V_FLOAT},
    [KW_ECOUPLE] = {"ecouple", "Ecouple", V_FLOAT},
    [KW_ECONSERVE] = {"econserve", "Econserve", V_FLOAT},
    [KW_THERMO_TEMP] = {"", "c_thermo_temp", V_FLOAT},
    [KW_THERMO_TEMP_V] = {"", "c_thermo_temp[1]", V_FLOAT},
    [KW_THERMO_TEMP_V2] = {"", "c_thermo_temp[2]", V_FLOAT},
    [KW_THERMO_TEMP_V3] = {"", "c_thermo_temp[3]", V_FLOAT},
    [KW_THERMO_TEMP_V4] = {"", "c_thermo_temp[4]", V_FLOAT},
    [KW_THERMO_TEMP_V5] = {"", "c_thermo_temp[5]", V_FLOAT},
    [KW_THERMO_TEMP_V6] = {"", "c_thermo_temp[6]", V_FLOAT},
};

/* thermo keywords that read the host arrays (the temperature or the kinetic
 * tensor) */
static int needs_host(int k)
{
    return k == KW_KE || k == KW_ETOTAL || k == KW_PE || k == KW_TEMP || k == KW_PRESS ||
           (k >= KW_PXX && k <= KW_PYZ) || k == KW_DENSITY || k == KW_ENTHALPY || k == KW_FMAX ||
           k == KW_FNORM || k == KW_ECOUPLE || k == KW_ECONSERVE;
}

/* gravel's `one`: LAMMPS' one is "step temp epair emol etotal press". For
 * granular flows the atom count (pours, lost atoms), kinetic energy and
 * volume say more than a temperature and the always-zero epair/emol, so
 * `one` prints those. */
static const char *const style_one[] = {"step", "atoms", "ke", "pe", "etotal", "vol"};
static const char *const style_multi[] = {"step", "atoms", "etotal", "ke", "pe", "vol"};

#define FMT_BIGINT_ONE "%8lld"
#define FMT_FLOAT_ONE "%12.8g"
#define FMT_BIGINT_MULTI "%14lld"
#define FMT_FLOAT_MULTI "%14.4f"

/* ---- state and text buffer ------------------------------------------------- */

struct output_state *output_state(struct gravel *g)
{
    if (!g->thermo.state) {
        g->thermo.state = gr_calloc(g, 1, sizeof *g->thermo.state);
        g->thermo.state->last_thermo = -1;
        g->thermo.state->pre_step = -1;
        g->thermo.state->wall0 = wall_clock();
    }
    return g->thermo.state;
}

static void text_clear(struct gravel *g)
{
    struct output_state *st = output_state(g);
    st->text_len = 0;
    if (st->text)
        st->text[0] = '\0';
}

static void text_add(struct gravel *g, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void text_add(struct gravel *g, const char *fmt, ...)
{
    struct output_state *st = output_state(g);
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    if (n < 0)
        return;
    if (st->text_len + (size_t)n + 1 > st->text_cap) {
        size_t cap = st->text_cap ? st->text_cap : 256;
        while (cap < st->text_len + (size_t)n + 1)
            cap *= 2;
        st->text = gr_realloc(g, st->text, cap);
        st->text_cap = cap;
    }
    va_start(ap, fmt);
    vsnprintf(st->text + st->text_len, st->text_cap - st->text_len, fmt, ap);
    va_end(ap);
    st->text_len += (size_t)n;
}

void thermo_settings_free(struct thermo_settings *t)
{
    free(t->every_var);
    free(t->format_line);
    free(t->format_int);
    free(t->format_float);
    for (int i = 0; i < GR_MAXTHERMO; i++) {
        free(t->format_col[i]);
        t->format_col[i] = NULL;
    }
    if (t->state)
        free(t->state->text);
    free(t->state);
    t->every_var = t->format_line = t->format_int = t->format_float = NULL;
    t->state = NULL;
}

/* ---- formats ------------------------------------------------------------------ */

/* See thermo.h. Output can grow by 2 chars per conversion (ll): a 60-char
 * input fits in 80 bytes. */
const char *output_format_fix(const char *f, int want_int, char *out)
{
    size_t o = 0;
    int nconv = 0;
    if (strlen(f) > 60)
        return "is longer than 60 characters";
    for (const char *p = f; *p;) {
        if (*p != '%') {
            out[o++] = *p++;
            continue;
        }
        if (p[1] == '%') {
            out[o++] = '%';
            out[o++] = '%';
            p += 2;
            continue;
        }
        if (nconv == 1)
            return "must contain exactly one conversion";
        out[o++] = *p++;
        while (*p && strchr("-+ #0", *p))
            out[o++] = *p++;
        int digits = 0;
        while (isdigit((unsigned char)*p) && digits < 4) {
            out[o++] = *p++;
            digits++;
        }
        if (digits > 3)
            return "has a field width over 999";
        if (*p == '.') {
            out[o++] = *p++;
            digits = 0;
            while (isdigit((unsigned char)*p) && digits < 4) {
                out[o++] = *p++;
                digits++;
            }
            if (digits > 3)
                return "has a precision over 999";
        }
        while (*p == 'l' || *p == 'L' || *p == 'h')
            p++; /* length modifiers: replaced by what the value needs */
        if (!*p)
            return "ends inside a conversion";
        char c = *p++;
        if (want_int && (c == 'd' || c == 'i')) {
            out[o++] = 'l';
            out[o++] = 'l';
            out[o++] = c;
        } else if (!want_int && strchr("eEfFgG", c)) {
            out[o++] = c;
        } else {
            return want_int ? "must convert an integer with %d"
                            : "must convert a floating-point value with %e, %f or %g";
        }
        nconv++;
    }
    out[o] = '\0';
    if (nconv != 1)
        return "must contain exactly one conversion";
    return NULL;
}

/* ---- columns ------------------------------------------------------------------- */

/* LAMMPS' implicit computes thermo_temp, thermo_pe and thermo_press,
 * referenced as c_thermo_temp / c_thermo_pe / c_thermo_press and
 * c_thermo_press[1..6] (pxx pyy pzz pxy pxz pyz) when no compute of that
 * ID was defined: the keyword they stand for, else -1. (The thermo
 * pressure is LAMMPS's thermo_press: it follows thermo_modify temp too.) */
static int implicit_compute(struct gravel *g, const char *s)
{
    if (strncmp(s, "c_thermo_temp", 13) == 0 && !compute_find(g, "thermo_temp")) {
        if (s[13] == '\0')
            return KW_THERMO_TEMP;
        if (s[13] == '[' && s[14] >= '1' && s[14] <= '6' && s[15] == ']' && s[16] == '\0')
            return KW_THERMO_TEMP_V + (s[14] - '1'); /* the kinetic tensor, extensive */
    }
    if (strcmp(s, "c_thermo_pe") == 0 && !compute_find(g, "thermo_pe"))
        return KW_PE;
    if (strncmp(s, "c_thermo_press", 14) == 0 && !compute_find(g, "thermo_press")) {
        if (s[14] == '\0')
            return KW_PRESS;
        if (s[14] == '[' && s[15] >= '1' && s[15] <= '6' && s[16] == ']' && s[17] == '\0')
            return KW_PXX + (s[15] - '1');
    }
    return -1;
}

static int keyword_index(const char *s)
{
    for (int k = 0; k < KW_COUNT; k++)
        if (strcmp(s, keywords[k].name) == 0)
            return k;
    return -1;
}

static void set_columns(struct gravel *g, const char *const *cols, int n)
{
    for (int i = 0; i < n; i++)
        snprintf(g->thermo.col[i], GR_NAMELEN, "%s", cols[i]);
    g->thermo.ncol = n;
}

/* Number of columns, resolving the default style `one`. */
static int columns(struct gravel *g)
{
    if (g->thermo.ncol == 0)
        set_columns(g, style_one, (int)(sizeof style_one / sizeof *style_one));
    return g->thermo.ncol;
}

/* Command-time check of one custom keyword. */
static void check_keyword(struct gravel *g, const char *s)
{
    if (strlen(s) >= GR_NAMELEN)
        gr_error(g, "keyword '%.64s...' is too long", s);
    if (keyword_index(s) >= 0)
        return;
    if (strncmp(s, "c_", 2) == 0) {
        char id[GR_NAMELEN];
        int index, col;
        if (!compute_parse_ref2(s, id, &index, &col))
            gr_error(g, "invalid compute reference '%s' (use c_ID, c_ID[N] or c_ID[I][J], N, I, "
                        "J >= 1)", s);
        /* as LAMMPS: the compute must exist when thermo_style names it */
        if (!compute_find(g, id) && implicit_compute(g, s) < 0)
            gr_error(g, "could not find thermo custom compute ID '%s'", id);
        return;
    }
    if (strncmp(s, "v_", 2) == 0) {
        if (!s[2])
            gr_error(g, "variable reference 'v_' has no name");
        for (const char *p = s + 2; *p; p++)
            if (!isalnum((unsigned char)*p) && *p != '_')
                gr_error(g, "invalid variable reference '%s'", s);
        if (!var_exists(g, s + 2))
            gr_error(g, "could not find thermo custom variable name '%s'", s + 2);
        return;
    }
    if (strncmp(s, "f_", 2) == 0) {
        char id[GR_NAMELEN];
        int index, col;
        if (!fix_parse_ref(s, id, &index, &col))
            gr_error(g, "invalid fix reference '%s' (use f_ID, f_ID[I] or f_ID[I][J], I, J >= 1)",
                     s);
        if (!fix_find(g, id))
            gr_error(g, "could not find thermo custom fix ID '%s'", id);
        return;
    }
    gr_error(g, "unknown keyword '%s' (known: step elapsed elaplong dt time cpu tpcpu spcpu "
                "atoms ke pe etotal vol density lx ly lz xlo xhi ylo yhi zlo zhi xy xz yz temp "
                "press pxx ... pyz epair evdwl emol enthalpy fmax fnorm nbuild ndanger xlat ylat "
                "zlat cella ... cellgamma cpuremain c_ID c_ID[N] f_ID v_name)", s);
}

/* A new thermo_style drops thermo_modify settings, as in LAMMPS. */
static void reset_modify(struct gravel *g)
{
    struct thermo_settings *t = &g->thermo;
    if (t->modified)
        gr_warn(g, "new thermo_style command, previous thermo_modify settings are lost");
    free(t->format_line);
    free(t->format_int);
    free(t->format_float);
    t->format_line = t->format_int = t->format_float = NULL;
    for (int i = 0; i < GR_MAXTHERMO; i++) {
        free(t->format_col[i]);
        t->format_col[i] = NULL;
    }
    t->flush = 0;
    t->lost = LOST_ERROR;
    t->multi = 0;
    t->norm = g->dom.units == UNITS_LJ;
    t->norm_set = 0;
    t->modified = 0;
}

/* ---- commands ------------------------------------------------------------------ */

void cmd_thermo(struct gravel *g, int argc, char **argv)
{
    if (argc != 1)
        gr_error(g, "expected: thermo N or thermo v_name");
    if (strncmp(argv[0], "v_", 2) == 0) {
        if (!argv[0][2])
            gr_error(g, "variable reference 'v_' has no name");
        free(g->thermo.every_var);
        g->thermo.every_var = gr_strdup(g, argv[0] + 2);
        g->thermo.every = 0;
        return;
    }
    int n = arg_int(g, argv[0], "the thermo interval");
    if (n < 0)
        gr_error(g, "the thermo interval must not be negative, got %d", n);
    free(g->thermo.every_var);
    g->thermo.every_var = NULL;
    g->thermo.every = n;
}

void cmd_thermo_style(struct gravel *g, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "expected: thermo_style one|multi|custom keyword...");
    const char *style = argv[0];
    if (strcmp(style, "one") == 0 || strcmp(style, "multi") == 0) {
        if (argc != 1)
            gr_error(g, "style '%s' takes no keywords", style);
        reset_modify(g);
        if (style[0] == 'o') {
            set_columns(g, style_one, (int)(sizeof style_one / sizeof *style_one));
        } else {
            set_columns(g, style_multi, (int)(sizeof style_multi / sizeof *style_multi));
            g->thermo.multi = 1;
        }
        return;
    }
    if (strcmp(style, "custom") != 0)
        gr_error(g, "unknown style '%.64s' (one, multi or custom)", style);
    if (argc < 2)
        gr_error(g, "style custom needs at least one keyword");
    if (argc - 1 > GR_MAXTHERMO)
        gr_error(g, "at most %d keywords, got %d", GR_MAXTHERMO, argc - 1);
    for (int i = 1; i < argc; i++)
        check_keyword(g, argv[i]);
    reset_modify(g);
    for (int i = 1; i < argc; i++)
        snprintf(g->thermo.col[i - 1], GR_NAMELEN, "%s", argv[i]);
    g->thermo.ncol = argc - 1;
}

static void set_string(struct gravel *g, char **dst, const char *s)
{
    char *d = gr_strdup(g, s);
    free(*dst);
    *dst = d;
}

/* One pass over the keywords into t; with apply 0 (t a scratch copy whose
 * strings are the live ones) nothing is freed or allocated: the pass only
 * checks, so a bad keyword leaves the settings as they were. */
static void thermo_modify_pass(struct gravel *g, int argc, char **argv,
                               struct thermo_settings *t, int apply)
{
    char buf[96];
    for (int i = 0; i < argc; i++) {
        const char *kw = argv[i];
        if (strcmp(kw, "norm") == 0) {
            arg_need(g, argc, i, 1, kw);
            t->norm = t->norm_user = arg_yesno(g, argv[++i], "norm");
            t->norm_set = 1;
        } else if (strcmp(kw, "flush") == 0) {
            arg_need(g, argc, i, 1, kw);
            t->flush = arg_yesno(g, argv[++i], "flush");
        } else if (strcmp(kw, "lost") == 0) {
            arg_need(g, argc, i, 1, kw);
            const char *v = argv[++i];
            if (strcmp(v, "error") == 0)
                t->lost = LOST_ERROR;
            else if (strcmp(v, "warn") == 0)
                t->lost = LOST_WARN;
            else if (strcmp(v, "ignore") == 0)
                t->lost = LOST_IGNORE;
            else
                gr_error(g, "lost must be error, warn or ignore, got '%.64s'", v);
        } else if (strcmp(kw, "line") == 0) {
            arg_need(g, argc, i, 1, kw);
            const char *v = argv[++i];
            if (strcmp(v, "one") == 0)
                t->multi = 0;
            else if (strcmp(v, "multi") == 0)
                t->multi = 1;
            else
                gr_error(g, "line must be one or multi, got '%.64s'", v);
        } else if (strcmp(kw, "format") == 0) {
            arg_need(g, argc, i, 1, kw);
            const char *what = argv[++i];
            if (strcmp(what, "none") == 0) {
                if (!apply)
                    continue;
                free(t->format_line);
                free(t->format_int);
                free(t->format_float);
                t->format_line = t->format_int = t->format_float = NULL;
                for (int k = 0; k < GR_MAXTHERMO; k++) {
                    free(t->format_col[k]);
                    t->format_col[k] = NULL;
                }
                continue;
            }
            arg_need(g, argc, i, 1, "format");
            const char *f = argv[++i];
            const char *bad;
            if (strcmp(what, "line") == 0) {
                /* words checked against the column kinds at run setup */
                if (strlen(f) > 2000)
                    gr_error(g, "format line is too long");
                if (apply)
                    set_string(g, &t->format_line, f);
            } else if (strcmp(what, "int") == 0) {
                if ((bad = output_format_fix(f, 1, buf)))
                    gr_error(g, "format int '%.64s' %s", f, bad);
                if (apply)
                    set_string(g, &t->format_int, f);
            } else if (strcmp(what, "float") == 0) {
                if ((bad = output_format_fix(f, 0, buf)))
                    gr_error(g, "format float '%.64s' %s", f, bad);
                if (apply)
                    set_string(g, &t->format_float, f);
            } else if (arg_is_number(what)) {
                int n = columns(g);
                int col = arg_int(g, what, "format column");
                if (col < 1 || col > n)
                    gr_error(g, "format column %d is outside 1..%d (the thermo_style columns)",
                             col, n);
                /* the kind of the column is checked at run setup */
                if (!strchr(f, '%'))
                    gr_error(g, "format '%.64s' for column %d has no conversion", f, col);
                if (strlen(f) > 60)
                    gr_error(g, "format '%.64s...' is longer than 60 characters", f);
                if (apply)
                    set_string(g, &t->format_col[col - 1], f);
            } else {
                gr_error(g, "format must be followed by line, int, float, none or a column "
                            "number, got '%.64s'", what);
            }
        } else if (strcmp(kw, "temp") == 0) {
            arg_need(g, argc, i, 1, kw);
            const char *id = argv[++i];
            struct compute *c = compute_get(g, id, "thermo_modify temp");
            if (!c->temp)
                gr_error(g, "thermo_modify temp: compute %s (%s) does not compute a "
                            "temperature", id, c->style->name);
            if (c->igroup != 0)
                gr_warn(g, "temperature for thermo pressure is not for group all");
            snprintf(t->temp_id, sizeof t->temp_id, "%s", id);
        } else if (strcmp(kw, "press") == 0 || strcmp(kw, "lost/bond") == 0 ||
                   strcmp(kw, "warn") == 0) {
            gr_error(g, "keyword '%s' is not supported by gravel", kw);
        } else {
            gr_error(g, "unknown keyword '%.64s' (norm, format, flush, lost, line, temp)", kw);
        }
    }
}

void cmd_thermo_modify(struct gravel *g, int argc, char **argv)
{
    if (argc < 1)
        gr_error(g, "expected keyword/value pairs");
    struct thermo_settings check = g->thermo;
    thermo_modify_pass(g, argc, argv, &check, 0);
    thermo_modify_pass(g, argc, argv, &g->thermo, 1);
    g->thermo.modified = 1;
}

/* ---- run setup ----------------------------------------------------------------- */

static enum vtype column_type(const struct output_state *st, int i)
{
    return st->kind[i] >= 0 ? keywords[st->kind[i]].type : V_FLOAT;
}

void thermo_init(struct gravel *g)
{
    struct thermo_settings *t = &g->thermo;
    struct output_state *st = output_state(g);
    int n = columns(g);
    st->ncol = n;
    for (int i = 0; i < n; i++) {
        const char *s = t->col[i];
        int k = keyword_index(s);
        if (k >= 0) {
            st->kind[i] = k;
        } else if ((k = implicit_compute(g, s)) >= 0) {
            st->kind[i] = k;
        } else if (strncmp(s, "c_", 2) == 0) {
            compute_ref_check(g, s, "thermo_style");
            st->kind[i] = KIND_COMPUTE;
        } else if (strncmp(s, "v_", 2) == 0) {
            if (!var_retrieve(g, s + 2))
                gr_error(g, "thermo_style: variable '%s' is not defined", s + 2);
            st->kind[i] = KIND_VARIABLE;
        } else if (strncmp(s, "f_", 2) == 0) {
            struct fix *f = fix_ref_check(g, s, "thermo_style");
            /* LAMMPS Thermo::init: a fix output current only every global_freq steps */
            if (t->every % f->global_freq)
                gr_error(g, "thermo_style: thermo every %d and fix %s (%s, output every %d "
                            "steps) are not computed at compatible times", t->every, f->id,
                         f->style->name, f->global_freq);
            st->kind[i] = KIND_FIX;
        } else {
            gr_error(g, "thermo_style: unknown keyword '%s'", s);
        }
    }
    /* the temperatures count their degrees of freedom at run setup */
    temp_setup(g, &g->thermo.temp);
    if (t->temp_id[0]) {
        struct compute *c = compute_find(g, t->temp_id);
        if (!c || !c->temp)
            gr_error(g, "thermo_modify temp: compute '%s' does not exist or is not a "
                        "temperature", t->temp_id);
        temp_setup(g, c->temp);
    }
    if (t->every_var && !var_retrieve(g, t->every_var))
        gr_error(g, "thermo: variable '%s' is not defined", t->every_var);

    /* formats, LAMMPS 2021 precedence */
    char line[2048] = "";
    if (t->format_line)
        snprintf(line, sizeof line, "%s", t->format_line);
    char *save = NULL;
    char *word = t->format_line ? strtok_r(line, " \t", &save) : NULL;
    for (int i = 0; i < n; i++) {
        int isint = column_type(st, i) == V_BIGINT;
        const char *f, *src;
        if (t->format_col[i]) {
            f = t->format_col[i];
            src = "format N";
        } else if (isint && t->format_int) {
            f = t->format_int;
            src = "format int";
        } else if (!isint && t->format_float) {
            f = t->format_float;
            src = "format float";
        } else if (t->format_line) {
            if (!word)
                gr_error(g, "thermo_modify: format line has fewer words than the %d columns", n);
            f = word;
            src = "format line";
        } else {
            f = isint ? (t->multi ? FMT_BIGINT_MULTI : FMT_BIGINT_ONE)
                      : (t->multi ? FMT_FLOAT_MULTI : FMT_FLOAT_ONE);
            src = NULL;
        }
        if (src) {
            const char *bad = output_format_fix(f, isint, st->fmt[i]);
            if (bad)
                gr_error(g, "thermo_modify: %s '%.64s' for column %d (%s, %s) %s", src, f,
                         i + 1, t->col[i], isint ? "an integer" : "a float", bad);
        } else {
            snprintf(st->fmt[i], sizeof st->fmt[i], "%s", f);
        }
        if (word)
            word = strtok_r(NULL, " \t", &save);
    }
}

/* ---- values -------------------------------------------------------------------- */

/* Kinetic energy as LAMMPS' thermo `ke`: T x dof/2 x kB of the thermo
 * temperature (translational with thermo_temp, plus rotational with a
 * temp/sphere from thermo_modify temp); 0 when it has no dof. */
static double kinetic_energy(struct gravel *g)
{
    struct temp_state *t = temp_thermo(g);
    double temp = temp_scalar(g, t);
    double ke = temp * 0.5 * temp_dof(g, t) * temp_boltz(g);
    for (int i = 0; i < g->styles.nfix; i++)
        if (g->styles.fix[i]->style->ke_adjust)
            ke += g->styles.fix[i]->style->ke_adjust(g, g->styles.fix[i]);
    return ke;
}

/* LAMMPS's fmax (the largest force component in magnitude) or fnorm (the
 * length of the whole force vector), in tag order (one process: several
 * ranks refuse both, src/parallel/par.c) */
static double force_norm(struct gravel *g, int max)
{
    const struct atoms *a = &g->atoms;
    const int *ord = atoms_tag_order(g);
    struct par_sum s = {0};
    double m = 0.0;
    for (int k = 0; k < a->n; k++) {
        const double *f = a->f + 3 * ord[k];
        for (int d = 0; d < 3; d++)
            m = fmax(m, fabs(f[d]));
        par_sum_add(g, &s, a->tag[ord[k]], f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    }
    if (max) {
        par_sum_total(g, &s); /* releases it */
        return m;
    }
    return sqrt(par_sum_total(g, &s));
}

/* the mass of every atom, summed in tag order over every rank's atoms */
static double total_mass(struct gravel *g)
{
    const struct atoms *a = &g->atoms;
    const int *ord = atoms_tag_order(g);
    struct par_sum m = {0};
    for (int k = 0; k < a->n; k++)
        par_sum_add(g, &m, a->tag[ord[k]], a->rmass[ord[k]]);
    return par_sum_total(g, &m);
}

static double volume(const struct gravel *g)
{
    const struct domain *d = &g->dom;
    double v = (d->hi[0] - d->lo[0]) * (d->hi[1] - d->lo[1]);
    if (d->dimension == 3)
        v *= d->hi[2] - d->lo[2];
    return v;
}

/* thermo_modify norm: the user's value wins over the units default whatever
 * the order of `units` and `thermo_modify` (LAMMPS resolves it at init). */
static int norm_flag(struct gravel *g)
{
    g->thermo.norm = g->thermo.norm_set ? g->thermo.norm_user : g->dom.units == UNITS_LJ;
    return g->thermo.norm;
}

static double clock_now(struct gravel *g)
{
    struct output_state *st = output_state(g);
    return st->firstflag ? 0.0 : wall_clock() - st->wall0;
}

/* The keywords a gathered evaluation cannot compute (the device's virial and
 * energies of each rank's contacts): their slot in output_state.pre, or -1. */
static const int pre_kw[PRE_KW] = {KW_PE,  KW_ETOTAL, KW_EPAIR, KW_PRESS, KW_PXX,
                                    KW_PYY, KW_PZZ,    KW_PXY,   KW_PXZ,   KW_PYZ};

static int pre_slot(int k)
{
    for (int q = 0; q < PRE_KW; q++)
        if (pre_kw[q] == k)
            return q;
    return -1;
}

/* Value of keyword k. Integers come back in *ival with *isint set. */
static double keyword_value(struct gravel *g, int k, bigint *ival, int *isint)
{
    struct output_state *st = output_state(g);
    /* every rank's atoms (collective: each rank evaluates the same keywords) */
    long long nall = par_natoms(g);
    double natoms = (double)nall;
    int norm = norm_flag(g) && nall > 0;
    *isint = keywords[k].type == V_BIGINT;
    if (par_gathered(g) && pre_slot(k) >= 0) { /* from before the gather (pre_take) */
        if (st->pre_step == g->step)
            return st->pre[pre_slot(k)];
        gr_error(g, "thermo keyword %s read by a compute or variable on every rank's atoms: "
                    "not built yet on %d MPI ranks (doc/parallel.md)", keywords[k].header,
                 comm_size());
    }
    switch ((enum kw_id)k) {
    case KW_STEP: *ival = g->step; return (double)g->step;
    case KW_ELAPSED: *ival = g->step - g->firststep; return (double)*ival;
    /* LAMMPS: since `run ... start` (else the run's first step) */
    case KW_ELAPLONG: *ival = g->step - g->beginstep; return (double)*ival;
    case KW_ATOMS: *ival = nall; return natoms;
    case KW_DT: return g->dt;
    case KW_TIME: return g->time;
    case KW_CPU: return clock_now(g);
    case KW_CPUREMAIN: {
        /* LAMMPS: wall time left, extrapolated from the run so far */
        double cpu = clock_now(g);
        bigint done = g->step - g->firststep, left = g->laststep - g->step;
        return done > 0 && left > 0 ? cpu * (double)left / (double)done : 0.0;
    }
    case KW_TPCPU: {
        double cpu = clock_now(g), v = 0.0;
        if (!st->firstflag) {
            double dc = cpu - st->last_tp_cpu, dtime = g->time - st->last_tp_time;
            v = dtime > 0 && dc > 0 ? dtime / dc : 0.0;
        }
        st->last_tp_cpu = cpu;
        st->last_tp_time = g->time;
        return v;
    }
    case KW_SPCPU: {
        double cpu = clock_now(g), v = 0.0;
        if (!st->firstflag) {
            double dc = cpu - st->last_sp_cpu;
            v = dc > 0 ? (double)(g->step - st->last_sp_step) / dc : 0.0;
        }
        st->last_sp_cpu = cpu;
        st->last_sp_step = g->step;
        return v;
    }
    case KW_KE: {
        double ke = kinetic_energy(g);
        return norm ? ke / natoms : ke;
    }
    case KW_ETOTAL: {
        /* pe: a potential's pair energy (granular contacts and walls have none)
         * and the fixes with fix_modify energy yes (gravity), as LAMMPS */
        double et = kinetic_energy(g) + pair_energy(g) + fix_energy_sum(g);
        return norm ? et / natoms : et;
    }
    case KW_PE: {
        double pe = pair_energy(g) + fix_energy_sum(g);
        return norm ? pe / natoms : pe;
    }
    case KW_ECOUPLE: /* the thermostats' and barostats' reservoir energy (ecouple fixes);
                      * LAMMPS does not divide it by the atoms under norm yes */
        return fix_ecouple_sum(g);
    case KW_ECONSERVE: { /* LAMMPS: pe + ke + ecouple, each as its keyword gives it */
        bigint iv;
        int is;
        double e = keyword_value(g, KW_PE, &iv, &is) + keyword_value(g, KW_KE, &iv, &is);
        *isint = 0;
        return e + keyword_value(g, KW_ECOUPLE, &iv, &is);
    }
    case KW_EPAIR: {
        double pe = pair_energy(g);
        return norm ? pe / natoms : pe;
    }
    case KW_EMOL: return 0.0;
    case KW_EVDWL: { /* the pair style's energy: epair without fixes, as LAMMPS */
        double pe = pair_energy(g);
        return norm ? pe / natoms : pe;
    }
    /* no charges, long-range solvers, tail corrections or bonds in granular scenes */
    case KW_ECOUL:
    case KW_ELONG:
    case KW_ETAIL:
    case KW_EBOND:
    case KW_EANGLE:
    case KW_EDIHED:
    case KW_EIMP: return 0.0;
    case KW_ENTHALPY: { /* LAMMPS: etotal + press vol / nktv2p, vol per atom under norm */
        double et = kinetic_energy(g) + pair_energy(g) + fix_energy_sum(g);
        double v = volume(g);
        if (norm) {
            et /= natoms;
            v /= natoms;
        }
        return et + pressure_scalar(g, temp_thermo(g)) * v;
    }
    case KW_FMAX:
    case KW_FNORM: return force_norm(g, k == KW_FMAX);
    case KW_NBUILD: *ival = g->eng ? g->eng->st.nbuilds : 0; return (double)*ival;
    case KW_NDANGER: *ival = g->eng ? g->eng->st.ndanger : 0; return (double)*ival;
    case KW_XLAT:
    case KW_YLAT:
    case KW_ZLAT: return g->dom.lat.a[k - KW_XLAT];
    case KW_TEMP: return temp_scalar(g, temp_thermo(g)); /* intensive */
    case KW_THERMO_TEMP: return temp_scalar(g, &g->thermo.temp);
    case KW_THERMO_TEMP_V:
    case KW_THERMO_TEMP_V2:
    case KW_THERMO_TEMP_V3:
    case KW_THERMO_TEMP_V4:
    case KW_THERMO_TEMP_V5:
    case KW_THERMO_TEMP_V6: { /* as it is: thermo_line_text normalizes, a variable does not */
        double tv[6];
        temp_vector(g, &g->thermo.temp, tv);
        return tv[k - KW_THERMO_TEMP_V];
    }
    case KW_PRESS: return pressure_scalar(g, temp_thermo(g)); /* intensive */
    case KW_PXX:
    case KW_PYY:
    case KW_PZZ:
    case KW_PXY:
    case KW_PXZ:
    case KW_PYZ: { /* intensive */
        double p[6];
        pressure_tensor(g, temp_thermo(g), 1, 1, p);
        return p[k - KW_PXX];
    }
    case KW_CELLA:
    case KW_CELLB:
    case KW_CELLC:
    case KW_CELLALPHA:
    case KW_CELLBETA:
    case KW_CELLGAMMA: { /* LAMMPS's cell lengths and angles (degrees) */
        const struct domain *d = &g->dom;
        double lx = d->hi[0] - d->lo[0], ly = d->hi[1] - d->lo[1], lz = d->hi[2] - d->lo[2];
        double b = sqrt(ly * ly + d->xy * d->xy);
        double c = sqrt(lz * lz + d->xz * d->xz + d->yz * d->yz);
        double deg = 180.0 / M_PI;
        switch (k) {
        case KW_CELLA: return lx;
        case KW_CELLB: return b;
        case KW_CELLC: return c;
        case KW_CELLALPHA: return acos((d->xy * d->xz + ly * d->yz) / (b * c)) * deg;
        case KW_CELLBETA: return acos(d->xz / c) * deg;
        default: return acos(d->xy / b) * deg;
        }
    }
    case KW_XY: return g->dom.xy;
    case KW_XZ: return g->dom.xz;
    case KW_YZ: return g->dom.yz;
    case KW_VOL: return volume(g);
    /* LAMMPS: the mass of every atom (group all) over the volume (area in 2d);
     * mv2d is 1 in lj, si and cgs */
    case KW_DENSITY: return total_mass(g) / volume(g);
    case KW_LX: return g->dom.hi[0] - g->dom.lo[0];
    case KW_LY: return g->dom.hi[1] - g->dom.lo[1];
    case KW_LZ: return g->dom.hi[2] - g->dom.lo[2];
    case KW_XLO: return g->dom.lo[0];
    case KW_XHI: return g->dom.hi[0];
    case KW_YLO: return g->dom.lo[1];
    case KW_YHI: return g->dom.hi[1];
    case KW_ZLO: return g->dom.lo[2];
    case KW_ZHI: return g->dom.hi[2];
    case KW_COUNT: break;
    }
    return 0.0;
}

int thermo_keyword_value(struct gravel *g, const char *name, double *out)
{
    int k = keyword_index(name);
    if (k >= 0) {
        bigint iv = 0;
        int isint;
        if (needs_host(k))
            run_sync_host(g);
        double v = keyword_value(g, k, &iv, &isint);
        *out = isint ? (double)iv : v;
        return 1;
    }
    if ((k = implicit_compute(g, name)) >= 0) {
        bigint iv;
        int isint;
        if ((k >= KW_THERMO_TEMP && k <= KW_THERMO_TEMP_V6) || needs_host(k))
            run_sync_host(g);
        *out = keyword_value(g, k, &iv, &isint);
        return 1;
    }
    if (strncmp(name, "c_", 2) == 0) {
        char id[GR_NAMELEN];
        int index, col;
        if (!compute_parse_ref2(name, id, &index, &col) || !compute_find(g, id))
            return 0;
        run_sync_host(g);
        /* LAMMPS: variables read a compute's value as it is, never normalized */
        *out = compute_ref_value(g, name, 0, "reference");
        return 1;
    }
    if (strncmp(name, "f_", 2) == 0) {
        char id[GR_NAMELEN];
        int index, col;
        if (!fix_parse_ref(name, id, &index, &col) || !fix_find(g, id))
            return 0;
        struct fix *f = fix_ref_check(g, name, "reference");
        if ((par_on(g) || par_gathered(g)) && !par_fix_value_global(f)) {
            char why[160];
            snprintf(why, sizeof why, "a variable reading fix %.40s (%.40s)", f->id,
                     f->style->name);
            par_refuse(g, why);
        }
        if (index == 0)
            run_sync_host(g);
        *out = fix_output(g, f, index, col, 0, "reference");
        return 1;
    }
    if (strncmp(name, "v_", 2) == 0 && var_retrieve(g, name + 2)) {
        *out = var_compute_equal(g, name + 2);
        return 1;
    }
    return 0;
}

/* ---- text ---------------------------------------------------------------------- */

static const char *column_name(struct gravel *g, int i)
{
    int k = output_state(g)->kind[i];
    const char *col = g->thermo.col[i];
    return k >= 0 && strncmp(col, "c_", 2) != 0 ? keywords[k].header : col;
}

const char *thermo_header_text(struct gravel *g)
{
    struct output_state *st = output_state(g);
    text_clear(g);
    if (!g->thermo.multi) {
        for (int i = 0; i < st->ncol; i++)
            text_add(g, "%s ", column_name(g, i));
        text_add(g, "\n");
    }
    return st->text ? st->text : "";
}

/* Several ranks, before variables are evaluated on the gathered atoms: the
 * step's pre_kw values, as keyword_value gives them on this rank's share. */
static void pre_take(struct gravel *g)
{
    struct output_state *st = output_state(g);
    for (int q = 0; q < PRE_KW; q++) {
        bigint iv = 0;
        int isint;
        st->pre[q] = keyword_value(g, pre_kw[q], &iv, &isint);
    }
    st->pre_step = g->step;
}

void thermo_pre_take(struct gravel *g)
{
    if (par_on(g))
        pre_take(g);
}

void thermo_pre_clear(struct gravel *g) { output_state(g)->pre_step = -1; }

/* c_ID...: a compute that evaluates on every rank's atoms (compute.h) */
static int gathers(struct gravel *g, const char *col)
{
    char id[GR_NAMELEN];
    size_t len = strcspn(col + 2, "[");
    if (len >= sizeof id)
        return 0;
    memcpy(id, col + 2, len);
    id[len] = 0;
    const struct compute *c = compute_find(g, id);
    return c && c->style->ranks == COMPUTE_RANKS_GATHER;
}

const char *thermo_line_text(struct gravel *g)
{
    struct output_state *st = output_state(g);
    struct thermo_settings *t = &g->thermo;
    double val[GR_MAXTHERMO];
    bigint ival[GR_MAXTHERMO];
    /* host arrays current once per line (computes and ke read them) */
    for (int i = 0; i < st->ncol; i++)
        if ((st->kind[i] >= 0 && needs_host(st->kind[i])) ||
            (st->kind[i] >= KW_THERMO_TEMP && st->kind[i] <= KW_THERMO_TEMP_V6) ||
            st->kind[i] == KIND_COMPUTE || st->kind[i] == KIND_FIX) {
            run_sync_host(g);
            break;
        }
    /* evaluate everything first: computes and variables may raise errors;
     * several ranks: the computes that need every atom after the rest, on
     * every rank's atoms gathered (one gather per line) */
    /* thermo_modify norm divides by every rank's atoms (collective here) */
    long long norm = norm_flag(g) ? par_natoms(g) : 0;
    int gather = 0, late[GR_MAXTHERMO], vars = 0;
    for (int i = 0; i < st->ncol; i++) { /* variables too: their keywords, group
                                          * functions and computes see every atom */
        late[i] = par_on(g) && ((st->kind[i] == KIND_COMPUTE && gathers(g, t->col[i])) ||
                                st->kind[i] == KIND_VARIABLE);
        vars |= late[i] && st->kind[i] == KIND_VARIABLE;
    }
    if (vars)
        pre_take(g);
    for (int pass = 0; pass < 2; pass++) {
        for (int i = 0; i < st->ncol; i++) {
            int k = st->kind[i], isint = 0;
            if (late[i] != pass)
                continue;
            if (late[i] && !gather) {
                par_gather_begin(g);
                gather = 1;
            }
            ival[i] = 0;
            if (k >= 0) {
                val[i] = keyword_value(g, k, &ival[i], &isint);
                if (k >= KW_THERMO_TEMP_V && k <= KW_THERMO_TEMP_V6 && norm > 0)
                    val[i] /= (double)norm; /* an extensive compute vector, as LAMMPS */
            } else if (k == KIND_COMPUTE) {
                val[i] = compute_ref_value(g, t->col[i], norm, "thermo_style");
            } else if (k == KIND_FIX) {
                val[i] = fix_ref_value(g, t->col[i]);
            } else {
                val[i] = var_compute_equal(g, t->col[i] + 2);
            }
        }
    }
    if (gather)
        par_gather_end(g);
    st->pre_step = -1; /* only this line's gathered pass reads them */
    text_clear(g);
    if (t->multi)
        text_add(g, "---------------- Step %8lld ----- CPU = %11.4f (sec) ----------------",
                 (long long)g->step, clock_now(g));
    for (int i = 0; i < st->ncol; i++) {
        if (t->multi) {
            if (i % 3 == 0)
                text_add(g, "\n");
            text_add(g, "%-8s = ", column_name(g, i));
        }
        if (column_type(st, i) == V_BIGINT)
            text_add(g, st->fmt[i], (long long)ival[i]);
        else
            text_add(g, st->fmt[i], val[i]);
        text_add(g, " ");
    }
    text_add(g, "\n");
    return st->text;
}
