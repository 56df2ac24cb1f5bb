/* fix_particletemplate_sphere.c - `fix ID group particletemplate/sphere seed
 * [atom_type T] [density style args] [radius style args] [volume_limit V]
 * [relative no]`: a spherical particle for fix particledistribution/discrete
 * (LIGGGHTS-PUBLIC 3.8 FixTemplateSphere). No hook: the insertion fixes draw
 * from it. Each particle draws its radius, then its density, from this
 * fix's Park-Miller stream seeded with `seed` (no warm-up), as LIGGGHTS.
 *
 * Styles (radius and density): constant V; uniform number MIN MAX (radius)
 * or uniform MIN MAX (density); gaussian [number] MU SIGMA; lognormal
 * [number] MU SIGMA. LIGGGHTS 3.8 accepts only constant; the others follow
 * its probability_distribution.h (and the 3.0 argument forms): gaussian and
 * lognormal redraw outside mu +- 3 sigma. `mass`-weighted radius styles are
 * refused as LIGGGHTS ("mass distribution not implemented"). Volume and mass
 * expectancies: 4/3 pi E[r^3] and E[density] x that. Full contract:
 * doc/styles/fix_particletemplate_sphere.md. */
#include <math.h>
#include <string.h>

#include "args.h"
#include "error.h"
#include "fix.h"
#include "fix_particletemplate_sphere.h"

#define WHO "fix particletemplate/sphere"

double pdf_sample(const struct pdf *p, struct rng_park *rng)
{
    double v;
    switch (p->style) {
    case PDF_UNIFORM:
        return p->min + rng_park_uniform(rng) * (p->max - p->min);
    case PDF_GAUSSIAN:
        do
            v = p->mu + rng_park_gaussian(rng) * p->sigma;
        while (v < p->min || v > p->max);
        return v;
    case PDF_LOGNORMAL:
        do
            v = exp(p->mu + rng_park_gaussian(rng) * p->sigma);
        while (v < p->min || v > p->max);
        return v;
    default:
        return p->mu;
    }
}

double pdf_mean(const struct pdf *p)
{
    switch (p->style) {
    case PDF_UNIFORM:
        return 0.5 * (p->min + p->max);
    case PDF_LOGNORMAL:
        return exp(p->mu + 0.5 * p->sigma * p->sigma);
    default:
        return p->mu;
    }
}

double pdf_cubic_mean(const struct pdf *p)
{
    double a = p->min, b = p->max;
    switch (p->style) {
    case PDF_UNIFORM:
        return 0.25 * (b * b * b + b * b * a + b * a * a + a * a * a);
    case PDF_GAUSSIAN:
        return p->mu * (p->mu * p->mu + 3 * p->sigma * p->sigma);
    case PDF_LOGNORMAL:
        return exp(3. * p->mu + 4.5 * p->sigma * p->sigma);
    default:
        return p->mu * p->mu * p->mu;
    }
}

int liggghts_seed(struct gravel *g, const char *s, const char *who)
{
    int seed = arg_int(g, s, "seed");
    int prime = seed >= 2;
    for (int d = 2; prime && (long long)d * d <= seed; d++)
        if (seed % d == 0)
            prime = 0;
    if (seed < 10000 || !prime)
        gr_error(g, "%s: Random number generation: It is required that the random seed value "
                    "is > 10000 and a prime number. The random seed used was %s (valid seeds "
                    "are e.g. 15485863, 15485867, 32452843, 32452867, 49979687, 49979693)",
                 who, s);
    return seed;
}

