/* test_restart.c - restart round trip and robustness under ASan/UBSan:
 * the state after read_restart equals the written state field by field; a
 * run continued from the file equals the uninterrupted run bit for bit; and
 * mutated files (every byte position class, checksum re-fixed so the parser
 * itself is exercised) and truncations are rejected or accepted cleanly,
 * never a crash, leak or undefined behaviour. */
#include "test.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "error.h"
#include "input.h"
#include "pair.h"
#include "restart.h"

static const char *deck =
    "units lj\natom_style sphere\nboundary p p f\n"
    "region box block 0 4 0 4 0 5\ncreate_box 2 box\n"
    "lattice sc 1.0 origin 0.5 0.5 0.5\nregion fill block 0 4 0 4 0 2 units box\n"
    "create_atoms 1 region fill\nset group all diameter 0.9 density 1.0\n"
    "set type 1 type/fraction 2 0.4 99\ngroup two type 2\nmass 2 3.0\n"
    "velocity all create 2.0 4928 loop geom\nvelocity all set 4.0 2.5 NULL sum yes units box\n"
    "pair_style gran/hooke/history 2000.0 NULL 50.0 NULL 0.5 1\npair_coeff * *\n"
    "neighbor 0.2 bin\ntimestep 0.001\n";
static const char *fixes =
    "fix 1 all nve/sphere\nfix 2 all gravity 1.0 vector 0 0 -1\n"
    "fix 3 all wall/gran hooke/history 2000.0 NULL 50.0 NULL 0.4 1 zplane 0.0 NULL\n";

static const char *fixes_run = "fix 1 all nve/sphere\nfix 2 all gravity 1.0 vector 0 0 -1\n"
                               "run 3\n";

static char path[256];

static struct gravel *engine_with(const char *a, const char *b, const char *c)
{
    struct gravel *g = test_engine();
    size_t len = strlen(a) + strlen(b) + strlen(c) + 1;
    char *s = malloc(len);
    snprintf(s, len, "%s%s%s", a, b, c);
    int rc = test_script(g, s);
    if (rc != GR_OK)
        printf("  script failed: %s\n", g->err.msg);
    CHECK(rc == GR_OK);
    free(s);
    return g;
}

static int same(const void *a, const void *b, size_t n) { return memcmp(a, b, n) == 0; }

TEST(state_round_trip)
{
    char cmd[400];
    snprintf(cmd, sizeof cmd, "run 40\nwrite_restart %s\n", path);
    struct gravel *a = engine_with(deck, fixes, cmd);
    snprintf(cmd, sizeof cmd, "read_restart %s\n", path);
    struct gravel *b = engine_with(cmd, "", "");
    int n = a->atoms.n;
    CHECK(n > 0 && b->atoms.n == n);
    CHECK(b->step == 40 && b->time == a->time && b->dt == a->dt);
    CHECK(b->dom.box_exists && same(b->dom.lo, a->dom.lo, sizeof a->dom.lo) &&
          same(b->dom.hi, a->dom.hi, sizeof a->dom.hi));
    CHECK(b->dom.periodic[0] && b->dom.periodic[1] && !b->dom.periodic[2]);
    CHECK(b->dom.units == UNITS_LJ && b->dom.dimension == 3);
    CHECK(b->atoms.ntypes == 2 && b->atoms.type_mass[2] == 3.0);
    CHECK(b->groups.n == a->groups.n && !strcmp(b->groups.name[1], "two"));
    CHECK(b->neigh.skin == 0.2);
    CHECK(b->styles.pair && !strcmp(b->styles.pair->style->name, "gran/hooke/history") &&
          same(b->styles.pair->coef, a->styles.pair->coef, sizeof a->styles.pair->coef));
    if (b->atoms.n == n) {
        size_t n3 = 3 * (size_t)n * sizeof(double);
        CHECK(same(b->atoms.tag, a->atoms.tag, (size_t)n * sizeof(int64_t)));
        CHECK(same(b->atoms.type, a->atoms.type, (size_t)n * sizeof(int)));
        CHECK(same(b->atoms.mask, a->atoms.mask, (size_t)n * sizeof(unsigned)));
        CHECK(same(b->atoms.x, a->atoms.x, n3) && same(b->atoms.v, a->atoms.v, n3));
        CHECK(same(b->atoms.omega, a->atoms.omega, n3) && same(b->atoms.f, a->atoms.f, n3));
        CHECK(same(b->atoms.radius, a->atoms.radius, (size_t)n * sizeof(double)));
        CHECK(same(b->atoms.rmass, a->atoms.rmass, (size_t)n * sizeof(double)));
        CHECK(same(b->atoms.image, a->atoms.image, 3 * (size_t)n * sizeof(int)));
    }
    gr_destroy(a);
    gr_destroy(b);
}

/* Sort key for comparing runs whose atoms may be in different orders. */
static void by_tag(const struct gravel *g, double *out)
{
    for (int i = 0; i < g->atoms.n; i++) {
        int64_t t = g->atoms.tag[i] - 1;
        memcpy(out + 9 * t, g->atoms.x + 3 * i, 3 * sizeof(double));
        memcpy(out + 9 * t + 3, g->atoms.v + 3 * i, 3 * sizeof(double));
        memcpy(out + 9 * t + 6, g->atoms.omega + 3 * i, 3 * sizeof(double));
    }
}

