/* The scene description (docs/scene-file.md): plain data in the file's units, with the line of each
   key. The reader (io/scene_read.h) fills it; the model is built from it. */
#ifndef ZP_SCENE_H
#define ZP_SCENE_H

#include <stddef.h>

#include "diag.h"

#define ZP_MAX_LINKS 8
#define ZP_MAX_SECTIONS 64
#define ZP_EXPR_MAX 256
#define ZP_NAME_MAX 128
#define ZP_SCENE_EVALS_PER_SECTION 5000 /* the search's default budget, per section */
#define ZP_MAX_DRIVE_PARAMS (4 * ZP_MAX_SECTIONS) /* parameters of a drive schedule */

/* Bounds the reader holds [solver] to (docs/scene-file.md), each also as text for its messages.
   Tolerances: tighter than 1e-14 (rtol) is below round-off for every method; looser than
   1e-2 answers nothing worth the name; atol in m, m/s, rad. t_max: CVODE sizes its first step
   from it (a first step of ~1e50 s fails at t = 0); a ride of 11 days is past any course.
   Rows: t_max / output_dt + 1 trajectory rows at most, refused before running (each row is
   held in memory, about 0.5 kB, and written to trajectory.csv: 1e6 rows is 0.5 GB). */
#define ZP_RTOL_MIN 1e-14
#define ZP_RTOL_MAX 1e-2
#define ZP_ATOL_MIN 1e-16
#define ZP_ATOL_MAX 1.0
#define ZP_T_MAX_MAX 1e6
#define ZP_MAX_ROWS 1000000
#define ZP_RTOL_MIN_S "1e-14"
#define ZP_RTOL_MAX_S "1e-2"
#define ZP_ATOL_MIN_S "1e-16"
#define ZP_ATOL_MAX_S "1"
#define ZP_T_MAX_MAX_S "1e6"
/* [solver] accuracy, s: 1e-12 is near the table's best (docs/trade.md); 1e-1 s is the loosest
   finish time worth ranking schedules by */
#define ZP_ACCURACY_MIN 1e-12
#define ZP_ACCURACY_MAX 1e-1
#define ZP_ACCURACY_MIN_S "1e-12"
#define ZP_ACCURACY_MAX_S "1e-1"

/* room for this many keys' "given" bits (io/scene_keys.def) */
#define ZP_SCENE_GIVEN_WORDS 2

