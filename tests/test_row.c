/* row.c: a packed row reads back bit for bit as the zp_row that was put (random rows of every
   size; a run's rows against its samples at the same times, which are kept whole), and the
   running load maxima equal fmax over zp_row_loads' hypot bit for bit, near ties included. */
#include <string.h>

#include "check.h"
#include "testutil.h"

#define NROWS 7
#define NLOADS 200000

static double uniform(double lo, double hi) {
    return lo + (hi - lo) * (rand() / (RAND_MAX + 1.0));
}

/* a row of m's size with random entries, zero beyond nlink as the simulator leaves them */
static void random_row(const zp_model *m, zp_row *r) {
    memset(r, 0, sizeof *r);
    r->t = uniform(0, 100);
    r->sec = rand() % ZP_MAX_SECTIONS;
    for (int j = 0; j < 2 + m->nlink; j++) {
        r->c.q[j] = uniform(-10, 10);
        r->c.v[j] = uniform(-10, 10);
    }
    r->w_drive = uniform(0, 1e4);
    r->w_damp = uniform(0, 1e3);
    for (int k = ZP_W_EFFECTS; k < m->nwork; k++) {
        r->w_effect[k - ZP_W_EFFECTS] = uniform(0, 1e3);
    }
    r->e_impulse = uniform(0, 1e3);
    r->loads.normal = uniform(-1e3, 1e3);
    r->loads.hold = uniform(-1e3, 1e3);
    for (int i = 0; i < m->nlink; i++) {
        r->loads.joint[i][0] = uniform(-1e3, 1e3);
        r->loads.joint[i][1] = uniform(-1e3, 1e3);
    }
    for (int b = 0; b <= m->nlink; b++) {
        r->loads.acc[b][0] = uniform(-100, 100);
        r->loads.acc[b][1] = uniform(-100, 100);
    }
}

/* every member of two rows the same bits (their padding aside) */
static int same_row(const zp_row *a, const zp_row *b) {
    const double wa[] = {a->t, a->w_drive, a->w_damp, a->e_impulse};
    const double wb[] = {b->t, b->w_drive, b->w_damp, b->e_impulse};
    return a->sec == b->sec && memcmp(wa, wb, sizeof wa) == 0 &&
           memcmp(a->w_effect, b->w_effect, sizeof a->w_effect) == 0 &&
           memcmp(&a->c, &b->c, sizeof a->c) == 0 &&
           memcmp(&a->loads, &b->loads, sizeof a->loads) == 0;
}

static void test_round_trip(void) {
    for (int nlink = 1; nlink <= ZP_MAX_LINKS; nlink++) {
        for (int nwork = ZP_W_EFFECTS; nwork <= ZP_W_MAX; nwork += ZP_EFFECT_NWORK) {
            zp_model m;
            memset(&m, 0, sizeof m);
            m.nlink = nlink;
            m.nwork = nwork;
            zp_row_store t;
            CHECK(zp_row_store_init(&t, &m, NROWS) == 0);
            static zp_row put[NROWS];
            for (int k = 0; k < NROWS; k++) {
                random_row(&m, &put[k]);
                zp_row_store_put(&t, &put[k]);
            }
            CHECK(t.n == NROWS);
            for (int k = 0; k < NROWS; k++) {
                zp_row got;
                memset(&got, 0xff, sizeof got); /* whatever was there before is overwritten */
                zp_row_store_get(&t, k, &got);
                CHECK(same_row(&got, &put[k]));
                CHECK(zp_row_store_t(&t, k) == put[k].t);
            }
            zp_row_store_free(&t);
            CHECK(t.v == NULL && t.n == 0);
        }
    }
}

/* a magnitude near `to`: exactly it, a few ulps either side, or a random share of it */
static void near(double to, double *a, double *b) {
    double th = uniform(0, 2 * M_PI), mag = to;
    int kind = rand() % 4;
    for (int u = rand() % 4; kind == 1 && u > 0; u--) {
        mag = nextafter(mag, INFINITY);
    }
    for (int u = rand() % 4; kind == 2 && u > 0; u--) {
        mag = nextafter(mag, 0);
    }
    if (kind == 3) {
        mag = to * uniform(0.5, 1.5);
    }
    *a = mag * cos(th);
    *b = mag * sin(th);
}

