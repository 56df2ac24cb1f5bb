/* state.h - the whole simulation as one struct, and the types every module shares.
 *
 * One `struct gravel` holds everything a script builds: interpreter state, the
 * domain, atoms, groups, regions, variables, styles and output settings. Modules
 * own their sub-structs (declared in their own headers) and export a small
 * prefixed API. Nothing here is global: tests create several engines at once.
 *
 * The bottom of the include order: this header declares types only and
 * includes no gravel header, so every module may include it. Creating and
 * destroying a simulation is gravel.h (the top); printing is log.h. */
#ifndef GR_STATE_H
#define GR_STATE_H

#include <stdint.h>
#include <stdio.h>
#include <setjmp.h>

#include "atom_fields.h"

#define GR_VERSION "0.1.0"

#define GR_MAXGROUP 32      /* groups are bits of a 32-bit per-atom mask */
#define GR_NAMELEN 64       /* longest ID of a fix, compute, region, group, dump */
#define HALT_SOFT 1         /* struct gravel's halt (fix halt's error soft | continue) */
#define HALT_CONTINUE 2

typedef int64_t bigint;

struct gravel;
struct par;
struct vars;                /* variable.c: opaque */
struct inp;                 /* input.c: opaque */
struct engine;              /* device.h: device state */
struct restart;             /* restart.c: restart settings and state pending from read_restart */
struct molecule;            /* molecule.h: molecule templates */

/* ---- domain: units, box, boundaries, lattice ------------------------------ */

enum units { UNITS_LJ, UNITS_SI, UNITS_CGS };

/* Boundary flag per face, as LAMMPS: p periodic, f fixed, s shrink-wrap, m shrink
 * with minimum. */
enum bflag { BND_P = 'p', BND_F = 'f', BND_S = 's', BND_M = 'm' };

struct lattice {
    int style;              /* 0 none, else LAT_SC ... (lattice.c) */
    double a[3];            /* spacing per dimension in box units (LAMMPS xlattice...) */
    double prim[3];         /* primitive cell edge lengths in box units (where points go;
                             * differs from a[] only with the `spacing` keyword) */
    double cell[3];         /* primitive edge lengths in units of `scale` (1, sqrt(3) ...);
                             * 0 after read_restart (then prim[] places the points) */
    double scale;           /* the lattice constant */
    double origin[3];       /* fractional origin */
    int nbasis;
    double basis[8][3];     /* fractional basis positions */
};

struct domain {
    enum units units;
    int dimension;          /* 2 or 3 (`dimension`, default 3); 2d: z periodic and thin,
                             * atoms in one z plane (domain_contact_periodic) */
    int box_exists;
    char bnd[3][2];         /* boundary flag per dimension and face (lo, hi) */
    int periodic[3];
    double lo[3], hi[3];    /* current box */
    int triclinic;          /* 1: a parallelepiped with tilt factors xy xz yz (LAMMPS's
                             * h = (Lx, Ly, Lz, yz, xz, xy); edge vectors a = (Lx,0,0),
                             * b = (xy,Ly,0), c = (xz,yz,Lz)); read_data's xy xz yz line,
                             * change_box triclinic, region prism boxes */
    double xy, xz, yz;      /* tilt factors (0 when orthogonal) */
    /* box deformation rates of the current run, LAMMPS's h_rate (d/dt of
     * Lx Ly Lz yz xz xy), and the group whose velocities are remapped when
     * they cross a periodic face (fix deform remap v; 0: none); reset at
     * each run start, set by the fixes' init (src/engine/box_change.h) */
    double h_rate[6];
    unsigned vremap_group;
    double minlo[3], minhi[3]; /* 'm' boundaries: the box never shrinks inside these */
    double small[3];        /* shrink-wrap margin: 1e-4 x box length at create_box/read_data */
    struct lattice lat;
};

/* ---- atoms: host-side structure of arrays (atom_style sphere) ------------- */

enum atom_heat { ATOM_HEAT_T = 1, ATOM_HEAT_Q = 2, ATOM_HEAT_BOTH = 3 };

struct atoms {
    int n, cap;
    int ntypes;
    ATOM_FIELDS(ATOM_FIELD_MEMBER) /* the per-atom arrays (atom_fields.h) */
    struct atom_custom cus; /* custom properties (fix property/atom i_ d_ i2_ d2_) */
    double *custom;         /* [cap * cus.slots]: their values, one record per atom */
    int molecule_flag;      /* 1: atoms carry molecule IDs (LAMMPS atom->molecule_flag) */
    int style_molecular;    /* atom_style hybrid sphere molecular: the IDs belong to the
                             * style (data files carry them), not to fix property/atom */
    int heat_flag;          /* ATOM_HEAT_* bits: fix property/atom temperature, heatflow
                             * (LAMMPS atom->temperature_flag, heatflow_flag) */
    char style[16];         /* the atom_style command's style ("": sphere, the default;
                             * variables' is_active) */
    int ellipsoid_flag;     /* atom_style ellipsoid superellipsoid (LAMMPS atom->
                             * superellipsoid_flag): the FW_ELLIPSOID fields */
    double temp_default;    /* temperature of a new atom (0; fix heat/gran's
                             * initial_temperature: LIGGGHTS's Temp default_value) */
    int allow_soft, allow_hard; /* LIGGGHTS's soft_particles, hard_particles yes */
    double *type_mass;      /* [ntypes+1] from the mass command; 0 = unset */
    int64_t maxtag;
    int *order;             /* scratch of atoms_tag_order() */
    int order_cap;
};

