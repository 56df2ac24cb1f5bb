/* kernel_text.h - the embedded text of one kernel source file, for the
 * tests that compile a header shared by host and device on their own. */
#ifndef KERNEL_TEXT_H
#define KERNEL_TEXT_H

#include <string.h>

#include "kernel_sources.h"

/* The text of kernels/<name> as the binary embeds it, or NULL. */
static inline const char *kernel_text_of(const char *name)
{
    for (int k = 0; gr_kernel_sources[k].name; k++)
        if (!strcmp(gr_kernel_sources[k].name, name))
            return gr_kernel_sources[k].text;
    return NULL;
}

#endif
