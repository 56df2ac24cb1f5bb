/* input.c - the script interpreter, following LAMMPS' parsing rules:
 *   1. a line whose last printable character is '&' continues on the next
 *      line (the '&' and the line break are removed); an odd number of """
 *      keeps reading lines, line breaks kept, until the closing """;
 *   2. '#' outside quotes starts a comment;
 *   3. $x, ${name} and $(expr[:fmt]) outside quotes are replaced by the
 *      variable's text or the expression's value (%.20g unless a format is
 *      given); substituted text is not scanned again;
 *   4. words are separated by white space; a word that starts with ', " or """
 *      runs to the matching quote, which must be followed by white space or
 *      the end; quotes are removed;
 *   5. the first word is the command, looked up in the command table; arity
 *      and phase are checked here, before the handler runs.
 * Physical lines end in LF, CR LF or a lone CR; a UTF-8 byte-order mark
 * before a source's first line is skipped. Commands may be of any length:
 * every buffer grows (one physical line up to INP_MAX_PHYSICAL); a read error
 * is an error, never an end of input. Each command runs under its
 * own setjmp boundary; errors are reported with the file and first line of
 * the command, and stop the reader. */
#include "input.h"

#include <ctype.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "command.h"
#include "error.h"
#include "expr.h"
#include "fileio.h"
#include "log.h"
#include "variable.h"

/* A growable byte buffer, always NUL-terminated once used. */
struct dbuf {
    char *p;
    size_t len, cap;
};

struct source {
    FILE *fp;               /* file or stream, or NULL for text */
    int close_fp;           /* we opened it */
    const char *buf;        /* in-memory text (inp_string) */
    size_t len, pos;
    char *name;
    int lineno;             /* lines read so far */
    char *gl;               /* getline buffer */
    size_t glcap;
};

struct inp {
    struct source *src;
    int nsrc, capsrc;
    char *label;            /* label being searched for, or NULL */
    int label_src;          /* index of the source being searched */
    char *label_file;       /* where the jump was, for "label not found" */
    int label_line;
    int jump_skip;          /* an exhausted `next` skips the next jump */
    int quit, quit_status;
    struct dbuf tmp;        /* names and expressions during substitution */
    struct dbuf expr;       /* the $(...) expression being evaluated */
    struct dbuf scratch;    /* inp_substitute's result */
    struct dbuf subin;      /* inp_substitute's input copy */
    int nest;               /* commands run by commands (if, run every) now active */
    int (*allow)(int argc, char **argv);
    long max_commands, ncommands;
    size_t max_line;
};

/* Per-invocation buffers of the read-execute loop. Nested calls (a command
 * that runs script text) get their own, so argv stays valid for the caller. */
struct frame {
    struct dbuf raw;        /* the command as read (continuations joined) */
    struct dbuf line;       /* comment stripped */
    struct dbuf work;       /* substituted, then split in place */
    char **argv;
    int argc, argvcap;
    char first[GR_NAMELEN]; /* first word before substitution, for messages */
};

struct inp *inp_create(void)
{
    return calloc(1, sizeof(struct inp));
}

static void pop_source(struct inp *in)
{
    struct source *s = &in->src[--in->nsrc];
    if (s->close_fp && s->fp)
        fclose(s->fp);
    free(s->name);
    free(s->gl);
    memset(s, 0, sizeof *s);
}

static void clear_label(struct inp *in)
{
    free(in->label);
    free(in->label_file);
    in->label = in->label_file = NULL;
}

void inp_destroy(struct inp *in)
{
    if (!in)
        return;
    while (in->nsrc > 0)
        pop_source(in);
    free(in->src);
    clear_label(in);
    free(in->tmp.p);
    free(in->scratch.p);
    free(in->expr.p);
    free(in->subin.p);
    free(in);
}

void inp_set_limits(struct gravel *g, int (*allow)(int argc, char **argv), long max_commands,
                    size_t max_line)
{
    g->inp->allow = allow;
    g->inp->max_commands = max_commands;
    g->inp->max_line = max_line;
}

/* ---- buffers ----------------------------------------------------------------- */

