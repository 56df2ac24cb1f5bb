/* test_compute.c - computes ke, ke/atom, erotate/sphere, reduce and
 * count/type on a hand-made 4-atom system with values worked out by hand,
 * groups, extensive flags, uncompute, and argument errors. */
#include "output_fixture.h"

/* atom  m    r     v           omega      type
 *  1    2    0.5   (1,2,3)     (1,0,0)    1
 *  2    1    1.0   (-1,0,2)    (0,2,0)    2
 *  3    3    0.25  (0,0,-2)    (1,1,1)    1
 *  4    0.5  0.5   (4,0,0)     (0,0,0)    2
 * ke = 1/2 (2*14 + 1*5 + 3*4 + 0.5*16) = 26.5
 * erotate = 1/2 * 0.4 * (2*.25*1 + 1*1*4 + 3*.0625*3 + 0) = 1.0125
 * group "even" (atoms 1 and 3): ke 20, erotate 0.2125 */
static struct gravel *make(void)
{
    struct gravel *g = test_engine();
    double lo[3] = {0, 0, 0}, hi[3] = {10, 10, 10};
    fx_box(g, lo, hi, 2);
    double v1[3] = {1, 2, 3}, w1[3] = {1, 0, 0};
    double v2[3] = {-1, 0, 2}, w2[3] = {0, 2, 0};
    double v3[3] = {0, 0, -2}, w3[3] = {1, 1, 1};
    double v4[3] = {4, 0, 0};
    fx_atom(g, 1, 1, 1, 1, 0.5, 2.0, v1, w1);
    fx_atom(g, 2, 2, 2, 2, 1.0, 1.0, v2, w2);
    fx_atom(g, 1, 3, 3, 3, 0.25, 3.0, v3, w3);
    fx_atom(g, 2, 4, 4, 4, 0.5, 0.5, v4, NULL);
    g->atoms.f[0] = 1.5;
    g->atoms.torque[3 * 3 + 2] = -7;
    fx_group_parity(g, 1, "even", 0);
    fx_group_parity(g, 2, "none", 5);
    return g;
}

static double scalar(struct gravel *g, const char *id)
{
    return compute_scalar(g, compute_find(g, id));
}

TEST(ke_and_erotate)
{
    struct gravel *g = make();
    CHECK(test_script(g, "compute k all ke\ncompute ke even ke\n"
                         "compute r all erotate/sphere\ncompute re even erotate/sphere\n") ==
          GR_OK);
    CHECK_NEAR(scalar(g, "k"), 26.5, 1e-13);
    CHECK_NEAR(scalar(g, "ke"), 20.0, 1e-13);
    CHECK_NEAR(scalar(g, "r"), 1.0125, 1e-14);
    CHECK_NEAR(scalar(g, "re"), 0.2125, 1e-14);
    struct compute *c = compute_find(g, "k");
    CHECK(c->scalar_flag && !c->vector_flag && c->extscalar);
    /* ke/atom: per atom, zero outside the group */
    CHECK(test_script(g, "compute ka even ke/atom\n") == GR_OK);
    const double *pa = compute_peratom(g, compute_find(g, "ka"));
    CHECK_NEAR(pa[0], 14.0, 1e-13);
    CHECK(pa[1] == 0.0);
    CHECK_NEAR(pa[2], 6.0, 1e-13);
    CHECK(pa[3] == 0.0);
    fx_destroy(g);
}

static void eval_rk(struct gravel *g, int argc, char **argv)
{
    (void)argc;
    (void)argv;
    compute_vector(g, compute_find(g, "rk"));
}

static void eval_named(struct gravel *g, int argc, char **argv)
{
    (void)argc;
    compute_scalar(g, compute_find(g, argv[0]));
}

