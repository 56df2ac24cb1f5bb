/* compute.h - computes: named diagnostics (`compute ID group style args`) that
 * thermo output, dumps and expressions read as c_ID / c_ID[N].
 *
 * A compute produces a global scalar, a global vector, a per-atom vector
 * (one value per host atom, in host order) or array, or local values (a
 * vector or an array of rows that are not atoms: pairs, contacts; LAMMPS's
 * local computes, written by dump local and reduced by compute reduce), as
 * its style declares. Computes
 * evaluate on the host arrays: callers inside a run call run_sync_host() first
 * (output does this before each thermo line). Values are recomputed on every
 * call; computes are O(N) passes over the host arrays.
 *
 * Styles register in styles/styles.def with COMPUTE(keyword, ident); the
 * descriptor is `const struct compute_style compute_style_<ident>` in
 * styles/compute_<ident>.c. */
#ifndef GR_COMPUTE_H
#define GR_COMPUTE_H

#include "state.h"

struct compute;

/* How a style evaluates in a run decomposed over MPI ranks (par.h). */
enum compute_ranks {
    COMPUTE_RANKS_NO,       /* not yet: the run stops (it reads the device's contacts) */
    COMPUTE_RANKS_SUMS,     /* on the owned atoms, summed over the ranks in tag order */
    COMPUTE_RANKS_GATHER,   /* on every rank's atoms, gathered in tag order for the output */
};

struct compute_style {
    const char *name;
    enum compute_ranks ranks;
    /* Parse the style arguments (argv after "ID group style"), set the
     * output flags and sizes, allocate c->data. Errors via gr_error; the
     * compute is freed by the caller then (destroy is called when set). */
    void (*create)(struct gravel *g, struct compute *c, int argc, char **argv);
    /* Resolve references to other computes (run setup, before each use);
     * NULL when the style has none. */
    void (*init)(struct gravel *g, struct compute *c);
    double (*scalar)(struct gravel *g, struct compute *c);     /* scalar_flag */
    void (*vector)(struct gravel *g, struct compute *c);       /* fill c->vector */
    void (*peratom)(struct gravel *g, struct compute *c);      /* fill c->peratom */
    /* local_flag: fill rows through compute_local_rows() (which sets
     * size_local_rows) */
    void (*local)(struct gravel *g, struct compute *c);
    /* array_flag: fill c->array through compute_array_rows() */
    void (*array)(struct gravel *g, struct compute *c);
    void (*destroy)(struct compute *c);                        /* free c->data */
};

struct compute {
    char id[GR_NAMELEN];
    const struct compute_style *style;
    int igroup;
    unsigned groupbit;          /* 1u << igroup */
    int scalar_flag, vector_flag, peratom_flag;
    int size_vector;
    int size_vector_variable;   /* 1: size_vector is known after each evaluation (property/chunk) */
    int size_peratom_cols;      /* 0: per-atom vector; else columns of a per-atom array */
    int extscalar, extvector;   /* 1: extensive, thermo divides by atoms when norm yes */
    double *vector;             /* [size_vector], owned */
    double *peratom;            /* [atoms.n] or [atoms.n][cols] after compute_peratom, owned */
    int peratom_cap;
    int array_flag;             /* a global array (com/chunk): c_ID[I][J] */
    int size_array_cols;
    int size_array_rows;        /* rows of the last evaluation */
    double *array;              /* [rows][cols], owned */
    int array_cap;
    int extarray;
    int local_flag;
    int size_local_cols;        /* 0: local vector; else columns of a local array */
    int size_local_rows;        /* rows of the last evaluation */
    double *local;              /* [rows][max(cols, 1)], owned */
    int local_cap;              /* rows allocated */
    void *data;                 /* style state */
    struct temp_state *temp;    /* temperature computes (temp, temp/sphere): their dof
                                 * and compute_modify settings (temperature.h); in data */
};

/* `compute ID group style args...` and `uncompute ID` (commands.def). */
void cmd_compute(struct gravel *g, int argc, char **argv);
void cmd_uncompute(struct gravel *g, int argc, char **argv);

/* The compute with this ID, or NULL. */
struct compute *compute_find(struct gravel *g, const char *id);
/* 1 when `name` is a compute style gravel has. */
int compute_style_known(const char *name);
/* Like compute_find but raises "unknown compute ID" naming `who`. */
struct compute *compute_get(struct gravel *g, const char *id, const char *who);

