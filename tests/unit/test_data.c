/* test_data.c - read_data of LAMMPS' chute data file (32000 atoms), the
 * shrink-wrap numbers LAMMPS prints for it, write_data -> read_data round
 * trips, and clean errors naming the data file line for bad files. */
#include "test.h"

#include <stdlib.h>
#include <unistd.h>

#include "atoms.h"
#include "domain.h"
#include "group.h"

/* The chute file lives beside the repository: ../shared from the repo root
 * (main checkout) or ../../shared from a worktree under wt/ (then the
 * workspace's absolute path). A missing file fails the chute tests. */
static const char *chute_path(void)
{
    static const char *cands[] = {"../shared/peers/chute/data.chute",
                                  "../../shared/peers/chute/data.chute",
                                  "/work/shared/peers/chute/data.chute"};
    for (int k = 0; k < 3; k++)
        if (access(cands[k], R_OK) == 0)
            return cands[k];
    return cands[0];
}
#define CHUTE chute_path()

static char tmpdir[64];

static const char *tmpfile_with(const char *name, const char *text)
{
    static char path[160];
    snprintf(path, sizeof path, "%s/%s", tmpdir, name);
    FILE *fp = fopen(path, "w");
    fputs(text, fp);
    fclose(fp);
    return path;
}

static struct gravel *read_chute(const char *boundary)
{
    struct gravel *g = test_engine();
    char s[256];
    snprintf(s, sizeof s, "units lj\natom_style sphere\nboundary %s\nread_data %s\n", boundary,
             CHUTE);
    if (test_script(g, s) != GR_OK)
        printf("  read failed: %s\n", g->err.msg);
    return g;
}

TEST(chute_loads)
{
    struct gravel *g = read_chute("p p fs");
    struct atoms *a = &g->atoms;
    CHECK(a->n == 32000 && a->ntypes == 2 && a->maxtag == 32000);
    CHECK(g->dom.lo[0] == 0 && g->dom.hi[0] == 40 && g->dom.hi[1] == 20);
    CHECK(g->dom.lo[2] == 0); /* 'f' lower face untouched */
    CHECK_NEAR(g->dom.hi[2], 37.2886 * (1 + 1e-4), 1e-12); /* 's' face moved out by small */
    int n2 = 0;
    for (int i = 0; i < a->n; i++)
        n2 += a->type[i] == 2;
    CHECK(n2 == 912);
    int i1 = atoms_find_tag(a, 1);
    CHECK(i1 >= 0);
    if (i1 < 0) {
        gr_destroy(g);
        return;
    }
    CHECK(a->x[3 * i1] == 19.4061 && a->x[3 * i1 + 1] == 6.46569 && a->x[3 * i1 + 2] == 14.5438);
    CHECK(a->image[3 * i1] == 33 && a->image[3 * i1 + 1] == 0);
    CHECK(a->radius[i1] == 0.5);
    CHECK_NEAR(a->rmass[i1], M_PI / 6, 1e-15);
    CHECK(a->v[3 * i1] == 7.36585 && a->v[3 * i1 + 1] == -0.294381 &&
          a->v[3 * i1 + 2] == 0.0381822);
    CHECK(a->omega[3 * i1] == -0.298859 && a->omega[3 * i1 + 1] == 0.876624 &&
          a->omega[3 * i1 + 2] == -0.389997);
    int i2 = atoms_find_tag(a, 2);
    CHECK(a->image[3 * i2 + 1] == 1 && a->v[3 * i2] == 9.02473);
    gr_destroy(g);
}

TEST(chute_shrink_wrap)
{
    /* LAMMPS 29Sep2021, boundary p p fs, run 0: Volume 29833.78309,
     * zlo 0, zhi 37.29222886 (reset_box on the atom extent) */
    struct gravel *g = read_chute("p p fs");
    double lo[3], hi[3];
    group_bounds(g, 0, lo, hi);
    CHECK_NEAR(hi[2], 37.2885, 1e-12);
    domain_shrink_wrap(g, lo, hi);
    CHECK_NEAR(g->dom.hi[2], 37.29222886, 1e-8);
    CHECK(g->dom.lo[2] == 0 && g->dom.lo[0] == 0 && g->dom.hi[0] == 40);
    CHECK_NEAR(domain_volume(g), 29833.78309, 1e-5);
    gr_destroy(g);
    /* 'm' never shrinks inside the initial face; 's' follows the atoms */
    g = test_engine();
    CHECK(test_script(g, "boundary p s m\nregion b block 0 10 0 10 0 10\ncreate_box 1 b\n")
          == GR_OK);
    double elo[3] = {1, 2, 3}, ehi[3] = {9, 8, 12};
    domain_shrink_wrap(g, elo, ehi);
    CHECK(g->dom.lo[0] == 0 && g->dom.hi[0] == 10);
    CHECK_NEAR(g->dom.lo[1], 2 - 1e-3, 1e-15);
    CHECK_NEAR(g->dom.hi[1], 8 + 1e-3, 1e-15);
    CHECK(g->dom.lo[2] == 0);
    CHECK_NEAR(g->dom.hi[2], 12 + 1e-3, 1e-15);
    double empty_lo[3] = {1, 1, 1}, empty_hi[3] = {0, 0, 0};
    domain_shrink_wrap(g, empty_lo, empty_hi); /* no atoms: unchanged */
    CHECK_NEAR(g->dom.hi[2], 12 + 1e-3, 1e-15);
    gr_destroy(g);
}

