/* Prints docs/scene-file.md's key tables from the scene reader's own table
   (src/io/scene_keys.def): for each section its `## [name]` heading and the table of its keys,
   as the page has them. tests/check_docs.py holds the page to this output; after adding or
   changing a key, paste the section's table printed here into the page. */
#include <stdio.h>

#include "scene_parse.h"

/* text for a table cell: a `|` would end the cell */
static void cell(const char *text) {
    fputs("| ", stdout);
    for (; *text; text++) {
        if (*text == '|') {
            putchar('\\');
        }
        putchar(*text);
    }
    putchar(' ');
}

int main(void) {
    for (int s = 0; s < S_COUNT; s++) {
        printf("## [%s]\n\n| key | default | expected | meaning |\n|---|---|---|---|\n",
               zp_scene_keys_sections[s].name);
        for (int k = 0; k < K_COUNT; k++) {
            const zp_scene_key *key = &zp_scene_keys[k];
            if (key->sec == s) {
                printf("| `%s` ", key->name);
                cell(key->dflt.docs);
                cell(key->expect);
                cell(key->doc);
                puts("|");
            }
        }
        putchar('\n');
    }
    return 0;
}