static void db_reserve(struct gravel *g, struct dbuf *b, size_t n)
{
    if (n + 1 <= b->cap)
        return;
    size_t cap = b->cap ? b->cap : 256;
    while (cap < n + 1)
        cap *= 2;
    b->p = gr_realloc(g, b->p, cap);
    b->cap = cap;
}

static void db_clear(struct gravel *g, struct dbuf *b)
{
    db_reserve(g, b, 0);
    b->len = 0;
    b->p[0] = '\0';
}

static void db_add(struct gravel *g, struct dbuf *b, const char *s, size_t n)
{
    size_t max = g->inp->max_line;
    if (max && b->len + n > max)
        gr_error(g, "line longer than the limit of %zu bytes", max);
    db_reserve(g, b, b->len + n);
    memcpy(b->p + b->len, s, n);
    b->len += n;
    b->p[b->len] = '\0';
}

static void frame_free(struct frame *fr)
{
    free(fr->raw.p);
    free(fr->line.p);
    free(fr->work.p);
    free(fr->argv);
    free(fr);
}

/* ---- sources ------------------------------------------------------------------ */

static struct source *push_source(struct gravel *g, const char *name)
{
    struct inp *in = g->inp;
    if (in->nsrc >= 1000)
        gr_error(g, "include files nested more than 1000 deep (does a file include itself?)");
    char *dup = gr_strdup(g, name);
    if (in->nsrc == in->capsrc) {
        int cap = in->capsrc ? 2 * in->capsrc : 8;
        struct source *ns = realloc(in->src, (size_t)cap * sizeof *ns);
        if (!ns) {
            free(dup);
            gr_error(g, "out of memory");
        }
        in->src = ns;
        in->capsrc = cap;
    }
    struct source *s = &in->src[in->nsrc++];
    memset(s, 0, sizeof *s);
    s->name = dup;
    return s;
}

/* Longest physical line of a script unless inp_set_limits gives one: a
 * longer line is an error (a binary file or an endless device), not a slow
 * march to out-of-memory. */
#define INP_MAX_PHYSICAL ((size_t)64 << 20)

/* Append one physical line (without its line break: "\n", "\r\n" or a lone
 * "\r") to b; a UTF-8 byte-order mark before the first line is dropped.
 * Returns 0 at end of input with nothing read; a read error (or a line that
 * cannot be held) is an error, never an end of input. NUL bytes become
 * spaces. */
static int read_physical(struct gravel *g, struct source *s, struct dbuf *b)
{
    const char *p;
    size_t n;
    if (s->fp) {
        size_t max = g->inp->max_line ? g->inp->max_line : INP_MAX_PHYSICAL;
        ssize_t r = fio_getline(s->fp, &s->gl, &s->glcap, max);
        if (r == FIO_ERR) {
            int e = errno ? errno : EIO;
            g->err.line = s->lineno + 1;
            if (e == EFBIG)
                gr_error(g, "line %d of %s is longer than %zu bytes (is it a text file?)",
                         s->lineno + 1, s->name, max);
            gr_error(g, "read error in %s after line %d: %s", s->name, s->lineno, strerror(e));
        }
        if (r == FIO_EOF)
            return 0;
        p = s->gl;
        n = (size_t)r;
    } else {
        if (s->pos >= s->len)
            return 0;
        p = s->buf + s->pos;
        n = 0;
        while (s->pos + n < s->len && p[n] != '\n' && p[n] != '\r')
            n++;
        size_t brk = 0;
        if (s->pos + n < s->len)
            brk = (p[n] == '\r' && s->pos + n + 1 < s->len && p[n + 1] == '\n') ? 2 : 1;
        s->pos += n + brk;
    }
    if (s->lineno == 0) {
        size_t bom = fio_bom(p, n);
        p += bom;
        n -= bom;
    }
    s->lineno++;
    size_t start = b->len;
    db_add(g, b, p, n);
    for (size_t i = start; i < b->len; i++)
        if (b->p[i] == '\0')
            b->p[i] = ' ';
    return 1;
}

static int count_triple(const char *s)
{
    int n = 0;
    for (const char *p = strstr(s, "\"\"\""); p; p = strstr(p + 3, "\"\"\""))
        n++;
    return n;
}