TEST(reduce)
{
    struct gravel *g = make();
    CHECK(test_script(g, "compute s all reduce sum vx vy vz\n"
                         "compute mn all reduce min vz\n"
                         "compute mx all reduce max radius diameter\n"
                         "compute av all reduce ave mass\n"
                         "compute ave even reduce ave mass\n"
                         "compute sq all reduce sumsq vx\n"
                         "compute asq all reduce avesq vx\n"
                         "compute ab all reduce sumabs vz\n"
                         "compute aab all reduce aveabs vz\n"
                         "compute ff all reduce sum fx tqz omegay x\n"
                         "compute ka all ke/atom\n"
                         "compute kae even ke/atom\n"
                         "compute rk all reduce sum c_ka c_kae\n"
                         "compute e none reduce min vx\n"
                         "compute e2 none reduce max vx\n"
                         "compute e3 none reduce ave vx\n") == GR_OK);
    struct compute *s = compute_find(g, "s");
    CHECK(s->vector_flag && s->size_vector == 3 && s->extvector == 1 && !s->scalar_flag);
    const double *v = compute_vector(g, s);
    CHECK(v[0] == 4.0 && v[1] == 2.0 && v[2] == 3.0);
    CHECK(scalar(g, "mn") == -2.0);
    CHECK(compute_find(g, "mn")->extscalar == 0);
    v = compute_vector(g, compute_find(g, "mx"));
    CHECK(v[0] == 1.0 && v[1] == 2.0);
    CHECK(compute_find(g, "mx")->extvector == 0);
    CHECK_NEAR(scalar(g, "av"), 1.625, 1e-15);
    CHECK_NEAR(scalar(g, "ave"), 2.5, 1e-15);
    CHECK(scalar(g, "sq") == 18.0);
    CHECK(compute_find(g, "sq")->extscalar == 1);
    CHECK(scalar(g, "asq") == 4.5);
    CHECK(scalar(g, "ab") == 7.0);
    CHECK(scalar(g, "aab") == 1.75);
    v = compute_vector(g, compute_find(g, "ff"));
    CHECK(v[0] == 1.5 && v[1] == -7.0 && v[2] == 2.0 + 1.0 && v[3] == 10.0);
    v = compute_vector(g, compute_find(g, "rk"));
    CHECK_NEAR(v[0], 26.5, 1e-13);
    CHECK_NEAR(v[1], 20.0, 1e-13);
    /* empty group: LAMMPS' sentinels */
    CHECK(scalar(g, "e") == 1.0e20);
    CHECK(scalar(g, "e2") == -1.0e20);
    CHECK(scalar(g, "e3") == 0.0);
    /* values follow the atoms */
    g->atoms.v[0] = 11;
    CHECK(compute_vector(g, s)[0] == 14.0);
    /* reducing a compute that is gone is caught */
    CHECK(test_script(g, "uncompute ka\n") == GR_OK);
    CHECK(fx_call(g, eval_rk, 0, NULL) == 1);
    CHECK(strstr(g->err.msg, "unknown compute ID 'ka'") != NULL);
    fx_destroy(g);
}

static void do_init_all(struct gravel *g, int argc, char **argv)
{
    (void)argc;
    (void)argv;
    compute_init_all(g);
}

TEST(reduce_references)
{
    struct gravel *g = make();
    CHECK(test_script(g, "compute ka all ke/atom\ncompute rk all reduce max c_ka\n"
                         "compute k all ke\n") == GR_OK);
    /* checked when the command is read, as LAMMPS: the compute is not added */
    CHECK(test_script(g, "compute bad all reduce sum c_k\n") == GR_ERR);
    CHECK(strstr(g->err.msg, "compute k (ke) does not produce per-atom values") != NULL);
    CHECK(compute_find(g, "bad") == NULL);
    CHECK(fx_call(g, do_init_all, 0, NULL) == 0);
    CHECK_NEAR(scalar(g, "rk"), 14.0, 1e-13);
    CHECK(test_script(g, "uncompute ka\n") == GR_OK);
    CHECK(fx_call(g, do_init_all, 0, NULL) == 1);
    CHECK(strstr(g->err.msg, "unknown compute ID 'ka'") != NULL);
    fx_destroy(g);
}

