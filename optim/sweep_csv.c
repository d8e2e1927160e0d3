/* sweep.csv rows and the checkpoint (sweep_csv.h): numbers in the fewest digits that read back
   exactly, so a row read from the checkpoint writes out as the same line. */
#include "sweep_csv.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "tx.h"

/* result columns before the forces: status .. evals (8), the limited quantities */
#define NFIXED (8 + ZP_LIMIT_COUNT)
#define LINE_MAX_BYTES                                                                             \
    16384 /* a row or grid line is shorter (a grid line of 10000 points:                           \
             twice 2500 hex digits, with 256 forces) */

static const char *zp_sweep_csv_limit_column(int i) {
    static const char *const columns[ZP_LIMIT_COUNT] = {
        [ZP_LIMIT_G] = "peak_g", [ZP_LIMIT_JOINT] = "peak_joint_force_N",
        [ZP_LIMIT_ARRIVAL] = "arrival_kmh", [ZP_LIMIT_KINK_DV] = "max_kink_dv_m_s",
        [ZP_LIMIT_G_ENVELOPE] = "g_envelope_share", [ZP_LIMIT_MIN_ARRIVAL] = "slowest_arrival_kmh",
        [ZP_LIMIT_DRIVE_POWER] = "drive_peak_power_W",
        [ZP_LIMIT_CABLE_TENSION] = "anchor_tension_N"};
    return columns[i];
}

void zp_sweep_csv_header(FILE *f, const zp_sweep *s, int np) {
    fputs("point", f);
    for (int v = 0; v < s->nvary; v++) {
        char col[64];
        zp_sweep_column(&s->vary[v], col, sizeof col);
        fprintf(f, ",%s", col);
    }
    fputs(",status,found,outcome,time_s,margin_deg,limit,verified,evals", f);
    for (int i = 0; i < ZP_LIMIT_COUNT; i++) {
        fprintf(f, ",%s", zp_sweep_csv_limit_column(i));
    }
    for (int k = 1; k <= np; k++) {
        fprintf(f, ",F%d_N", k);
    }
    fputs(",message\n", f);
}

static void put_num(FILE *f, double x) {
    char buf[32];
    zp_sweep_format(x, buf, sizeof buf);
    fprintf(f, ",%s", buf);
}

/* the last field and the line's end: the message without the characters that would break
   the CSV line */
static void put_message(FILE *f, const char *msg) {
    fputc(',', f);
    for (const char *c = msg; *c; c++) {
        fputc(*c == ',' ? ';' : *c == '"' ? '\'' : *c == '\n' || *c == '\r' ? ' ' : *c, f);
    }
    fputc('\n', f);
}

void zp_sweep_csv_row(FILE *f, const zp_sweep *s, int p, const zp_study_row *r) {
    fprintf(f, "%d", p);
    for (int v = 0; v < s->nvary; v++) {
        put_num(f, zp_sweep_value(s, v, p));
    }
    if (r->failed) {
        fputs(",failed", f);
        for (int k = 1; k < NFIXED + r->np; k++) {
            fputc(',', f); /* the empty result columns and forces */
        }
    } else {
        fprintf(f, ",ok,%d,%s", r->found, zp_sim_outcome_name(r->outcome));
        put_num(f, r->time);
        put_num(f, r->margin);
        fprintf(f, ",%s,%d,%ld", r->limit, r->verified, r->evals);
        for (int i = 0; i < ZP_LIMIT_COUNT; i++) {
            put_num(f, r->reached[i]);
        }
        for (int k = 0; k < r->np; k++) {
            put_num(f, r->force[k]);
        }
    }
    put_message(f, r->message);
}

static int num_field(const char *t, double *x) {
    char *end;
    *x = strtod(t, &end);
    return end == t || *end ? -1 : 0;
}

/* Every field read back is range-checked: a checkpoint is a text file a user may edit, and a
   value zipopt would never write (inf, a negative count, a point off the grid) must not
   reach the study's summary or index its arrays. */

