/* The search's files (report_files.h). */
#include "report_files.h"

#include "out_csv.h"
#include "out_html.h"

int zp_report_files_write(zp_tx *t, const zp_answer *a, const zp_report_place *w, char *err,
                          size_t errlen) {
    const zp_problem *p = a->pb;
    const char *names[] = {"report.md", "schedule.ini", "summary.json", "trajectory.csv"};
    FILE *f[4];
    if (zp_tx_open_set(t, names, f, 4, err, errlen)) {
        return -1;
    }
    zp_report_write_md(f[0], a, w);
    char note[200];
    snprintf(note, sizeof note,
             "%s of the search%s: %s, %.6f s; rerun with zipopt simulate SCENE.ini --schedule "
             "this-file",
             a->found ? "best schedule" : "CLOSEST CANDIDATE (nothing met the constraints)",
             a->res.interrupted ? " (interrupted)" : "", zp_sim_outcome_name(a->v.run->outcome),
             a->v.run->time);
    zp_schedule best = zp_drive_with(&p->sched, a->res.force);
    zp_checkpoint_write_schedule(f[1], &p->sc, &best, note);
    zp_summary_write_json(f[2], a);
    zp_out_csv_trajectory(f[3], p->m, zp_sim_rows(a->best));
    /* report.html: report.md as one page a person can share, its figures inside it */
    char title[300];
    snprintf(title, sizeof title, "zipopt: best forcing, %s", p->sc.name);
    return zp_out_html_report(t, "report.md", "report.html", title, err, errlen) ? -1 : 0;
}
