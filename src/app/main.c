/* argv -> command. The only place that picks the exit status. */
#include <gsl/gsl_errno.h>
#include <stdio.h>
#include <string.h>

#include "cli.h"

int main(int argc, char **argv) {
    /* GSL's default handler aborts; every GSL call's status is checked instead */
    gsl_set_error_handler_off();
    if (argc >= 2 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"))) {
        zp_cli_usage(stdout);
        return ZP_EXIT_OK;
    }
    if (argc >= 2 && !strcmp(argv[1], "--version")) {
        printf("zipopt %s\n", ZIPOPT_VERSION);
        return ZP_EXIT_OK;
    }
    if (argc >= 2 && !strcmp(argv[1], "simulate")) {
        return zp_cmd_simulate(argc - 1, argv + 1);
    }
    if (argc >= 2 && !strcmp(argv[1], "check")) {
        return zp_cmd_check(argc - 1, argv + 1);
    }
    if (argc >= 2 && !strcmp(argv[1], "landscape")) {
        return zp_cmd_landscape(argc - 1, argv + 1);
    }
    if (argc >= 2 && !strcmp(argv[1], "tradeoff")) {
        return zp_cmd_tradeoff(argc - 1, argv + 1);
    }
    if (argc >= 2 && !strcmp(argv[1], "bench")) {
        return zp_cmd_bench(argc - 1, argv + 1);
    }
    return zp_cmd_search(argc, argv);
}