static int same_atoms(const struct gravel *a, const struct gravel *b)
{
    if (a->atoms.n != b->atoms.n)
        return 0;
    for (int i = 0; i < a->atoms.n; i++) {
        int j = atoms_find_tag(&b->atoms, a->atoms.tag[i]);
        if (j < 0 || a->atoms.type[i] != b->atoms.type[j] ||
            a->atoms.radius[i] != b->atoms.radius[j] ||
            fabs(a->atoms.rmass[i] - b->atoms.rmass[j]) > 1e-15 * a->atoms.rmass[i])
            return 0;
        for (int d = 0; d < 3; d++)
            if (a->atoms.x[3 * i + d] != b->atoms.x[3 * j + d] ||
                a->atoms.v[3 * i + d] != b->atoms.v[3 * j + d] ||
                a->atoms.omega[3 * i + d] != b->atoms.omega[3 * j + d] ||
                a->atoms.image[3 * i + d] != b->atoms.image[3 * j + d])
                return 0;
    }
    return 1;
}

static char *slurp(const char *path)
{
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return NULL;
    fseek(fp, 0, SEEK_END);
    long n = ftell(fp);
    rewind(fp);
    char *s = malloc((size_t)n + 1);
    s[fread(s, 1, (size_t)n, fp)] = '\0';
    fclose(fp);
    return s;
}

TEST(round_trip)
{
    char p1[160], p2[160], s[512];
    snprintf(p1, sizeof p1, "%s/rt1.data", tmpdir);
    snprintf(p2, sizeof p2, "%s/rt2.data", tmpdir);
    struct gravel *g = read_chute("p p f");
    CHECK(g->atoms.n == 32000);
    if (g->atoms.n != 32000) {
        gr_destroy(g);
        return;
    }
    /* make masses and diameters non-trivial before writing */
    CHECK(test_script(g, "set type 2 diameter 1.3\nset type 2 density 2.7\nmass 1 2.0\n"
                         "set atom 5 diameter 0\nset atom 5 mass 0.25\n") == GR_OK);
    snprintf(s, sizeof s, "write_data %s\n", p1);
    CHECK(test_script(g, s) == GR_OK);
    struct gravel *h = test_engine();
    snprintf(s, sizeof s, "boundary p p f\nread_data %s\nwrite_data %s\n", p1, p2);
    CHECK(test_script(h, s) == GR_OK);
    CHECK(same_atoms(g, h));
    int i5 = atoms_find_tag(&h->atoms, 5);
    CHECK(i5 >= 0 && h->atoms.radius[i5] == 0 && h->atoms.rmass[i5] == 0.25); /* point particle */
    CHECK(h->atoms.ntypes == 2 && h->atoms.type_mass[1] == 2.0);
    for (int d = 0; d < 3; d++)
        CHECK(g->dom.lo[d] == h->dom.lo[d] && g->dom.hi[d] == h->dom.hi[d]);
    char *t1 = slurp(p1), *t2 = slurp(p2);
    CHECK(t1 && t2 && strcmp(t1, t2) == 0);
    free(t1);
    free(t2);
    gr_destroy(g);
    gr_destroy(h);
    CHECK_ERROR("region b block 0 1 0 1 0 1\ncreate_box 1 b\nwrite_data /nonexistent/dir/x\n",
                "cannot write data file '/nonexistent/dir/x'", 3);
    CHECK_ERROR("region b block 0 1 0 1 0 1\ncreate_box 1 b\nwrite_data x.data pair ik\n",
                "pair must be ii or ij", 3);
}

#define HEAD "LAMMPS data file\n\n2 atoms\n1 atom types\n\n0 10 xlo xhi\n0 10 ylo yhi\n" \
             "0 10 zlo zhi\n\nAtoms # sphere\n\n"

