/* kernel_sources.h - the kernels/<name>.cl files, embedded at build time by
 * tools/embed.c; the table ends with a NULL name. */
#ifndef GR_KERNEL_SOURCES_H
#define GR_KERNEL_SOURCES_H

struct kernel_source {
    const char *name;   /* file name, e.g. "common.cl" */
    const char *text;
};

extern const struct kernel_source gr_kernel_sources[];

#endif
