/* What zipopt added to a scene: each key the file did not give, with the value it took
   (CONFIG.md defaults, the file's stem for the name), for `check`. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_parse.h"
#include "scene_read.h"

_Static_assert(K_COUNT <= 64, "zp_scene.given holds one bit per key");

static void list(char *out, size_t cap, const double *v, int n) {
    size_t len = 0;
    out[0] = '\0';
    for (int i = 0; i < n && len < cap; i++) {
        len += (size_t)snprintf(out + len, cap - len, "%s%g", i ? ", " : "", v[i]);
    }
}

/* the value key k holds in sc, as scene-file text */
static void value_text(const zp_scene *sc, int k, char *out, size_t cap) {
    const double *num = NULL, *pair = NULL;
    switch (k) {
    case K_NAME: snprintf(out, cap, "%s", sc->name); return;
    case K_DIRECTION: snprintf(out, cap, "%s", sc->direction); return;
    case K_METHOD: snprintf(out, cap, "%s", sc->method); return;
    case K_FORMULATION: snprintf(out, cap, "%s", sc->formulation); return;
    case K_SEARCH_METHOD: snprintf(out, cap, "%s", sc->search_method); return;
    case K_MAX_EVALS: snprintf(out, cap, "%ld", sc->max_evals); return;
    case K_SEED: snprintf(out, cap, "%lu", sc->seed); return;
    case K_SAMPLES: snprintf(out, cap, "%d", sc->robust_samples); return;
    case K_VERIFY_SAMPLES: snprintf(out, cap, "%d", sc->verify_samples); return;
    case K_DAMPING: list(out, cap, sc->damping, sc->ndamping); return;
    case K_FORCES: snprintf(out, cap, "0 for every section"); return;
    case K_DRAG_AREA: snprintf(out, cap, "none (no drag)"); return;
    case K_GRAVITY: num = &sc->gravity; break;
    case K_DEATH_ANGLE: num = &sc->death_angle; break;
    case K_MIN: num = &sc->force_min; break;
    case K_MAX: num = &sc->force_max; break;
    case K_RTOL: num = &sc->rtol; break;
    case K_ATOL: num = &sc->atol; break;
    case K_T_MAX: num = &sc->t_max; break;
    case K_OUTPUT_DT: num = &sc->output_dt; break;
    case K_MARGIN: num = &sc->margin; break;
    case K_SEARCH_RTOL: num = &sc->search_rtol; break;
    case K_FORCE_ERROR: num = &sc->force_error; break;
    case K_START_ANGLE: num = &sc->start_angle; break;
    case K_AIR_DENSITY: num = &sc->air_density; break;
    case K_WIND: num = &sc->wind; break;
    case K_ROLLING: num = &sc->rolling; break;
    case K_KINK_RADIUS: num = &sc->kink_radius; break;
    case K_MASS_RANGE: pair = sc->mass_range; break;
    case K_LENGTH_RANGE: pair = sc->length_range; break;
    case K_TROLLEY_MASS_RANGE: pair = sc->trolley_mass_range; break;
    case K_DAMPING_RANGE: pair = sc->damping_range; break;
    case K_MAX_G:
    case K_MAX_JOINT_FORCE:
    case K_MAX_ARRIVAL_SPEED:
    case K_MAX_KINK_DV: snprintf(out, cap, "off"); return;
    default: snprintf(out, cap, "(required, not given)"); return;
    }
    if (num) {
        /* the shortest text that reads back as the same double */
        for (int digits = 15; digits <= 17; digits++) {
            snprintf(out, cap, "%.*g", digits, *num);
            if (strtod(out, NULL) == *num) {
                break;
            }
        }
    } else {
        list(out, cap, pair, 2);
    }
}

int zp_scene_print_added(const zp_scene *sc, FILE *f, const char *indent) {
    int n = 0;
    for (int s = 0; s < S_COUNT; s++) {
        int optional = s == S_LIMITS || s == S_ROBUST || s == S_PHYSICS;
        int any = s == S_ROBUST && sc->robust;
        for (int k = 0; k < K_COUNT; k++) {
            any |= zp_scene_keys[k].sec == s && (sc->given >> k & 1);
        }
        if (optional && !any) {
            fprintf(f, "%s[%s]: none given, all off\n", indent, zp_scene_sec_names[s]);
            continue;
        }
        for (int k = 0; k < K_COUNT; k++) {
            if (zp_scene_keys[k].sec == s && !(sc->given >> k & 1)) {
                char v[256];
                value_text(sc, k, v, sizeof v);
                fprintf(f, "%s[%s] %s = %s\n", indent, zp_scene_sec_names[s],
                        zp_scene_keys[k].name, v);
                n++;
            }
        }
    }
    return n;
}
