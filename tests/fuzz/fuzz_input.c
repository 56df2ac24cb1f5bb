/* fuzz_input.c - libFuzzer target: arbitrary bytes as an input script.
 *
 * Each input runs on a fresh engine with no screen and no log, inside a
 * scratch directory (print/log may write files there). Commands that would
 * start the OpenCL engine, write outputs endlessly or read outside the
 * scratch directory are refused through inp_set_limits(), and a command
 * budget ends `jump SELF` loops that never finish. Build and run: make fuzz. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "gravel.h"
#include "input.h"

static const char *denied[] = {"run", "minimize", "create_atoms", "read_data", "write_data",
                               "read_restart", "write_restart", "restart", "dump",
                               "dump_modify", "shell", NULL};

/* Files named in include/jump/print must stay in the scratch directory
 * (no '/'), so the fuzzer never reads /dev/stdin or writes elsewhere. `log`
 * is allowed only as `log none`: a log file per input made every run slow
 * (opening and echoing into files) without reaching new code. */
static int allow(int argc, char **argv)
{
    for (int i = 0; denied[i]; i++)
        if (strcmp(argv[0], denied[i]) == 0)
            return 0;
    if (strcmp(argv[0], "log") == 0 && (argc < 2 || strcmp(argv[1], "none") != 0))
        return 0;
    for (int i = 1; i < argc; i++)
        if (strchr(argv[i], '/') && (!strcmp(argv[0], "include") || !strcmp(argv[0], "jump") ||
                                     !strcmp(argv[0], "log") || !strcmp(argv[0], "print")))
            return 0;
    return 1;
}

static char scratch[] = "/tmp/gravel-fuzz-XXXXXX";

static void remove_scratch(void)
{
    char cmd[64];
    snprintf(cmd, sizeof cmd, "rm -rf %s", scratch);
    if (chdir("/") == 0 && system(cmd) != 0)
        fprintf(stderr, "fuzz_input: could not remove %s\n", scratch);
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc; (void)argv;
    if (!mkdtemp(scratch) || chdir(scratch) != 0)
        abort();
    atexit(remove_scratch);
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    struct gravel *g = gr_create();
    g->screen = NULL;
    g->echo = ECHO_NONE;
    inp_set_limits(g, allow, 1000, (size_t)4 << 20);
    inp_string(g, text, "fuzz.in");
    gr_destroy(g);
    free(text);
    return 0;
}
