/* fix_particledistribution_discrete.c - `fix ID group
 * particledistribution/discrete[/numberbased|/massbased] seed N tpl1 w1 ...
 * tplN wN`: the particles an insertion fix inserts are drawn from N
 * particletemplate/sphere fixes with weights w (LIGGGHTS-PUBLIC 3.8
 * FixParticledistributionDiscrete). Weights are mass fractions (number
 * fractions for /numberbased), normalised with a warning when they do not
 * sum to 1; mass fractions become number fractions w_i / massexpect_i
 * (renormalised). Per insertion step the fix splits the count over the
 * templates (pdist_randomize) with its own Park-Miller stream (seed, no
 * warm-up); the templates are ordered by volume expectancy, largest first
 * (LIGGGHTS's bubble sort), and the inserting fix places them in that
 * order. Full contract: doc/styles/fix_particledistribution_discrete.md. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "args.h"
#include "error.h"
#include "fix.h"
#include "fix_particledistribution_discrete.h"
#include "log.h"

static void create_any(struct gravel *g, struct fix *f, int argc, char **argv, int mass_based,
                       const char *who)
{
    if (argc < 4)
        gr_error(g, "%s: not enough arguments (expected seed N template1 weight1 ...)", who);
    struct pdist *d = gr_calloc(g, 1, sizeof *d);
    f->data = d;
    d->seed = liggghts_seed(g, argv[0], who);
    rng_park_init(&d->rng, d->seed);
    d->groupbit = f->groupbit;
    d->n = arg_int(g, argv[1], "number of templates");
    if (d->n < 1 || d->n > 100000)
        gr_error(g, "%s: illegal number of templates %s", who, argv[1]);
    if (argc != 2 + 2 * d->n)
        gr_error(g, "%s: # of templates does not match # of arguments (%d templates need %d "
                    "words after the seed, got %d)", who, d->n, 1 + 2 * d->n, argc - 1);
    int n = d->n;
    d->tpl = gr_calloc(g, (size_t)n, sizeof *d->tpl);
    d->tpl_id = gr_calloc(g, (size_t)n, sizeof *d->tpl_id);
    d->w = gr_calloc(g, (size_t)n, sizeof(double));
    d->order = gr_calloc(g, (size_t)n, sizeof(int));
    d->parttogen = gr_calloc(g, (size_t)n, sizeof(int));
    d->remainder = gr_calloc(g, (size_t)n, sizeof(double));
    for (int i = 0; i < n; i++) {
        d->tpl[i] = ptemplate_of(g, argv[2 + 2 * i], who);
        snprintf(d->tpl_id[i], GR_NAMELEN, "%s", argv[2 + 2 * i]);
        d->w[i] = arg_double(g, argv[3 + 2 * i], "weight");
        if (!(d->w[i] >= 0))
            gr_error(g, "%s: invalid weight %s", who, argv[3 + 2 * i]);
        for (int j = 0; j < i; j++)
            if (d->tpl[j] == d->tpl[i])
                gr_error(g, "%s: cannot use the same template twice (%s)", who, d->tpl_id[i]);
    }
    double sum = 0;
    for (int i = 0; i < n; i++)
        sum += d->w[i];
    if (!(sum > 0))
        gr_error(g, "%s: the weights sum to %g (need > 0)", who, sum);
    if (fabs(sum - 1.) > 0.00001)
        gr_warn(g, "particledistribution/discrete: sum of distribution weights != 1, "
                   "normalizing distribution");
    for (int i = 0; i < n; i++)
        d->w[i] /= sum;
    for (int i = 0; i < n; i++)
        (void)ptemplate_volexpect(g, d->tpl[i], d->tpl_id[i]);
    if (mass_based) {
        gr_print(g, "Fix particledistribution/discrete (id %s): distribution based on mass%%:\n",
                 f->id);
        for (int i = 0; i < n; i++)
            gr_print(g, "    %s: d=%e (max. bounding sphere) mass%%=%f%%\n", d->tpl_id[i],
                     2. * d->tpl[i]->radius.max, 100. * d->w[i]);
        sum = 0;
        for (int i = 0; i < n; i++) {
            d->w[i] /= d->tpl[i]->massexpect;
            sum += d->w[i];
        }
        for (int i = 0; i < n; i++)
            d->w[i] /= sum;
    }
    gr_print(g, "Fix particledistribution/discrete (id %s): distribution based on number%%:\n",
             f->id);
    for (int i = 0; i < n; i++)
        gr_print(g, "    %s: d=%e (max. bounding sphere) number%%=%f%%\n", d->tpl_id[i],
                 2. * d->tpl[i]->radius.max, 100. * d->w[i]);
    d->minrad = 1000.;
    d->mintype = 10000;
    for (int i = 0; i < n; i++) {
        const struct ptemplate *t = d->tpl[i];
        d->volexpect += t->volexpect * d->w[i];
        d->massexpect += t->massexpect * d->w[i];
        d->maxtype = t->type > d->maxtype ? t->type : d->maxtype;
        d->mintype = t->type < d->mintype ? t->type : d->mintype;
        d->maxrad = t->radius.max > d->maxrad ? t->radius.max : d->maxrad;
        d->minrad = t->radius.min < d->minrad ? t->radius.min : d->minrad;
        d->order[i] = i;
    }
    /* LIGGGHTS's bubble sort by volume expectancy, largest first */
    int swapped, left = n;
    do {
        swapped = 0;
        for (int i = 0; i < n - 1; i++)
            if (d->tpl[d->order[i]]->volexpect < d->tpl[d->order[i + 1]]->volexpect) {
                int tmp = d->order[i];
                d->order[i] = d->order[i + 1];
                d->order[i + 1] = tmp;
                swapped = 1;
            }
        left--;
    } while (swapped && left > 0);
}

