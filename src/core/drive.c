/* The drive schedule: its kinds (one table), the force at a state of the trolley and the way it
   points, its break times, its parameters (labels, unit, sections, bounds), its constant pushes
   and its [drive] forces text. Everything that depends on the kind lives here. */
#include "drive.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "text.h"

/* What a kind of schedule is: every question the rest of zipopt asks about a schedule that
   depends on its kind is one entry here. */
typedef struct kind {
    const char *name;         /* [drive] kind */
    const char *noun, *nouns; /* one parameter, several: labels are noun + 1-based index */
    const char *unit;         /* of every parameter */
    /* how many parameters s's sections take */
    int (*nparam)(const zp_schedule *s);
    /* the section parameter k acts on (0-based), and the stretch [from, to] (m) where */
    int (*section)(const zp_schedule *s, int k);
    void (*span)(const zp_schedule *s, int k, const double *xb, double *from, double *to);
    /* N, the schedule's force at st, before any cap; where it jumps in time */
    double (*force)(const zp_schedule *s, const zp_drive_state *st);
    int (*breaks)(const zp_schedule *s, double *t, int max);
    /* s's parameters p pushing F everywhere */
    void (*constant)(const zp_schedule *s, double F, double *p);
    /* section sec's drive in words */
    void (*label)(const zp_schedule *s, int sec, char *buf, size_t cap);
} kind;

/* kind constant (ZP_SCHED_SECTIONS): parameter k is section k's force, at every t, x, v */
static int const_nparam(const zp_schedule *s) {
    return s->nsec;
}

static int const_section(const zp_schedule *s, int k) {
    (void)s;
    return k;
}

static void const_span(const zp_schedule *s, int k, const double *xb, double *from, double *to) {
    (void)s;
    *from = xb[k];
    *to = xb[k + 1];
}

static double const_force(const zp_schedule *s, const zp_drive_state *st) {
    return s->p[st->sec];
}

static int const_breaks(const zp_schedule *s, double *t, int max) {
    (void)s;
    (void)t;
    (void)max;
    return 0;
}

static void const_constant(const zp_schedule *s, double F, double *p) {
    for (int k = 0; k < s->np; k++) {
        p[k] = F;
    }
}

static void const_label(const zp_schedule *s, int sec, char *buf, size_t cap) {
    snprintf(buf, cap, "%g N", s->p[sec]);
}

/* kind profile (ZP_SCHED_PROFILE): parameter k is knot k % knots of section k / knots, at the
   share j / (knots - 1) of the section; the force is linear in x between knots, so continuous
   in x: only its slope changes at a knot, and the integrator needs no stop there */
static int prof_nparam(const zp_schedule *s) {
    return s->nsec * s->knots;
}

static int prof_section(const zp_schedule *s, int k) {
    return k / s->knots;
}

static void prof_span(const zp_schedule *s, int k, const double *xb, double *from, double *to) {
    int sec = k / s->knots, j = k % s->knots;
    if (s->knots == 1) {
        const_span(s, sec, xb, from, to);
        return;
    }
    *from = *to = xb[sec] + (xb[sec + 1] - xb[sec]) * j / (s->knots - 1);
}

static double prof_force(const zp_schedule *s, const zp_drive_state *st) {
    const double *p = s->p + st->sec * s->knots;
    if (s->knots == 1) {
        return p[0]; /* the constant kind, bit for bit */
    }
    /* a trolley a hair past its section's ends (an event located within its tolerance) takes
       the end knot's force */
    double a = s->xb[st->sec], b = s->xb[st->sec + 1];
    double u = fmin(fmax((st->x - a) / (b - a), 0), 1) * (s->knots - 1);
    int j = u < s->knots - 1 ? (int)u : s->knots - 2;
    return p[j] + (p[j + 1] - p[j]) * (u - j);
}

static void prof_label(const zp_schedule *s, int sec, char *buf, size_t cap) {
    const double *p = s->p + sec * s->knots;
    if (s->knots == 1) {
        snprintf(buf, cap, "%g N", p[0]);
    } else {
        snprintf(buf, cap, "%g..%g N", p[0], p[s->knots - 1]);
    }
}

