/* Scene files (docs/scene-file.md) -> zp_scene, the reader's entry points: defaults, the file read
   whole (capped in size), the line pass (scene_lines.c), every key read as its line of
   scene_keys.def says and the rules joining them; every violation reported as
   FILE:LINE: [section] key: what; expected. */
#include "scene_load.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scene_parse.h"

static void set_defaults(zp_scene *sc, const char *path) {
    memset(sc, 0, sizeof *sc);
    snprintf(sc->path, sizeof sc->path, "%s", path);
    /* the name is the file's stem: no folders, no extension */
    const char *base = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
    if (snprintf(sc->name, sizeof sc->name, "%s", base) >= (int)sizeof sc->name) {
        sc->name[0] = '\0'; /* too long: no name, rather than a shortened one */
    }
    char *dot = strrchr(sc->name, '.');
    if (dot && dot != sc->name) {
        *dot = '\0';
    }
    zp_scene_values_defaults(sc);
    /* the keys whose default the table leaves to hand (HAND) */
    sc->ndamping = 1;
    sc->death_angle = 180;
    sc->ndeath = 1;
    for (int i = 0; i < ZP_MAX_LINKS; i++) {
        sc->death_angles[i] = 180;
    }
    sc->max_evals = ZP_SCENE_EVALS_PER_SECTION;
    /* [robust] ranges at 100 % of nominal mean "not varied" */
    for (int i = 0; i < 2; i++) {
        sc->mass_range[i] = sc->length_range[i] = 100;
        sc->trolley_mass_range[i] = sc->damping_range[i] = 100;
    }
}

/* a scene is a few kilobytes; the cap keeps /dev/zero or a wrong file from eating memory */
#define SCENE_FILE_MAX (1 << 20)

char *zp_scene_load_read_file(const char *path, size_t *len, zp_diag *d) {
    FILE *f = fopen(path, "rb");
    if (!f) {
        zp_diag_add(d, path, 0, NULL, NULL, "cannot open: %s; expected a readable scene file",
                    strerror(errno));
        return NULL;
    }
    char *text = malloc(SCENE_FILE_MAX + 2);
    size_t n = text ? fread(text, 1, SCENE_FILE_MAX + 1, f) : 0;
    int failed = ferror(f);
    fclose(f);
    if (!text || failed || n > SCENE_FILE_MAX) {
        free(text);
        zp_diag_add(d, path, 0, NULL, NULL, "cannot read: %s",
                    !text    ? "out of memory"
                    : failed ? "read error"
                             : "the file is larger than 1 MiB; expected a scene file");
        return NULL;
    }
    text[n] = '\0';
    *len = n;
    return text;
}

/* the lines of keys that later stages judge, for their messages */
static void keep_lines(const parse_ctx *c, zp_scene *sc) {
    sc->line_forces = c->key_line[K_FORCES];
    sc->line_method = c->key_line[K_METHOD];
    sc->line_formulation = c->key_line[K_FORMULATION];
    sc->line_search_method = c->key_line[K_SEARCH_METHOD];
    sc->line_kink_radius = c->key_line[K_KINK_RADIUS];
    /* 0 also when refused: the search's default budget stands */
    sc->line_max_evals = c->key_bad[K_MAX_EVALS] ? 0 : c->key_line[K_MAX_EVALS];
}

/* whether key k must be given: [course]'s not where [cable] lays the course */
static int required(const parse_ctx *c, int k) {
    const zp_scene_key *key = &zp_scene_keys[k];
    return key->dflt.how == D_REQUIRED && !(key->sec == S_COURSE && c->sec_line[S_CABLE]);
}

/* the second pass: raw values -> sc, key by key in the table's order (a required key that is
   absent reported, a special key by its own reader), then the rules joining keys */
static void read_keys(parse_ctx *c, zp_scene *sc) {
    sc->cable = c->sec_line[S_CABLE] != 0;
    sc->line_cable = c->sec_line[S_CABLE];
    for (int k = 0; k < K_COUNT; k++) {
        const zp_scene_key *key = &zp_scene_keys[k];
        if (!c->key_line[k] && required(c, k)) {
            zp_scene_values_missing(c, k, key->dflt.text);
        } else if (key->read) {
            key->read(c, sc, k);
        } else {
            zp_scene_values_plain(c, sc, k);
        }
    }
    sc->robust = c->sec_line[S_ROBUST] != 0;
    sc->brake = c->sec_line[S_BRAKE] != 0;
    keep_lines(c, sc);
    zp_scene_rules(c, sc);
}

