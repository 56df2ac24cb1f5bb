/* main.c - PLACEHOLDER command line: gravel -in FILE. */
#include <stdio.h>
#include <string.h>

#include "gravel.h"
#include "input.h"

int main(int argc, char **argv)
{
    struct gravel *g = gr_create();
    if (!g)
        return 1;
    int rc = GR_OK;
    const char *in = NULL;
    for (int i = 1; i < argc; i++)
        if ((!strcmp(argv[i], "-in") || !strcmp(argv[i], "-i")) && i + 1 < argc)
            in = argv[++i];
    rc = in ? inp_file(g, in) : inp_stream(g, stdin, "stdin");
    gr_destroy(g);
    return rc == GR_ERR ? 1 : 0;
}
