/* fix_particletemplate_sphere.h - the particle template of LIGGGHTS's fix
 * particletemplate/sphere, read by fix particledistribution/discrete and
 * the insertion fixes (fix_insert.h). */
#ifndef GR_FIX_PARTICLETEMPLATE_SPHERE_H
#define GR_FIX_PARTICLETEMPLATE_SPHERE_H

#include "random.h"
#include "state.h"

struct fix;

enum pdf_style { PDF_CONSTANT, PDF_UNIFORM, PDF_GAUSSIAN, PDF_LOGNORMAL };

/* A radius or density distribution (LIGGGHTS probability_distribution.h):
 * constant mu; uniform in [min, max]; gaussian mu sigma and lognormal
 * exp(mu + sigma N) truncated (redrawn) outside mu +- 3 sigma. */
struct pdf {
    enum pdf_style style;
    double mu, sigma, min, max;
};

double pdf_sample(const struct pdf *p, struct rng_park *rng);
double pdf_mean(const struct pdf *p);        /* E[X] */
double pdf_cubic_mean(const struct pdf *p);  /* E[X^3] */

struct ptemplate {
    int seed;                   /* as given (LIGGGHTS seed_orig) */
    struct rng_park rng;        /* random_insertion: radius, then density per particle */
    int type;
    struct pdf radius, density;
    double volexpect, massexpect, vol_limit;
    unsigned groupbit;
    int have_radius, have_density;
    /* particletemplate/multisphere: the clump (fix_particletemplate_multisphere.h),
     * NULL for a sphere; radius is then constant at its bounding sphere's */
    struct mstemplate *ms;
};

/* Set up t for fix f from `seed` (argv[0]): seed check and stream, defaults
 * (type 1, volume_limit 1e-12). */
void ptemplate_start(struct gravel *g, struct fix *f, struct ptemplate *t, int argc, char **argv,
                     const char *who);
/* LIGGGHTS FixTemplateSphere's keyword at argv[i] (atom_type, radius,
 * density, volume_limit, relative): the words consumed, 0 if not one. */
int ptemplate_keyword(struct gravel *g, struct ptemplate *t, int argc, char **argv, int i,
                      const char *who);
/* The template of fix `id`, or an error naming `who` when there is no such
 * fix or it is not a particletemplate/sphere or /multisphere. */
struct ptemplate *ptemplate_of(struct gravel *g, const char *id, const char *who);
/* Expected particle volume; error when below volume_limit (as LIGGGHTS). */
double ptemplate_volexpect(struct gravel *g, const struct ptemplate *t, const char *id);
/* One particle: radius draw then density draw (constant: no draw; a
 * multisphere template draws nothing). */
void ptemplate_draw(struct ptemplate *t, double *radius, double *density);

/* The fix's restart state: its stream (fix write_restart/read_restart). */
size_t ptemplate_write_restart(struct gravel *g, struct fix *f, unsigned char *buf, size_t cap);
void ptemplate_read_restart(struct gravel *g, struct fix *f, const unsigned char *buf,
                            size_t len);

/* A LIGGGHTS random seed: an int > 10000 that is prime (LIGGGHTS Random),
 * else an error naming `who`. */
int liggghts_seed(struct gravel *g, const char *s, const char *who);

#endif