/* Read one command (physical lines joined per rules 1) into fr->raw; sets
 * g->err.file/line to its first line. Returns 0 at end of the source. */
static int read_command(struct gravel *g, struct source *s, struct frame *fr)
{
    db_clear(g, &fr->raw);
    int first = s->lineno + 1;
    g->err.file = s->name;
    g->err.line = first;
    if (!read_physical(g, s, &fr->raw))
        return 0;
    for (;;) {
        if (count_triple(fr->raw.p) % 2) {
            db_add(g, &fr->raw, "\n", 1);
            if (!read_physical(g, s, &fr->raw))
                gr_error(g, "unterminated triple quote \"\"\" (the file ends before it closes)");
            continue;
        }
        size_t m = fr->raw.len;
        while (m > 0 && isspace((unsigned char)fr->raw.p[m - 1]))
            m--;
        if (m == 0 || fr->raw.p[m - 1] != '&')
            return 1;
        fr->raw.len = m - 1;
        fr->raw.p[m - 1] = '\0';
        if (!read_physical(g, s, &fr->raw))
            return 1; /* '&' on the last line: run what we have */
    }
}

/* ---- rules 2-4 ----------------------------------------------------------------- */

/* Quote tracking shared by comment stripping and substitution: returns the
 * new state (0 none, 1 single, 2 double, 3 triple) and advances *pp past a
 * triple quote's extra characters. */
static int quote_step(const char **pp, int q)
{
    const char *p = *pp;
    if (q == 0) {
        if (strncmp(p, "\"\"\"", 3) == 0) {
            *pp += 2;
            return 3;
        }
        return *p == '"' ? 2 : *p == '\'' ? 1 : 0;
    }
    if (q == 3 && strncmp(p, "\"\"\"", 3) == 0) {
        *pp += 2;
        return 0;
    }
    if ((q == 2 && *p == '"') || (q == 1 && *p == '\''))
        return 0;
    return q;
}

static void strip_comment(struct gravel *g, const struct dbuf *raw, struct dbuf *out)
{
    db_clear(g, out);
    const char *p = raw->p;
    int q = 0;
    for (; *p; p++) {
        if (*p == '#' && !q)
            break;
        q = quote_step(&p, q);
    }
    db_add(g, out, raw->p, (size_t)(p - raw->p));
}

static void append_number(struct gravel *g, struct dbuf *out, double x, const char *fmt)
{
    char small[64];
    int n;
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wformat-nonliteral"
    n = snprintf(small, sizeof small, fmt, x);
    if (n < 0)
        gr_error(g, "cannot format %g with '%s'", x, fmt);
    if ((size_t)n < sizeof small) {
        db_add(g, out, small, (size_t)n);
    } else {
        struct dbuf *t = &g->inp->tmp;
        db_reserve(g, t, (size_t)n);
        snprintf(t->p, (size_t)n + 1, fmt, x);
        db_add(g, out, t->p, (size_t)n);
    }
#pragma GCC diagnostic pop
}

/* Replace $x, ${name}, $(expr[:fmt]) in `in` into out. With quotes != 0, text
 * between quotes is copied unchanged (rule 6). */
