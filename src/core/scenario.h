/* Uncertainty (docs/model.md): a scenario is the nominal model with its forces, masses, lengths,
   damping and start angles changed, derived from the built model without re-parsing or
   re-compiling the course. */
#ifndef ZP_SCENARIO_H
#define ZP_SCENARIO_H

#include "limit.h" /* what a scenario's run is judged by, for the headers' users */
#include "sim.h"

/* One scenario: factors on the nominal values (1: nominal) and start angles. */
typedef struct zp_scenario {
    double force[ZP_MAX_SECTIONS]; /* factor on each section's force */
    double mass, length, trolley, damping; /* factors on all link masses, all link lengths, the
                                              trolley mass, every joint's damping */
    double theta[ZP_MAX_LINKS];    /* rad, each link's start angle from the vertical */
    int wind_set;                  /* 1: wind replaces the nominal wind */
    double wind;                   /* m/s, horizontal */
} zp_scenario;

void zp_scenario_nominal(zp_scenario *s);
/* out = nom with s's masses, lengths and damping. out shares nom's course (borrowed): it
   lives no longer than nom and is never passed to zp_model_free. */
void zp_scenario_model(const zp_model *nom, const zp_scenario *s, zp_model *out);
/* The start of s: nominal (the docs/model.md start, zp_state_start) with each of the nlink links
   turned to s->theta, at rest. */
void zp_scenario_start(const zp_chain *nominal, int nlink, const zp_scenario *s, zp_chain *c);
#endif