/* property/atom: one attribute = per-atom vector, several = array; reduce
 * and references by column. */
TEST(property_atom)
{
    struct gravel *g = make();
    CHECK(test_script(g, "compute pv even property/atom radius\n"
                         "compute pa all property/atom x vz id diameter\n"
                         "compute r1 all reduce max c_pv\n"
                         "compute r2 all reduce sum c_pa[2] c_pa[3] c_pa[4]\n") == GR_OK);
    struct compute *pv = compute_find(g, "pv"), *pa = compute_find(g, "pa");
    CHECK(pv->peratom_flag && pv->size_peratom_cols == 0);
    CHECK(pa->peratom_flag && pa->size_peratom_cols == 4);
    const double *v = compute_peratom(g, pv);
    CHECK(v[0] == 0.5 && v[1] == 0.0 && v[2] == 0.25 && v[3] == 0.0);
    v = compute_peratom(g, pa);
    CHECK(v[0] == 1 && v[1] == 3 && v[2] == 1 && v[3] == 1.0); /* atom 1: x, vz, id, diameter */
    CHECK(v[12] == 4 && v[13] == 0 && v[14] == 4 && v[15] == 1.0);
    CHECK(scalar(g, "r1") == 0.5);
    v = compute_vector(g, compute_find(g, "r2"));
    CHECK(v[0] == 3.0 && v[1] == 10.0 && v[2] == 1.0 + 2.0 + 0.5 + 1.0);
    /* wrong forms are errors of the command itself (as LAMMPS) */
    CHECK(test_script(g, "compute bad1 all reduce sum c_pa\n") == GR_ERR);
    CHECK(strstr(g->err.msg, "compute pa has 4 per-atom columns; use c_pa[N]") != NULL);
    CHECK(test_script(g, "compute bad2 all reduce sum c_pv[1]\n") == GR_ERR);
    CHECK(strstr(g->err.msg, "compute pv has one per-atom value; use c_pv") != NULL);
    CHECK(test_script(g, "compute bad3 all reduce sum c_pa[5]\n") == GR_ERR);
    CHECK(strstr(g->err.msg, "c_pa[5] is out of range") != NULL);
    CHECK(!compute_find(g, "bad1") && !compute_find(g, "bad2") && !compute_find(g, "bad3"));
    /* and at evaluation, when the referenced compute changed since */
    CHECK(test_script(g, "compute pq all property/atom x vz\ncompute bad4 all reduce sum c_pq[2]\n"
                         "uncompute pq\ncompute pq all property/atom x\n") == GR_OK);
    CHECK(fx_call(g, eval_named, 1, (char *[]){"bad4"}) == 1);
    CHECK(strstr(g->err.msg, "compute pq has one per-atom value; use c_pq") != NULL);
    fx_destroy(g);
}

TEST(count_type)
{
    struct gravel *g = make();
    CHECK(test_script(g, "compute c all count/type atom\ncompute ce even count/type atom\n") ==
          GR_OK);
    struct compute *c = compute_find(g, "c");
    CHECK(c->vector_flag && c->size_vector == 2 && c->extvector == 1);
    const double *v = compute_vector(g, c);
    CHECK(v[0] == 2.0 && v[1] == 2.0);
    v = compute_vector(g, compute_find(g, "ce"));
    CHECK(v[0] == 2.0 && v[1] == 0.0);
    fx_destroy(g);
}

