/* The drive schedule: its kinds, the force at (t, x, section), its break times and its
   [drive] forces text. Everything that depends on the kind lives here. */
#include "drive.h"

#include <stdio.h>
#include <string.h>

#include "numtext.h"

static const char *const dir_names[ZP_DRIVE_COUNT] = {"horizontal", "tangent"};

const char *zp_drive_dir_name(zp_drive_dir d) {
    return dir_names[d];
}

int zp_drive_dir_find(const char *name) {
    for (int i = 0; i < ZP_DRIVE_COUNT; i++) {
        if (!strcmp(name, dir_names[i])) {
            return i;
        }
    }
    return -1;
}

zp_schedule zp_schedule_sections(int nsec, const double *force, double lo, double hi) {
    zp_schedule s = {.kind = ZP_SCHED_SECTIONS, .nsec = nsec, .np = nsec};
    for (int k = 0; k < nsec; k++) {
        s.p[k] = force ? force[k] : 0;
        s.lo[k] = lo;
        s.hi[k] = hi;
    }
    return s;
}

zp_schedule zp_schedule_with(const zp_schedule *sh, const double *p) {
    zp_schedule s = *sh;
    memcpy(s.p, p, sizeof *p * (size_t)s.np);
    return s;
}

zp_schedule zp_schedule_of_scene(const zp_scene *sc) {
    zp_schedule s = zp_schedule_sections(sc->nsec, NULL, sc->force_min, sc->force_max);
    s.kind = (zp_sched_kind)sc->drive_kind;
    if (sc->nforce > 0) {
        s.np = sc->nforce;
        memcpy(s.p, sc->forces, sizeof *s.p * (size_t)s.np);
    }
    return s;
}

zp_schedule zp_schedule_scaled(const zp_schedule *s, const double *scale) {
    zp_schedule out = *s;
    for (int k = 0; k < s->nsec; k++) { /* per-section constants: one parameter a section */
        out.p[k] = s->p[k] * scale[k];
    }
    return out;
}

double zp_schedule_force(const zp_schedule *s, double t, double x, int sec) {
    (void)t;
    (void)x;
    return s->p[sec];
}

int zp_schedule_breaks(const zp_schedule *s, double *t, int max) {
    (void)s;
    (void)t;
    (void)max;
    return 0;
}

int zp_schedule_parse(const char *text, int nsec, zp_schedule *s, char *why, size_t whylen) {
    double p[ZP_SCHED_MAX_PARAMS];
    int n = zp_text_items(text, p, ZP_SCHED_MAX_PARAMS, why, whylen);
    if (n < 0) {
        return -1;
    }
    if (n != nsec) {
        snprintf(why, whylen, "%d value%s, expected %d (one per section)", n, n == 1 ? "" : "s",
                 nsec);
        return -2;
    }
    *s = zp_schedule_sections(nsec, p, 0, 0);
    return 0;
}

int zp_schedule_format(const zp_schedule *s, char *buf, size_t cap) {
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

void zp_schedule_label(const zp_schedule *s, int sec, char *buf, size_t cap) {
    snprintf(buf, cap, "%g N", s->p[sec]);
}
