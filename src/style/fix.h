/* fix.h - fixes: operations applied to a group of atoms at fixed points of
 * each time step (`fix ID group style args`, `unfix ID`).
 *
 * A style is a descriptor (struct fix_style) in styles/fix_<ident>.c plus,
 * when it has device work, kernels in kernels/fix_<ident>.cl. Registration is
 * one FIX(keyword, ident) row in styles/styles.def.
 *
 * Life cycle of an instance:
 *   create()   at the `fix` command: parse and validate the arguments, set
 *              f->hooks (HOOK_* bits), f->needs (NEED_* bits), f->sources
 *              (kernel files the run program must include) and f->defines
 *              (extra build options, without the leading "-D "). May not
 *              touch the device.
 *   prepare()  optional, at every `run` before the program is assembled:
 *              settle what the fix takes from commands given after it
 *              (fix surface/local makes its wall here, from pair_coeff).
 *   init()     at every `run`, after the program is built, the atoms are on
 *              the device and the pair parameters are packed and uploaded
 *              (g->eng->pair_param, the pair style's record
 *              g->styles.pair->caps: src/style/pair.h): create kernels with
 *              eng_kernel(), size per-atom device state (f->peratom_bytes),
 *              check other styles. What the core must know about a style is
 *              declared in its descriptor (.flags: FIX_*), never found by
 *              its name.
 *   hooks      called by the run loop in LAMMPS' Verlet order, only for the
 *              bits set in f->hooks:
 *                initial_integrate -> (neighbor) -> pair -> post_force
 *                -> final_integrate -> end_of_step
 *              During the setup force computation (step 0 of a run) only
 *              post_force runs, with eng_in_setup(g) true (LAMMPS' setup():
 *              no shear-history update).
 *   pre_force  (HOOK_PRE_FORCE) called on every step after the neighbor
 *              decision (and rebuild) and before the pair forces (LAMMPS's
 *              pre_force), and once at setup before the setup forces, with
 *              eng_in_setup(g) true (LAMMPS's setup_pre_force); a fix with
 *              this hook turns off the fused look-ahead of the next step.
 *   post_integrate  (HOOK_POST_INTEGRATE) called on every step after
 *              every fix's initial_integrate and before the neighbor
 *              decision (LAMMPS's post_integrate: fix wall/reflect); a fix
 *              with this hook turns off the fused initial_integrate stage
 *              and the look-ahead, so the rebuild check sees its moves.
 *   pre_exchange  (HOOK_PRE_EXCHANGE) called on every step whose neighbor
 *              list is rebuilt, after initial_integrate and before the
 *              rebuild (LAMMPS' pre_exchange), with the atoms on the device.
 *              A fix that sets f->force_reneighbor forces a rebuild on the
 *              step f->next_reneighbor (LAMMPS' next_reneighbor; 0 = none);
 *              the run loop compares it with the step, nothing else.
 *              Atom insertion (fix pour) happens here: run_sync_host(),
 *              atoms_add() on the host, then eng_append() (engine.h) puts
 *              the new atoms on the device behind the others, keeping the
 *              contact history of the existing contacts.
 *   reserve()  optional, at every `run` before the upload: the most atoms
 *              the fix may add within the run's nsteps steps and their
 *              largest radius (device capacity, neighbor cut-off).
 *   destroy()  at unfix/clear: free f->data (not device objects: kernels
 *              belong to the engine and die with the program).
 *
 * Device access for hooks (src/engine/device.h): eng_atoms(g) gives the per-atom
 * buffers in device order (the rows of src/state/atom_fields.h: x, v, f, omega,
 * torque, radius, rmass, type, mask, tag, image, mol; n atoms). Buffers are
 * swapped when atoms are re-sorted, so set kernel arguments in every hook
 * call (cheap), never once in init().
 *
 * Per-atom state that must follow the atoms through re-sorts (e.g. wall
 * contact history) is declared by setting f->peratom_bytes (a multiple of 4)
 * in init(); the engine then provides f->peratom (eng_fix_state, engine.h),
 * a zero-filled device buffer of peratom_bytes per atom in device order,
 * permuted with the atoms on every neighbor rebuild and kept across runs
 * while the atoms are unchanged. */
#ifndef GR_FIX_H
#define GR_FIX_H

#include "state.h"
#include "ocl.h"

enum fix_hook {
    HOOK_INITIAL_INTEGRATE = 1 << 0,
    HOOK_POST_FORCE = 1 << 1,
    HOOK_FINAL_INTEGRATE = 1 << 2,
    HOOK_END_OF_STEP = 1 << 3,
    HOOK_PRE_EXCHANGE = 1 << 4,
    HOOK_PRE_FORCE = 1 << 5,
    HOOK_POST_INTEGRATE = 1 << 6,
};

