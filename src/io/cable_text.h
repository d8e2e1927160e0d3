/* What `check` tells a designer about a cable scene (docs/model.md "A cable that sags"): the
   unloaded rope, and the loaded paths of the nominal rider and of the population's lightest
   and heaviest. */
#ifndef ZP_CABLE_TEXT_H
#define ZP_CABLE_TEXT_H

#include <stdio.h>

#include "model.h"

/* The rope as it hangs alone (sag, lowest point, tension at each anchor), then per rider the
   load, the sag below the chord at mid-span and its largest value, the lowest point, the end
   slope and the largest tensions at the trolley and at each anchor over the ride; the riders
   are the nominal one and, with [robust] mass ranges, the lightest and heaviest. Nothing
   without a cable. */
void zp_cable_text_print(FILE *f, const zp_model *m, const zp_scene *sc);
/* The same as members of check --json's "cable" object (after its n keys given): the
   unstretched length, "unloaded" (null for a weightless rope), the ride's x range and
   "riders", one object per rider. Nothing without a cable. */
void zp_cable_text_json(FILE *f, const zp_model *m, const zp_scene *sc, int n);

/* A rider check shows: its name and load (N, with the trolley). */
typedef struct zp_cable_text_rider {
    const char *who; /* "nominal", "lightest", "heaviest" */
    double load;
} zp_cable_text_rider;
/* The riders into out: the nominal one, and with [robust] mass ranges the lightest and the
   heaviest; returns how many (0 without a cable). */
int zp_cable_text_riders(const zp_model *m, const zp_scene *sc, zp_cable_text_rider out[3]);

#endif
