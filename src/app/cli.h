/* Command-line helpers shared by the commands: option parsing, the scene operand, number
   lists, usage text (loading is setup.h). Commands return the process exit status (0, 1, 2). */
#ifndef ZP_CLI_H
#define ZP_CLI_H

#include <getopt.h>
#include <stdio.h>
#include <time.h>

#include "tx.h"
#include "scene.h"

enum { ZP_EXIT_OK = 0, ZP_EXIT_FAIL = 1, ZP_EXIT_USAGE = 2, ZP_EXIT_NONE = 3 };

/* Parses "a,b,c" into at most max doubles; returns the count, or -1 (with why) on a bad
   number or an empty item. */
int zp_cli_parse_list(const char *text, double *out, int max, char *why, size_t whylen);
/* The longest path (scene, --out, --schedule) taken: the output code appends file names
   and temporary suffixes inside 1024-byte buffers. */
#define ZP_CLI_PATH_MAX 900
/* Options of one command: values from 256 up, so none is taken for a short option; 'h' is
   --help (and -h). */
enum { ZP_OPT_FIRST = 256 };

/* Prints "zipopt <cmd>: <message>" on stderr (cmd may be ""), control bytes escaped. */
void zp_cli_error(const char *cmd, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* text as zp_cli_error shows it (control bytes escaped, zp_diag_put_escaped) in buf (len
   bytes, cut to fit), for a user's text (a path, an argument) in a line printed otherwise. */
const char *zp_cli_shown(const char *text, char *buf, size_t len);
/* Starts a parse of argv (getopt_long keeps its place in globals: one parse at a time). */
void zp_cli_opts_begin(void);
/* The next option of `zipopt <cmd>` by getopt_long: options and operands in any order,
   --name=value, `--` ends the options. Returns the option's val (its value in optarg), -1
   after the last (operands are then argv[optind..argc)), or '?' once the one message for
   the mistake is printed: an unknown option (with the nearest known one), an ambiguous
   abbreviation, a missing value or a value given to a flag. */
int zp_cli_opts_next(const char *cmd, int argc, char **argv, const struct option *opts);
/* The operands after the options: at most one scene file (a path of at most
   ZP_CLI_PATH_MAX characters) into *scene (left as is when none); 0, or -1 with the message
   printed. */
int zp_cli_scene_operand(const char *cmd, int argc, char **argv, const char **scene);
/* A path given for opt: 0 if at most ZP_CLI_PATH_MAX characters, else -1 with the message. */
int zp_cli_path_ok(const char *cmd, const char *opt, const char *path);
/* A whole number from lo to hi for opt (digits only); 0, or -1 with the one message (out
   of range, or not a whole number). */
int zp_cli_whole(const char *cmd, const char *opt, const char *text, unsigned long lo,
                 unsigned long hi, unsigned long *out);
/* A time in seconds > 0 for opt (--max-time); 0, or -1 with the one message. */
int zp_cli_seconds(const char *cmd, const char *opt, const char *text, double *out);
/* Begins the command's one transaction (out_file.h) in --out DIR itself when out is given,
   else in out/<scene name>/<folder> (docs/commands.md "Files"); says why on stderr for `zipopt
   <cmd>` and returns -1 on failure. */
int zp_cli_out_begin(zp_tx *t, const char *cmd, const char *folder, const char *out,
                     const zp_scene *sc);
/* Commits t (then t->dir and t->written say what was written), or says why and "nothing was
   written" on stderr for `zipopt <cmd>`. 0 or -1. */
int zp_cli_out_commit(zp_tx *t, const char *cmd);
/* Draws the n gnuplot scripts in t (gnuplot.h; *missing: gnuplot is not installed, so only the
   data and scripts are there), then commits t; on either failure aborts t and says why and
   "nothing was written" for `zipopt <cmd>`. 0 or -1. */
int zp_cli_out_draw_commit(zp_tx *t, const char *cmd, const char *const *scripts, int n,
                           int *missing);
/* s of wall time since t0 (CLOCK_MONOTONIC), for progress lines and summaries. */
double zp_cli_since(const struct timespec *t0);
void zp_cli_usage(FILE *f);

int zp_cmd_simulate(int argc, char **argv);
int zp_cmd_check(int argc, char **argv);
int zp_cmd_landscape(int argc, char **argv);
int zp_cmd_search(int argc, char **argv);
int zp_cmd_bench(int argc, char **argv);
int zp_cmd_tradeoff(int argc, char **argv);
int zp_cmd_sweep(int argc, char **argv);

#endif
