/* wall_gran_kernels.h - the kernels of fix wall/gran and wall/gran/region,
 * declared once: read by the host (styles/fix/fix_wall_gran.c picks its kernel
 * by source, model and jkr from this table) and by the device
 * (kernels/fix_wall_gran.cl instantiates every row). Valid C and OpenCL C;
 * the fix lists it among its kernel sources, before fix_wall_gran.cl. */
#ifndef GR_WALL_GRAN_KERNELS_H
#define GR_WALL_GRAN_KERNELS_H

/* the wall's contact law (`fix wall/gran ID group <model> ...`) */
enum wall_gran_model { WG_HOOKE, WG_HOOKE_HISTORY, WG_HERTZ_HISTORY, WG_GRANULAR,
                       WG_LIGGGHTS /* model ...: pair gran's (kernels/pair_gran.cl) */,
                       WG_LIGGGHTS_ROW /* the same with an epsd rolling model's history */ };
/* the contact source: plane or cylinder (kernels/wall.cl WALL_KERNEL),
 * mesh (MESH_KERNEL), region (kernels/wall_region.cl REGION_KERNEL) */
enum wall_gran_source { WG_WALL, WG_MESH, WG_REGION };

/* kernel name, source, model, jkr (a granular jkr wall: held beyond touch
 * to the pull-off distance; meshes take no jkr) */
#define WALL_GRAN_KERNELS(K)                                                                   \
    K(wall_gran_hooke, WG_WALL, WG_HOOKE, 0)                                                   \
    K(wall_gran_hooke_history, WG_WALL, WG_HOOKE_HISTORY, 0)                                   \
    K(wall_gran_hertz_history, WG_WALL, WG_HERTZ_HISTORY, 0)                                   \
    K(wall_gran_granular, WG_WALL, WG_GRANULAR, 0)                                             \
    K(wall_gran_granular_jkr, WG_WALL, WG_GRANULAR, 1)                                         \
    K(wall_gran_liggghts, WG_WALL, WG_LIGGGHTS, 0)                                             \
    K(wall_gran_liggghts_row, WG_WALL, WG_LIGGGHTS_ROW, 0)                                     \
    K(mesh_gran_hooke, WG_MESH, WG_HOOKE, 0)                                                   \
    K(mesh_gran_hooke_history, WG_MESH, WG_HOOKE_HISTORY, 0)                                   \
    K(mesh_gran_hertz_history, WG_MESH, WG_HERTZ_HISTORY, 0)                                   \
    K(mesh_gran_granular, WG_MESH, WG_GRANULAR, 0)                                             \
    K(mesh_gran_liggghts, WG_MESH, WG_LIGGGHTS, 0)                                             \
    K(mesh_gran_liggghts_row, WG_MESH, WG_LIGGGHTS_ROW, 0)                                     \
    K(region_gran_hooke, WG_REGION, WG_HOOKE, 0)                                               \
    K(region_gran_hooke_history, WG_REGION, WG_HOOKE_HISTORY, 0)                               \
    K(region_gran_hertz_history, WG_REGION, WG_HERTZ_HISTORY, 0)                               \
    K(region_gran_granular, WG_REGION, WG_GRANULAR, 0)                                         \
    K(region_gran_granular_jkr, WG_REGION, WG_GRANULAR, 1)

#endif