static void test_running_max(void) {
    zp_model m;
    memset(&m, 0, sizeof m);
    m.nlink = ZP_MAX_LINKS;
    m.g = 9.81;
    double joint[ZP_MAX_LINKS] = {0}, acc_g[ZP_MAX_LINKS] = {0};
    double ref_joint[ZP_MAX_LINKS] = {0}, ref_acc[ZP_MAX_LINKS] = {0};
    int same = 1, near_ties = 0;
    for (int k = 0; k < NLOADS; k++) {
        zp_loads ld;
        memset(&ld, 0, sizeof ld);
        for (int i = 0; i < m.nlink; i++) {
            double *j = ld.joint[i], *a = ld.acc[i + 1];
            switch (rand() % 6) {
            case 0: /* around the maximum so far: the hypot decides */
                near(ref_joint[i], &j[0], &j[1]);
                near(ref_acc[i] * m.g, &a[0], &a[1]);
                a[1] -= m.g;
                near_ties++;
                break;
            case 1: /* tiny, huge, not finite */
                j[0] = (double[]){1e-200, 1e200, INFINITY, NAN, -0.0}[rand() % 5];
                j[1] = (double[]){1e-170, 1e160, -INFINITY, 0, 3}[rand() % 5];
                a[0] = (double[]){1e-200, 1e200, NAN, 0}[rand() % 4];
                a[1] = (double[]){-m.g, 1e-300, 1e180, 2}[rand() % 4];
                break;
            default:
                j[0] = uniform(-1e3, 1e3) * pow(10, -(rand() % 6));
                j[1] = uniform(-1e3, 1e3) * pow(10, -(rand() % 6));
                a[0] = uniform(-100, 100);
                a[1] = uniform(-100, 100);
            }
        }
        /* an occasional start afresh, as each run's peaks are */
        if (rand() % 1000 == 0) {
            memset(joint, 0, sizeof joint);
            memset(acc_g, 0, sizeof acc_g);
            memset(ref_joint, 0, sizeof ref_joint);
            memset(ref_acc, 0, sizeof ref_acc);
        }
        zp_row_loads_max(&m, &ld, joint, acc_g);
        double jv[ZP_MAX_LINKS], av[ZP_MAX_LINKS];
        zp_row_loads(&m, &ld, jv, av);
        for (int i = 0; i < m.nlink; i++) {
            ref_joint[i] = fmax(ref_joint[i], jv[i]);
            ref_acc[i] = fmax(ref_acc[i], av[i]);
        }
        same &= memcmp(joint, ref_joint, sizeof joint) == 0 &&
                memcmp(acc_g, ref_acc, sizeof acc_g) == 0;
    }
    CHECK(same);
    CHECK(near_ties > NLOADS / 10);
}

/* the seed's rows against samples at every row time: the same zp_row, the one kept whole */
static void test_run_rows(void) {
    zp_scene sc;
    zp_model *m = tu_seed_model(&sc);
    zp_sim_opts o = tu_opts(&sc, 1e-6);
    o.output_dt = 0.02;
    o.track_loads = 1;
    enum { NSAMPLE = 1500 };
    static double at[NSAMPLE];
    for (int k = 0; k < NSAMPLE; k++) {
        at[k] = k * o.output_dt; /* as the simulator spaces its rows */
    }
    double f[ZP_MAX_SECTIONS] = {10, 10, 10};
    zp_schedule sched = zp_drive_sections(m->nsec, f, 0, 0);
    zp_input in = {.sched = &sched, .sample_t = at, .nsample = NSAMPLE};
    zp_sim *s = zp_sim_create(m, &o);
    static zp_result r;
    CHECK(s && zp_sim_run(m, s, &in, &r) == ZP_OK);
    CHECK(r.outcome == ZP_OUTCOME_FINISHED && r.ncross == 2);
    int ns;
    const zp_row *smp = zp_sim_samples(s, &ns);
    const zp_row_store *rows = zp_sim_rows(s);
    CHECK(ns > 1000 && rows->n == ns + 1); /* and the end */
    int same = 1;
    for (int k = 0; k < ns && k < rows->n; k++) {
        zp_row got;
        zp_row_store_get(rows, k, &got);
        same &= same_row(&got, &smp[k]);
    }
    CHECK(same);
    zp_row end;
    zp_row_store_get(rows, rows->n - 1, &end);
    CHECK(end.t == r.time && end.c.q[0] == r.x);
    zp_sim_free(s);
    zp_model_free(m);
}

int main(void) {
    srand(27);
    test_round_trip();
    test_running_max();
    test_run_rows();
    return CHECK_DONE();
}
