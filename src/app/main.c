/* argv -> command. The only place that picks the exit status. */
#include <gsl/gsl_errno.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "course.h"

static const struct {
    const char *name;
    int (*run)(int argc, char **argv);
} commands[] = {
    {"simulate", zp_cmd_simulate},
    {"check", zp_cmd_check},
    {"landscape", zp_cmd_landscape},
    {"tradeoff", zp_cmd_tradeoff},
    {"sweep", zp_cmd_sweep},
    {"bench", zp_cmd_bench},
};
#define NCOMMAND ((int)(sizeof commands / sizeof commands[0]))

/* a first word that is neither a command nor a file: a typo of a command, said as such,
   rather than a scene file that cannot be read; 0 if word may be a scene file */
static int unknown_command(const char *word) {
    const char *names[NCOMMAND];
    for (int i = 0; i < NCOMMAND; i++) {
        names[i] = commands[i].name;
    }
    int near = zp_diag_nearest(word, names, NCOMMAND);
    if (word[0] == '-' || access(word, F_OK) == 0 || near < 0) {
        return 0;
    }
    zp_cli_error("", "unknown command '%s'; did you mean '%s'? (see zipopt --help)", word,
                 names[near]);
    return 1;
}

/* the overview, then every command's own --help: the text zipopt(1) is made from */
static void usage_all(void) {
    zp_cli_usage(stdout);
    char prog[] = "zipopt", help[] = "--help";
    char *args[] = {prog, help, NULL};
    printf("\nThe search, zipopt [SCENE.ini]:\n\n");
    zp_cmd_search(2, args);
    for (int i = 0; i < NCOMMAND; i++) {
        char name[16];
        snprintf(name, sizeof name, "%s", commands[i].name);
        args[0] = name;
        printf("\nzipopt %s:\n\n", name);
        commands[i].run(2, args);
    }
}

int main(int argc, char **argv) {
    /* before any thread (OpenMP's, OpenMPI's) exists, so every one of them blocks the signals
       the output transaction takes in its own thread */
    zp_tx_signals_start();
    zp_course_notices_to(stderr);
    /* GSL's default handler aborts; every GSL call's status is checked instead */
    gsl_set_error_handler_off();
    if (argc >= 2 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"))) {
        zp_cli_usage(stdout);
        return ZP_EXIT_OK;
    }
    if (argc >= 2 && !strcmp(argv[1], "--help-all")) {
        usage_all();
        return ZP_EXIT_OK;
    }
    if (argc >= 2 && !strcmp(argv[1], "--version")) {
        /* --json: the same as one JSON object, like every command's */
        if (argc >= 3 && !strcmp(argv[2], "--json")) {
            printf("{\"name\": \"zipopt\", \"version\": \"%s\"}\n", ZIPOPT_VERSION);
        } else {
            printf("zipopt %s\n", ZIPOPT_VERSION);
        }
        return ZP_EXIT_OK;
    }
    for (int i = 0; argc >= 2 && i < NCOMMAND; i++) {
        if (!strcmp(argv[1], commands[i].name)) {
            return commands[i].run(argc - 1, argv + 1);
        }
    }
    if (argc >= 2 && unknown_command(argv[1])) {
        return ZP_EXIT_USAGE;
    }
    return zp_cmd_search(argc, argv);
}
