/* Reading scene files (docs/scene-file.md): INI text -> zp_scene, every rule checked, every problem
   reported with file, line and key. */
#ifndef ZP_SCENE_READ_H
#define ZP_SCENE_READ_H

#include <stdio.h>

#include "scene.h"

/* Reads and validates a scene file (every docs/scene-file.md rule). On error fills d and returns
   ZP_ERR_INPUT; sc then holds defaults plus whatever parsed. */
zp_status zp_scene_load(const char *path, zp_scene *sc, zp_diag *d);
/* The same from text in memory; path only names it in messages. */
zp_status zp_scene_load_string(const char *text, const char *path, zp_scene *sc, zp_diag *d);
/* The file as zp_scene_load reads it: whole, at most 1 MiB, NUL-terminated after len bytes
   (caller frees); NULL with the reason in d. A NUL byte inside is left for the loader. */
char *zp_scene_load_read_file(const char *path, size_t *len, zp_diag *d);
/* zp_scene_load_string of len bytes: a NUL byte inside is reported with its line. With
   need_name (every command: it writes under out/<name>/), a scene must give a plain folder
   name, its [scene] name or its file's stem, as zp_scene_load and zp_scene_load_string
   require; without (the library), a missing one leaves sc->name empty when the stem is none. */
zp_status zp_scene_load_text(const char *text, size_t len, const char *path, int need_name,
                             zp_scene *sc, zp_diag *d);
/* zp_scene_load with the choice of need_name (zp_scene_load_text). */
zp_status zp_scene_load_file(const char *path, int need_name, zp_scene *sc, zp_diag *d);
/* The built-in seed scene (docs/scene-file.md's example). */
void zp_scene_load_seed(zp_scene *sc);
/* Lays a schedule file (only [drive] forces) over sc. */
zp_status zp_scene_load_overlay_schedule(const char *path, zp_scene *sc, zp_diag *d);
/* Parses "a, b, c" (finite decimal numbers, docs/scene-file.md lists) into at most max doubles;
   returns the count, or -1 with why on an empty or bad item or more than max items. */
int zp_scene_values_parse_list(const char *text, double *out, int max, char *why, size_t whylen);

/* Writes, one per line after indent, each key the file did not give with the value zipopt
   took for it (`[solver] rtol = 1e-08`); an optional section with no key is one line. Returns
   how many keys were added. */
int zp_scene_show_added(const zp_scene *sc, FILE *f, const char *indent);

/* Writes the settings of [limits], [robust] and [physics]: the keys given (every [robust] key
   of a robust scene, defaults included). Text: one line per section, `limits: max_g = 12;
   max_arrival_speed = 90` or `limits: none`. JSON (json != 0): the members `"limits": {..},
   "robust": {..}, "physics": {..}` of an object, numbers and lists as JSON numbers; more (may
   be NULL) adds members to each section's object after its n keys (what the caller derived from
   them: the cable's equilibria), s its name ("cable"). */
typedef void (*zp_scene_show_more)(FILE *f, const char *s, int n, const void *user);
void zp_scene_show_optional(const zp_scene *sc, FILE *f, int json, zp_scene_show_more more,
                            const void *user);

#endif
