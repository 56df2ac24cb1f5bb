/* fix_wall_gran.cl - the LAMMPS granular wall models (fix wall/gran, 2021
 * semantics; host side styles/fix_wall_gran.c): the wall stage of the
 * contact pipeline (kernels/wall.cl) with the pair evaluators of
 * pair_gran_hooke.cl, pair_gran_hooke_history.cl and
 * pair_gran_hertz_history.cl, so the wall physics is the pair physics. */

WALL_KERNEL(wall_gran_hooke, gran_hooke_eval)
WALL_KERNEL(wall_gran_hooke_history, gran_hooke_history_eval)
WALL_KERNEL(wall_gran_hertz_history, gran_hertz_history_eval)

/* mesh walls (fix wall/gran ... mesh): the same laws against triangles */
MESH_KERNEL(mesh_gran_hooke, gran_hooke_eval)
MESH_KERNEL(mesh_gran_hooke_history, gran_hooke_history_eval)
MESH_KERNEL(mesh_gran_hertz_history, gran_hertz_history_eval)

/* region walls (fix wall/gran/region): the same laws against region surfaces */
REGION_KERNEL(region_gran_hooke, gran_hooke_eval)
REGION_KERNEL(region_gran_hooke_history, gran_hooke_history_eval)
REGION_KERNEL(region_gran_hertz_history, gran_hertz_history_eval)