/* a finite number in [lo, hi]; 0, else -1 */
static int finite_field(const char *t, double lo, double hi, double *x) {
    return num_field(t, x) || !isfinite(*x) || *x < lo || *x > hi ? -1 : 0;
}

/* NaN, or a finite number not below lo */
static int nan_or_field(const char *t, double lo, double *x) {
    return !num_field(t, x) && isnan(*x) ? 0 : finite_field(t, lo, HUGE_VAL, x);
}

/* a whole number in [lo, hi] (decimal digits, an optional minus); 0, else -1 */
static int whole_field(const char *t, long lo, long hi, long *v) {
    char *end;
    errno = 0;
    *v = strtol(t, &end, 10);
    int digits = t[t[0] == '-'] >= '0' && t[t[0] == '-'] <= '9';
    return !digits || *end || errno || *v < lo || *v > hi ? -1 : 0;
}

/* "0" or "1" */
static int flag_field(const char *t, int *v) {
    *v = t[0] == '1';
    return (t[0] == '0' || t[0] == '1') && !t[1] ? 0 : -1;
}

/* a limit as zp_study_row holds it: "none", or names of [a-z_.] joined by '+' */
static int limit_field(const char *t) {
    size_t n = strlen(t);
    return n && n < sizeof((zp_study_row *)0)->limit &&
                   strspn(t, "abcdefghijklmnopqrstuvwxyz_.+") == n
               ? 0
               : -1;
}

/* the result fields of a row that did not fail: status .. evals, then the forces */
static int parse_result(char **fld, int np, zp_study_row *r) {
    r->outcome = ZP_OUTCOME_COUNT;
    for (int o = 0; o < ZP_OUTCOME_COUNT; o++) {
        if (!strcmp(fld[2], zp_sim_outcome_name((zp_outcome)o))) {
            r->outcome = (zp_outcome)o;
        }
    }
    snprintf(r->limit, sizeof r->limit, "%s", fld[5]);
    int bad = flag_field(fld[1], &r->found) || r->outcome == ZP_OUTCOME_COUNT ||
              finite_field(fld[3], 0, HUGE_VAL, &r->time) ||
              finite_field(fld[4], -HUGE_VAL, HUGE_VAL, &r->margin) || limit_field(fld[5]) ||
              flag_field(fld[6], &r->verified) || whole_field(fld[7], 0, LONG_MAX, &r->evals);
    for (int i = 0; i < ZP_LIMIT_COUNT && !bad; i++) {
        bad = finite_field(fld[8 + i], 0, HUGE_VAL, &r->reached[i]);
    }
    for (int k = 0; k < np && !bad; k++) {
        bad = finite_field(fld[NFIXED + k], -HUGE_VAL, HUGE_VAL, &r->force[k]);
    }
    return bad ? -1 : 0;
}

/* buf cut at its commas into at most maxf fields; their count */
static int split(char *buf, char **fld, int maxf) {
    int n = 0;
    for (char *c = buf; n < maxf; c++) {
        fld[n++] = c;
        c += strcspn(c, ",");
        if (!*c) {
            break;
        }
        *c = '\0';
    }
    return n;
}

int zp_sweep_csv_parse(const char *line, const zp_sweep *s, int np, int *p, zp_study_row *r) {
    enum { MAXF = 1 + ZP_SWEEP_MAX_VARY + NFIXED + ZP_SCHED_MAX_PARAMS + 1 };
    char buf[8192], *fld[MAXF];
    snprintf(buf, sizeof buf, "%s", line);
    int n = split(buf, fld, MAXF);
    memset(r, 0, sizeof *r);
    r->np = np;
    long pl;
    if (n != 1 + s->nvary + NFIXED + np + 1 || whole_field(fld[0], 0, s->npoint - 1, &pl)) {
        return -1;
    }
    *p = (int)pl;
    for (int v = 0; v < s->nvary; v++) {
        double x;
        if (num_field(fld[1 + v], &x) || x != zp_sweep_value(s, v, *p)) {
            return -1;
        }
    }
    char **res = fld + 1 + s->nvary;
    snprintf(r->message, sizeof r->message, "%s", fld[n - 1]);
    if (!strcmp(res[0], "failed")) {
        r->failed = 1;
        return 0;
    }
    return strcmp(res[0], "ok") ? -1 : parse_result(res, np, r);
}