/* Evaluate. Each raises an error when the compute has no such output. */
double compute_scalar(struct gravel *g, struct compute *c);
const double *compute_vector(struct gravel *g, struct compute *c);
/* Evaluate the global array: c->size_array_rows rows of size_array_cols,
 * row-major, valid until the next evaluation. */
const double *compute_array(struct gravel *g, struct compute *c);
/* Per-atom values, length g->atoms.n (times size_peratom_cols for arrays,
 * row-major), host order. */
const double *compute_peratom(struct gravel *g, struct compute *c);
/* Per-atom column for reference index (0: the vector of a per-atom-vector
 * compute; N: column N of a per-atom array): value of atom i is
 * p[i * *stride]. Errors name `who`. */
const double *compute_peratom_ref(struct gravel *g, struct compute *c, int index, int *stride,
                                  const char *who);
/* Evaluate the local values of c: returns the row count, *data the rows
 * (row-major, max(size_local_cols, 1) per row), valid until the next
 * evaluation. */
int compute_local(struct gravel *g, struct compute *c, const double **data);
/* For styles: room for `rows` rows in c->local (size_local_rows = rows);
 * returns c->local. */
double *compute_local_rows(struct gravel *g, struct compute *c, int rows);
/* Check that compute `id` has local output matching `index` (0: its local
 * vector; N: column N of its local array). */
void compute_local_check(struct gravel *g, const char *id, int index, const char *who);
/* Check at setup that compute `id` has per-atom output matching `index`. */
void compute_peratom_check(struct gravel *g, const char *id, int index, const char *who);

/* Parse "c_ID" or "c_ID[N]": copies ID into id (GR_NAMELEN), sets *index to
 * N (1-based) or 0. Returns 0 when `ref` does not have that form. */
int compute_parse_ref(const char *ref, char *id, int *index);
/* The same, also accepting "c_ID[I][J]" (an element of a global array):
 * *col is J, 0 without a second index. */
int compute_parse_ref2(const char *ref, char *id, int *index, int *col);
/* Room for `rows` rows of c->array (size_array_rows = rows); returns it. */
double *compute_array_rows(struct gravel *g, struct compute *c, int rows);

/* Value of reference `ref` ("c_ID" scalar, "c_ID[N]" vector element or
 * "c_ID[I][J]" array element: out of range is an error, as LAMMPS),
 * divided by the atom count `norm` (every rank's: thermo_modify norm; 0:
 * not normalized) when the value is extensive. Errors name `who` (e.g.
 * "thermo_style"). */
double compute_ref_value(struct gravel *g, const char *ref, long long norm, const char *who);
/* Check that `ref` names an existing compute with the right kind of output
 * (scalar for c_ID, vector with N in range for c_ID[N], array with J in
 * range for c_ID[I][J]). */
void compute_ref_check(struct gravel *g, const char *ref, const char *who);

/* Run setup: let every compute resolve its references. */
void compute_init_all(struct gravel *g);
/* Free every compute (called from styles_free on clear and destroy). */
void compute_free_all(struct gravel *g);

/* A temperature compute argument (compute pressure, stress/atom): copies ID
 * into id (GR_NAMELEN), or "" for NULL; errors name `who`. */
void compute_temp_arg(struct gravel *g, const char *arg, char *id, const char *who);
/* The temperature named by such an ID ("": NULL; thermo_temp without a
 * compute of that ID: the thermo temperature, as LAMMPS's implicit one);
 * an error when the compute is not a temperature. */
struct temp_state *compute_temp_named(struct gravel *g, const char *id, const char *who);

/* LAMMPS's term keywords of compute pressure and stress/atom (argv after the
 * temperature ID): ke sets *keflag, pair or virial *virialflag; fix and the
 * molecular terms (bond angle dihedral improper kspace) add nothing here;
 * none given sets both. Errors name `who`. */
void compute_virial_terms(struct gravel *g, int argc, char **argv, int *keflag, int *virialflag,
                          const char *who);

/* Mass-velocity^2 to energy factor of the current units (1 in lj, si, cgs). */
double compute_mvv2e(const struct gravel *g);

#endif
