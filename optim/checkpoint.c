/* The schedule files of the search: checkpoint.ini while it runs and schedule.ini at the end,
   both a scene file with only [drive] forces (CONFIG.md). */
#include "report.h"

void zp_report_write_schedule(FILE *f, const zp_scene *sc, const double *force,
                              const char *comment) {
    fprintf(f, "; %s\n; scene: %s\n[drive]\nforces = ", comment, sc->name);
    for (int k = 0; k < sc->nsec; k++) {
        fprintf(f, "%.17g%s", force[k], k + 1 < sc->nsec ? ", " : "\n");
    }
}