#define GRID_FIXED 17 /* the grid line's fields before the forces: "grid" .. survived */

static void put_bits(FILE *f, const unsigned char *bits, int npoint) {
    fputc(',', f);
    for (int i = 0; i < (npoint + 7) / 8; i++) {
        fprintf(f, "%02x", bits[i]);
    }
}

/* npoint bits from hex (none set past the last point); the number set, or -1 */
static int parse_bits(const char *hex, unsigned char *bits, int npoint) {
    int nbyte = (npoint + 7) / 8, nset = 0;
    if (strlen(hex) != 2 * (size_t)nbyte || strspn(hex, "0123456789abcdef") != strlen(hex)) {
        return -1;
    }
    for (int i = 0; i < nbyte; i++) {
        char two[3] = {hex[2 * i], hex[2 * i + 1], 0};
        bits[i] = (unsigned char)strtoul(two, NULL, 16);
        for (int b = 0; b < 8; b++) {
            if (bits[i] >> b & 1) {
                nset++;
                if (8 * i + b >= npoint) {
                    return -1;
                }
            }
        }
    }
    return nset;
}

void zp_sweep_csv_grid(FILE *f, const zp_grid_result *g, int npoint) {
    fprintf(f, "grid,%d,%d,%d,%d,%d,%ld,%d,%d,%d,%d,%d", g->failed, g->found, g->nominal,
            g->ncorner, g->nscen, g->evals, g->rounds, g->kept, g->nheld, g->nadded, g->last_found);
    put_num(f, g->time);
    put_num(f, g->margin);
    fprintf(f, ",%d", g->worst);
    put_num(f, g->worst_margin);
    fprintf(f, ",%d", g->survived);
    for (int k = 0; k < g->np; k++) {
        put_num(f, g->force[k]);
    }
    put_bits(f, g->ok, npoint);
    put_bits(f, g->added, npoint);
    put_message(f, g->message);
}

int zp_sweep_csv_grid_parse(const char *line, int np, int npoint, zp_grid_result *g) {
    enum { MAXF = GRID_FIXED + ZP_SCHED_MAX_PARAMS + 3 };
    char buf[LINE_MAX_BYTES], *fld[MAXF];
    snprintf(buf, sizeof buf, "%s", line);
    int n = split(buf, fld, MAXF);
    memset(g, 0, sizeof *g);
    if (n != GRID_FIXED + np + 3 || strcmp(fld[0], "grid")) {
        return -1; /* another study's, or a line of an older zipopt (fewer fields) */
    }
    /* each whole number with its range: flags, grid points, counts */
    const long npt = npoint;
    const struct {
        int at;
        long lo, hi;
        int *to;
    } whole[] = {
        {1, 0, 1, &g->failed},      {2, 0, 1, &g->found},         {3, 0, npt - 1, &g->nominal},
        {4, 0, npt, &g->ncorner},   {5, 0, INT_MAX, &g->nscen},   {7, 0, INT_MAX, &g->rounds},
        {8, 0, INT_MAX, &g->kept},  {9, 0, npt, &g->nheld},       {10, 0, npt, &g->nadded},
        {11, 0, 1, &g->last_found}, {14, -1, npt - 1, &g->worst}, {16, 0, npt, &g->survived},
    };
    int bad = 0;
    for (size_t i = 0; i < sizeof whole / sizeof whole[0] && !bad; i++) {
        long v;
        bad = whole_field(fld[whole[i].at], whole[i].lo, whole[i].hi, &v);
        *whole[i].to = (int)v;
    }
    g->np = np;
    /* time and margins are NaN where no run gave them (the grid's own "none") */
    bad = bad || whole_field(fld[6], 0, LONG_MAX, &g->evals) || g->kept > g->rounds ||
          nan_or_field(fld[12], 0, &g->time) || nan_or_field(fld[13], -HUGE_VAL, &g->margin) ||
          nan_or_field(fld[15], -HUGE_VAL, &g->worst_margin);
    for (int k = 0; k < np && !bad; k++) {
        bad = finite_field(fld[GRID_FIXED + k], -HUGE_VAL, HUGE_VAL, &g->force[k]);
    }
    bad = bad || parse_bits(fld[n - 3], g->ok, npoint) != g->survived ||
          parse_bits(fld[n - 2], g->added, npoint) < 0;
    snprintf(g->message, sizeof g->message, "%s", fld[n - 1]);
    return bad ? -1 : 0;
}

