/* The scene file's key table, compiled from scene_keys.def: each key's section, member of
   zp_scene, rule, default, expected text and meaning, for the reader, check and the docs. */
#include <limits.h>
#include <math.h>
#include <stddef.h>

#include "scene_parse.h"

_Static_assert(K_COUNT <= 64 * ZP_SCENE_GIVEN_WORDS, "zp_scene.given holds one bit per key");

/* the table's vocabulary, one macro per word, kept on one line each (clang-format 14 would
   split the _Generic selections and brace initializers apart) */
/* clang-format off */

/* a member of zp_scene (not evaluated: its type and size only) */
#define M(member) (((zp_scene *)0)->member)
#define AT(member) .field = offsetof(zp_scene, member), .size = sizeof M(member)

/* the value column: the member's C type must be the one the reader stores (else no match) */
#define NUMBER(member, r) AT(member), .type = _Generic(M(member), double: T_NUMBER), .rule = r
#define WHOLE(member, lo, hi) \
    AT(member), .type = _Generic(M(member), int: T_INT, long: T_LONG, unsigned long: T_ULONG), \
    .min = lo, .max = hi
#define TEXT(member) AT(member), .type = _Generic(M(member), char *: T_TEXT)
#define MEMBER(member) AT(member), .type = T_OTHER
#define BY(reader, ...) __VA_ARGS__, .read = reader

/* the rules of NUMBER: lo, hi, lo open, hi open */
#define ANY {-INFINITY, INFINITY, 0, 0}
#define GT(a) {a, INFINITY, 1, 0}
#define GE(a) {a, INFINITY, 0, 0}
#define IN(a, b) {a, b, 0, 0}
#define IN_OC(a, b) {a, b, 1, 0}
#define IN_CO(a, b) {a, b, 0, 1}

/* the default column; a number's docs show it as written in the table */
#define NUM(v) {D_VALUE, v, NULL, #v}
#define TXT(s) {D_VALUE, 0, s, "`" s "`"}
#define OFF {D_OFF, 0, NULL, "off"}
#define REQUIRED(what) {D_REQUIRED, 0, what, "*required*"}
#define HAND(docs) {D_HAND, 0, NULL, docs}

/* clang-format on */

#define ZP_SECTION(id, ...)
#define ZP_KEY(id, section, key, value, default_, expected, meaning)                               \
    [K_##id] = {.sec = S_##section,                                                                \
                .name = key,                                                                       \
                value,                                                                             \
                .dflt = default_,                                                                  \
                .expect = expected,                                                                \
                .doc = meaning},
const zp_scene_key zp_scene_keys[K_COUNT] = {
#include "scene_keys.def"
};
#undef ZP_KEY
#undef ZP_SECTION

#define ZP_KEY(id, ...)
#define ZP_SECTION(id, section, optional_) [S_##id] = {section, optional_},
const zp_scene_section zp_scene_keys_sections[S_COUNT] = {
#include "scene_keys.def"
};
#undef ZP_SECTION
#undef ZP_KEY
