/* atom_fields.h - the per-atom field table (atom_style sphere): every
 * per-atom array, declared once and expanded wherever the whole set is
 * handled (LAMMPS's fields_grow / fields_copy / fields_restart lists of
 * atom_vec_sphere.cpp, written here as one X-macro).
 *
 * ATOM_FIELDS(X) calls X(name, ctype, dev, width, when, life, sect, what) once
 * per field, in the order of the restart file's per-atom sections:
 *   name   member of struct atoms (gravel.h: host, ctype *, `width` per atom,
 *          interleaved) and of struct dev_atoms (engine.h: cl_mem, device order)
 *   ctype  host element type
 *   dev    device representation:
 *            FD_POS   REAL, relative to the engine's origin; in single precision
 *                     split into x (high part) and dev_atoms.xlo (low part)
 *            FD_REAL  REAL (float or double): converted from and to double
 *            FD_RAW   the host bytes as they are (int = cl_int, unsigned =
 *                     cl_uint, int64_t = cl_long)
 *   width  elements per atom
 *   when   runs that hold it on the device: FW_ALWAYS; FW_ROTATION (some
 *          active style needs rotation); FW_MOLECULE (atoms carry molecule IDs,
 *          atoms.molecule_flag); FW_HEAT (atoms store a temperature:
 *          fix property/atom temperature heatflow, atoms.heat_flag);
 *          FW_ELLIPSOID (atom_style ellipsoid superellipsoid,
 *          atoms.ellipsoid_flag). The host array always exists.
 *   life   FL_STATE: moves with its atom when the device re-sorts by cell
 *          (neighbor.c); FL_STEP: recomputed every step (forces, torques), not
 *          moved (the force buffer is the re-sort's scratch)
 *   sect   restart section holding it (restart.c): FS_ATOMS, FS_MOLECULE,
 *          FS_HEAT or FS_ELLIPSOID;
 *          each section writes its fields in table order, n * width raw host
 *          elements each
 *   what   words for allocation errors
 *
 * Driven by the table: host growth, slot copy, append and release
 * (atoms.c), device allocation, upload, append and download (engine.c), the
 * cell re-sort (neighbor.c), restart write, read and apply (restart.c).
 * A per-atom exchange between processes (MPI pack/unpack) is one more
 * expansion over FL_STATE rows. Commands that give fields meaning (set,
 * dump custom, compute property/atom, replicate, read_data) name them
 * individually. */
#ifndef GR_ATOM_FIELDS_H
#define GR_ATOM_FIELDS_H

#include <stdint.h>

enum atom_field_dev { FD_POS, FD_REAL, FD_RAW };
enum atom_field_when { FW_ALWAYS, FW_ROTATION, FW_MOLECULE, FW_HEAT, FW_ELLIPSOID };
enum atom_field_life { FL_STATE, FL_STEP };
enum atom_field_sect { FS_ATOMS, FS_MOLECULE, FS_HEAT, FS_ELLIPSOID };

/* Meanings: tag the global ID (1-based); type 1..ntypes; mask the group bits
 * (bit 0 = "all"); x, v, f, omega, torque xyz per atom; rmass the per-atom
 * mass; image the periodic image counts; mol the molecule ID (0 = none);
 * temperature LAMMPS's per-atom temperature and heatflow the heat flowing
 * into the atom in the step (pair and wall conduction, summed like the
 * forces; fix heat/flow integrates it); heatsource a heat input of its own
 * (LIGGGHTS's property/atom heatSource, set by `set ... property/atom
 * heatSource Q`; 0 unless set), added to heatflow in the update.
 * Superellipsoids (atom_style ellipsoid superellipsoid, LAMMPS 30 Mar 2026's
 * bonus_super record, src/state/superellipsoid.h): shape the three semi-axes
 * (all 0: a point particle, LAMMPS's ellipsoid flag -1), block the
 * blockiness exponents n1 n2 (2 2: an ellipsoid), quat the orientation
 * (w i j k, body to space), angmom the space-frame angular momentum,
 * inertia the principal moments of the body frame; radius holds the
 * bounding radius there. */