/* the checkpoint's first two lines: what study it belongs to, then the CSV header */
static char *study_head(const zp_sweep *s, const char *base, int np) {
    uint64_t h = 0xcbf29ce484222325ULL; /* FNV-1a of the scene text */
    for (const unsigned char *c = (const unsigned char *)base; *c; c++) {
        h = (h ^ *c) * 0x100000001b3ULL;
    }
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    if (!f) {
        return NULL;
    }
    fprintf(f, "# zipopt sweep checkpoint: version=%s run=%s scene=%016llx np=%d vary=",
            ZIPOPT_VERSION, zp_study_kind_name(s->kind), (unsigned long long)h, np);
    for (int v = 0; v < s->nvary; v++) {
        fprintf(f, "%s%s", v ? " " : "", s->vary[v].text);
    }
    fputc('\n', f);
    zp_sweep_csv_header(f, s, np);
    fclose(f);
    return text;
}

/* the whole rows of an old checkpoint into rows/done; returns the length of the good part,
   or -1 when it belongs to another study */
static long read_rows(const char *old, const char *head, const zp_sweep *s, int np,
                      zp_study_row *rows, unsigned char *done, int *ndone, zp_grid_result *grid,
                      int *grid_done) {
    size_t hl = strlen(head);
    if (strncmp(old, head, hl)) {
        /* cut short while its head was written: nothing to keep; else another study's */
        return strncmp(old, head, strlen(old)) ? -1 : 0;
    }
    size_t pos = hl;
    char line[LINE_MAX_BYTES];
    for (;;) {
        size_t len = strcspn(old + pos, "\n");
        int p;
        zp_study_row r;
        zp_grid_result g;
        if (!old[pos + len] || len >= sizeof line) {
            break; /* the last line, torn by a kill */
        }
        snprintf(line, sizeof line, "%.*s", (int)len, old + pos);
        if (!strncmp(line, "grid,", 5)) {
            /* one an older zipopt wrote (without the rounds) is passed over: searched again */
            if (!zp_sweep_csv_grid_parse(line, np, s->npoint, &g)) {
                *grid = g;
                *grid_done = 1;
            }
        } else if (zp_sweep_csv_parse(line, s, np, &p, &r)) {
            break;
        } else {
            *ndone += !done[p];
            done[p] = 1;
            rows[p] = r;
        }
        pos += len + 1;
    }
    return (long)pos;
}

/* the whole of the open file fd as a string (caller frees), its length in *len; NULL if it
   cannot be read */
static char *read_fd(int fd, size_t *len) {
    size_t cap = 4096, n = 0;
    char *text = malloc(cap);
    for (ssize_t got; text; n += (size_t)got) {
        if (n + 1 == cap) {
            char *grown = realloc(text, cap *= 2);
            if (!grown) {
                free(text);
                return NULL;
            }
            text = grown;
        }
        got = read(fd, text + n, cap - 1 - n);
        if (got < 0) {
            free(text);
            return NULL;
        }
        if (got == 0) {
            text[n] = '\0';
            *len = n;
            return text;
        }
    }
    return NULL;
}

