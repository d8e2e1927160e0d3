/* Command-line helpers shared by the commands: the scene argument, number lists, usage text
   (loading is setup.h). Commands return the process exit status (0, 1, 2). */
#ifndef ZP_CLI_H
#define ZP_CLI_H

#include <stdio.h>

#include "scene.h"

enum { ZP_EXIT_OK = 0, ZP_EXIT_FAIL = 1, ZP_EXIT_USAGE = 2, ZP_EXIT_NONE = 3 };

/* Parses "a,b,c" into at most max doubles; returns the count, or -1 (with why) on a bad
   number or an empty item. */
int zp_cli_parse_list(const char *text, double *out, int max, char *why, size_t whylen);
/* The positional argument of a command (its scene file): stores arg in *scene unless arg
   looks like an option or a scene was given already, which it reports for `zipopt <cmd>`
   (cmd may be "") and returns -1. */
int zp_cli_scene_arg(const char *cmd, const char *arg, const char **scene);
/* The output folder: --out DIR if given, else out/<scene name> (CLI.md "Files"). */
void zp_cli_out_dir(const char *out, const zp_scene *sc, char *dir, size_t cap);
/* The registries' names and docs, for --help. */
void zp_cli_print_registries(FILE *f);
void zp_cli_usage(FILE *f);

int zp_cmd_simulate(int argc, char **argv);
int zp_cmd_check(int argc, char **argv);
int zp_cmd_landscape(int argc, char **argv);
int zp_cmd_search(int argc, char **argv);
int zp_cmd_bench(int argc, char **argv);
int zp_cmd_tradeoff(int argc, char **argv);

#endif