static void substitute(struct gravel *g, const char *in, struct dbuf *out, int quotes)
{
    struct dbuf *t = &g->inp->tmp;
    db_clear(g, out);
    int q = 0;
    const char *p = in;
    while (*p) {
        if (*p != '$' || q) {
            const char *s = p;
            if (quotes)
                q = quote_step(&p, q);
            p++;
            db_add(g, out, s, (size_t)(p - s));
            continue;
        }
        const char *v = p + 1;
        if (*v == '{') {
            const char *close = strchr(v + 1, '}');
            if (!close)
                gr_error(g, "'${' without a closing '}'");
            db_clear(g, t);
            db_add(g, t, v + 1, (size_t)(close - v - 1));
            if (t->len == 0)
                gr_error(g, "empty variable name in '${}'");
            const char *val = var_retrieve(g, t->p);
            if (!val)
                gr_error(g, "variable '%s' is not defined (in ${%s})", t->p, t->p);
            db_add(g, out, val, strlen(val));
            p = close + 1;
        } else if (*v == '(') {
            int depth = 0;
            const char *e = v;
            for (; *e; e++) {
                if (*e == '(')
                    depth++;
                else if (*e == ')' && --depth == 0)
                    break;
            }
            if (!*e)
                gr_error(g, "'$(' without a matching ')'");
            db_clear(g, t);
            db_add(g, t, v + 1, (size_t)(e - v - 1));
            /* optional ":format" after the expression, at parenthesis depth 0 */
            const char *fmt = "%.20g";
            int d = 0;
            for (char *c = t->p; *c; c++) {
                if (*c == '(')
                    d++;
                else if (*c == ')')
                    d--;
                else if (*c == ':' && d == 0) {
                    *c = '\0';
                    fmt = c + 1;
                    if (!expr_format_ok(fmt))
                        gr_error(g, "invalid format '%.64s' in $(...:format): expected one %%f, "
                                 "%%e or %%g conversion", fmt);
                    break;
                }
            }
            /* evaluate from a private copy: formatting may use tmp */
            struct dbuf *ex = &g->inp->expr;
            db_clear(g, ex);
            db_add(g, ex, t->p, strlen(t->p));
            char fmtcopy[64];
            if (strlen(fmt) >= sizeof fmtcopy)
                gr_error(g, "format in $(...:format) longer than 63 characters");
            strcpy(fmtcopy, fmt);
            double x = expr_eval(g, ex->p);
            append_number(g, out, x, fmtcopy);
            p = e + 1;
        } else if (*v == '\0') {
            gr_error(g, "'$' at the end of the line (use $x, ${name} or $(expression))");
        } else if (isspace((unsigned char)*v)) {
            gr_error(g, "'$' followed by white space (use $x, ${name} or $(expression))");
        } else {
            char name[2] = {*v, '\0'};
            const char *val = var_retrieve(g, name);
            if (!val)
                gr_error(g, "variable '%s' is not defined (in $%s; use ${name} for longer names)",
                         name, name);
            db_add(g, out, val, strlen(val));
            p = v + 1;
        }
    }
}

static const char *substitute_copy(struct gravel *g, const char *text, int quotes)
{
    struct dbuf *s = &g->inp->scratch;
    /* text may point into scratch from a previous call: substitute a copy */
    struct dbuf *c = &g->inp->subin;
    db_clear(g, c);
    db_add(g, c, text, strlen(text));
    substitute(g, c->p, s, quotes);
    return s->p;
}

const char *inp_substitute(struct gravel *g, const char *text)
{
    return substitute_copy(g, text, 0);
}

const char *inp_substitute_quoted(struct gravel *g, const char *text)
{
    return substitute_copy(g, text, 1);
}

static void add_arg(struct gravel *g, struct frame *fr, char *word)
{
    if (fr->argc == fr->argvcap) {
        int cap = fr->argvcap ? 2 * fr->argvcap : 32;
        fr->argv = gr_realloc(g, fr->argv, (size_t)cap * sizeof(char *));
        fr->argvcap = cap;
    }
    fr->argv[fr->argc++] = word;
}

/* Split fr->work in place into fr->argv (rule 4). */
static void tokenize(struct gravel *g, struct frame *fr)
{
    static const char *ws = " \t\n\v\f\r";
    fr->argc = 0;
    char *p = fr->work.p;
    for (;;) {
        p += strspn(p, ws);
        if (!*p)
            break;
        char *start, *stop, *next;
        if (strncmp(p, "\"\"\"", 3) == 0) {
            stop = strstr(p + 3, "\"\"\"");
            if (!stop)
                gr_error(g, "unterminated triple quote \"\"\"");
            start = p + 3;
            next = stop + 3;
        } else if (*p == '"' || *p == '\'') {
            stop = strchr(p + 1, *p);
            if (!stop)
                gr_error(g, "unterminated %s quote (%c) starting at '%.20s'",
                         *p == '"' ? "double" : "single", *p, p);
            start = p + 1;
            next = stop + 1;
        } else {
            start = p;
            stop = p + strcspn(p, ws);
            next = *stop ? stop + 1 : stop;
            *stop = '\0';
            add_arg(g, fr, start);
            p = next;
            continue;
        }
        if (*next && !isspace((unsigned char)*next))
            gr_error(g, "closing quote must be followed by white space, got '%c'", *next);
        *stop = '\0';
        add_arg(g, fr, start);
        p = *next ? next + 1 : next;
    }
    add_arg(g, fr, NULL);
    fr->argc--;
}

