/* The schedule files of the search: checkpoint.ini while it runs and schedule.ini at the end,
   both a scene file with only [drive] forces (docs/scene-file.md). */
#include "report.h"

void zp_checkpoint_write_schedule(FILE *f, const zp_scene *sc, const zp_schedule *sched,
                              const char *comment) {
    char text[ZP_SCHED_MAX_PARAMS * 26];
    zp_drive_format(sched, text, sizeof text);
    fprintf(f, "; %s\n; scene: %s\n[drive]\nforces = %s\n", comment, sc->name, text);
}
