/* zipopt's public C API (libzipopt.so, pkg-config zipopt): load a scene, set its drive forces,
   simulate, read the result and the trajectory, search for the fastest survivable schedule.
   Units are SI and radians throughout (the program's CSV shows degrees; this API does not). */
#ifndef ZIPOPT_H
#define ZIPOPT_H

/* Names start with zipopt_, not the zp_ of the sources: the internal headers already use
   zp_scene, zp_result, zp_sim_run and more, and a public prefix that names the library is the
   one a user's own code will not collide with. Only these names are exported from the
   library; everything else in it is hidden. */
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(ZIPOPT_BUILDING) && defined(__GNUC__)
#define ZIPOPT_API __attribute__((visibility("default")))
#else
#define ZIPOPT_API
#endif

/* The version of this header; zipopt_version() gives the library's. The library's SONAME
   changes with the major version: a program built against this header keeps working with any
   library of the same major version. */
#define ZIPOPT_VERSION_MAJOR 0
#define ZIPOPT_VERSION_MINOR 1

/* Threads: the library keeps no global mutable state of its own. Each handle is used by one
   thread at a time; different handles may be used from different threads at once. Loading a
   scene and running a search take one process-wide lock, because libmatheval's expression
   parser keeps globals and NLopt's random seed is process-wide (a search stays reproducible
   only when no other search runs beside it); simulations of different scenes run in parallel.
   Errors are returned as text, never printed; the library never exits. Loading a scene turns
   GSL's abort-on-error handler off (gsl_set_error_handler_off), as every GSL call is checked.

   A NULL handle is refused, never followed: a function that makes something returns NULL with
   why in err, a count or index returns -1, a number NaN, a text or array NULL. An output array
   may be NULL: nothing is copied, and the count is returned as usual. */

/* Outcomes of a simulation (the program's outcome names: zipopt_outcome_name). */
enum { ZIPOPT_FINISHED = 0, ZIPOPT_DIED = 1, ZIPOPT_STALLED = 2 };

typedef struct zipopt_scene zipopt_scene;   /* a loaded scene: model, options, drive forces */
typedef struct zipopt_run zipopt_run;       /* one simulation's result and trajectory */
typedef struct zipopt_search zipopt_search; /* one search's answer */

/* "0.1.0": the library's version. */
ZIPOPT_API const char *zipopt_version(void);

/* Loads a scene file (docs/scene-file.md). NULL on bad input with every problem in err, one per line,
   each "FILE:LINE: [section] key: what is wrong; what is expected" (truncated to errlen). */
ZIPOPT_API zipopt_scene *zipopt_scene_load(const char *path, char *err, size_t errlen);
/* The same from scene text in memory; name stands for the file in messages (NULL: "<string>"). */
ZIPOPT_API zipopt_scene *zipopt_scene_load_string(const char *text, const char *name, char *err,
                                                  size_t errlen);
ZIPOPT_API void zipopt_scene_free(zipopt_scene *s); /* NULL is fine */

/* [scene] name, or the file's stem; "" when neither gives one (the library writes no folder
   named by it, so a scene needs no name here, unlike the program's commands). */
ZIPOPT_API const char *zipopt_scene_name(const zipopt_scene *s);
ZIPOPT_API int zipopt_scene_sections(const zipopt_scene *s);     /* course sections */
ZIPOPT_API int zipopt_scene_links(const zipopt_scene *s);        /* chain links */
/* The drive schedule's parameters, as its kind counts them ([drive] forces: one force per
   section, N): how many; the label of parameter k, 0-based ("section 2"), into buf (room for
   cap; returns its length as snprintf does, -1 when k is out of range); their unit ("N"); their
   search bounds ([drive] min, max) into lo and hi (room for n each; either may be NULL),
   returning how many the scene has. */
ZIPOPT_API int zipopt_scene_params(const zipopt_scene *s);
ZIPOPT_API int zipopt_scene_param_label(const zipopt_scene *s, int k, char *buf, size_t cap);
ZIPOPT_API const char *zipopt_scene_param_unit(const zipopt_scene *s);
ZIPOPT_API int zipopt_scene_param_bounds(const zipopt_scene *s, double *lo, double *hi, int n);
/* Copies the drive forces (the schedule's parameters, zipopt_scene_params of them) into force
   (room for n); returns how many the scene has (copying at most n). */
ZIPOPT_API int zipopt_scene_forces(const zipopt_scene *s, double *force, int n);
/* Replaces the drive forces (the schedule's parameters, the [drive] forces override). 0, or -1
   with why in err (a wrong count, a value that is not finite); the scene is unchanged then. */
