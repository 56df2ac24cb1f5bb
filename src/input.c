/* input.c - PLACEHOLDER interpreter: whitespace split, no substitution.
 * Replaced wholesale by the interpreter owner. */
#include "input.h"

#include <stdlib.h>
#include <string.h>

#include "command.h"
#include "error.h"

struct inp {
    int dummy;
};

struct inp *inp_create(void) { return calloc(1, sizeof(struct inp)); }
void inp_destroy(struct inp *in) { free(in); }

static int run_line(struct gravel *g, char *line, const char *name, int lineno)
{
    char *argv[256];
    int argc = 0;
    char *hash = strchr(line, '#');
    if (hash)
        *hash = '\0';
    for (char *t = strtok(line, " \t\r\n"); t && argc < 256; t = strtok(NULL, " \t\r\n"))
        argv[argc++] = t;
    if (argc == 0)
        return GR_OK;
    jmp_buf jb;
    g->err.cmd = argv[0];
    g->err.file = name;
    g->err.line = lineno;
    g->err.jmp = &jb;
    if (setjmp(jb)) {
        gr_report_error(g);
        g->err.jmp = NULL;
        return GR_ERR;
    }
    const struct command *c = cmd_find(argv[0]);
    if (!c)
        gr_error(g, "unknown command");
    c->fn(g, argc - 1, argv + 1);
    g->err.jmp = NULL;
    return GR_OK;
}

int inp_stream(struct gravel *g, FILE *fp, const char *name)
{
    char buf[4096];
    int lineno = 0;
    while (fgets(buf, sizeof buf, fp)) {
        lineno++;
        int rc = run_line(g, buf, name, lineno);
        if (rc)
            return rc;
    }
    return GR_OK;
}

int inp_file(struct gravel *g, const char *path)
{
    FILE *fp = fopen(path, "r");
    if (!fp)
        gr_error(g, "cannot open input script %s", path);
    int rc = inp_stream(g, fp, path);
    fclose(fp);
    return rc;
}

int inp_string(struct gravel *g, const char *text, const char *name)
{
    FILE *fp = fmemopen((void *)text, strlen(text), "r");
    if (!fp)
        return GR_ERR;
    int rc = inp_stream(g, fp, name);
    fclose(fp);
    return rc;
}