/* clang-format off */
#define ATOM_FIELDS(X)                                                                       \
    X(tag,    int64_t,  FD_RAW,  1, FW_ALWAYS,   FL_STATE, FS_ATOMS,    "tags")               \
    X(type,   int,      FD_RAW,  1, FW_ALWAYS,   FL_STATE, FS_ATOMS,    "types")              \
    X(mask,   unsigned, FD_RAW,  1, FW_ALWAYS,   FL_STATE, FS_ATOMS,    "group masks")        \
    X(x,      double,   FD_POS,  3, FW_ALWAYS,   FL_STATE, FS_ATOMS,    "positions")          \
    X(v,      double,   FD_REAL, 3, FW_ALWAYS,   FL_STATE, FS_ATOMS,    "velocities")         \
    X(f,      double,   FD_REAL, 3, FW_ALWAYS,   FL_STEP,  FS_ATOMS,    "forces")             \
    X(omega,  double,   FD_REAL, 3, FW_ROTATION, FL_STATE, FS_ATOMS,    "angular velocities") \
    X(torque, double,   FD_REAL, 3, FW_ROTATION, FL_STEP,  FS_ATOMS,    "torques")            \
    X(radius, double,   FD_REAL, 1, FW_ALWAYS,   FL_STATE, FS_ATOMS,    "radii")              \
    X(rmass,  double,   FD_REAL, 1, FW_ALWAYS,   FL_STATE, FS_ATOMS,    "masses")             \
    X(image,  int,      FD_RAW,  3, FW_ALWAYS,   FL_STATE, FS_ATOMS,    "image flags")        \
    X(mol,    int64_t,  FD_RAW,  1, FW_MOLECULE, FL_STATE, FS_MOLECULE, "molecule IDs")       \
    X(temperature, double, FD_REAL, 1, FW_HEAT,  FL_STATE, FS_HEAT,     "temperatures")       \
    X(heatflow, double, FD_REAL, 1, FW_HEAT,     FL_STEP,  FS_HEAT,     "heat flows")         \
    X(heatsource, double, FD_REAL, 1, FW_HEAT,   FL_STATE, FS_HEAT,     "heat sources")       \
    X(shape,  double,   FD_REAL, 3, FW_ELLIPSOID, FL_STATE, FS_ELLIPSOID, "semi-axes")        \
    X(block,  double,   FD_REAL, 2, FW_ELLIPSOID, FL_STATE, FS_ELLIPSOID, "blockiness")       \
    X(quat,   double,   FD_REAL, 4, FW_ELLIPSOID, FL_STATE, FS_ELLIPSOID, "quaternions")      \
    X(angmom, double,   FD_REAL, 3, FW_ELLIPSOID, FL_STATE, FS_ELLIPSOID, "angular momenta")  \
    X(inertia, double,  FD_REAL, 3, FW_ELLIPSOID, FL_STATE, FS_ELLIPSOID, "principal moments")
/* clang-format on */

/* Declares one pointer member per field (struct atoms, struct image). */
#define ATOM_FIELD_MEMBER(name, ctype, dev, width, when, life, sect, what) ctype *name;

/* ---- custom per-atom properties (fix property/atom i_name d_name i2_name N
 * d2_name N; atom_custom.h) ------------------------------------------------
 * Defined at run time, so not rows of the table: one more per-atom record,
 * atoms.custom, of `slots` doubles per atom (an integer property holds
 * exact integers in its slots). Every whole-set handling of the table rows
 * treats this record as one more FL_STATE row of FD_RAW doubles: host growth,
 * append, copy and release (atoms.c), device allocation, upload, download
 * and the cell re-sort (engine.c, neighbor.c), the MPI records (par.c) and
 * the restart file (restart.c, section "custom"). */
#define GR_MAXCUSTOM 32
#define GR_CUSTOMLEN 64
#define GR_CUSTOM_DEFS 16 /* columns of a property that can have their own new-atom value */
struct custom_prop {
    char name[GR_CUSTOMLEN];    /* without its i_ d_ i2_ d2_ prefix */
    int isint;                  /* 1: i_ / i2_ (integers), 0: d_ / d2_ */
    int cols;                   /* 0: a vector; N >= 1: an array of N columns */
    int slot;                   /* its first slot in the per-atom record */
    char fix[GR_CUSTOMLEN];     /* the fix property/atom that defines it */
    int restored;               /* read from a restart file, not yet defined again */
    double def[GR_CUSTOM_DEFS]; /* a new atom's values, by column (LIGGGHTS's fix
                                 * property/atom defaults; 0 otherwise) */
};
struct atom_custom {
    int n;                      /* properties defined */
    int slots;                  /* doubles per atom of atoms.custom */
    struct custom_prop p[GR_MAXCUSTOM];
};

#endif
