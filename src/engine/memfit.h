/* memfit.h - will the run fit? The device memory a run needs, estimated
 * before its first large allocation and checked again, exactly, when the
 * contacts are counted, against what the device and the process may hold.
 *
 * Need: per atom slot, the run's per-atom fields (eng_atom_bytes) and the
 * neighbor data (nbr_atom_bytes); per contact, the partners, the partner
 * side's index, history and records (nbr_contact_bytes) and the contact's
 * accuracy record (acc_contact_bytes), at the capacity the contact buffers
 * are allocated with (nbr_capacity). Limits: CL_DEVICE_GLOBAL_MEM_SIZE (or
 * env GRAVEL_DEVICE_MEMORY), the process's address-space limit (ulimit -v,
 * which on a CPU device the host arrays share), and the largest single
 * allocation (CL_DEVICE_MAX_MEM_ALLOC_SIZE). A run that would not fit
 * stops with what it needs, the limit, and about how many particles would
 * fit at the same contacts per particle. Fix per-atom state, wall records
 * and other small buffers are checked as they are allocated (ocl_alloc). */
#ifndef GR_MEMFIT_H
#define GR_MEMFIT_H

#include <stddef.h>

#include "state.h"

/* Run start, before the upload: n atom slots and the contacts estimated
 * from the host atoms' local number density (a coarse grid) at the
 * neighbor cut-off; a lattice or a dense packing is estimated within ~10 %. */
void mem_fit_run(struct gravel *g, int n);
/* At a neighbor build that grows the contact buffers: the run with
 * `ncontact` contacts (the device atoms' own count), before any of them is
 * allocated. */
void mem_fit_contacts(struct gravel *g, size_t ncontact);

#endif
