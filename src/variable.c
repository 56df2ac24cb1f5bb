/* variable.c - PLACEHOLDER: variables land with the interpreter. */
#include "variable.h"

#include <stdlib.h>

#include "error.h"

struct vars {
    int n;
};

struct vars *var_create(void) { return calloc(1, sizeof(struct vars)); }
void var_destroy(struct vars *v) { free(v); }
void var_set_index(struct gravel *g, const char *name, int n, char **values)
{
    (void)name; (void)n; (void)values;
    gr_error(g, "variables are not implemented yet");
}
const char *var_retrieve(struct gravel *g, const char *name) { (void)g; (void)name; return NULL; }
double var_compute_equal(struct gravel *g, const char *name)
{
    gr_error(g, "variable '%s' is not defined", name);
}
double expr_eval(struct gravel *g, const char *text)
{
    gr_error(g, "cannot evaluate '%s' yet", text);
}
