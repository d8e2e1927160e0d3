/* libFuzzer target: any bytes as a scene file (the INI reader and every docs/scene-file.md check,
   then the model build, which compiles each section's f(x) through the expression reader)
   and as a lone course expression. Bad input must end in a status, never a crash. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "course.h"
#include "model.h"
#include "scene_load.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    char *text = malloc(size + 1);
    if (!text) {
        return 0;
    }
    memcpy(text, data, size);
    text[size] = '\0';
    static zp_scene sc; /* large */
    zp_diag d;
    zp_diag_init(&d);
    if (zp_scene_load_string(text, "fuzz.ini", &sc, &d) == ZP_OK) {
        zp_model_free(zp_model_build(&sc, &d));
    }
    zp_course_err e;
    const char *expr = text;
    zp_course *c = zp_course_create(1, &expr, &e);
    if (c) {
        zp_course_eval(c, 0, 0.5);
    }
    zp_course_free(c);
    free(text);
    return 0;
}