/* ---- groups ---------------------------------------------------------------- */

/* group ID dynamic parent [region R] [var V] [property P] [every N]:
 * membership is re-evaluated at the start of each run and every N steps
 * (group.c) */
struct group_dyn {
    int on, parent, every;
    char region[GR_NAMELEN], var[GR_NAMELEN], prop[GR_NAMELEN];
};

struct groups {
    int n;                  /* slots in use (0 = "all" always) */
    char name[GR_MAXGROUP][GR_NAMELEN];
    int used[GR_MAXGROUP];
    struct group_dyn dyn[GR_MAXGROUP];
};

/* ---- regions --------------------------------------------------------------- */

struct region;              /* region.c */
struct regions {
    int n, cap;
    struct region **r;
};

/* ---- neighbor and run settings -------------------------------------------- */

enum neigh_style { NEIGH_BIN = 1, NEIGH_MULTI = 2 };
#define GR_MAXCOLL 64
#define GR_MAXCOLL_RANGE 256
struct neigh_settings {
    double skin;
    int style;              /* NEIGH_BIN or NEIGH_MULTI (neighbor skin bin|multi) */
    /* neighbor multi collections (neigh_modify collection/type|interval);
     * ncoll 0: one collection per atom type */
    int ncoll, coll_interval;
    double coll_cut[GR_MAXCOLL];        /* collection/interval: upper diameters, ascending */
    int ncoll_range, coll_range[GR_MAXCOLL_RANGE][3]; /* collection/type: types lo..hi -> coll */
    int every, delay, check, once;
    bigint sort_every;      /* atom_modify sort: re-sort period in steps (< 0: every rebuild, 0: never) */
    int one, page;          /* capacity hints (neigh_modify one/page) */
    int nexclude;
    int exclude_group[16][2]; /* group index pairs excluded (neigh_modify exclude group) */
    int exclude_type[16][2];
    int nexclude_type;
    int exclude_mol[16][2];   /* (group, 1 intra | 0 inter): neigh_modify exclude molecule/... */
    int nexclude_mol;
};

enum thermo_lost { LOST_ERROR, LOST_WARN, LOST_IGNORE };

/* A temperature (src/engine/temperature.h): what it counts and its degrees of
 * freedom; the implicit thermo_temp and every compute temp, temp/sphere. */
enum temp_kind {
    TEMP_TRANS, TEMP_SPHERE_ALL, TEMP_SPHERE_ROTATE,
    TEMP_COM,                   /* about the group's centre-of-mass velocity (temp/com) */
    TEMP_PARTIAL,               /* the components in flags only (temp/partial) */
    TEMP_REGION,                /* the group's atoms in a region, counted each time (temp/region) */
    TEMP_PROFILE                /* about each spatial bin's mean velocity (temp/profile) */
};
struct temp_state {
    enum temp_kind kind;
    unsigned groupbit;
    double extra_dof;           /* compute_modify extra/dof (default: dimension) */
    int extra_set;              /* extra/dof given (else the dimension at use) */
    int dynamic;                /* compute_modify dynamic/dof yes */
    double dof;                 /* counted at run setup (temp_setup) */
    double dof_natoms;          /* atoms of the group at that count */
    int dof_valid;              /* dof holds the count of the current run */
    int flags[3];               /* TEMP_PARTIAL: the components counted (x y z);
                                 * TEMP_PROFILE: the components whose bin mean is removed */
    int nbin[3];                /* TEMP_PROFILE: bins along x y z */
    char region[GR_NAMELEN];    /* TEMP_REGION: the region's ID, */
    const void *region_obj;     /* the region resolved by its compute (init), */
    int (*region_in)(const void *region_obj, const double x[3]); /* and its test */
    char bias_id[GR_NAMELEN];   /* temp/sphere's `bias ID` ("" none), */
    struct temp_state *bias;    /* that temperature, whose bias is taken out of the
                                 * velocities (resolved at init), else NULL */
};