/* `radius|density STYLE args` at argv[i]; returns the words consumed. */
static int parse_pdf(struct gravel *g, struct pdf *p, int argc, char **argv, int i,
                     int is_radius, const char *who)
{
    const char *what = argv[i], *s = argv[i + 1];
    if (!strcmp(s, "constant")) {
        arg_need(g, argc, i, 2, what);
        p->style = PDF_CONSTANT;
        p->mu = p->min = p->max = arg_double(g, argv[i + 2], what);
        if (!(p->mu > 0))
            gr_error(g, "%s: %s must be > 0, got %s", who, what, argv[i + 2]);
        return 3;
    }
    int k = i + 2;
    if (!strcmp(s, "uniform") || !strcmp(s, "gaussian") || !strcmp(s, "lognormal")) {
        /* radius takes number|mass first (LIGGGHTS 3.0); density does not */
        if (is_radius || (k < argc && (!strcmp(argv[k], "number") || !strcmp(argv[k], "mass")))) {
            arg_need(g, argc, i, 2, what);
            if (!strcmp(argv[k], "mass"))
                gr_error(g, "%s: mass distribution not implemented for %s (use number)", who, s);
            if (strcmp(argv[k], "number"))
                gr_error(g, "%s: expecting 'mass' or 'number' after '%s %s', got '%.64s'", who,
                         what, s, argv[k]);
            k++;
        }
        if (k + 1 >= argc)
            gr_error(g, "%s: not enough arguments for %s %s", who, what, s);
        double a = arg_double(g, argv[k], what), b = arg_double(g, argv[k + 1], what);
        if (!strcmp(s, "uniform")) {
            if (!(a > 0 && b > 0 && a < b))
                gr_error(g, "%s: illegal min or max value for %s (%s %s: need 0 < min < max)", who,
                         what, argv[k], argv[k + 1]);
            p->style = PDF_UNIFORM;
            p->min = a, p->max = b;
            p->mu = 0.5 * (a + b);
        } else if (!strcmp(s, "gaussian")) {
            if (!(a > 0))
                gr_error(g, "%s: illegal mu value for %s: %s", who, what, argv[k]);
            if (!(b > 0))
                gr_error(g, "%s: illegal sigma value for %s: %s", who, what, argv[k + 1]);
            p->style = PDF_GAUSSIAN;
            p->mu = a, p->sigma = b;
            p->min = a - 3 * b, p->max = a + 3 * b;
            if (p->min < 0)
                gr_error(g, "%s: Probablity distribution: mu-3*sigma < 0, please increase mu "
                            "or decrease sigma (%s %s %s)", who, what, argv[k], argv[k + 1]);
        } else {
            if (!(b > 0))
                gr_error(g, "%s: illegal sigma value for %s: %s", who, what, argv[k + 1]);
            p->style = PDF_LOGNORMAL;
            p->mu = a, p->sigma = b;
            p->min = exp(a - 3 * b), p->max = exp(a + 3 * b);
        }
        return k + 2 - i;
    }
    gr_error(g, "%s: invalid %s random style '%.64s' (constant, uniform, gaussian, lognormal)", who,
             what, s);
}

int ptemplate_keyword(struct gravel *g, struct ptemplate *t, int argc, char **argv, int i,
                      const char *who)
{
    const char *k = argv[i];
    if (!strcmp(k, "atom_type")) {
        arg_need(g, argc, i, 1, k);
        t->type = arg_int(g, argv[i + 1], "atom_type");
        if (t->type < 1)
            gr_error(g, "%s: invalid atom type (must be >=1), got %s", who, argv[i + 1]);
        return 2;
    }
    if (!strcmp(k, "radius") || !strcmp(k, "density")) {
        arg_need(g, argc, i, 2, k);
        int isr = k[0] == 'r';
        int n = parse_pdf(g, isr ? &t->radius : &t->density, argc, argv, i, isr, who);
        if (isr)
            t->have_radius = 1;
        else
            t->have_density = 1;
        return n;
    }
    if (!strcmp(k, "volume_limit")) {
        arg_need(g, argc, i, 1, k);
        t->vol_limit = arg_double(g, argv[i + 1], k);
        if (!(t->vol_limit > 0))
            gr_error(g, "%s: volume_limit > 0 required, got %s", who, argv[i + 1]);
        return 2;
    }
    if (!strcmp(k, "relative")) {
        arg_need(g, argc, i, 1, k);
        if (arg_yesno(g, argv[i + 1], k))
            gr_error(g, "%s: relative yes (radii relative to a reference) is not "
                        "supported: no command here reads relative radii", who);
        return 2;
    }
    return 0;
}

