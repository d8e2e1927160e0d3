/* The paths of one cable by load (cable_paths.h): a list searched by exact load under a lock.
   Design note: a list, not a hash: a search holds tens of scenarios and a verification a few
   thousand, each asked for once when its model is derived, never per simulation. */
#include "cable_paths.h"

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>

struct zp_cable_paths {
    zp_cable cable;
    double x_lo, x_hi;
    pthread_mutex_t lock;
    int n, cap;
    double *load;          /* owned: n loads, N */
    zp_cable_path **paths; /* owned: n paths */
};

zp_cable_paths *zp_cable_paths_create(const zp_cable *c, double x_lo, double x_hi) {
    zp_cable_paths *ps = calloc(1, sizeof *ps);
    if (!ps) {
        return NULL;
    }
    ps->cable = *c;
    ps->x_lo = x_lo;
    ps->x_hi = x_hi;
    pthread_mutex_init(&ps->lock, NULL);
    return ps;
}

void zp_cable_paths_free(zp_cable_paths *ps) {
    if (!ps) {
        return;
    }
    for (int i = 0; i < ps->n; i++) {
        zp_cable_path_free(ps->paths[i]);
    }
    free(ps->load);
    free(ps->paths);
    pthread_mutex_destroy(&ps->lock);
    free(ps);
}

/* the path already built for load, NULL if none; under the lock */
static zp_cable_path *find(const zp_cable_paths *ps, double load) {
    for (int i = 0; i < ps->n; i++) {
        if (ps->load[i] == load) {
            return ps->paths[i];
        }
    }
    return NULL;
}

/* p kept for load; 0, or -1 out of memory; under the lock */
static int keep(zp_cable_paths *ps, double load, zp_cable_path *p) {
    if (ps->n == ps->cap) {
        int cap = ps->cap ? 2 * ps->cap : 8;
        double *l = realloc(ps->load, sizeof *l * (size_t)cap);
        ps->load = l ? l : ps->load;
        zp_cable_path **pp = realloc(ps->paths, sizeof *pp * (size_t)cap);
        ps->paths = pp ? pp : ps->paths;
        if (!l || !pp) {
            return -1;
        }
        ps->cap = cap;
    }
    ps->load[ps->n] = load;
    ps->paths[ps->n++] = p;
    return 0;
}

const zp_cable_path *zp_cable_paths_get(zp_cable_paths *ps, double load, char *why,
                                        size_t whylen) {
    pthread_mutex_lock(&ps->lock);
    const zp_cable_path *have = find(ps, load);
    pthread_mutex_unlock(&ps->lock);
    if (have) {
        return have;
    }
    zp_cable_path *p = zp_cable_path_create(&ps->cable, load, ps->x_lo, ps->x_hi, why, whylen);
    if (!p) {
        return NULL;
    }
    pthread_mutex_lock(&ps->lock);
    zp_cable_path *other = find(ps, load);
    int kept = !other && keep(ps, load, p) == 0;
    pthread_mutex_unlock(&ps->lock);
    if (!kept) {
        zp_cable_path_free(p);
        if (!other) {
            snprintf(why, whylen, "out of memory keeping the cable's path");
        }
    }
    return kept ? p : other;
}

const zp_cable *zp_cable_paths_cable(const zp_cable_paths *ps) {
    return &ps->cable;
}