static const kind kinds[ZP_SCHED_KIND_COUNT] = {
    [ZP_SCHED_SECTIONS] = {"constant", "section", "sections", "N", const_nparam, const_section,
                           const_span, const_force, const_breaks, const_constant, const_label},
    [ZP_SCHED_PROFILE] = {"profile", "knot", "knots", "N", prof_nparam, prof_section, prof_span,
                          prof_force, const_breaks, const_constant, prof_label},
};

static const kind *kind_of(const zp_schedule *s) {
    return &kinds[s->kind];
}

static const char *const dir_names[ZP_DRIVE_COUNT] = {"horizontal", "tangent"};

const char *zp_drive_dir_name(zp_drive_dir d) {
    return dir_names[d];
}

int zp_drive_plain(const zp_schedule *s) {
    return s->kind == ZP_SCHED_SECTIONS && !(s->power > 0);
}

const char *zp_drive_kind_name(zp_sched_kind k) {
    return kinds[k].name;
}

int zp_drive_kind_find(const char *name) {
    for (int i = 0; i < ZP_SCHED_KIND_COUNT; i++) {
        if (!strcmp(name, kinds[i].name)) {
            return i;
        }
    }
    return -1;
}

int zp_drive_dir_find(const char *name) {
    for (int i = 0; i < ZP_DRIVE_COUNT; i++) {
        if (!strcmp(name, dir_names[i])) {
            return i;
        }
    }
    return -1;
}

/* kind's shape on nsec sections (knots each), every parameter in [lo, hi] and 0 */
static zp_schedule shape_of(zp_sched_kind kind, int nsec, int knots, double lo, double hi) {
    zp_schedule s = {.kind = kind, .nsec = nsec, .knots = knots};
    s.np = kind_of(&s)->nparam(&s);
    for (int k = 0; k < s.np; k++) {
        s.lo[k] = lo;
        s.hi[k] = hi;
    }
    return s;
}

zp_schedule zp_drive_sections(int nsec, const double *force, double lo, double hi) {
    zp_schedule s = shape_of(ZP_SCHED_SECTIONS, nsec, 1, lo, hi);
    for (int k = 0; force && k < s.np; k++) {
        s.p[k] = force[k];
    }
    return s;
}

zp_schedule zp_drive_profile(int nsec, int knots, double x_start, const double *x_end,
                             const double *force, double lo, double hi) {
    zp_schedule s = shape_of(ZP_SCHED_PROFILE, nsec, knots, lo, hi);
    s.xb[0] = x_start;
    memcpy(s.xb + 1, x_end, sizeof *x_end * (size_t)nsec);
    for (int k = 0; force && k < s.np; k++) {
        s.p[k] = force[k];
    }
    return s;
}

zp_schedule zp_drive_with(const zp_schedule *sh, const double *p) {
    zp_schedule s = *sh;
    memcpy(s.p, p, sizeof *p * (size_t)s.np);
    return s;
}

zp_schedule zp_drive_of_scene(const zp_scene *sc) {
    zp_schedule s = sc->drive_kind == ZP_SCHED_PROFILE
                        ? zp_drive_profile(sc->nsec, sc->drive_knots, sc->x_start, sc->x_end,
                                           NULL, sc->force_min, sc->force_max)
                        : zp_drive_sections(sc->nsec, NULL, sc->force_min, sc->force_max);
    s.power = sc->drive_power;
    if (sc->nforce > 0) {
        s.np = sc->nforce;
        memcpy(s.p, sc->forces, sizeof *s.p * (size_t)s.np);
    }
    return s;
}

zp_schedule zp_drive_constant(const zp_schedule *shape, double F) {
    zp_schedule s = *shape;
    kind_of(shape)->constant(shape, F, s.p);
    return s;
}