void ptemplate_start(struct gravel *g, struct fix *f, struct ptemplate *t, int argc, char **argv,
                     const char *who)
{
    if (g->dom.dimension != 3)
        gr_error(g, "%s: this fix is for 3D simulations only", who);
    if (argc < 1)
        gr_error(g, "%s: not enough arguments (expected seed keyword values ...)", who);
    t->seed = liggghts_seed(g, argv[0], who);
    rng_park_init(&t->rng, t->seed);
    t->type = 1;
    t->vol_limit = 1e-12;
    t->groupbit = f->groupbit;
}

static void create(struct gravel *g, struct fix *f, int argc, char **argv)
{
    struct ptemplate *t = gr_calloc(g, 1, sizeof *t);
    f->data = t;
    ptemplate_start(g, f, t, argc, argv, WHO);
    for (int i = 1; i < argc;) {
        int n = ptemplate_keyword(g, t, argc, argv, i, WHO);
        if (!n)
            gr_error(g, WHO ": unrecognized keyword '%.64s' (atom_type, density, radius, "
                        "volume_limit, relative)", argv[i]);
        i += n;
    }
    if (!t->have_density)
        gr_error(g, WHO ": have to define 'density'");
    if (!t->have_radius)
        gr_error(g, WHO ": have to define 'radius'");
    if (t->type > g->atoms.ntypes)
        gr_error(g, WHO ": atom_type %d is larger than the number of atom types %d", t->type,
                 g->atoms.ntypes);
    t->volexpect = pdf_cubic_mean(&t->radius) * 4. * M_PI / 3.;
    t->massexpect = pdf_mean(&t->density) * t->volexpect;
}

struct ptemplate *ptemplate_of(struct gravel *g, const char *id, const char *who)
{
    struct fix *f = fix_find(g, id);
    if (!f)
        gr_error(g, "%s: invalid ID for fix particletemplate provided: %.64s", who, id);
    if (strcmp(f->style->name, "particletemplate/sphere") &&
        strcmp(f->style->name, "particletemplate/multisphere"))
        gr_error(g, "%s: fix %s is not of type particletemplate (it is %s)", who, id,
                 f->style->name);
    return f->data;
}

double ptemplate_volexpect(struct gravel *g, const struct ptemplate *t, const char *id)
{
    if (t->volexpect < t->vol_limit)
        gr_error(g, "fix particletemplate/sphere %s: Volume expectancy too small (%g < "
                    "volume_limit %g). Change 'volume_limit' if you are sure you know what "
                    "you're doing", id, t->volexpect, t->vol_limit);
    return t->volexpect;
}

void ptemplate_draw(struct ptemplate *t, double *radius, double *density)
{
    if (t->ms) { /* a clump: no draw (LIGGGHTS FixTemplateMultiplespheres) */
        *radius = t->radius.mu;
        *density = t->density.mu;
        return;
    }
    *radius = pdf_sample(&t->radius, &t->rng);
    *density = pdf_sample(&t->density, &t->rng);
}

/* Restart files carry the stream (LIGGGHTS writes its state too). */
size_t ptemplate_write_restart(struct gravel *g, struct fix *f, unsigned char *buf, size_t cap)
{
    (void)g;
    const struct ptemplate *t = f->data;
    if (buf && cap >= sizeof t->rng)
        memcpy(buf, &t->rng, sizeof t->rng);
    return sizeof t->rng;
}

void ptemplate_read_restart(struct gravel *g, struct fix *f, const unsigned char *buf, size_t len)
{
    struct ptemplate *t = f->data;
    if (len != sizeof t->rng)
        gr_error(g, "fix %s: restart state of %zu bytes, expected %zu", f->id, len,
                 sizeof t->rng);
    memcpy(&t->rng, buf, sizeof t->rng);
}

const struct fix_style fix_style_particletemplate_sphere = {
    .name = "particletemplate/sphere",
    .create = create,
    .write_restart = ptemplate_write_restart,
    .read_restart = ptemplate_read_restart,
};