/* Per-atom fields / device features a style needs. */
enum fix_need {
    NEED_ROTATION = 1 << 0,     /* omega and torque arrays */
};

/* What a style declares about itself (struct fix_style .flags), read by the
 * core instead of naming styles:
 *   FIX_FROZEN       its group is held in place (fix freeze): a contact
 *                    with a held atom takes the moving atom's mass as m*
 *                    (LAMMPS pair gran's freeze group); the run uses the
 *                    first such fix's group (fix_frozen_groupbit).
 *   FIX_CONSERVING   it only integrates or holds atoms (nve, nve/sphere,
 *                    freeze): no work on the system, so a scene of such fixes
 *                    and a conservative pair law reports its energy drift.
 *   FIX_STORES_IDS   it holds atoms by their IDs (fix rigid/small's bodies):
 *                    commands that renumber atoms refuse while it exists
 *                    (LAMMPS's Fix::stores_ids).
 *   FIX_OUTPUT       it only samples and writes (ave/chunk, ave/time,
 *                    ave/histo): it never moves an atom or changes a force,
 *                    so read_restart continues exactly when its arguments
 *                    differ from the writer's (another file, `append`).
 *   FIX_WALL         its walls push particles by contact (wall/gran,
 *                    wall/gran/region, wall/pair): a particle centred on a
 *                    wall's surface is a likely cause of a non-finite run.
 *   FIX_BOX_CHANGE   it changes the box's size during a run (deform, npt,
 *                    nph: LAMMPS's box_change_size), so layouts laid out on
 *                    the box (spatial bins) may change with it. */
enum fix_flag {
    FIX_FROZEN = 1 << 0,
    FIX_CONSERVING = 1 << 1,
    FIX_STORES_IDS = 1 << 2,
    FIX_OUTPUT = 1 << 3,
    FIX_WALL = 1 << 4,
    FIX_BOX_CHANGE = 1 << 5,
};

#define FIX_MAX_SOURCES 10

struct fix;
struct fused_op;

