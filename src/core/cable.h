/* A zip line's cable between two anchors (MODEL.md "A cable that sags", CONFIG.md [cable]):
   its description checked, its unstretched length from a tension, and how it hangs unloaded. */
#ifndef ZP_CABLE_H
#define ZP_CABLE_H

#include <stddef.h>

#include "diag.h"
#include "scene.h"

/* What [cable] gives: plain data. Exactly one of length and tension is given (> 0), the other
   is 0. Loads are forces (N) throughout, so the cable needs no gravity: a caller turns masses
   into the load W = g m with its own g. */
typedef struct zp_cable_def {
    double xa, ya;  /* m, anchor A, where the ride starts */
    double xb, yb;  /* m, anchor B, xb > xa */
    double length;  /* m, unstretched length L0; 0: derived from tension */
    double tension; /* N, horizontal tension of the unloaded cable; 0: length is given */
    double weight;  /* N/m, per unstretched metre, >= 0 */
    double ea;      /* N, axial stiffness E A > 0; INFINITY: inextensible */
} zp_cable_def;

/* A checked cable: read-only once built, shared by any number of threads. */
typedef struct zp_cable {
    double xa, ya, xb, yb; /* m, the anchors, xa < xb */
    double length;         /* m, unstretched length L0 */
    double weight;         /* N/m, per unstretched metre */
    double ea;             /* N; INFINITY: inextensible */
    double compliance;     /* 1/N, 1 / ea (0: inextensible) */
} zp_cable;

/* Checks d and fills c (L0 solved from the unloaded tension when d gives a tension). Returns
   ZP_OK, or ZP_ERR_INPUT with what is wrong and what is expected in why (c unspecified):
   non-finite numbers, xa >= xb, weight < 0, ea <= 0, both or neither of length and tension, an
   inextensible length not longer than |AB| (it cannot hang), a tension on a weightless
   inextensible cable (the taut chord under any tension). ZP_ERR_NUMERIC when L0 could not be
   solved for. An elastic cable of any length hangs, stretched when shorter than |AB|. */
/* The scene's [cable] as a description (an ea not given: inextensible). */
zp_cable_def zp_cable_def_of_scene(const zp_scene *sc);
zp_status zp_cable_build(const zp_cable_def *d, zp_cable *c, char *why, size_t whylen);

/* How the cable hangs under its own weight alone (one elastic catenary from A to B). */
typedef struct zp_cable_unloaded {
    double h;            /* N, horizontal tension */
    double va, vb;       /* N, how hard the cable pulls A down, and B down */
    double ta, tb;       /* N, tension at A, at B */
    double sag_mid;      /* m, the chord's height minus the cable's at x = (xa + xb) / 2 */
    double x_low, y_low; /* m, the lowest point (an anchor when the cable only falls or rises) */
} zp_cable_unloaded;

/* The unloaded shape of c into u. ZP_ERR_INPUT for a weightless cable not shorter than |AB|
   (it has no shape of its own: it is slack or inextensible and taut), ZP_ERR_NUMERIC when the
   equilibrium is not found; why says which. */
zp_status zp_cable_hang(const zp_cable *c, zp_cable_unloaded *u, char *why, size_t whylen);
/* The unstretched distance from A (m) at which the unloaded cable u of c is above x, for
   xa <= x <= xb; NAN if not found. */
double zp_cable_hang_distance(const zp_cable *c, const zp_cable_unloaded *u, double x);

#endif
