/* test_fuzz_corpus.c - replay the fuzzer's corpus (tests/fuzz/found/, the
 * edge-minimal set of a fuzzing campaign: scripts, data, restart, molecule
 * and dump files) in process, through the fuzz harness itself (tests/fuzz/fuzz_input.c:
 * the same command allow-list, command budget and scratch directory), in
 * this ASan+UBSan build. An input passes when it ends (error or not) without
 * a sanitizer report; a report names the input through the death callback.
 * Also checks the corpus holds each of the input kinds (scripts, data,
 * restart, molecule, dump and mesh files). */
#include <dirent.h>
#include <limits.h>
#include <sanitizer/common_interface_defs.h>
#include <stdint.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include "test.h"

#include "../fuzz/fuzz_input.c"

static char current[PATH_MAX + 64];

static void on_death(void)
{
    printf("FAIL fuzz_corpus_input %s (sanitizer report above)\n", current);
    fflush(stdout);
}

static int cmp_str(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

static char dir[PATH_MAX];
static int n_inputs, n_data, n_restart, n_molecule, n_dump, n_script, n_mesh;

static int is_mesh(const uint8_t *b, size_t n)
{
    return has_prefix(b, n, "#!stl\n") || has_prefix(b, n, "#!stlb\n") ||
           has_prefix(b, n, "#!vtk\n");
}

static int replay_file(const char *name)
{
    snprintf(current, sizeof current, "%s/%s", dir, name);
    FILE *fp = fopen(current, "rb");
    if (!fp)
        return 0;
    struct stat st;
    if (fstat(fileno(fp), &st) != 0 || !S_ISREG(st.st_mode)) {
        fclose(fp);
        return 0;
    }
    size_t n = (size_t)st.st_size;
    uint8_t *buf = malloc(n + 1);
    size_t got = buf ? fread(buf, 1, n, fp) : 0;
    fclose(fp);
    if (!buf || got != n) {
        free(buf);
        return 0;
    }
    LLVMFuzzerTestOneInput(buf, n);
    int data = has_prefix(buf, n, "#!data\n"), restart = has_prefix(buf, n, "#!restart");
    int molecule = has_prefix(buf, n, "#!molecule\n"), dump = has_prefix(buf, n, "#!dump\n");
    n_data += data;
    n_restart += restart;
    n_molecule += molecule;
    n_dump += dump;
    n_mesh += is_mesh(buf, n);
    n_script += !data && !restart && !molecule && !dump && !is_mesh(buf, n);
    free(buf);
    return 1;
}

TEST(fuzz_corpus_replay)
{
    DIR *dp = opendir(dir);
    CHECK(dp != NULL);
    if (!dp)
        return;
    char **names = NULL;
    int nn = 0, cap = 0;
    struct dirent *de;
    while ((de = readdir(dp))) {
        if (de->d_name[0] == '.')
            continue;
        if (nn == cap) {
            cap = cap ? 2 * cap : 256;
            names = realloc(names, (size_t)cap * sizeof *names);
        }
        names[nn++] = strdup(de->d_name);
    }
    closedir(dp);
    if (nn)
        qsort(names, (size_t)nn, sizeof *names, cmp_str);
    int argc = 1;
    char *argv0[] = {"test_fuzz_corpus", NULL};
    char **argv = argv0;
    LLVMFuzzerInitialize(&argc, &argv);
    for (int i = 0; i < nn; i++) {
        n_inputs += replay_file(names[i]);
        free(names[i]);
    }
    free(names);
    printf("  %d inputs replayed: %d scripts, %d data files, %d restart files, %d molecule "
           "files, %d dump files, %d mesh files\n", n_inputs, n_script, n_data, n_restart,
           n_molecule, n_dump, n_mesh);
    CHECK(n_inputs == nn && n_inputs >= 100);
    CHECK(n_script > 0 && n_data > 0 && n_restart > 0 && n_molecule > 0 && n_dump > 0 &&
          n_mesh > 0);
}

int main(void)
{
    if (!getcwd(dir, sizeof dir - 32))
        return 1;
    strcat(dir, "/tests/fuzz/found");
    __sanitizer_set_death_callback(on_death);
    RUN(fuzz_corpus_replay);
    return 0;
}