#define GR_MAXTHERMO 64
struct thermo_settings {
    int every;                      /* 0 = first and last step only */
    char *every_var;                /* thermo v_name */
    int ncol;
    char col[GR_MAXTHERMO][GR_NAMELEN];
    int norm;                       /* thermo_modify norm (lj default yes) */
    int norm_set;
    int norm_user;                  /* the value given to thermo_modify norm */
    struct temp_state temp;         /* the implicit thermo_temp (compute temp, group all) */
    char temp_id[GR_NAMELEN];       /* thermo_modify temp ID; "" = thermo_temp */
    int flush;
    enum thermo_lost lost;
    char *format_line;              /* thermo_modify format line "..." */
    char *format_int, *format_float;
    char *format_col[GR_MAXTHERMO];
    int multi;                      /* thermo_modify line multi / thermo_style multi */
    int modified;                   /* some thermo_modify setting was given */
    struct output_state *state;     /* output.c: run-time schedule, clocks, progress */
};

/* ---- styles: fixes, computes, pair, dumps ---------------------------------- */

struct fix;                 /* fix.h */
struct compute;             /* compute.h */
struct pair;                /* pair.h */
struct dump;                /* dump.h */

struct styles {
    struct pair *pair;      /* NULL until pair_style */
    struct pair *surf;      /* pair_style hybrid's surface sub-style (surf/granular),
                             * split off the particle laws; NULL: none */
    char *pair_cmds;        /* the pair_style and pair_coeff lines that made it
                             * (one per line; the accuracy map replays them) */
    int nfix, nfix_cap;
    struct fix **fix;
    int ncompute, ncompute_cap;
    struct compute **compute;
    int ndump, ndump_cap;
    struct dump **dump;
};

/* ---- options from the command line ----------------------------------------- */

enum echo_mode { ECHO_NONE = 0, ECHO_SCREEN = 1, ECHO_LOG = 2, ECHO_BOTH = 3 };

struct options {
    char device[32];        /* "", "cpu", "gpu" or an index */
    int single;             /* -precision single */
    int progress;           /* -progress */
    int quiet_screen;       /* -screen none */
    int check;              /* -check: each run prints the accuracy map instead */
    int lammps2021;         /* -compat lammps2021: reproduce that version's quirks */
};

/* ---- error context: where the command being run came from ------------------ */

struct errctx {
    const char *cmd;        /* command name, for the "ERROR: cmd:" prefix */
    const char *file;       /* script file name or "stdin" */
    int line;               /* first line of the command in that file */
    const char *text;       /* the command line as read (for the echo under the error) */
    jmp_buf *jmp;           /* active unwind target; NULL = print and exit(1) */
    char msg[1024];         /* last error message, for tests */
    int nwarn;
};

/* ---- the simulation ---------------------------------------------------------- */

struct gravel {
    struct options opt;
    struct errctx err;
    struct inp *inp;
    struct vars *vars;

    FILE *screen;           /* stdout unless -screen none (then NULL) */
    FILE *logfile;          /* log.gravel unless -log none */
    char *logname;          /* its name, for write errors (NULL: not opened by gr_log_open) */
    int *logerr;            /* errno of the log's first failed write, 0 while none failed
                             * (heap, owned with logname; NULL for a log set directly) */
    FILE *thermolog;        /* LIGGGHTS's thermo_log file, or NULL; its name and errno as */
    char *thermologname;    /* the log's (log.c); kept across `clear`, as LIGGGHTS's */
    int *thermologerr;
    enum echo_mode echo;

    struct domain dom;
    struct atoms atoms;
    struct groups groups;
    struct regions regions;

    double dt;
    int dt_set;
    struct neigh_settings neigh;
    struct thermo_settings thermo;
    struct styles styles;

    bigint step;            /* current timestep */
    double time;            /* elapsed simulated time */
    bigint firststep, laststep; /* of the current run */
    bigint beginstep;       /* `run ... start N` (else the run's first step): elaplong */
    bigint endstep;         /* `run ... stop N` (else the run's last step): ramp() */
    bigint run_start;       /* cmd_run -> run_begin: the start keyword, -1 none */
    bigint run_stop;        /* cmd_run -> run_begin: the stop keyword, -1 none */
    int running;            /* 1 from a run's setup to its end (LAMMPS's whichflag):
                             * ramp() between runs gives its first value */
    bigint laststep_reset;

    int nmolecule;          /* molecule templates (`molecule` command) */
    struct molecule **molecules;
    struct engine *eng;     /* device state, alive across runs; NULL before the first run */
    struct restart *restart; /* restart.c; NULL until restart/read_restart */
    struct par *par;        /* src/parallel/par.h: the processor grid, a decomposed run */
    uint64_t seed_counter;
    int warned_ignored[16]; /* commands with no meaning here warn once */
    int halt;               /* fix halt met its condition (LAMMPS's expired timer): the
                             * run ends after the step; HALT_SOFT: later runs are
                             * skipped, HALT_CONTINUE: cleared at the run's end */
    int in_run_every;       /* > 0 while `run ... every` executes its commands (clear
                             * refuses: the run goes on with the simulation) */
};

#endif