TEST(continuation_bit_identical)
{
    char cmd[400];
    struct gravel *ref = engine_with(deck, fixes, "run 80\n");
    snprintf(cmd, sizeof cmd, "run 40\nwrite_restart %s\n", path);
    struct gravel *a = engine_with(deck, fixes, cmd);
    snprintf(cmd, sizeof cmd, "read_restart %s\n", path);
    struct gravel *b = engine_with(cmd, fixes, "run 40\n");
    int n = ref->atoms.n;
    CHECK(b->atoms.n == n && b->step == 80);
    if (b->atoms.n == n) {
        double *x0 = calloc((size_t)n * 9, sizeof(double)), *x1 = calloc((size_t)n * 9,
                                                                          sizeof(double));
        by_tag(ref, x0);
        by_tag(b, x1);
        CHECK(same(x0, x1, (size_t)n * 9 * sizeof(double)));
        free(x0);
        free(x1);
    }
    gr_destroy(ref);
    gr_destroy(a);
    gr_destroy(b);
}

/* FNV-1a 64 with the standard offset basis (restart format 2). */
static uint64_t fnv(const unsigned char *p, size_t n)
{
    uint64_t h = 14695981039346656037ull;
    for (size_t i = 0; i < n; i++)
        h = (h ^ p[i]) * 1099511628211ull;
    return h;
}

static unsigned char *slurp(const char *p, size_t *n)
{
    FILE *f = fopen(p, "rb");
    if (!f)
        return NULL;
    fseek(f, 0, SEEK_END);
    long sz = ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *b = malloc((size_t)sz + 1);
    *n = fread(b, 1, (size_t)sz, f);
    fclose(f);
    return b;
}

/* Read the bytes as a restart file in a fresh engine; with `then`, also run
 * that script text when the read succeeded. GR_OK or GR_ERR, message in msg. */
static int read_bytes_then(const unsigned char *b, size_t n, char *msg, size_t msglen,
                           const char *then)
{
    char mpath[300];
    snprintf(mpath, sizeof mpath, "%s.mut", path);
    FILE *f = fopen(mpath, "wb");
    fwrite(b, 1, n, f);
    fclose(f);
    struct gravel *g = test_engine();
    char cmd[400];
    snprintf(cmd, sizeof cmd, "read_restart %s\n", mpath);
    int rc = test_script(g, cmd);
    if (rc == GR_OK && then)
        rc = test_script(g, then);
    snprintf(msg, msglen, "%s", g->err.msg);
    gr_destroy(g);
    remove(mpath);
    return rc;
}

static int read_bytes(const unsigned char *b, size_t n, char *msg, size_t msglen)
{
    return read_bytes_then(b, n, msg, msglen, NULL);
}

TEST(mutations_never_crash)
{
    char cmd[400];
    snprintf(cmd, sizeof cmd, "run 20\nwrite_restart %s\n", path);
    struct gravel *a = engine_with(deck, fixes, cmd);
    gr_destroy(a);
    size_t n = 0;
    unsigned char *good = slurp(path, &n);
    CHECK(good && n > RESTART_HEADER_BYTES);
    if (!good)
        return;
    unsigned char *b = malloc(n);
    char msg[1024];
    /* every truncation class: header, section headers, inside arrays */
    int bad = 0;
    for (size_t cut = 0; cut < n; cut += 1 + n / 97) {
        int rc = read_bytes(good, cut, msg, sizeof msg);
        bad += rc != GR_ERR || !strstr(msg, "read_restart");
    }
    CHECK(bad == 0);
    /* flipped bits with the checksum fixed up: the parser's own checks */
    srand(12345);
    int ok = 0, err = 0, other = 0;
    for (int it = 0; it < 400; it++) {
        memcpy(b, good, n);
        size_t off = RESTART_HEADER_BYTES + (size_t)rand() % (n - RESTART_HEADER_BYTES);
        /* bias towards the first 600 bytes, where counts and headers live */
        if (it % 2)
            off = RESTART_HEADER_BYTES + (size_t)rand() % 600 % (n - RESTART_HEADER_BYTES);
        b[off] ^= (unsigned char)(1u << (rand() % 8));
        uint64_t h = fnv(b + RESTART_HEADER_BYTES, n - RESTART_HEADER_BYTES);
        memcpy(b + 24, &h, 8);
        /* the first accepted files also run: bad values must stop cleanly too */
        int rc = read_bytes_then(b, n, msg, sizeof msg, ok < 25 ? fixes_run : NULL);
        if (rc == GR_OK || (ok < 25 && rc == GR_ERR && !strstr(msg, "read_restart")))
            ok++;
        else if (rc == GR_ERR && strstr(msg, "read_restart"))
            err++;
        else
            other++;
    }
    printf("  mutations: %d accepted (values only; the first 25 also ran), %d rejected\n", ok,
           err);
    CHECK(other == 0 && err > 0);
    /* without the fix-up every flip is a checksum error */
    memcpy(b, good, n);
    b[n - 3] ^= 4;
    CHECK(read_bytes(b, n, msg, sizeof msg) == GR_ERR && strstr(msg, "checksum mismatch"));
    free(b);
    free(good);
}

