/* The commands' setup: the quiet preparation (lib/prep.c), its problems printed in one round so
   a user fixes a file at once, registry names included. */
#include "setup.h"

#include <stdio.h>

#include "cli.h"

int zp_setup_load(const char *cmd, const char *path, const zp_overrides *ov, zp_problem *p) {
    zp_diag d;
    zp_diag_init(&d);
    if (zp_prep_load(cmd, path, NULL, ov, p, &d) == 0) {
        return 0;
    }
    zp_diag_print(&d, stderr);
    int n = d.n + d.dropped;
    zp_cli_error("", "%s: %d error%s; nothing was written", p->sc.path, n, n == 1 ? "" : "s");
    return -1;
}

void zp_setup_free(zp_problem *p) {
    zp_problem_free(p);
}
