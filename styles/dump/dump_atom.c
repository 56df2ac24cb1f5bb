/* dump_atom.c - `dump ID group atom N file`: LAMMPS' dump atom, the text
 * format of dump custom with the fixed fields "id type xs ys zs" (scaled
 * coordinates), or "x y z" with `dump_modify scale no`, followed by
 * "ix iy iz" with `dump_modify image yes`. Writing, files and formats are
 * dump custom's (dump_custom.c). */
#include <string.h>

#include "args.h"
#include "dump.h"
#include "dump_custom.h"
#include "error.h"

extern const struct dump_style dump_style_custom;

/* (Re)build the custom columns for the scale/image settings (formats given
 * earlier with dump_modify are dropped with the old columns). */
static void atom_columns(struct gravel *g, struct dump *d, int scale, int image)
{
    char *fields[8] = {"id", "type", "xs", "ys", "zs", "ix", "iy", "iz"};
    if (!scale) {
        fields[2] = "x";
        fields[3] = "y";
        fields[4] = "z";
    }
    if (d->data)
        dump_style_custom.destroy(d);
    dump_style_custom.create(g, d, image ? 8 : 5, fields);
}

static void atom_create(struct gravel *g, struct dump *d, int argc, char **argv)
{
    (void)argv;
    if (argc != 0)
        gr_error(g, "dump atom takes no arguments after the file name, got %d", argc);
    atom_columns(g, d, 1, 0); /* LAMMPS defaults: scale yes, image no */
}

static int atom_modify(struct gravel *g, struct dump *d, int argc, char **argv, int i,
                       int apply)
{
    const char *kw = argv[i];
    if (strcmp(kw, "scale") == 0 || strcmp(kw, "image") == 0) {
        arg_need(g, argc, i, 1, kw);
        int yes = arg_yesno(g, argv[i + 1], kw);
        /* the settings live in the column names */
        int scale = dump_custom_has_field(d, "xs");
        int image = dump_custom_has_field(d, "ix");
        if (kw[0] == 's')
            scale = yes;
        else
            image = yes;
        if (apply)
            atom_columns(g, d, scale, image);
        return 2;
    }
    return dump_style_custom.modify(g, d, argc, argv, i, apply);
}

static void atom_init(struct gravel *g, struct dump *d)
{
    dump_style_custom.init(g, d);
}

static void atom_write(struct gravel *g, struct dump *d, FILE *fp, const int *idx, int n)
{
    dump_style_custom.write(g, d, fp, idx, n);
}

static void atom_destroy(struct dump *d)
{
    dump_style_custom.destroy(d);
}

const struct dump_style dump_style_atom = {
    .name = "atom",
    .append = 1,
    .create = atom_create,
    .modify = atom_modify,
    .init = atom_init,
    .write = atom_write,
    .destroy = atom_destroy,
};