ZIPOPT_API int zipopt_scene_set_forces(zipopt_scene *s, const double *force, int n, char *err,
                                       size_t errlen);
/* Lays a schedule file (a scene file with only [drive] forces, as the search writes
   schedule.ini) over the scene's drive forces, as `zipopt simulate --schedule FILE` does. 0, or
   -1 with every problem in err (FILE:LINE: [drive] forces: ...); the scene is unchanged then. */
ZIPOPT_API int zipopt_scene_load_schedule(zipopt_scene *s, const char *path, char *err,
                                          size_t errlen);

/* Simulates the scene's forces with its [solver] settings, exactly as `zipopt simulate` does
   (same bits). NULL when the integrator broke down (err says where and why) or memory ran out.
   The run owns its copy of everything: free it with zipopt_run_free. */
ZIPOPT_API zipopt_run *zipopt_simulate(zipopt_scene *s, char *err, size_t errlen);
ZIPOPT_API void zipopt_run_free(zipopt_run *r); /* NULL is fine */
/* The gradient of the scene's run at its forces, exact (forward sensitivities, `zipopt simulate
   --gradient`): d time / d p_k (s per N: the finish, death or stall time) into dtime and
   d margin angle / d p_k (deg per N: the largest relative joint angle reached) into dmargin,
   for each schedule parameter p_k (n at least their count). Returns the count, *smooth 1 where
   the run is differentiable there (0: it meets a point where it is not, e.g. trapped at a
   kink), or -1 with why in err. */
ZIPOPT_API int zipopt_gradient(zipopt_scene *s, double *dtime, double *dmargin, int n,
                               int *smooth, char *err, size_t errlen);

/* The [limits] keys ("max_g", "max_joint_force", ...: docs/scene-file.md [limits]) in the order
   zipopt_gradient_limits fills its rows; NULL past the last. */
ZIPOPT_API const char *zipopt_limit_key(int i);
/* The derivatives of each [limits] value the scene sets, from the same kind of run as
   zipopt_gradient (`zipopt simulate --json`'s gradient.limits): row i of d (n numbers each, n at
   least the parameter count; room for n times the number of keys) for zipopt_limit_key(i), in
   that limit's unit per parameter unit (g, N, km/h, m/s, W per N); a row of NaN where the scene
   does not set that limit or it has no derivative there (the arrival speed of a ride that did
   not finish); smooth[i] (room for the number of keys) 1 where the row is given and
   differentiable, 0 otherwise (`zipopt simulate --gradient` says why). A peak is
   differentiated where the run reaches it (the drive's power at its exact peak, which
   drive_peak_power samples at the steps' ends). Returns the parameter count, or -1 with why in
   err. */
ZIPOPT_API int zipopt_gradient_limits(zipopt_scene *s, double *d, int n, int *smooth, char *err,
                                      size_t errlen);

ZIPOPT_API int zipopt_run_outcome(const zipopt_run *r);  /* ZIPOPT_FINISHED, _DIED, _STALLED */
ZIPOPT_API const char *zipopt_outcome_name(int outcome); /* "finished", .. ; NULL if unknown */
/* Why a stalled run stalled ("t_max", "rolled_back", ..), "" for the others. */
ZIPOPT_API const char *zipopt_run_stall(const zipopt_run *r);
/* A number of the result by name (zipopt_run_key lists them); NaN for an unknown name:
   time (s), x (m), speed (m/s), died_link (1-based, 0 when alive), kinks (crossings),
   e_initial, e_final, w_drive, w_damp, e_impulse, energy_residual (J: e_final - e_initial -
   w_drive + w_damp + e_impulse + w_drag + w_fric + w_brake), constraint_residual (m), steps,
   rhs_evals, wall_s (s), w_drag, w_fric (J: drag and friction work taken out, 0 without
   [physics]), w_brake (J: the brake zone's work taken out, 0 without [brake]),
   peak_g (g: the largest felt acceleration of any link's centre), peak_joint_force (N),
   max_kink_dv (m/s), arrival_kmh (km/h; NaN when the trolley did not arrive), normal_min,
   normal_max (N: the course's force on the trolley, + pushing up), rejected_steps,
   drive_peak_power (W: the largest |F_applied v| at the steps' ends), drive_energy (J: the
   drive's work, w_drive), drive_time_at_cap (s: the time the drive's power cap bound): the
   quantities [limits] judge, as `zipopt simulate --json` reports them (the drive's in its
   `drive` object). */