struct fix_style {
    const char *name;
    unsigned flags;             /* FIX_* (above) */
    void (*create)(struct gravel *g, struct fix *f, int argc, char **argv);
    void (*init)(struct gravel *g, struct fix *f);                 /* optional */
    /* optional: at every `run`, before the program is assembled (before
     * init and before f->hooks, f->needs, f->sources are read): a fix
     * settles what it takes from commands given after it (fix
     * surface/local: its wall's model from pair_coeff ... surf/granular). */
    void (*prepare)(struct gravel *g, struct fix *f);
    void (*initial_integrate)(struct gravel *g, struct fix *f);
    void (*post_force)(struct gravel *g, struct fix *f);
    void (*final_integrate)(struct gravel *g, struct fix *f);
    void (*end_of_step)(struct gravel *g, struct fix *f);
    void (*pre_exchange)(struct gravel *g, struct fix *f);
    void (*pre_force)(struct gravel *g, struct fix *f);
    void (*post_integrate)(struct gravel *g, struct fix *f);
    /* atoms this fix may insert in the next nsteps steps (0: none); sets
     * *rmax to their largest radius (see header comment) */
    int (*reserve)(struct gravel *g, struct fix *f, bigint nsteps, double *rmax);
    void (*destroy)(struct fix *f);                                /* optional */
    /* Optional: LAMMPS's Fix::setup, called once per run after the setup
     * force computation (step 0 of the run, forces current) and before the
     * first thermo line; independent of the hook bits. */
    void (*setup)(struct gravel *g, struct fix *f);
    /* Restart files (restart.c), optional: global state of the instance as
     * bytes. write_restart stores at most cap bytes at buf and returns the
     * size (called with buf NULL to ask the size). read_restart gets exactly
     * those bytes back for a fix re-created with the same ID and style, at
     * the start of the next run (after init); it validates len itself. */
    size_t (*write_restart)(struct gravel *g, struct fix *f, unsigned char *buf, size_t cap);
    void (*read_restart)(struct gravel *g, struct fix *f, const unsigned char *buf, size_t len);
    /* Optional: this fix's per-particle work at `hook` as one fused op
     * (src/engine/fused.h), run inside the scene's kernels instead of the hook;
     * return 0 when it cannot be fused this run. Called at run setup,
     * after init. */
    int (*fuse)(struct gravel *g, struct fix *f, unsigned hook, struct fused_op *op);
    /* Optional: LAMMPS's Fix::post_neighbor, called after every neighbor
     * rebuild (the setup one included), once the atoms are in their new
     * device order and wrapped into the box. */
    void (*post_neighbor)(struct gravel *g, struct fix *f);
    /* Optional: degrees of freedom this fix removes from the atoms of
     * groupbit (LAMMPS Fix::dof, e.g. rigid bodies); temperatures subtract
     * the sum over fixes. */
    double (*dof)(struct gravel *g, struct fix *f, unsigned groupbit);
    /* Optional: added to thermo ke and etotal (LIGGGHTS's fix multisphere:
     * a body counts 1/2 M vcm^2, not its atoms' 1/2 sum m v^2). */
    double (*ke_adjust)(struct gravel *g, struct fix *f);
    /* Optional: the magnitude of the uniform acceleration this fix applies
     * to its atoms (fix gravity): the -check accuracy map's free-fall speed. */
    double (*acceleration)(const struct fix *f);
    /* Optional: reset_timestep moved the step counter by `shift` steps
     * (between runs). A motion timed by its own start step (time_origin)
     * moves that origin by shift, so its clock, and the motion, continue
     * where they stood; step-keyed caches move with it. */
    void (*reset_step)(struct gravel *g, struct fix *f, bigint shift);
    /* Optional: LAMMPS's Fix::modify_param, the style's own fix_modify
     * keywords: argv[0] is the keyword; returns the words it used (0: not
     * its keyword). */
    int (*modify_param)(struct gravel *g, struct fix *f, int argc, char **argv);
    /* Optional: `unfix ID` is about to delete the fix (LIGGGHTS's pre_delete):
     * what it leaves behind (fix move/mesh: the mesh stays where it moved it). */
    void (*unfix)(struct gravel *g, struct fix *f);
    /* Global vector for `f_ID[i]` in thermo output, optional: size_vector
     * values (the instance's f->size_vector starts from it; create may
     * change it), vector(g, f, i) returns value i (1-based) at the current
     * step. */
    int size_vector;
    double (*vector)(struct gravel *g, struct fix *f, int i);
    /* Global array for `f_ID[i][j]`, optional: element (i, j), 1-based,
     * within the instance's f->size_array_rows x f->size_array_cols. */
    double (*array)(struct gravel *g, struct fix *f, int i, int j);
    /* Global scalar for `f_ID` in thermo output, optional, extensive (divided
     * by the atom count under thermo_modify norm yes); host arrays current.
     * energy_global: the scalar is an energy that `fix_modify ID energy yes`
     * adds to the thermo pe (LAMMPS's energy_global_flag); ecouple: the
     * scalar is the energy exchanged with a reservoir (a thermostat's or
     * barostat's), summed by thermo `ecouple` (LAMMPS's ecouple_flag). */
    double (*scalar)(struct gravel *g, struct fix *f);
    int energy_global, ecouple;
    /* Per-atom output for `f_ID` / `f_ID[i]` in dump custom and compute
     * reduce (LAMMPS's peratom_flag), optional: the instance's
     * f->peratom_flag and f->size_peratom_cols (0: a vector) say whether
     * and what; returns g->atoms.n values (times the columns, row-major)
     * in host order, current, valid until the next call. */
    const double *(*peratom_values)(struct gravel *g, struct fix *f);
};

