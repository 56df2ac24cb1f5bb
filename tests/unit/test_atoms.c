/* test_atoms.c - host atom arrays: add, grow, remove, tag lookup. */
#include "test.h"

#include "atoms.h"

TEST(add_grow_remove)
{
    struct gravel *g = test_engine();
    atoms_set_ntypes(g, 2);
    for (int i = 0; i < 3000; i++) {
        double x[3] = {i, 2.0 * i, 3.0 * i};
        atoms_add(g, 0, 1 + i % 2, x, 0.5, 1.0);
    }
    CHECK(g->atoms.n == 3000);
    CHECK(g->atoms.cap >= 3000);
    CHECK(g->atoms.tag[2999] == 3000);
    CHECK(atoms_find_tag(&g->atoms, 1500) == 1499);
    atoms_remove(g, 0);
    CHECK(g->atoms.n == 2999);
    CHECK(g->atoms.tag[0] == 3000);
    CHECK(g->atoms.x[1] == 2.0 * 2999);
    CHECK(atoms_find_tag(&g->atoms, 1) == -1);
    gr_destroy(g);
}

/* Every row of the field table (atom_fields.h) moves with atoms_remove, and a
 * slot reused by atoms_add starts from zero whatever it held before. */
TEST(every_field_moves_and_resets)
{
    struct gravel *g = test_engine();
    struct atoms *a = &g->atoms;
    a->ellipsoid_flag = 1; /* every row held (atoms_holds) */
    atoms_set_ntypes(g, 1);
    double x[3] = {1, 2, 3};
    atoms_add(g, 0, 1, x, 0.5, 1.0);
    atoms_add(g, 0, 1, x, 0.5, 1.0);
    int k = 0;
#define FILL(name, ctype, dev, width, when, life, sect, what)                                  \
    memset(a->name + (width), 0x41 + k++, (width) * sizeof(ctype));
    ATOM_FIELDS(FILL)
#undef FILL
    atoms_remove(g, 0); /* atom 2 moves into slot 0 */
    CHECK(a->n == 1);
    k = 0;
#define MOVED(name, ctype, dev, width, when, life, sect, what)                                 \
    {                                                                                         \
        unsigned char want[64];                                                               \
        memset(want, 0x41 + k++, sizeof want);                                                \
        if (memcmp(a->name, want, (width) * sizeof(ctype)))                                   \
            printf("  field %s not moved by atoms_remove\n", #name);                         \
        CHECK(!memcmp(a->name, want, (width) * sizeof(ctype)));                               \
    }
    ATOM_FIELDS(MOVED)
#undef MOVED
    atoms_remove(g, 0);
    double y[3] = {4, 5, 6};
    int i = atoms_add(g, 7, 1, y, 0.25, 2.0); /* reuses the filled slot 0 */
    CHECK(i == 0 && a->tag[0] == 7 && a->type[0] == 1 && a->mask[0] == 1u);
    CHECK(a->x[0] == 4 && a->x[1] == 5 && a->x[2] == 6);
    CHECK(a->radius[0] == 0.25 && a->rmass[0] == 2.0);
#define ZERO(name, ctype, dev, width, when, life, sect, what)                                  \
    {                                                                                         \
        static const unsigned char zero[64];                                                  \
        const char *given = "tag type mask x radius rmass";                                   \
        if (!strstr(given, #name) && memcmp(a->name, zero, (width) * sizeof(ctype)))           \
            printf("  field %s of a reused slot is not zero\n", #name);                      \
        CHECK(strstr(given, #name) || !memcmp(a->name, zero, (width) * sizeof(ctype)));        \
    }
    ATOM_FIELDS(ZERO)
#undef ZERO
    gr_destroy(g);
}

/* Without atom_style ellipsoid superellipsoid its rows are not held: appends,
 * removals and growth leave them untouched (zero pages that cost no memory). */
TEST(unheld_rows_untouched)
{
    struct gravel *g = test_engine();
    struct atoms *a = &g->atoms;
    atoms_set_ntypes(g, 1);
    double x[3] = {1, 2, 3};
    atoms_add(g, 0, 1, x, 0.5, 1.0);
    atoms_add(g, 0, 1, x, 0.5, 1.0);
    CHECK(!atoms_holds(a, FW_ELLIPSOID) && atoms_holds(a, FW_ALWAYS) && atoms_holds(a, FW_HEAT));
    a->quat[0] = 11.0;
    a->quat[4] = 22.0;
    atoms_remove(g, 0); /* atom 2 moves into slot 0; its quaternion does not */
    CHECK(a->n == 1 && a->quat[0] == 11.0);
    for (int i = 0; i < 5000; i++) /* growth: the unheld rows' content is not copied */
        atoms_add(g, 0, 1, x, 0.5, 1.0);
    CHECK(a->quat[0] == 0.0 && a->tag[0] == 2);
    gr_destroy(g);
}

int main(void)
{
    RUN(add_grow_remove);
    RUN(every_field_moves_and_resets);
    RUN(unheld_rows_untouched);
    return 0;
}
