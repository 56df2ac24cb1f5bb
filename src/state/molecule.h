/* molecule.h - molecule templates (`molecule ID file [keyword values]`),
 * LAMMPS's Molecule class as granular decks use it: per-atom coordinates,
 * types, diameters, masses and molecule IDs read from a LAMMPS molecule
 * file, plus the derived quantities fix pour and fix rigid/small insert
 * with (geometric centre, total mass, centre of mass, inertia tensor, its
 * principal axes and quaternion, body-frame displacements).
 *
 * The derived values are computed on demand, once each, in LAMMPS's order
 * (mol_compute_center, _mass, _com, _inertia); header values of the file
 * (`mass`, `com`, `inertia`) take precedence over the atoms' values, as in
 * LAMMPS. Bonds, angles, charges, special lists and shake info have no
 * meaning for granular spheres: a file with them is an error. A template
 * may also (or only) hold granular surface triangles, LAMMPS 4 Jul 2026's
 * `N points` / `N triangles` headers and Points ("ID x y z") and Triangles
 * ("ID mol type p1 p2 p3") sections, read by fix surface/global and
 * surface/local. */
#ifndef GR_MOLECULE_H
#define GR_MOLECULE_H

#include "state.h"

struct molecule {
    char id[GR_NAMELEN];
    int natoms;
    double *x;              /* 3 per atom (scaled) */
    int *type;              /* per atom, type offset applied */
    double *radius;         /* per atom, or NULL (no Diameters section) */
    double *rmass;          /* per atom, or NULL (no Masses section) */
    int64_t *molecule;      /* per atom molecule IDs (Molecules section), or NULL */
    int nmolecules;         /* distinct IDs of the Molecules section (1 without) */
    int ntypes;             /* largest type of the template */
    int npoints, ntris;     /* surface triangles (0: none) */
    double *points;         /* 3 per point (scaled) */
    int *tri;               /* 3 corner point indices (0-based) per triangle */
    int *tri_mol, *tri_type; /* per triangle: surface molecule ID and type (>= 1) */
    /* header values */
    int massflag, comflag, inertiaflag;
    double masstotal, com[3], itensor[6]; /* itensor: xx yy zz xy xz yz (file order) */
    /* derived (mol_compute_*) */
    int centerflag, massdone, comdone, inertiadone;
    double center[3], molradius;
    double *dx;             /* 3 per atom: x - center */
    double *dxcom;          /* 3 per atom: x - com */
    double *dxbody;         /* 3 per atom: dxcom in the principal-axes frame */
    int comatom;            /* 1-based atom closest to the com */
    double maxextent;       /* largest distance from comatom to an atom */
    double inertia[3];      /* principal moments, decreasing (0 below 1e-7 x max) */
    double ex[3], ey[3], ez[3], quat[4];
};

/* `molecule` command. */
void cmd_molecule(struct gravel *g, int argc, char **argv);
/* The template with this ID, or NULL. */
struct molecule *molecule_find(struct gravel *g, const char *id);
/* An error when template m has no atoms (a surface-only one). */
void mol_require_atoms(struct gravel *g, const struct molecule *m);
void molecules_free(struct gravel *g);
/* Free one template (one not in the list, e.g. a clump template's). */
void mol_free(struct molecule *m);

/* LAMMPS Molecule::compute_center / compute_mass / compute_com /
 * compute_inertia (each once; later calls return at once). */
void mol_compute_center(struct molecule *m);
void mol_compute_mass(struct gravel *g, struct molecule *m);
void mol_compute_com(struct gravel *g, struct molecule *m);
void mol_compute_inertia(struct gravel *g, struct molecule *m);

/* LAMMPS's random orientation of an inserted molecule (fix pour, create_atoms):
 * in 3d an axis of three draws u - 0.5, normalised, in 2d the z axis; then the
 * angle 2 pi u. `uniform` draws from `rng` in (0, 1) or [0, 1). */
void mol_random_quat(int dim, double (*uniform)(void *rng), void *rng, double quat[4]);
/* Atom k of m rotated by rot about the geometric centre placed at center
 * (needs mol_compute_center): rot dx_k + center, LAMMPS's matvec then add3. */
void mol_place_atom(const struct molecule *m, const double rot[3][3], const double center[3],
                    int k, double out[3]);

#endif