/* pair granular/superellipsoid's state (section 14: models and contact
 * history) in a file written while two particles touch: every flipped bit
 * inside that section (checksum fixed up) is either refused by read_restart
 * or read and run; never a crash (ASan/UBSan). */
static const char *sqe_deck =
    "units si\natom_style ellipsoid superellipsoid\nboundary p p p\n"
    "region box block 0 20 0 20 0 20 units box\ncreate_box 1 box\n"
    "create_atoms 1 single 8.0 10.0 10.0 units box\n"
    "create_atoms 1 single 12.0 10.5 10.0 units box\n"
    "set type 1 shape 1.5 1.0 1.0\nset type 1 block 4.0 4.0\nset type 1 mass 1.0\n"
    "set atom 2 quat 1 2 3 40\nset atom 1 angmom 0.01 0.02 0.0\ngroup moving id 1\n"
    "velocity moving set 3.0 0.0 0.0\nneighbor 0.5 bin\ntimestep 0.002\n"
    "pair_style granular/superellipsoid\npair_coeff * * hooke 1000.0 0.0 tangential "
    "linear_history 285.0 0.0 0.5 damping mass_velocity\nfix integr all nve/asphere\n";

TEST(superellipsoid_state_mutations)
{
    char cmd[400];
    snprintf(cmd, sizeof cmd, "run 470\nwrite_restart %s\n", path);
    struct gravel *a = engine_with(sqe_deck, "", cmd);
    gr_destroy(a);
    size_t n = 0;
    unsigned char *good = slurp(path, &n);
    CHECK(good && n > RESTART_HEADER_BYTES);
    if (!good)
        return;
    /* find section 14 */
    size_t off = RESTART_HEADER_BYTES, lo = 0, len = 0;
    while (off + 16 <= n) {
        uint32_t id;
        uint64_t sl;
        memcpy(&id, good + off, 4);
        memcpy(&sl, good + off + 8, 8);
        if (id == 14)
            lo = off + 16, len = (size_t)sl;
        off += 16 + (size_t)sl;
    }
    CHECK(lo > 0 && len >= 203); /* the style name, 1 model (72 bytes), 1 contact (88) */
    if (!lo) {
        free(good);
        return;
    }
    unsigned char *b = malloc(n);
    char msg[1024];
    srand(4242);
    int ok = 0, err = 0, other = 0;
    for (int it = 0; it < 300; it++) {
        memcpy(b, good, n);
        b[lo + (size_t)rand() % len] ^= (unsigned char)(1u << (rand() % 8));
        uint64_t h = fnv(b + RESTART_HEADER_BYTES, n - RESTART_HEADER_BYTES);
        memcpy(b + 24, &h, 8);
        int rc = read_bytes_then(b, n, msg, sizeof msg, "fix integr all nve/asphere\nrun 5\n");
        if (rc == GR_OK || !strstr(msg, "read_restart"))
            ok++; /* read: the run went through or stopped with its own error */
        else if (rc == GR_ERR)
            err++;
        else
            other++;
    }
    printf("  superellipsoid state mutations: %d read and run, %d refused\n", ok, err);
    CHECK(other == 0 && err > 0 && ok > 0);
    free(b);
    free(good);
}

TEST(errors)
{
    CHECK_ERROR("read_restart /nonexistent/dir/x.rst\n", "cannot open restart file", 1);
    CHECK_ERROR("region b block 0 1 0 1 0 1\ncreate_box 1 b\nwrite_restart "
                "/nonexistent/dir/x.rst\n", "cannot open restart file", 3);
    CHECK_ERROR("read_restart a.rst remap\n", "not needed", 1);
    CHECK_ERROR("read_restart a%.rst\n", "per-processor", 1);
    CHECK_ERROR("region b block 0 1 0 1 0 1\ncreate_box 1 b\nwrite_restart a.rst nfile 2\n",
                "not supported", 3);
    CHECK_ERROR("restart 10 a b c\n", "too many arguments", 1);
    CHECK_ERROR("restart 10 a a\n", "must differ", 1);
    CHECK_ERROR("restart 0 a\n", "takes no file names", 1);
    CHECK_ERROR("restart x a\n", "restart interval", 1);
    CHECK_ERROR("restart 10 a**\n", "more than one", 1);
    CHECK_ERROR("read_restart /tmp/gravel_no_such_*.rst\n", "no restart file matches", 1);
}

int main(void)
{
    snprintf(path, sizeof path, "/tmp/gravel_test_restart_%ld.rst", (long)getpid());
    RUN(state_round_trip);
    RUN(continuation_bit_identical);
    RUN(mutations_never_crash);
    RUN(superellipsoid_state_mutations);
    RUN(errors);
    remove(path);
    return 0;
}