/* ---- dispatch ------------------------------------------------------------------- */

static void echo(struct gravel *g, const char *text)
{
    if ((g->echo & ECHO_SCREEN) && g->screen)
        fprintf(g->screen, "%s\n", text);
    if ((g->echo & ECHO_LOG) && g->logfile)
        fprintf(g->logfile, "%s\n", text);
}

/* Copy the first white-space separated word of s into buf (truncated). */
static const char *first_word(const char *s, char *buf, size_t cap, const char **rest)
{
    s += strspn(s, " \t\n\v\f\r");
    size_t n = strcspn(s, " \t\n\v\f\r");
    if (rest)
        *rest = s + n;
    if (n >= cap)
        n = cap - 1;
    memcpy(buf, s, n);
    buf[n] = '\0';
    return buf;
}

static const char *phase_problem(const struct gravel *g, enum phase ph)
{
    if (ph == PH_PRE_BOX && g->dom.box_exists)
        return "must come before the simulation box is created (create_box or read_data)";
    if (ph == PH_POST_BOX && !g->dom.box_exists)
        return "needs a simulation box: use create_box or read_data first";
    return NULL;
}

/* Execute the command in fr->raw. Returns GR_OK or GR_QUIT; errors unwind. */
static int execute(struct gravel *g, struct frame *fr)
{
    struct inp *in = g->inp;
    g->err.cmd = "input";
    g->err.text = fr->raw.p;
    strip_comment(g, &fr->raw, &fr->line);
    if (in->label) {
        /* skipping to a label: only `label NAME` matters, nothing is substituted */
        char w1[GR_NAMELEN], w2[GR_NAMELEN];
        const char *rest;
        first_word(fr->line.p, w1, sizeof w1, &rest);
        first_word(rest, w2, sizeof w2, NULL);
        if (strcmp(w1, "label") == 0 && strcmp(w2, in->label) == 0)
            clear_label(in);
        return GR_OK;
    }
    echo(g, fr->raw.p);
    g->err.cmd = first_word(fr->line.p, fr->first, sizeof fr->first, NULL);
    if (!fr->first[0])
        g->err.cmd = "input";
    substitute(g, fr->line.p, &fr->work, 1);
    if (strcmp(fr->work.p, fr->line.p) != 0)
        echo(g, fr->work.p);
    tokenize(g, fr);
    if (fr->argc == 0)
        return GR_OK;
    const char *name = fr->argv[0];
    g->err.cmd = name;
    const struct command *c = cmd_find(name);
    if (!c)
        gr_error(g, "unknown command '%.64s' (nearest known command: '%s')", name,
                 cmd_nearest(name));
    if (in->allow && !in->allow(fr->argc, fr->argv))
        gr_error(g, "command not allowed here");
    if (in->max_commands && ++in->ncommands > in->max_commands)
        gr_error(g, "more than %ld commands executed; stopping", in->max_commands);
    int nargs = fr->argc - 1;
    if (nargs < c->min_args || (c->max_args >= 0 && nargs > c->max_args)) {
        if (c->min_args == c->max_args)
            gr_error(g, "expects %d argument%s, got %d", c->min_args,
                     c->min_args == 1 ? "" : "s", nargs);
        if (nargs < c->min_args)
            gr_error(g, "expects at least %d argument%s, got %d", c->min_args,
                     c->min_args == 1 ? "" : "s", nargs);
        gr_error(g, "expects at most %d argument%s, got %d", c->max_args,
                 c->max_args == 1 ? "" : "s", nargs);
    }
    const char *ph = phase_problem(g, c->phase);
    if (ph)
        gr_error(g, "%s", ph);
    c->fn(g, nargs, fr->argv + 1);
    /* a failed log write (disk full) stops the script at this command */
    if (g->logfile)
        fflush(g->logfile);
    gr_log_check(g);
    return in->quit ? GR_QUIT : GR_OK;
}