ZIPOPT_API double zipopt_run_get(const zipopt_run *r, const char *key);
ZIPOPT_API const char *zipopt_run_key(int i); /* the i-th name, NULL past the last */
/* Largest |relative joint angle| of each link over the run (rad) into angle (room for n);
   returns the number of links. */
ZIPOPT_API int zipopt_run_max_angles(const zipopt_run *r, double *angle, int n);
/* Kink crossings, time order: rows of 6 numbers (t s, x m, from and to sections 1-based,
   impulse N s, energy lost J) into out (room for max rows); returns how many there are. */
ZIPOPT_API int zipopt_run_kinks(const zipopt_run *r, double *out, int max);

/* The trajectory, one row every [solver] output_dt and one at the end: rows x columns doubles,
   row-major, owned by the run. Columns: t (s), section (1-based), x, y (m), speed (m/s),
   theta1..N (rad from the downward vertical, ccw), omega1..N (rad/s), phi1..N (rad, relative
   joint angles), kinetic, potential, drive_work, damper_work, impulse_loss (J). */
ZIPOPT_API int zipopt_run_rows(const zipopt_run *r);
ZIPOPT_API int zipopt_run_columns(const zipopt_run *r);
ZIPOPT_API const char *zipopt_run_column(const zipopt_run *r, int j); /* NULL out of range */
ZIPOPT_API const double *zipopt_run_trajectory(const zipopt_run *r);

/* Called, one call at a time, when the best improves (improved = 1) and now and then (0):
   simulations so far, seconds since the start, whether a survivable schedule is known, its
   finish time (s) and forces (the schedule's nparam parameters, valid during the call). A
   nonzero return stops the search, which then answers with the best so far, marked
   interrupted. */
typedef int (*zipopt_progress_fn)(void *user, long evals, double wall_s, int found, double time,
                                  const double *force, int nparam, int improved);

/* Searches the scene's [drive] min..max box for the fastest schedule that finishes with every
   relative joint angle [optimize] margin below death_angle. max_evals <= 0 and seed < 0 take
   the scene's. progress may be NULL; stop (may be NULL) stops the search when it becomes
   nonzero, from any thread or a signal handler. NULL with why in err on failure. */
ZIPOPT_API zipopt_search *zipopt_search_run(zipopt_scene *s, long max_evals, long seed,
                                            zipopt_progress_fn progress, void *user,
                                            volatile int *stop, char *err, size_t errlen);
ZIPOPT_API void zipopt_search_free(zipopt_search *r); /* NULL is fine */
/* A number of the answer by name (zipopt_search_key lists them); NaN for an unknown name:
   found (1 when a survivable schedule was found), time (s, its finish), angle (rad, its
   largest relative joint angle), evals, feasible, failed (simulations), threads, wall_s,
   interrupted, base_found, base_force (N, the best constant push), base_time (s); time,
   angle and the base_ numbers are NaN when nothing survivable was found. How sure it is, as
   summary.json's convergence says: rounds, polishes, basins, reached_best, converged,
   budget_ran_out, time_ran_out (0 or 1), unseen_basins (the Boender-Rinnooy Kan estimate),
   budget_to_help (simulations; NaN unless the budget or time ran out first), islands,
   islands_polished. With [robust]: scenarios (held), verify_samples (fresh scenarios checked),
   verify_survived, verify_margin_kept, verify_limits_kept, verify_all_kept, lower_95 (the 95 %
   lower bound of P(survivable)), worst_margin_deg (over everything held and verified),
   headroom and headroom_breaks (the factor on the stated box up to which the answer holds
   along the worst direction found, and where it breaks), fastest_s, slowest_s,
   arrival_low_kmh, arrival_high_kmh (the population's spread over the fresh scenarios that
   finish), headroom_force_error, headroom_rider_mass, headroom_rider_size,
   headroom_trolley_mass, headroom_joint_damping, headroom_start_angle, headroom_wind (the same
   factor along each range alone; NaN where the scene does not vary it); NaN without
   [robust]. A search
   stopped before it began runs nothing: interrupted, and its forces are the scene's. */
ZIPOPT_API double zipopt_search_get(const zipopt_search *r, const char *key);
ZIPOPT_API const char *zipopt_search_key(int i); /* the i-th name, NULL past the last */
/* The best schedule's parameters (N per section for per-section forces) into force (room for
   n); returns how many there are (zipopt_scene_params). zipopt_scene_set_forces then
   zipopt_simulate reruns it. */
ZIPOPT_API int zipopt_search_forces(const zipopt_search *r, double *force, int n);

#ifdef __cplusplus
}
#endif

#endif
