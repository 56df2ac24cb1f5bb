/* fix_move_mesh.c - `fix ID group move/mesh mesh MESHID style args`: a rigid
 * motion of the mesh of a fix mesh/surface, LIGGGHTS names and arguments:
 *
 *   linear vx vy vz                         x(t) = x0 + v t
 *   wiggle amplitude ax ay az period T      x(t) = x0 + A sin(2 pi t / T)
 *   rotate origin ox oy oz axis ax ay az period T
 *                                           rotation by 2 pi t / T about the
 *                                           axis through o (right hand rule)
 *
 * t counts from the step the fix was created, in steps run: reset_timestep
 * moves that origin with the step counter, so the motion continues across
 * it (LAMMPS 2021's fix move, timed from the step alone, jumps back; later
 * LAMMPS refuses the reset). Several move/mesh fixes on one
 * mesh stack: each motion acts on the mesh as the earlier ones left it, in
 * the order of the fixes (fix_mesh_surface.c composes them into one rigid
 * pose x = R x0 + d with surface velocity v(p) = V0 + omega x p, exact at
 * every step: no drift from integrating the motion). The group is ignored,
 * as in LIGGGHTS. Restart state: the time origin. */
#include <math.h>
#include <string.h>

#include "args.h"
#include "error.h"
#include "fix_mesh_surface.h"
#include "rigid_math.h"

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    if (argc < 3 || strcmp(argv[0], "mesh") != 0)
        gr_error(g, "fix move/mesh expects 'mesh MESHID style args' (style linear, wiggle or "
                    "rotate)");
    struct mesh_surface *ms = mesh_surface_get(g, argv[1], "fix move/mesh");
    if (ms->has_surface_vel)
        gr_error(g, "fix move/mesh: cannot apply move to a mesh using keyword 'surface_vel' "
                    "(mesh %s)", argv[1]);
    struct mesh_motion mo;
    memset(&mo, 0, sizeof mo);
    snprintf(mo.mesh, sizeof mo.mesh, "%s", argv[1]);
    const char *st = argv[2];
    int used;
    if (!strcmp(st, "linear")) {
        arg_need(g, argc, 2, 3, st);
        mo.kind = MOVE_LINEAR;
        for (int k = 0; k < 3; k++)
            mo.v[k] = arg_double(g, argv[3 + k], "linear velocity");
        used = 6;
    } else if (!strcmp(st, "wiggle")) {
        arg_need(g, argc, 2, 6, st);
        if (strcmp(argv[3], "amplitude") || strcmp(argv[7], "period"))
            gr_error(g, "fix move/mesh wiggle expects 'amplitude ax ay az period T'");
        mo.kind = MOVE_WIGGLE;
        for (int k = 0; k < 3; k++)
            mo.v[k] = arg_double(g, argv[4 + k], "wiggle amplitude");
        mo.period = arg_positive(g, argv[8], "wiggle period");
        used = 9;
    } else if (!strcmp(st, "rotate")) {
        arg_need(g, argc, 2, 10, st);
        if (strcmp(argv[3], "origin") || strcmp(argv[7], "axis") || strcmp(argv[11], "period"))
            gr_error(g, "fix move/mesh rotate expects 'origin ox oy oz axis ax ay az period T'");
        mo.kind = MOVE_ROTATE;
        for (int k = 0; k < 3; k++) {
            mo.origin[k] = arg_double(g, argv[4 + k], "rotate origin");
            mo.axis[k] = arg_double(g, argv[8 + k], "rotate axis");
        }
        if (rm_unit_axis(mo.axis, mo.axis))
            gr_error(g, "fix move/mesh rotate axis is zero");
        mo.period = arg_positive(g, argv[12], "rotate period");
        if (!ms->ref_set) {
            memcpy(ms->ref, mo.origin, sizeof ms->ref);
            ms->ref_set = 1;
        }
        used = 13;
    } else {
        gr_error(g, "unknown fix move/mesh style '%.64s' (expected linear, wiggle or rotate)",
                 st);
    }
    if (argc > used)
        gr_error(g, "fix move/mesh %s: unexpected argument '%.64s'", st, argv[used]);
    mo.time_origin = g->step;
    struct mesh_motion *p = gr_malloc(g, sizeof *p);
    *p = mo;
    f->data = p;
    f->hooks = 0;
}

static size_t write_restart(struct gravel *g, struct fix *f, unsigned char *buf, size_t cap)
{
    (void)g;
    int64_t origin = ((struct mesh_motion *)f->data)->time_origin;
    if (buf && cap >= sizeof origin)
        memcpy(buf, &origin, sizeof origin);
    return sizeof origin;
}

static void read_restart(struct gravel *g, struct fix *f, const unsigned char *buf, size_t len)
{
    int64_t origin;
    if (len != sizeof origin)
        gr_error(g, "fix %s: restart state of %zu bytes, expected %zu", f->id, len,
                 sizeof origin);
    memcpy(&origin, buf, sizeof origin);
    ((struct mesh_motion *)f->data)->time_origin = origin;
}

/* reset_timestep: the motion keeps its own clock (t = step - origin) */
static void reset_step(struct gravel *g, struct fix *f, bigint shift)
{
    (void)g;
    ((struct mesh_motion *)f->data)->time_origin += shift;
}

/* unfix: the mesh stays where the motion put it (LIGGGHTS moves the mesh's
 * nodes). With other motions on the mesh the pose is a composition that
 * baking would break: refused (LIGGGHTS allows unfixing the last one). */
static void unfix(struct gravel *g, struct fix *f)
{
    const struct mesh_motion *mo = f->data;
    for (int i = 0; i < g->styles.nfix; i++) {
        const struct fix *o = g->styles.fix[i];
        if (o != f && o->style == f->style && !strcmp(((struct mesh_motion *)o->data)->mesh,
                                                       mo->mesh))
            gr_error(g, "unfix %s: fix move/mesh %s also moves mesh %s: unfixing one of "
                        "superposed fix move/mesh commands is not supported", f->id, o->id,
                     mo->mesh);
    }
    mesh_surface_bake(g, mo->mesh);
}

const struct fix_style fix_style_move_mesh = {
    .name = "move/mesh",
    .create = create,
    .unfix = unfix,
    .reset_step = reset_step,
    .write_restart = write_restart,
    .read_restart = read_restart,
};
