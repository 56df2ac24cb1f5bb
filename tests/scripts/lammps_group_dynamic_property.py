#!/usr/bin/env python3
"""lammps_group_dynamic_property.py - `group ID dynamic ... property P` as
LAMMPS's (2021 FixGroup: P the bare name of a custom per-atom vector).

The falling bed of peer.py with fix property/atom i_flag d_w: the lower
atoms flagged (i_flag 1), d_w nonzero above z = 4; dynamic groups on the
integer vector alone (every 10), on the floating one, and on the integer
vector within a region the bed falls through (region + property); their
counts (count()) and the z velocity of the last one's centre of mass
(vcm()) every 100 steps over two runs, i_flag set again between them.
lmp 2021 prints the same counts and to 1e-9 the same velocities. Then the
errors: a name that is no custom vector, a custom array, an invalid name.
One line PASS/FAIL per case; without `lmp` the comparison FAILs naming it."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "lib"))
from peer import expect_errors, falling_bed, thermo_against_lmp  # noqa: E402

HEAD = falling_bed(extra="fix p all property/atom i_flag d_w i2_arr 2\n"
                         "set group all i_flag 0\nregion lowz block INF INF INF INF 0 3 "
                         "units box\ngroup low region lowz\nset group low i_flag 1\n"
                         "variable wz atom z*(z>4)\nset group all d_w v_wz\n")
DECK = HEAD + """region mid block INF INF INF INF 1.5 3.5 units box
group gi dynamic all property flag every 10
group gd dynamic all property w
group gr dynamic all region mid property flag
variable ni equal count(gi)
variable nd equal count(gd)
variable nr equal count(gr)
variable kr equal vcm(gr,z)
thermo_style custom step v_ni v_nd v_nr v_kr
thermo_modify format float %.15g
thermo 100
run 1000
set group top i_flag 1
run 500
"""


def main():
    with tempfile.TemporaryDirectory() as tmp:
        ok, got, _, _, _ = thermo_against_lmp("group_dynamic_property", DECK, 5, 17, tmp, 1e-9,
                                              1e-12)
        err = os.path.join(tmp, "err")
        os.mkdir(err)
        expect_errors({
            "property_missing": ("group d dynamic all property nope\nrun 0\n",
                                 "custom per-atom vector nope for group dynamic d does not "
                                 "exist"),
            "property_array": ("group d dynamic all property arr\nrun 0\n",
                               "custom per-atom vector arr for group dynamic d does not exist"),
            "property_name": ("group d dynamic all property a-b\n",
                              "'a-b' is not a custom vector's name"),
        }, HEAD, err)


if __name__ == "__main__":
    sys.exit(main())