typedef struct zp_scene {
    char path[1024];           /* the file this came from, for messages */
    char name[ZP_NAME_MAX];    /* [scene] name, default: the file's stem */
    double gravity;            /* m/s^2 */

    double x_start;                          /* m */
    int nsec;                                /* [course] section lines */
    double x_end[ZP_MAX_SECTIONS];           /* m, right end of each section */
    char expr[ZP_MAX_SECTIONS][ZP_EXPR_MAX]; /* f(x) text of each section */
    int sec_line[ZP_MAX_SECTIONS];           /* line of each section key */

    double trolley_mass; /* kg */

    int nlink;
    double lengths[ZP_MAX_LINKS]; /* m, from the trolley down */
    double masses[ZP_MAX_LINKS];  /* kg */
    int ndamping;                 /* 1 (all joints) or nlink */
    double damping[ZP_MAX_LINKS]; /* N m s/rad */
    double death_angle;           /* deg, the largest joint's (all of them when one is given) */
    int ndeath;                   /* death_angle values given: 1 (every joint) or nlink */
    double death_angles[ZP_MAX_LINKS]; /* deg, per joint (each set, also from one value) */

    char direction[16];                /* horizontal | tangent */
    int drive_kind;                    /* zp_sched_kind (drive.h) of the forces */
    int drive_knots;                   /* kind profile: forces per section (default 3) */
    double drive_power;                /* W, the cap on |F_applied v|; 0: none */
    double drive_response;             /* s, the applied force's lag time tau; 0: at once */
    int nforce;                        /* parameters; 0 when absent: all forces 0 */
    double forces[ZP_MAX_DRIVE_PARAMS]; /* the schedule's parameters (N per section) */
    double force_min, force_max;       /* N, search bounds */

    char method[32];      /* integrator name (method registry) */
    char formulation[32]; /* formulation name (formulation registry) */
    double rtol, atol;
    double accuracy;  /* s on the finish time, 0: not given (method and rtol decide) */
    double t_max;     /* s */
    double output_dt; /* s */

    double margin;  /* deg */
    long max_evals; /* simulations the search may spend */
    unsigned long seed;
    int objective_slowest;  /* [optimize] objective = slowest: the slowest finish over the held
                               scenarios is minimised, not the nominal rider's */
    char
        search_method[32]; /* integrator of the search's runs (the answer is rerun with [solver]) */
    double search_rtol;     /* their rtol; atol = rtol / 100 */

    /* [limits] (docs/scene-file.md): each 0 when absent, meaning off */
    double max_g;             /* g, peak felt acceleration |a - g| / g at any link's centre */
    double max_joint_force;   /* N, peak joint reaction at any joint */
    double max_arrival_speed; /* km/h, trolley speed at x_end */
    double max_kink_dv;       /* m/s, |v+ - v-| of the trolley at any kink */
    double min_arrival_speed; /* km/h, every rider arrives at least this fast; 0: off */
    double max_drive_power;   /* W, peak |F_applied v| the drive delivers over the ride */
    double max_cable_tension; /* N, [cable]: the largest anchor tension over the ride */
    int nenv;                 /* g_envelope levels, 0: none */
    double env_g[8], env_s[8]; /* g, s: felt g above env_g[l] for at most env_s[l] at a time */
    unsigned g_links;         /* bit i: link i + 1's felt g is judged (max_g, g_envelope); 0: all */

    /* [robust] (docs/scene-file.md): ranges in % of nominal; {100, 100} and 0 when absent */
    int robust;                   /* 1 when the scene has a [robust] section */
    double force_error;           /* %, each section's force * (1 + u), |u| <= p / 100 */
    double mass_range[2];         /* % of the nominal link masses, all links together */
    double length_range[2];       /* % of the nominal link lengths, all links together */
    double trolley_mass_range[2]; /* % of the nominal trolley mass */
    double damping_range[2];      /* % of the nominal joint damping */
    double start_angle;           /* deg, each link may start swung by up to this either way */
    int robust_samples;           /* scenarios every candidate is held to (default 64) */
    int verify_samples;           /* fresh scenarios the answer is checked on (default 2000) */
    int wind_varied;              /* 1: wind_range given */
    double wind_range[2];         /* m/s, the horizontal wind's range (needs drag_area) */
    unsigned scale_links;         /* bit i: mass_range and length_range scale link i + 1; 0: all */
    double safety_factor;         /* the box held is the stated one widened this much about the
                                     nominal (default 1); reports stay against the stated box */

    /* [physics] (docs/scene-file.md, docs/model.md "Optional effects"): all off when absent */
    int ndrag;                             /* 0: no drag; else nlink + 1 */
    double drag_area[ZP_MAX_LINKS + 1];    /* m^2, Cd*A of the trolley, then each link */
    double air_density;                    /* kg/m^3 (default 1.225) */
    double wind;                           /* m/s, horizontal, + toward +x */
    double rolling;                        /* rolling-resistance coefficient mu (default 0) */
    double kink_radius;                    /* m, 0: sharp kinks */

    /* [cable] (docs/scene-file.md, docs/model.md "A cable that sags"), instead of [course]: the
       reader then fills x_start and the drive sections (nsec, x_end) from it, expr stays empty */
    int cable;                   /* 1 when the scene has a [cable] section */
    double cable_a[2], cable_b[2]; /* m, anchors A (the ride starts) and B */
    double cable_length;         /* m, unstretched length; 0: from cable_tension */
    double cable_tension;        /* N, unloaded horizontal tension; 0: cable_length is given */
    double cable_weight;         /* N/m, per unstretched metre */
    double cable_ea;             /* N, axial stiffness; 0: inextensible */

    /* [brake] (docs/scene-file.md, docs/model.md "A brake zone"): off when absent */
    int brake;             /* 1 when the scene has a [brake] section */
    double brake_start;    /* m, the zone's first x */
    double brake_end;      /* m, its last x (default: the course's end) */
    double brake_eddy;     /* N s/m, force eddy * speed against the motion */
    double brake_friction; /* N, force of this size against the motion; holds at rest */

    /* bit k set: the file gave key k of the reader's table (io/scene_keys.def), so `check` can
       show every key zipopt added itself */
    unsigned long long given[ZP_SCENE_GIVEN_WORDS];

    /* lines of keys that later stages judge (0 if absent), for their messages */
    int line_forces, line_method, line_formulation, line_search_method, line_kink_radius;
    int line_cable; /* the [cable] header's line */
    int line_max_evals; /* 0: max_evals not given: ZP_SCENE_EVALS_PER_SECTION per section */
} zp_scene;

/* 1 when the file gave key k of the key table (io/scene_keys.def) */
static inline int zp_scene_given(const zp_scene *sc, int k) {
    return (int)(sc->given[k / 64] >> (k % 64) & 1);
}

#endif
