/* command.c - the command table built from commands.def, and name lookup. */
#include "command.h"

#include <string.h>

const struct command gr_commands[] = {
#define CMD(name, fn, min, max, phase, summary) {name, fn, min, max, phase, summary},
#include "commands.def"
#undef CMD
    {NULL, NULL, 0, 0, PH_ANY, NULL}};

const struct command *cmd_find(const char *name)
{
    for (const struct command *c = gr_commands; c->name; c++)
        if (strcmp(c->name, name) == 0)
            return c;
    return NULL;
}

static int edit_distance(const char *a, const char *b)
{
    int la = (int)strlen(a), lb = (int)strlen(b);
    if (la > 63 || lb > 63)
        return 99;
    int d[64][64];
    for (int i = 0; i <= la; i++)
        d[i][0] = i;
    for (int j = 0; j <= lb; j++)
        d[0][j] = j;
    for (int i = 1; i <= la; i++)
        for (int j = 1; j <= lb; j++) {
            int sub = d[i - 1][j - 1] + (a[i - 1] != b[j - 1]);
            int del = d[i - 1][j] + 1, ins = d[i][j - 1] + 1;
            int m = sub < del ? sub : del;
            d[i][j] = m < ins ? m : ins;
        }
    return d[la][lb];
}

const char *cmd_nearest(const char *name)
{
    const char *best = NULL;
    int bestd = 1 << 30;
    for (const struct command *c = gr_commands; c->name; c++) {
        int dist = edit_distance(name, c->name);
        if (dist < bestd) {
            bestd = dist;
            best = c->name;
        }
    }
    return best;
}