/* Run commands until the source stack shrinks back to `base` entries. */
static int run_sources(struct gravel *g, int base)
{
    struct inp *in = g->inp;
    struct frame *fr = calloc(1, sizeof *fr);
    struct errctx saved = g->err;
    volatile int rc = GR_OK;
    if (!fr) {
        while (in->nsrc > base)
            pop_source(in);
        return GR_ERR;
    }
    while (in->nsrc > base) {
        jmp_buf jb;
        g->err.jmp = &jb;
        if (setjmp(jb)) {
            gr_report_error(g);
            rc = GR_ERR;
            break;
        }
        struct source *s = &in->src[in->nsrc - 1];
        g->err.cmd = "input"; /* errors before a command name is known */
        g->err.text = NULL;
        if (!read_command(g, s, fr)) {
            if (in->label && in->label_src == in->nsrc - 1) {
                g->err.cmd = "jump";
                g->err.file = in->label_file;
                g->err.line = in->label_line;
                gr_error(g, "label '%s' not found in %s", in->label, s->name);
            }
            pop_source(in);
            continue;
        }
        if (execute(g, fr) == GR_QUIT) {
            rc = GR_QUIT;
            break;
        }
    }
    while (in->nsrc > base)
        pop_source(in);
    if (rc == GR_ERR || base == 0) {
        clear_label(in);
        in->jump_skip = 0;
    }
    if (base == 0)
        in->quit = 0;
    frame_free(fr);
    g->err.cmd = saved.cmd;
    g->err.file = saved.file;
    g->err.line = saved.line;
    g->err.text = saved.text;
    g->err.jmp = saved.jmp;
    return rc;
}

int inp_stream(struct gravel *g, FILE *fp, const char *name)
{
    int base = g->inp->nsrc;
    struct source *s = push_source(g, name);
    s->fp = fp;
    return run_sources(g, base);
}

/* Open a script: `include` and `jump FILE` need a regular file (a directory,
 * FIFO or device is an error at the command's own line, before anything is
 * read); `-in` (streams 1) also takes a pipe, FIFO or terminal. With raise 0
 * the error is reported and NULL returned. */
static FILE *open_script(struct gravel *g, const char *path, int streams, int raise)
{
    const char *why;
    FILE *fp = fio_open_read(path, streams, &why);
    if (!fp) {
        if (raise)
            gr_error(g, "cannot open input script '%s': %s", path, why);
        snprintf(g->err.msg, sizeof g->err.msg, "cannot open input script '%s': %s", path, why);
        const char *text = g->err.text;
        g->err.text = NULL;
        gr_report_error(g);
        g->err.text = text;
    }
    return fp;
}

int inp_file(struct gravel *g, const char *path)
{
    FILE *fp = open_script(g, path, 1, 0);
    if (!fp)
        return GR_ERR;
    int base = g->inp->nsrc;
    struct source *s = push_source(g, path);
    s->fp = fp;
    s->close_fp = 1;
    return run_sources(g, base);
}

int inp_string(struct gravel *g, const char *text, const char *name)
{
    int base = g->inp->nsrc;
    struct source *s = push_source(g, name);
    s->buf = text;
    s->len = strlen(text);
    return run_sources(g, base);
}

/* ---- flow support ------------------------------------------------------------- */

/* How deep commands that run commands (`if`, `run ... every`) may nest: a
 * variable that expands to a command running itself (`variable c string
 * "if 1 then ${c}"`) stops here instead of overflowing the stack. Each level
 * is a few C frames; 100 is far beyond any script's need. */
#define INP_MAX_NEST 100

int inp_run_commands(struct gravel *g, int n, char **cmds)
{
    struct inp *in = g->inp;
    if (in->nest >= INP_MAX_NEST)
        gr_error(g, "commands run by if or run every nested more than %d deep (does a "
                    "variable expand to a command that runs itself?)", INP_MAX_NEST);
    char **copy = gr_calloc(g, (size_t)(n > 0 ? n : 1), sizeof *copy);
    jmp_buf *outer = g->err.jmp, jb;
    in->nest++;
    g->err.jmp = &jb;
    if (setjmp(jb)) {
        for (int i = 0; i < n; i++)
            free(copy[i]);
        free(copy);
        in->nest--;
        g->err.jmp = outer;
        if (outer)
            longjmp(*outer, 1);
        gr_report_error(g);
        exit(1);
    }
    for (int i = 0; i < n; i++)
        copy[i] = gr_strdup(g, cmds[i]);
    int rc = GR_OK;
    for (int i = 0; i < n && rc == GR_OK; i++)
        rc = inp_one(g, copy[i]);
    in->nest--;
    g->err.jmp = outer;
    for (int i = 0; i < n; i++)
        free(copy[i]);
    free(copy);
    return rc;
}