static void create_mass(struct gravel *g, struct fix *f, int argc, char **argv)
{
    create_any(g, f, argc, argv, 1, "fix particledistribution/discrete");
}

static void create_number(struct gravel *g, struct fix *f, int argc, char **argv)
{
    create_any(g, f, argc, argv, 0, "fix particledistribution/discrete/numberbased");
}

static void create_massbased(struct gravel *g, struct fix *f, int argc, char **argv)
{
    create_any(g, f, argc, argv, 1, "fix particledistribution/discrete/massbased");
}

struct pdist *pdist_of(struct gravel *g, const char *id, const char *who)
{
    struct fix *f = fix_find(g, id);
    if (!f || strncmp(f->style->name, "particledistribution/discrete", 29))
        gr_error(g, "%s: Fix insert requires you to define a valid ID for a fix of type "
                    "particledistribution/discrete (got '%.64s')", who, id);
    return f->data;
}

int pdist_max_count(const struct pdist *d, int ntotal)
{
    return ntotal + d->n;
}

int pdist_randomize(struct pdist *d, int ntotal, int exact, struct ins_particle *list)
{
    int n = d->n;
    if (!exact) {
        for (int i = 0; i < n; i++)
            d->parttogen[i] = (int)((double)ntotal * d->w[i] + rng_park_uniform(&d->rng));
    } else {
        int truncated = 0;
        for (int i = 0; i < n; i++) {
            d->parttogen[i] = (int)((double)ntotal * d->w[i]);
            truncated += d->parttogen[i];
            d->remainder[i] = (double)ntotal * d->w[i] - (double)d->parttogen[i];
        }
        int gap = ntotal - truncated;
        for (int k = 0; k < gap; k++) {
            double r = rng_park_uniform(&d->rng) * (double)gap, rsum = d->remainder[0];
            int j = 0;
            while (rsum < r && j < n - 1)
                rsum += d->remainder[++j];
            d->parttogen[j]++;
        }
    }
    /* each template draws its particles (template order), stored by size order */
    int start[n > 0 ? n : 1], count = 0;
    for (int k = 0; k < n; k++) {
        start[d->order[k]] = count;
        count += d->parttogen[d->order[k]];
    }
    for (int i = 0; i < n; i++) {
        struct ptemplate *t = d->tpl[i];
        for (int j = 0; j < d->parttogen[i]; j++) {
            struct ins_particle *p = list + start[i] + j;
            double r, dens;
            ptemplate_draw(t, &r, &dens);
            p->type = t->type;
            p->radius = r;
            p->density = dens;
            p->volume = t->ms ? t->volexpect : r * r * r * 4. * M_PI / 3.;
            p->mass = t->ms ? t->massexpect : p->density * p->volume;
            p->tpl = t;
            p->groupbit = t->groupbit | d->groupbit;
            p->x[0] = p->x[1] = p->x[2] = 0;
        }
    }
    return count;
}

static void destroy(struct fix *f)
{
    struct pdist *d = f->data;
    if (d) {
        free(d->tpl);
        free(d->tpl_id);
        free(d->w);
        free(d->order);
        free(d->parttogen);
        free(d->remainder);
    }
    free(d);
}

/* Restart files carry the stream. */
static size_t write_restart(struct gravel *g, struct fix *f, unsigned char *buf, size_t cap)
{
    (void)g;
    const struct pdist *d = f->data;
    if (buf && cap >= sizeof d->rng)
        memcpy(buf, &d->rng, sizeof d->rng);
    return sizeof d->rng;
}

static void read_restart(struct gravel *g, struct fix *f, const unsigned char *buf, size_t len)
{
    struct pdist *d = f->data;
    if (len != sizeof d->rng)
        gr_error(g, "fix %s: restart state of %zu bytes, expected %zu", f->id, len,
                 sizeof d->rng);
    memcpy(&d->rng, buf, sizeof d->rng);
}

const struct fix_style fix_style_particledistribution_discrete = {
    .name = "particledistribution/discrete",
    .create = create_mass,
    .destroy = destroy,
    .write_restart = write_restart,
    .read_restart = read_restart,
};

const struct fix_style fix_style_particledistribution_discrete_numberbased = {
    .name = "particledistribution/discrete/numberbased",
    .create = create_number,
    .destroy = destroy,
    .write_restart = write_restart,
    .read_restart = read_restart,
};

const struct fix_style fix_style_particledistribution_discrete_massbased = {
    .name = "particledistribution/discrete/massbased",
    .create = create_massbased,
    .destroy = destroy,
    .write_restart = write_restart,
    .read_restart = read_restart,
};
