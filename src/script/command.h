/* command.h - the command table: one row per script command.
 *
 * Each row carries the handler, its arity and the phase it is legal in; the
 * dispatcher (input.c) checks all three before the handler runs, so handlers
 * parse only their own keywords. Rows live in commands.def, grouped by the
 * module that implements them; adding a command is one line there. */
#ifndef GR_COMMAND_H
#define GR_COMMAND_H

#include "state.h"

enum phase {
    PH_ANY,         /* legal any time */
    PH_PRE_BOX,     /* only before the box exists (create_box, read_data) */
    PH_POST_BOX     /* only once the box exists */
};

typedef void (*cmd_fn)(struct gravel *g, int argc, char **argv);

struct command {
    const char *name;
    cmd_fn fn;
    int min_args, max_args;     /* max -1 = unbounded */
    enum phase phase;
    const char *summary;        /* one line for -h */
};

#define CMD(name, fn, min, max, phase, summary) void fn(struct gravel *g, int argc, char **argv);
#include "commands.def"
#undef CMD

extern const struct command gr_commands[];      /* ends with a NULL name */
const struct command *cmd_find(const char *name);
/* The known name closest to `name` (edit distance), for "did you mean". */
const char *cmd_nearest(const char *name);

#endif