TEST(registry)
{
    struct gravel *g = make();
    CHECK(test_script(g, "compute a all ke\nuncompute a\ncompute a all erotate/sphere\n") ==
          GR_OK);
    CHECK(g->styles.ncompute == 1);
    CHECK(strcmp(compute_find(g, "a")->style->name, "erotate/sphere") == 0);
    CHECK(test_script(g, "compute b even ke\n") == GR_OK);
    CHECK(compute_find(g, "b")->groupbit == 2u);
    /* a failed create leaves nothing registered */
    CHECK(test_script(g, "compute z all reduce bogus vx\n") == GR_ERR);
    CHECK(compute_find(g, "z") == NULL && g->styles.ncompute == 2);
    char id[GR_NAMELEN];
    int index;
    CHECK(compute_parse_ref("c_abc[12]", id, &index) && strcmp(id, "abc") == 0 && index == 12);
    CHECK(compute_parse_ref("c_abc", id, &index) && index == 0);
    CHECK(!compute_parse_ref("c_abc[", id, &index));
    CHECK(!compute_parse_ref("c_abc[1]x", id, &index));
    CHECK(!compute_parse_ref("c_[1]", id, &index));
    CHECK(!compute_parse_ref("v_abc", id, &index));
    fx_destroy(g);
}

TEST(errors)
{
    FX_CHECK_ERROR("compute 1 all kinetic\n", "unknown compute style 'kinetic'", 1);
    FX_CHECK_ERROR("compute 1 all ke\ncompute 1 all ke\n", "compute ID '1' already exists", 2);
    FX_CHECK_ERROR("compute a-b all ke\n", "only letters, digits and underscores", 1);
    FX_CHECK_ERROR("compute 1 nogroup ke\n", "unknown group 'nogroup'", 1);
    FX_CHECK_ERROR("compute 1 all ke extra\n", "takes no arguments", 1);
    FX_CHECK_ERROR("compute 1 all erotate/sphere x\n", "takes no arguments", 1);
    FX_CHECK_ERROR("compute 1 all reduce sum\n", "a mode and at least one input", 1);
    FX_CHECK_ERROR("compute 1 all reduce total vx\n", "unknown mode 'total'", 1);
    FX_CHECK_ERROR("compute 1 all reduce sum vw\n", "unknown input 'vw'", 1);
    FX_CHECK_ERROR("compute 1 all reduce sum v_a\nprint $(c_1)\n",
                   "compute reduce: variable 'a' is not defined", 2);
    FX_CHECK_ERROR("compute 1 all reduce sum f_a\n", "no fix with ID 'a' for f_a", 1);
    FX_CHECK_ERROR("fix 1 all nve\ncompute 1 all reduce sum f_1\n",
                   "fix 1 (nve) does not calculate per-atom values", 2);
    FX_CHECK_ERROR("compute 1 all reduce sum c_1\n", "cannot reduce itself", 1);
    FX_CHECK_ERROR("compute 1 all reduce sum vx inputs local\n",
                   "inputs local takes only c_ID and c_ID[N] of local computes: 'vx' is per atom",
                   1);
    FX_CHECK_ERROR("compute k all ke/atom\ncompute 1 all reduce sum c_k inputs local\n",
                   "compute k (ke/atom) does not produce local values", 2);
    FX_CHECK_ERROR("compute 1 all reduce sum vx inputs atoms\n", "inputs expects peratom or local",
                   1);
    FX_CHECK_ERROR("compute 1 all reduce sum vx inputs\n", "inputs expects peratom or local", 1);
    FX_CHECK_ERROR("compute 1 all reduce sum inputs local\n", "a mode and at least one input",
                   1);
    FX_CHECK_ERROR("compute 1 all reduce max vx replace 1 2\n", "'replace' is not supported", 1);
    FX_CHECK_ERROR("compute 1 all property/atom\n", "at least one attribute", 1);
    FX_CHECK_ERROR("compute 1 all property/atom x q\n", "unknown attribute 'q'", 1);
    FX_CHECK_ERROR("compute 1 all count/type bond\n", "supports only 'atom'", 1);
    FX_CHECK_ERROR("\nuncompute nope\n", "unknown compute ID 'nope'", 2);
    CHECK_ERROR("compute 1 all ke\n", "needs a simulation box", 1);
}

int main(void)
{
    RUN(ke_and_erotate);
    RUN(reduce);
    RUN(reduce_references);
    RUN(property_atom);
    RUN(count_type);
    RUN(registry);
    RUN(errors);
    return 0;
}
