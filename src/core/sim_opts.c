/* The run options a scene's [solver] section asks for, the method and rtol of [solver] accuracy
   picked from the work-precision table (accuracy.c). */
#include "sim_opts.h"

#include "accuracy.h"

zp_status zp_sim_opts_from_scene(const zp_scene *sc, zp_sim_opts *o, zp_diag *d) {
    *o = (zp_sim_opts){.rtol = sc->rtol,
                       .atol = sc->atol,
                       .t_max = sc->t_max,
                       .output_dt = sc->output_dt,
                       .max_steps = 2000000,
                       .track_loads = 1};
    o->method = zp_method_find(sc->method);
    o->formulation = zp_formulation_find(sc->formulation);
    if (o->method < 0) {
        zp_diag_add(d, sc->path, sc->line_method, "solver", "method",
                    "unknown method '%s'; expected one of those listed by zipopt --help",
                    sc->method);
    }
    if (o->formulation < 0) {
        zp_diag_add(d, sc->path, sc->line_formulation, "solver", "formulation",
                    "unknown formulation '%s'; expected one of those listed by zipopt --help",
                    sc->formulation);
    }
    if (sc->accuracy > 0 && o->method >= 0) {
        /* a method given beside accuracy restricts the pick to it */
        zp_accuracy_pick(sc->accuracy, sc->line_method ? o->method : -1, zp_accuracy_stiff(sc), o);
    }
    return o->method < 0 || o->formulation < 0 ? ZP_ERR_INPUT : ZP_OK;
}