/* text of len bytes (a NUL inside is reported); need_name: see zp_scene_load_text */
static zp_status load_text(const char *text, size_t len, const char *path, int need_name,
                           zp_scene *sc, zp_diag *d) {
    set_defaults(sc, path);
    parse_ctx *c = calloc(1, sizeof *c);
    if (!c) {
        zp_diag_add(d, path, 0, NULL, NULL, "out of memory reading the scene");
        return ZP_ERR_NOMEM;
    }
    c->file = path;
    c->d = d;
    c->need_name = need_name;
    zp_scene_lines_parse(c, text, len);
    read_keys(c, sc);
    for (int k = 0; k < K_COUNT; k++) {
        if (c->key_line[k]) {
            sc->given[k / 64] |= 1ull << (k % 64);
        }
    }
    int nbad = zp_scene_lines_flush(c);
    free(c);
    return nbad ? ZP_ERR_INPUT : ZP_OK;
}

zp_status zp_scene_load_text(const char *text, size_t len, const char *path, int need_name,
                             zp_scene *sc, zp_diag *d) {
    return load_text(text, len, path, need_name, sc, d);
}

zp_status zp_scene_load_string(const char *text, const char *path, zp_scene *sc, zp_diag *d) {
    return load_text(text, strlen(text), path ? path : "<string>", 1, sc, d);
}

zp_status zp_scene_load_file(const char *path, int need_name, zp_scene *sc, zp_diag *d) {
    size_t len;
    char *text = zp_scene_load_read_file(path, &len, d);
    if (!text) {
        set_defaults(sc, path);
        return ZP_ERR_INPUT;
    }
    zp_status st = load_text(text, len, path, need_name, sc, d);
    free(text);
    return st;
}

zp_status zp_scene_load(const char *path, zp_scene *sc, zp_diag *d) {
    return zp_scene_load_file(path, 1, sc, d);
}

void zp_scene_load_seed(zp_scene *sc) {
    set_defaults(sc, "<built-in seed scene>");
    strcpy(sc->name, "seed");
    static const double x_end[] = {60, 100, 140};
    static const char *const expr[] = {"(x/10 - 3)^2 + 1", "-x/10 + 16", "-(x/10 - 12)^2 + 10"};
    sc->x_start = 0;
    sc->nsec = 3;
    for (int i = 0; i < 3; i++) {
        sc->x_end[i] = x_end[i];
        strcpy(sc->expr[i], expr[i]);
        sc->forces[i] = 100;
    }
    sc->nforce = 3;
    sc->trolley_mass = 30;
    sc->nlink = 3;
    static const double masses[] = {15, 5, 2};
    for (int i = 0; i < 3; i++) {
        sc->lengths[i] = 5;
        sc->masses[i] = masses[i];
    }
    for (int i = 0; i < ZP_MAX_LINKS; i++) {
        sc->damping[i] = 1;
    }
}

zp_status zp_scene_load_overlay_schedule(const char *path, zp_scene *sc, zp_diag *d) {
    size_t len;
    char *text = zp_scene_load_read_file(path, &len, d);
    if (!text) {
        return ZP_ERR_INPUT;
    }
    parse_ctx *c = calloc(1, sizeof *c);
    if (!c) {
        free(text);
        zp_diag_add(d, path, 0, NULL, NULL, "out of memory reading the schedule");
        return ZP_ERR_NOMEM;
    }
    c->file = path;
    c->d = d;
    c->schedule = 1;
    zp_scene_lines_parse(c, text, len);
    free(text);
    /* the forces must fit the scene they are laid over */
    zp_schedule shape = zp_drive_of_scene(sc), sched;
    if (zp_scene_sections_parse_forces(c, &shape, &sched) == 0) {
        zp_scene_values_missing(c, K_FORCES, "the forces (N), one per section");
    }
    int nbad = zp_scene_lines_flush(c);
    free(c);
    if (nbad) {
        return ZP_ERR_INPUT;
    }
    zp_scene_sections_set_forces(sc, &sched);
    /* sc->path names the scene, not this file: no line there to point at */
    sc->line_forces = 0;
    return ZP_OK;
}