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

int main(void)
{
    RUN(add_grow_remove);
    return 0;
}