void zp_drive_constant_bounds(const zp_schedule *shape, double *lo, double *hi) {
    *lo = shape->lo[0];
    *hi = shape->hi[0];
    for (int k = 1; k < shape->np; k++) {
        *lo = fmax(*lo, shape->lo[k]);
        *hi = fmin(*hi, shape->hi[k]);
    }
}

zp_schedule zp_drive_scaled(const zp_schedule *s, const double *scale) {
    zp_schedule out = *s;
    for (int k = 0; k < s->np; k++) {
        out.p[k] = s->p[k] * scale[kind_of(s)->section(s, k)];
    }
    return out;
}

/* 1 when a force F at speed v asks for more than the drive's power */
static int over_power(const zp_schedule *s, double F, double v) {
    return s->power > 0 && fabs(F * v) > s->power;
}

double zp_drive_force(const zp_schedule *s, const zp_drive_state *st) {
    double F = kind_of(s)->force(s, st);
    return over_power(s, F, st->v) ? copysign(s->power / fabs(st->v), F) : F;
}

int zp_drive_capped(const zp_schedule *s, const zp_drive_state *st) {
    return over_power(s, kind_of(s)->force(s, st), st->v);
}

double zp_drive_lag_rate(const zp_schedule *s, double tau, const zp_drive_state *st,
                         double applied) {
    return (zp_drive_force(s, st) - applied) / tau;
}

int zp_drive_breaks(const zp_schedule *s, double *t, int max) {
    return kind_of(s)->breaks(s, t, max);
}

int zp_drive_param_section(const zp_schedule *s, int k) {
    return kind_of(s)->section(s, k);
}

void zp_drive_param_label(const zp_schedule *s, int k, char *buf, size_t cap) {
    snprintf(buf, cap, "%s %d", kind_of(s)->noun, k + 1);
}

void zp_drive_param_span(const zp_schedule *s, int k, const double *xb, double *from, double *to) {
    kind_of(s)->span(s, k, xb, from, to);
}

const char *zp_drive_param_noun(const zp_schedule *s, int plural) {
    return plural ? kind_of(s)->nouns : kind_of(s)->noun;
}

const char *zp_drive_unit(const zp_schedule *s) {
    return kind_of(s)->unit;
}

int zp_drive_parse(const zp_schedule *shape, const char *text, zp_schedule *s, char *why,
                   size_t whylen) {
    double p[ZP_SCHED_MAX_PARAMS];
    int n = zp_text_items(text, p, ZP_SCHED_MAX_PARAMS, why, whylen);
    if (n < 0) {
        return -1;
    }
    if (n != shape->np) {
        if (shape->kind == ZP_SCHED_PROFILE) {
            snprintf(why, whylen, "%d value%s, expected %d (%d sections x %d knots)", n,
                     n == 1 ? "" : "s", shape->np, shape->nsec, shape->knots);
        } else {
            snprintf(why, whylen, "%d value%s, expected %d (one per %s)", n, n == 1 ? "" : "s",
                     shape->np, kind_of(shape)->noun);
        }
        return -2;
    }
    *s = zp_drive_with(shape, p);
    return 0;
}

int zp_drive_parse_sections(const char *text, int nsec, zp_schedule *s, char *why, size_t whylen) {
    zp_schedule shape = zp_drive_sections(nsec, NULL, 0, 0);
    return zp_drive_parse(&shape, text, s, why, whylen);
}

int zp_drive_format(const zp_schedule *s, char *buf, size_t cap) {
    size_t len = 0;
    int total = 0;
    if (cap) {
        buf[0] = '\0';
    }
    for (int k = 0; k < s->np; k++) {
        /* %.17g: every double reads back to the same bits */
        int w = snprintf(buf + len, cap > len ? cap - len : 0, "%s%.17g", k ? ", " : "", s->p[k]);
        total += w;
        len = (size_t)total < cap ? (size_t)total : cap;
    }
    return total;
}

void zp_drive_section_label(const zp_schedule *s, int sec, char *buf, size_t cap) {
    kind_of(s)->label(s, sec, buf, cap);
}
