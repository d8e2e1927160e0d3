/* The trajectory table: state (angles in degrees), centres of mass, energy terms, loads. */
#include "out_csv.h"

#include <math.h>

#define DEG (180.0 / M_PI)

static void header(FILE *f, const zp_model *m) {
    fputs("t,section,x,y,speed", f);
    for (int i = 1; i <= m->nlink; i++) {
        fprintf(f, ",theta%d_deg", i);
    }
    for (int i = 1; i <= m->nlink; i++) {
        fprintf(f, ",omega%d_deg_s", i);
    }
    for (int i = 1; i <= m->nlink; i++) {
        fprintf(f, ",phi%d_deg", i);
    }
    fputs(",com0_x,com0_y", f);
    for (int i = 1; i <= m->nlink; i++) {
        fprintf(f, ",com%d_x,com%d_y", i, i);
    }
    fputs(",kinetic,potential,energy,drive_work,damper_work,impulse_loss,normal_force", f);
    for (int k = 0; zp_effect_work_shown(m->physics) && k < ZP_EFFECT_NWORK; k++) {
        fprintf(f, ",%s", zp_effect_work_names(k)->column);
    }
    for (int i = 1; i <= m->nlink; i++) {
        fprintf(f, ",joint%d_fx,joint%d_fy", i, i);
    }
    for (int i = 1; i <= m->nlink; i++) {
        fprintf(f, ",acc%d_g", i);
    }
    fputc('\n', f);
}

void zp_out_csv_trajectory(FILE *f, const zp_model *m, const zp_row_store *rows) {
    header(f, m);
    for (int k = 0; k < rows->n; k++) {
        zp_row row;
        zp_row_store_get(rows, k, &row);
        const zp_row *r = &row;
        zp_row_view v;
        zp_row_derive(m, r, &v);
        fprintf(f, "%.10g,%d,%.10g,%.10g,%.10g", r->t, r->sec + 1, r->c.q[0], r->c.q[1], v.speed);
        for (int i = 0; i < m->nlink; i++) {
            fprintf(f, ",%.10g", r->c.q[2 + i] * DEG);
        }
        for (int i = 0; i < m->nlink; i++) {
            fprintf(f, ",%.10g", r->c.v[2 + i] * DEG);
        }
        for (int i = 0; i < m->nlink; i++) {
            fprintf(f, ",%.10g", v.phi[i] * DEG);
        }
        for (int b = 0; b <= m->nlink; b++) {
            fprintf(f, ",%.10g,%.10g", v.com[b][0], v.com[b][1]);
        }
        fprintf(f, ",%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g", v.e.kinetic, v.e.potential,
                v.e.kinetic + v.e.potential, r->w_drive, r->w_damp, r->e_impulse, r->loads.normal);
        for (int k = 0; zp_effect_work_shown(m->physics) && k < ZP_EFFECT_NWORK; k++) {
            fprintf(f, ",%.10g", r->w_effect[k]);
        }
        for (int i = 0; i < m->nlink; i++) {
            fprintf(f, ",%.10g,%.10g", r->loads.joint[i][0], r->loads.joint[i][1]);
        }
        for (int i = 0; i < m->nlink; i++) {
            fprintf(f, ",%.10g", v.acc_g[i]);
        }
        fputc('\n', f);
    }
}