static void bad_file(const char *text, const char *what, int line)
{
    const char *p = tmpfile_with("bad.data", text);
    char script[256];
    snprintf(script, sizeof script, "boundary p p f\n\nread_data %s\n", p);
    char want[256];
    if (line > 0)
        snprintf(want, sizeof want, "bad.data:%d: %s", line, what);
    else
        snprintf(want, sizeof want, "%s", what);
    CHECK_ERROR(script, want, 3);
}

TEST(good_small_file)
{
    const char *p = tmpfile_with("ok.data", HEAD "1 1 1.0 2.0 1 2 3\n2 1 0 3.0 12 5 5 \n\n"
                                              "Velocities\n\n2 1 2 3 4 5 6\n1 0 0 0 0 0 0\n");
    char script[256];
    snprintf(script, sizeof script, "read_data %s shift 0 0 1\n", p);
    struct gravel *g = test_engine();
    CHECK(test_script(g, script) == GR_OK);
    CHECK(g->atoms.n == 2);
    CHECK_NEAR(g->atoms.rmass[0], 2.0 * M_PI / 6, 1e-15);
    CHECK(g->atoms.rmass[1] == 3.0);                       /* diameter 0: density is mass */
    CHECK(g->atoms.x[3] == 2 && g->atoms.image[3] == 1);   /* wrapped into the periodic box */
    CHECK(g->atoms.x[2] == 4 && g->atoms.v[3] == 1 && g->atoms.omega[5] == 6);
    gr_destroy(g);
    /* LIGGGHTS' granular hint has the same columns */
    const char *gran = tmpfile_with("gran.data", "LIGGGHTS\n\n1 atoms\n1 atom types\n\n"
                                                 "Atoms # granular\n\n1 1 0.5 2500 0 0 0\n");
    snprintf(script, sizeof script, "read_data %s\n", gran);
    g = test_engine();
    CHECK(test_script(g, script) == GR_OK);
    CHECK(g->atoms.n == 1 && g->atoms.radius[0] == 0.25);
    gr_destroy(g);
    p = tmpfile_with("ok.data", HEAD "1 1 1.0 2.0 1 2 3\n2 1 0 3.0 12 5 5 \n\n"
                                   "Velocities\n\n2 1 2 3 4 5 6\n1 0 0 0 0 0 0\n");
    /* extra/atom/types and group, as LAMMPS */
    snprintf(script, sizeof script, "read_data %s extra/atom/types 2 group fromfile\n"
             "set atom 1 type 3\n", p);
    g = test_engine();
    CHECK(test_script(g, script) == GR_OK);
    CHECK(g->atoms.ntypes == 3 && g->atoms.type[0] == 3);
    int ig = group_find(g, "fromfile");
    CHECK(ig > 0 && group_count(g, ig) == 2);
    gr_destroy(g);
    snprintf(script, sizeof script, "read_data %s group all\n", p);
    CHECK_ERROR(script, "group 'all' always holds every atom", 1);
    snprintf(script, sizeof script, "read_data %s extra/atom/types -1\n", p);
    CHECK_ERROR(script, "extra/atom/types must be between 0 and 1000000", 1);
}