zp_status zp_sweep_csv_checkpoint_open(zp_sweep_checkpoint *c, int dirfd, const char *dir,
                                   const zp_sweep *s, const char *base, int np, int resume,
                                   zp_study_row *rows, unsigned char *done, int *ndone,
                                   zp_grid_result *grid, int *grid_done, char *err, size_t errlen) {
    c->f = NULL;
    c->dirfd = -1;
    *ndone = 0;
    *grid_done = 0;
    snprintf(c->path, sizeof c->path, "%s/checkpoint.csv", dir);
    char *head = study_head(s, base, np), *old = NULL;
    /* never through a link planted at the name: the file is opened in the folder itself;
       without blocking (a FIFO would wait for a writer forever), and a regular file only */
    int fd = head ? openat(dirfd, "checkpoint.csv",
                           O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK, 0644)
                  : -1;
    struct stat st;
    if (fd >= 0 && (fstat(fd, &st) || !S_ISREG(st.st_mode))) {
        snprintf(err, errlen, "%s is not a regular file; expected the checkpoint of a study",
                 c->path);
        free(head);
        close(fd);
        return ZP_ERR_INPUT;
    }
    size_t len = 0;
    long keep = -2;
    if (fd >= 0 && resume && (old = read_fd(fd, &len)) != NULL && len > 0) {
        keep = strlen(old) == len ? read_rows(old, head, s, np, rows, done, ndone, grid, grid_done)
                                  : -1;
    }
    /* the head up to the version of zipopt that wrote it */
    const char *after = strstr(head, " run=");
    int other_version = keep == -1 && strncmp(old, head, (size_t)(after - head));
    free(old);
    if (keep == -1) {
        snprintf(err, errlen,
                 "%s belongs to another study (%s); run without --resume to start afresh", c->path,
                 other_version ? "another zipopt version wrote it, or it is not a checkpoint"
                               : "its scene, --vary or --run differ");
        free(head);
        close(fd);
        return ZP_ERR_INPUT;
    }
    /* a buffer larger than any line: each line reaches the file in one write(), so a signal
       that ends the job lands before or after it, never inside */
    if (fd < 0 || fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK) ||
        ftruncate(fd, keep > 0 ? keep : 0) || lseek(fd, 0, SEEK_END) < 0 ||
        (c->dirfd = fcntl(dirfd, F_DUPFD_CLOEXEC, 0)) < 0 || !(c->f = fdopen(fd, "a")) ||
        setvbuf(c->f, NULL, _IOFBF, LINE_MAX_BYTES)) {
        snprintf(err, errlen, "%s: %s", c->path, head ? strerror(errno) : "out of memory");
        free(head);
        if (fd >= 0) {
            close(fd);
        }
        return ZP_ERR_IO;
    }
    if (keep <= 0) {
        fputs(head, c->f);
    }
    free(head);
    if (fflush(c->f)) {
        snprintf(err, errlen, "%s: %s", c->path, strerror(errno));
        fclose(c->f);
        c->f = NULL;
        return ZP_ERR_IO;
    }
    return ZP_OK;
}

/* the line just formatted, to the disk */
static int push(zp_sweep_checkpoint *c) {
    return fflush(c->f) || fsync(fileno(c->f)) ? -1 : 0;
}

int zp_sweep_csv_checkpoint_add(zp_sweep_checkpoint *c, const zp_sweep *s, int p,
                            const zp_study_row *r) {
    zp_sweep_csv_row(c->f, s, p, r);
    return push(c);
}

int zp_sweep_csv_checkpoint_add_grid(zp_sweep_checkpoint *c, const zp_sweep *s,
                                 const zp_grid_result *g) {
    zp_sweep_csv_grid(c->f, g, s->npoint);
    return push(c);
}

void zp_sweep_csv_checkpoint_close(zp_sweep_checkpoint *c, int remove_file) {
    if (c->f) {
        fclose(c->f);
        c->f = NULL;
    }
    if (c->dirfd >= 0) {
        if (remove_file) {
            unlinkat(c->dirfd, "checkpoint.csv", 0);
        }
        close(c->dirfd);
        c->dirfd = -1;
    }
}
