/* dump_custom.h - what dump custom (styles/dump/dump_custom.c) offers the dump
 * styles built on it (dump atom). */
#ifndef GR_DUMP_CUSTOM_H
#define GR_DUMP_CUSTOM_H

#include <stdio.h>

struct dump;
struct gravel;

/* dump_modify format state of a dump's N columns (dump custom, dump local). */
struct dump_formats {
    char *line, *fint, *ffloat; /* format line|int|float, NULL unset */
    char **col;                 /* [n]: format N, NULL unset */
    int n;
};

/* The columns of a dump, as dump_formats_modify asks about them. */
struct dump_columns {
    const void *ctx;
    int (*is_int)(const void *ctx, int k);
    const char *(*name)(const void *ctx, int k);
    const char *noun;           /* the columns in messages: "fields", "values" */
};

/* dump_modify format line|int|float|N "fmt" | format none | format "fmt"
 * (LIGGGHTS's and old LAMMPS's line: a word with a %) at argv[i]: the words
 * used (0: not `format`); every format is checked, stored only with
 * `apply`. */
int dump_formats_modify(struct gravel *g, struct dump_formats *fm, const struct dump_columns *dc,
                        int argc, char **argv, int i, int apply);
void dump_formats_free(struct dump_formats *fm);

/* LAMMPS's snapshot header: TIMESTEP, NUMBER OF <what> (count), BOX BOUNDS
 * with the boundary flags and the three lo hi [tilt] lines. */
void dump_box_header(struct gravel *g, FILE *fp, const char *what, long long count);

/* dump custom (and dump atom, built on it): 1 if the dump has field `name`. */
int dump_custom_has_field(const struct dump *d, const char *name);

#endif