TEST(bad_files)
{
    CHECK_ERROR("read_data /nonexistent.data\n", "cannot open data file '/nonexistent.data'", 1);
    bad_file(HEAD "1 1 1 1 1 1 1\n", "unexpected end of file in the Atoms section (read 1 of 2", 12);
    bad_file(HEAD "1 1 1 1 1 abc 1\n2 1 1 1 1 1 1\n", "expected a number for coordinate, got 'abc'",
             12);
    bad_file(HEAD "1 1 1 1 1 1 1\n2 2 1 1 1 1 1\n", "atom type 2 is outside 1..1", 13);
    bad_file(HEAD "1 1 1 1 1 1 1\n2 1 1 1 1 1\n", "expected 7 values on this Atoms line", 13);
    bad_file(HEAD "1 1 1 1 1 1\n", "Atoms lines for atom_style sphere need 7 or 10 values", 12);
    bad_file(HEAD "1 1 1 1 1 1 1\n1 1 1 1 2 2 2\n", "duplicate atom ID 1", 0);
    bad_file(HEAD "1 1 1 1 1 1 1\n2 1 1 1 1 1 11\n", "atom 2 is outside the box in z", 13);
    bad_file(HEAD "1 1 -1 1 1 1 1\n2 1 1 1 1 1 1\n", "diameter must not be negative", 12);
    bad_file(HEAD "1 1 1 0 1 1 1\n2 1 1 1 1 1 1\n", "density must be positive", 12);
    bad_file(HEAD "1 1 1 1 1 1 1\n\n2 1 1 1 1 1 1\n", "blank line inside the Atoms section", 13);
    bad_file(HEAD "1 1 1 1 1 1 1\n2 1 1 1 1 1 1\n3 1 1 1 1 1 1\n",
             "expected a section keyword, got '3'", 14);
    bad_file(HEAD "1 1 1 1 1 1 1\n2 1 1 1 1 1 1\n\nVelocities\n\n7 0 0 0 0 0 0\n",
             "Velocities for unknown atom ID 7", 17);
    bad_file(HEAD "1 1 1 1 1 1 1\n2 1 1 1 1 1 1\n\nBonds\n\n1 1 1 2\n", "section 'Bonds' is not "
             "supported", 15);
    bad_file("LAMMPS data file\n\n2 atoms\n1 atom types\n\n0 10 xlo xhi\n\nAtoms # atomic\n\n",
             "Atoms are for atom_style atomic", 8);
    bad_file("LAMMPS data file\n\n2 atoms\n2 bonds\n", "atom_style sphere has no bonds", 4);
    /* boundary p p f: a tilt across the non-periodic z is refused */
    bad_file("LAMMPS data file\n\n2 atoms\n1 atom types\n0 0.5 0 xy xz yz\n",
             "cannot skew a triclinic box along a non-periodic dimension", 0);
    bad_file("LAMMPS data file\n\n2 atoms\n0 q 0 xy xz yz\n",
             "expected a number for tilt factor, got 'q'", 4);
    bad_file("LAMMPS data file\n\n2 atoms\n5 10 xlo xhi\n1 atom types\n5 1 ylo yhi\n",
             "box bounds must satisfy ylo < yhi", 6);
    bad_file("LAMMPS data file\n\n2 atoms\n42\n", "unknown header line", 4);
    bad_file("LAMMPS data file\n\n1 atom types\n\nAtoms\n\n", "the header has no 'N atoms' line", 0);
    bad_file("", "the data file is empty", 0);
    bad_file("LAMMPS\n\n2 atoms\n1 atom types\n\n", "has no Atoms section for its 2 atoms", 0);
    bad_file(HEAD "1 1 1 1 1 1 1 0 0 0 0 0 0 0 0 0 0 0 0 0\n", "too many values", 12);
    /* coefficient sections: skipped with nocoeff, an error without */
    const char *pc = tmpfile_with("pc.data", "LAMMPS\n\n1 atoms\n2 atom types\n\nPair Coeffs # lj/cut\n\n"
                                             "1 1 1\n2 1 1\n\nAtoms\n\n1 2 1 1 0 0 0\n");
    char sc[256];
    snprintf(sc, sizeof sc, "read_data %s nocoeff\n", pc);
    struct gravel *gp = test_engine();
    CHECK(test_script(gp, sc) == GR_OK);
    CHECK(gp->atoms.n == 1 && gp->atoms.type[0] == 2);
    gr_destroy(gp);
    snprintf(sc, sizeof sc, "read_data %s\n", pc);
    CHECK_ERROR(sc, "pc.data:6: section 'Pair Coeffs' is not supported", 1);
    /* a NUL byte */
    const char bin[] = "LAMMPS\n\n2 atoms\n1 atom\0 types\n";
    char path[160];
    snprintf(path, sizeof path, "%s/bin.data", tmpdir);
    FILE *fp = fopen(path, "wb");
    fwrite(bin, 1, sizeof bin - 1, fp);
    fclose(fp);
    char script[256];
    snprintf(script, sizeof script, "read_data %s\n", path);
    CHECK_ERROR(script, "bin.data:4: binary data", 1);
    /* nothing half-read survives a failed read_data */
    struct gravel *g = test_engine();
    const char *p = tmpfile_with("half.data", HEAD "1 1 1 1 1 1 1\n2 1 1 1 1 zz 1\n");
    snprintf(script, sizeof script, "read_data %s\n", p);
    CHECK(test_script(g, script) == GR_ERR);
    CHECK(g->dom.box_exists == 0 && g->atoms.n == 0);
    gr_destroy(g);
    snprintf(script, sizeof script, "region b block 0 1 0 1 0 1\ncreate_box 1 b\nread_data %s\n",
             CHUTE);
    CHECK_ERROR(script, "", 3); /* phase error (dispatcher or handler) */
    snprintf(script, sizeof script, "read_data %s add merge\n", CHUTE);
    CHECK_ERROR(script, "keyword 'add' is not supported", 1);
}

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/gravel_test_data.XXXXXX");
    if (!mkdtemp(tmpdir))
        return 1;
    RUN(chute_loads);
    RUN(chute_shrink_wrap);
    RUN(round_trip);
    RUN(good_small_file);
    RUN(bad_files);
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmpdir);
    if (system(cmd) != 0)
        return 1;
    return 0;
}
