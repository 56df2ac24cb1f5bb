/* fix_granular_mdr_ranks.h - fix granular/mdr on several MPI ranks
 * (doc/parallel.md, phase 1): every step the mdr bookkeeping's inputs of
 * every rank are gathered to every rank, which evaluates the whole host
 * part (styles/fix/fix_granular_mdr.c) in tag order exactly as one process
 * does, so the per-atom state kept by tag stays the same on every rank and
 * each rank takes back what its own atoms and contacts need.
 *
 * Gathered: each owned atom's tag, position, radius, mass, group mask and
 * its rows of the mdr walls' per-atom state, in tag order; each contact
 * whose lower-tag atom this rank owns (so every contact of one process's
 * list once), its tags and history row, in ascending (lower tag, higher
 * tag). Taken back: the owned atoms' radii and wall rows, and every local
 * contact's row by tag pair (the contacts between an owned atom and a
 * ghost on both ranks, the same bits). */
#ifndef GR_FIX_GRANULAR_MDR_RANKS_H
#define GR_FIX_GRANULAR_MDR_RANKS_H

#include <stddef.h>
#include <stdint.h>

struct gravel;

/* The atoms the host part reads (index: position in the set). On one
 * process g->atoms' own arrays; on several ranks every rank's atoms in tag
 * order. */
struct mdr_atoms {
    int n;
    const int64_t *tag;
    const double *x;
    double *radius;
    const double *rmass;
    const unsigned *mask;
};

#define MDR_RANKS_WALLS 64

struct mdr_ranks {
    int n;                       /* every rank's atoms */
    int64_t *tag;
    double *x, *radius, *rmass;
    unsigned *mask;
    int nown;                    /* this rank's owned atoms and their index in the set */
    int *own;
    int nw;                      /* mdr walls: per-atom row widths, every atom's rows */
    size_t stride[MDR_RANKS_WALLS];
    double *wall[MDR_RANKS_WALLS];
    int nc, hw;                  /* every contact: atoms (set indices, lower tag first), rows */
    int *ci, *cj;
    double *hist;
    int nloc;                    /* this rank's contacts: index in the gathered ones or -1 */
    int *loc;
};

/* Collective. The owned atoms (g->atoms after run_sync_host) with their
 * rows of nw walls (stride[k] doubles per atom in own[k], NULL: none) from
 * every rank into r, and the set as *v. */
void mdr_ranks_atoms(struct gravel *g, struct mdr_ranks *r, int nw, const size_t *stride,
                     double *const *own, struct mdr_atoms *v);
/* The set's radii of the owned atoms into radius (g->atoms.radius). */
void mdr_ranks_radius_back(const struct mdr_ranks *r, double *radius);
/* The set's rows of wall k of the owned atoms into own (owned order). */
void mdr_ranks_wall_back(const struct mdr_ranks *r, int k, double *own);
/* Collective. This rank's nc contacts (device slots ci, cj; hw doubles of
 * history each) from every rank, as above. */
void mdr_ranks_contacts(struct gravel *g, struct mdr_ranks *r, int nc, const int *ci,
                        const int *cj, const double *hist, int hw);
/* The gathered rows of this rank's contacts into hist (rows of a pair in no
 * rank's gathered contacts unchanged). */
void mdr_ranks_contacts_back(const struct mdr_ranks *r, double *hist);
void mdr_ranks_free(struct mdr_ranks *r);

#endif
