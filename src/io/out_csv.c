/* The trajectory table: state (angles in degrees), centres of mass, energy terms, loads; its
   columns are out_columns.c's. */
#include "out_csv.h"

#include "out_columns.h"

void zp_out_csv_trajectory(FILE *f, const zp_model *m, const zp_row_store *rows) {
    zp_out_column col[ZP_OUT_COLUMNS_MAX];
    int n = zp_out_columns(m, col);
    for (int j = 0; j < n; j++) {
        fprintf(f, "%s%s", j ? "," : "", col[j].csv);
    }
    fputc('\n', f);
    for (int k = 0; k < rows->n; k++) {
        zp_row r;
        double v[ZP_OUT_COLUMNS_MAX];
        zp_row_store_get(rows, k, &r);
        zp_out_columns_values(m, &r, v);
        for (int j = 0; j < n; j++) {
            fprintf(f, j ? ",%.10g" : "%.10g", v[j] * col[j].csv_scale);
        }
        fputc('\n', f);
    }
}