struct fix {
    char id[GR_NAMELEN];
    const struct fix_style *style;
    int igroup;
    unsigned groupbit;          /* 1u << igroup */
    unsigned hooks;             /* HOOK_* */
    unsigned needs;             /* NEED_* */
    int nsources;
    const char *sources[FIX_MAX_SOURCES];   /* kernel file names, e.g. "fix_gravity.cl" */
    char defines[256];          /* extra build options, each NAME or NAME=VALUE separated by
                                 * " -D " (the engine adds the first -D), e.g. "VREMAP" */
    void *data;                 /* style state, freed by destroy (or free() if no destroy) */
    /* engine-managed per-atom device state (see header comment) */
    size_t peratom_bytes;
    cl_mem peratom;
    cl_mem peratom_tmp;
    size_t peratom_cap;         /* atoms the buffers hold */
    uint64_t arghash;           /* hash of group, style and arguments (restart.c compares) */
    unsigned fused_hooks;       /* hooks run inside fused kernels this run (src/engine/fused.c) */
    int time_depend;            /* 1: its schedule is in absolute steps (fix pour):
                                 * reset_timestep refuses (LAMMPS) */
    int force_reneighbor;       /* 1: next_reneighbor forces a rebuild on that step */
    int halts;                  /* 1: its per-step hooks launch only kernels that take the
                                 * halt (KARGS_halt) and keep no host state from one step
                                 * to the next, so its steps may be decided on speculation
                                 * (src/engine/neighbor.h, nbr_decide) */
    bigint next_reneighbor;     /* step of the forced rebuild (0 = none) */
    int energy;                 /* fix_modify energy yes: scalar counted in pe */
    /* The instance's global output (LAMMPS's Fix flags), which f_ID,
     * f_ID[i] and f_ID[i][j] read (fix_ref_*). cmd_fix fills them from the
     * descriptor before create (scalar_flag and vector_flag from the
     * .scalar and .vector hooks, size_vector from .size_vector, outputs
     * extensive, global_freq 1); a style whose output depends on its
     * arguments (fix ave/time) sets them in create. Extensive values are
     * divided by the atom count under thermo_modify norm yes; extvector -1:
     * per element, extlist[i - 1]. global_freq: the output is current only
     * on multiples of it (thermo and readers check). */
    int scalar_flag, vector_flag, array_flag;
    int size_vector;
    int size_array_rows, size_array_cols;
    int extscalar, extvector, extarray;
    const int *extlist;         /* [size_vector] when extvector is -1; owned by the style */
    int global_freq;
    /* per-atom output current only every peratom_freq steps (LAMMPS's
     * peratom_freq: fix ave/atom's Nfreq; 1 by default): a dump reading
     * it must write on multiples of it */
    int peratom_freq;
    int peratom_flag;           /* per-atom output (style->peratom_values) */
    int size_peratom_cols;      /* ... 0: a vector; else an array's columns */
    int rows_variable;          /* the vector's length or the array's rows change at run
                                 * time: elements beyond them read as 0, not an error
                                 * (LAMMPS's size_vector_variable, size_array_rows_variable) */
};

/* Parse "f_ID", "f_ID[I]" or "f_ID[I][J]" (I, J >= 1): copies ID into id
 * (GR_NAMELEN), sets *index to I (0: the scalar) and *col to J (0: none).
 * Returns 0 when `ref` does not have that form. */
int fix_parse_ref(const char *ref, char *id, int *index, int *col);
/* The fix a reference names, checked: it exists and has the output the
 * reference asks for (scalar, vector element I in range, array column J in
 * range). Errors name `who`. */
struct fix *fix_ref_check(struct gravel *g, const char *ref, const char *who);
/* Output (index, col) of f (as fix_parse_ref sets them), divided by the
 * atom count `norm` (every rank's; 0: not normalized) when that output is
 * extensive. A row beyond the array's current rows is an error naming `who`. */
double fix_output(struct gravel *g, struct fix *f, int index, int col, long long norm,
                  const char *who);
/* Per-atom reference `f_ID` / `f_ID[N]` (ref) checked: the fix exists and
 * has that per-atom output (a vector for f_ID, column N of an array).
 * Errors name `who`. */
struct fix *fix_peratom_check(struct gravel *g, const char *ref, const char *who);
/* Its values: atom i's is p[i * *stride] (host order), current. */
const double *fix_peratom_ref(struct gravel *g, const char *ref, int *stride, const char *who);
/* 1 when output (index, col) of f is extensive. */
int fix_output_extensive(const struct fix *f, int index, int col);

/* The fix with this ID, or NULL. */
struct fix *fix_find(struct gravel *g, const char *id);
/* The first fix of this style name (e.g. "gravity"), or NULL. */
struct fix *fix_find_style(struct gravel *g, const char *style);
/* 1 when `name` is a fix style gravel has. */
int fix_style_known(const char *name);
/* The first fix that applies a uniform acceleration (style->acceleration),
 * or NULL. */
struct fix *fix_find_acceleration(struct gravel *g);
/* The group bit of the first FIX_FROZEN fix (0: none). */
unsigned fix_frozen_groupbit(struct gravel *g);
/* 1 when every fix is FIX_CONSERVING (none: 1). */
int fix_all_conserving(const struct gravel *g);
/* Free every fix (clear/destroy). */
void fix_free_all(struct gravel *g);
/* Sum of the scalars of fixes with fix_modify energy yes (not normalized;
 * host arrays must be current). */
double fix_energy_sum(struct gravel *g);
/* Sum of the scalars of the fixes whose style has ecouple (thermo ecouple). */
double fix_ecouple_sum(struct gravel *g);
/* Error "cannot reset timestep with a time-dependent fix defined (fix ID
 * style)" if a fix has time_depend (reset_timestep, read_dump, rerun). */
void fix_check_time_reset(struct gravel *g);
/* reset_timestep moved the step counter by shift: every fix's reset_step. */
void fix_reset_step(struct gravel *g, bigint shift);
/* Union of NEED_* over all fixes. */
unsigned fix_needs_all(struct gravel *g);

#endif
