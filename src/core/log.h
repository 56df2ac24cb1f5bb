/* log.h - output to screen and log file, and the log file itself.
 *
 * Every message a run prints goes through gr_print (screen unless
 * `-screen none`, and the log); errors and warnings are error.h. The log
 * file is g->logfile with its name and first failed write (state.h). */
#ifndef GR_LOG_H
#define GR_LOG_H

struct gravel;

/* Output to screen and log, like LAMMPS' utils::logmesg. */
void gr_print(struct gravel *g, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

/* The log file (-log, `log`): open (closing the previous one, checked),
 * 0 or an errno, or -1 with the message in g->err.msg when closing the
 * previous log found a failed write); check that every write so far to it
 * (and to the thermo log) succeeded, else close it and raise "cannot write
 * log file 'F': reason"; close, 0 or -1 with the message in g->err.msg. */
int gr_log_open(struct gravel *g, const char *path, int append);
void gr_log_check(struct gravel *g);
int gr_log_close(struct gravel *g);
/* Close the log and the thermo log without checking their writes and forget
 * their names (destroy). */
void gr_log_release(struct gravel *g);

/* LIGGGHTS's thermo log (`thermo_log FILE [append] | none`): the thermo
 * header and rows also go to g->thermolog, checked with the log by
 * gr_log_check ("cannot write thermo log file 'F': reason"); open and
 * close as the log's (0, an errno, or -1 with the message in g->err.msg). */
int gr_thermolog_open(struct gravel *g, const char *path, int append);
int gr_thermolog_close(struct gravel *g);
void gr_thermolog_write(struct gravel *g, const char *text);

#endif