int inp_one(struct gravel *g, const char *text)
{
    struct frame *fr = gr_calloc(g, 1, sizeof *fr);
    struct errctx saved = g->err;
    jmp_buf jb;
    g->err.jmp = &jb;
    if (setjmp(jb)) {
        /* the message (naming the inner command) is set; free our frame and
         * let the caller's boundary report it with the enclosing line */
        frame_free(fr);
        g->err.cmd = saved.cmd;
        g->err.text = saved.text;
        g->err.jmp = saved.jmp;
        if (saved.jmp)
            longjmp(*saved.jmp, 1);
        gr_report_error(g);
        exit(1);
    }
    db_add(g, &fr->raw, text, strlen(text));
    int rc = execute(g, fr);
    frame_free(fr);
    g->err.cmd = saved.cmd;
    g->err.text = saved.text;
    g->err.jmp = saved.jmp;
    return rc;
}

void inp_include(struct gravel *g, const char *path)
{
    FILE *fp = open_script(g, path, 0, 1);
    struct source *s;
    /* push_source may raise: do not leak the open file */
    if (g->inp->nsrc >= 1000) {
        fclose(fp);
        gr_error(g, "include files nested more than 1000 deep (does a file include itself?)");
    }
    s = push_source(g, path);
    s->fp = fp;
    s->close_fp = 1;
}

void inp_jump(struct gravel *g, const char *file, const char *label)
{
    struct inp *in = g->inp;
    if (in->jump_skip) {
        in->jump_skip = 0;
        return;
    }
    if (in->nsrc == 0)
        gr_error(g, "jump is only possible while reading a script");
    char *l = label ? strdup(label) : NULL;
    char *f = strdup(g->err.file ? g->err.file : "?");
    if ((label && !l) || !f) {
        free(l);
        free(f);
        gr_error(g, "out of memory");
    }
    struct source *s = &in->src[in->nsrc - 1];
    if (strcmp(file, "SELF") == 0) {
        if (s->fp) {
            if (fseek(s->fp, 0, SEEK_SET) != 0) {
                free(l);
                free(f);
                gr_error(g, "cannot jump SELF in %s: it cannot be rewound (a pipe or "
                         "terminal); use -in FILE", s->name);
            }
            clearerr(s->fp);
        } else {
            s->pos = 0;
        }
        s->lineno = 0;
    } else {
        const char *why = NULL;
        FILE *fp = fio_open_read(file, 0, &why);
        char *name = fp ? strdup(file) : NULL;
        if (!fp || !name) {
            if (fp)
                fclose(fp);
            free(l);
            free(f);
            gr_error(g, "cannot open input script '%s': %s", file, why ? why : "out of memory");
        }
        if (s->close_fp && s->fp)
            fclose(s->fp);
        free(s->name);
        free(s->gl);
        memset(s, 0, sizeof *s);
        s->fp = fp;
        s->close_fp = 1;
        s->name = name;
        g->err.file = f; /* the old name is gone; keep messages valid */
    }
    clear_label(in);
    if (l) {
        in->label = l;
        in->label_file = f;
        in->label_line = g->err.line;
        in->label_src = in->nsrc - 1;
    } else {
        free(f);
        if (g->err.file == f)
            g->err.file = NULL;
    }
}

void inp_skip_next_jump(struct gravel *g)
{
    g->inp->jump_skip = 1;
}

void inp_quit(struct gravel *g, int status)
{
    g->inp->quit = 1;
    g->inp->quit_status = status;
}

int inp_quit_status(const struct gravel *g)
{
    return g->inp->quit_status;
}
