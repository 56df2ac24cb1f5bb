/* dump_custom.h - what dump custom (styles/dump/dump_custom.c) offers the dump
 * styles built on it (dump atom). */
#ifndef GR_DUMP_CUSTOM_H
#define GR_DUMP_CUSTOM_H

struct dump;

/* dump custom (and dump atom, built on it): 1 if the dump has field `name`. */
int dump_custom_has_field(const struct dump *d, const char *name);

#endif
