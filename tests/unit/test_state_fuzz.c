/* test_state_fuzz.c - random command lines for the state commands (fixed
 * seed): every line must end in GR_OK or a clean GR_ERR, never a crash
 * (ASan/UBSan build), and the engine must keep its invariants: atom types
 * in 1..ntypes, every atom in group "all", periodic coordinates inside the
 * box, positive masses, unique tags. Argument counts respect the command
 * table's arity, as the dispatcher guarantees to handlers. */
#include "test.h"

#include <stdlib.h>
#include <unistd.h>

#include "atoms.h"
#include "command.h"

#ifndef FUZZ_SEED
#define FUZZ_SEED 12345
#endif

static unsigned long rng_state = FUZZ_SEED;
static unsigned rnd(unsigned n)
{
    rng_state = rng_state * 6364136223846793005ull + 1442695040888963407ull;
    return (unsigned)((rng_state >> 33) % n);
}

static const char *word(void)
{
    static const char *w[] = {
        "0", "1", "2", "3", "-1", "0.5", "1e30", "-1e30", "nan", "inf", "INF", "-INF", "EDGE",
        "NULL", "*", "2*", "*2", "1*3", "abc", "x", "y", "z", "box", "lattice", "in", "out",
        "all", "g1", "r1", "r2", "side", "units", "yes", "no", "gaussian", "uniform", "geom",
        "loop", "dist", "mom", "rot", "sum", "overlap", "maxtry", "remap", "10", "100",
        "1000000000000", "2147483648", "<", "<>", "<=", "1:3", "1:9:2", "type", "id", "mass",
        "diameter", "density", "omega", "vx", "image", "region", "group", "single", "random",
        "block", "sphere", "cylinder", "cone", "plane", "union", "intersect", "delete",
        "exclude", "every", "delay", "check", "page", "one", "create", "set", "zero", "linear",
        "angular", "ramp", "scale", "fcc", "bcc", "sc", "hcp", "diamond", "none", "origin",
        "spacing", "orient", "subtract", "empty", "clear", "p", "f", "s", "m", "fs", "pf"};
    return w[rnd(sizeof w / sizeof *w)];
}

/* Valid lines to mutate: 0-2 of their words are replaced by random words. */
static const char *templates[] = {
    "create_atoms 1 random 20 5 NULL overlap 0.5 maxtry 20",
    "create_atoms 1 single 0.5 0.5 0.5 units box remap yes",
    "create_atoms 2 region r1",
    "set group all diameter 0.8",
    "set type 1 density 2.0 omega 1 2 3",
    "set atom 1*5 type 2 vx 1.0 image 1 0 0",
    "set region r1 mass 1.5",
    "group g2 region r1",
    "group g3 id <> 2 9",
    "group g4 subtract all g1",
    "velocity all create 1.0 3 dist gaussian loop all rot yes",
    "velocity g1 set 1 NULL 0 sum yes units box",
    "velocity all zero angular",
    "velocity all ramp vx 0 1 z 0 2",
    "region r3 union 2 r1 r2",
    "region r4 cone x 1 1 1 0.5 0 2 side out",
    "region r5 plane 1 1 1 0 0 1 units box",
    "lattice hcp 0.9 origin 0.1 0.2 0.3",
    "neigh_modify every 2 delay 4 exclude type 1 2",
    "mass * 2.0",
    "region r1 delete",
};

static void mutated_line(char *buf, size_t n)
{
    char tmp[512];
    snprintf(tmp, sizeof tmp, "%s", templates[rnd(sizeof templates / sizeof *templates)]);
    char *w[32];
    int nw = 0;
    for (char *t = strtok(tmp, " "); t && nw < 32; t = strtok(NULL, " "))
        w[nw++] = t;
    int nmut = (int)rnd(3);
    for (int k = 0; k < nmut; k++) {
        int at = 1 + (int)rnd((unsigned)(nw - 1));
        w[at] = (char *)word();
    }
    buf[0] = '\0';
    for (int k = 0; k < nw; k++) {
        size_t len = strlen(buf);
        snprintf(buf + len, n - len, "%s%s", k ? " " : "", w[k]);
    }
    strncat(buf, "\n", n - strlen(buf) - 1);
}

static void random_line(char *buf, size_t n)
{
    if (rnd(2)) {
        mutated_line(buf, n);
        return;
    }
    static const char *cmds[] = {"units", "dimension", "atom_style", "boundary", "lattice",
                                 "region", "create_box", "create_atoms", "set", "group",
                                 "velocity", "mass", "neighbor", "neigh_modify", "timestep"};
    const char *name = cmds[rnd(sizeof cmds / sizeof *cmds)];
    snprintf(buf, n, "%s", name);
    /* respect the table's arity: the dispatcher rejects other counts */
    const struct command *c = cmd_find(name);
    int hi = c->max_args < 0 ? c->min_args + 10 : c->max_args;
    int nw = c->min_args + (int)rnd((unsigned)(hi - c->min_args + 1));
    for (int k = 0; k < nw; k++) {
        size_t len = strlen(buf);
        snprintf(buf + len, n - len, " %s", word());
    }
    strncat(buf, "\n", n - strlen(buf) - 1);
}

static int invariants(const struct gravel *g)
{
    const struct atoms *a = &g->atoms;
    for (int i = 0; i < a->n; i++) {
        if (a->type[i] < 1 || a->type[i] > a->ntypes || !(a->mask[i] & 1u) || !(a->rmass[i] > 0))
            return 0;
        for (int d = 0; d < 3; d++)
            if (g->dom.periodic[d] &&
                !(a->x[3 * i + d] >= g->dom.lo[d] - 1e-9 && a->x[3 * i + d] <= g->dom.hi[d]))
                return 0;
        if (i > 0 && a->tag[i] == a->tag[i - 1])
            return 0;
    }
    return 1;
}

TEST(random_scripts)
{
    static const char *setups[] = {
        "lattice fcc 0.8\nregion b block 0 3 0 3 0 3\ncreate_box 2 b\ncreate_atoms 1 box\n"
        "region r1 sphere 2 2 2 1.5\nregion r2 block 0 1 0 1 0 1\ngroup g1 type 1\n",
        "boundary p p fs\nregion b block 0 5 0 5 0 5 units box\ncreate_box 3 b\n"
        "create_atoms 2 random 50 7 NULL overlap 0.9\nregion r1 cylinder z 2 2 1 INF INF\n",
        ""};
    int bad = 0, lines = 0, ok = 0;
    for (int rep = 0; rep < 300; rep++) {
        struct gravel *g = test_engine();
        if (test_script(g, setups[rep % 3]) != GR_OK)
            bad++;
        for (int k = 0; k < 100; k++) {
            char line[512];
            random_line(line, sizeof line);
            int rc = test_script(g, line);
            lines++;
            ok += rc == GR_OK;
            if ((rc != GR_OK && rc != GR_ERR) || (rc == GR_ERR && !strchr(g->err.msg, ':'))) {
                printf("  unexpected rc %d for: %s", rc, line);
                bad++;
            }
            if (!invariants(g)) {
                printf("  invariant broken after: %s", line);
                bad++;
                break;
            }
        }
        gr_destroy(g);
    }
    CHECK(bad == 0);
    CHECK(lines == 30000);
    CHECK(ok > 2000); /* some random lines are valid and change state */
    printf("  %d of %d random lines succeeded\n", ok, lines);
}

/* Byte-level mutations of a small valid data file: read_data must succeed or
 * fail cleanly, and leave either a full state or none. */
TEST(mutated_data_files)
{
    static const char base[] =
        "LAMMPS data file\n\n3 atoms\n2 atom types\n\n0 10 xlo xhi\n0 10 ylo yhi\n"
        "0 10 zlo zhi\n\nMasses\n\n1 1.0\n2 2.0\n\nAtoms # sphere\n\n"
        "1 1 1.0 1.0 1 1 1 0 0 0\n2 2 0.5 2.0 2 2 2 1 0 -1\n3 1 0 3.0 9.5 9.5 9.5 0 0 0\n\n"
        "Velocities\n\n1 0 0 0 0 0 0\n2 1 2 3 4 5 6\n3 -1 -1 -1 0 0 0\n";
    static const char alphabet[] = " \n\t#-+.eE019xyzAtomsVelocitiesMasses\r\0";
    char path[] = "/tmp/gravel_fuzz_data.XXXXXX";
    int fd = mkstemp(path);
    CHECK(fd >= 0);
    if (fd < 0)
        return;
    close(fd);
    int ok = 0, bad = 0;
    for (int rep = 0; rep < 1500; rep++) {
        char buf[sizeof base + 64];
        size_t n = sizeof base - 1;
        memcpy(buf, base, n);
        int nmut = 1 + (int)rnd(4);
        for (int k = 0; k < nmut; k++) {
            size_t at = rnd((unsigned)n);
            switch (rnd(3)) {
            case 0: buf[at] = alphabet[rnd(sizeof alphabet - 1)]; break;
            case 1: memmove(buf + at, buf + at + 1, n - at - 1); n--; break;
            default:
                if (n < sizeof buf - 1) {
                    memmove(buf + at + 1, buf + at, n - at);
                    buf[at] = alphabet[rnd(sizeof alphabet - 1)];
                    n++;
                }
            }
        }
        FILE *fp = fopen(path, "wb");
        fwrite(buf, 1, n, fp);
        fclose(fp);
        struct gravel *g = test_engine();
        char script[128];
        snprintf(script, sizeof script, "boundary p p f\nread_data %s\n", path);
        int rc = test_script(g, script);
        if (rc == GR_OK) {
            ok++;
            if (!g->dom.box_exists || !invariants(g))
                bad++;
        } else if (rc != GR_ERR || g->dom.box_exists || g->atoms.n != 0) {
            bad++;
        }
        gr_destroy(g);
    }
    remove(path);
    CHECK(bad == 0);
    CHECK(ok > 10);
    printf("  %d of 1500 mutated data files read\n", ok);
}

int main(void)
{
    RUN(random_scripts);
    RUN(mutated_data_files);
    return 0;
}
