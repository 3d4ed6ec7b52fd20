/*
 * rig_sil.c - software in the loop: a wheel-slide protection written in C
 * brakes the rig through a patch of low adhesion, in a fixed-rate loop as on
 * a real-time target (rt_loop.h, as rig_realtime.c).
 *
 *   make -C csrc sil                  # builds csrc/build/rig_sil
 *   csrc/build/rig_sil [period_ms [sleep|free [records.f64]]]
 *
 * The scenario of examples/slide_protection.py: the roller held at 5 m/s;
 * from 0.2 s the wheelset braked with a torque worth an adhesion of 0.25;
 * mu0 0.4, 0.1 from 1.5 s to 3.5 s, 0.4 again; 5 s.  Each sample the rig is
 * read (rr_rig_read: the encoders, the drives' torques), the controller
 * computes its command and the rig holds it (rr_rig_write), then the plant
 * runs over the sample (rr_rig_advance): nothing is allocated in the loop.
 * The controller is examples/slide_protection.py's SlideProtection with the
 * same operations in the same order, so at the 4 ms period the records
 * (written as raw doubles, RR_REC_COUNT per sample, when a file is named)
 * are the Python run's bit for bit (tests/test_rig_c_program.py).  Prints
 * the largest creepage in and after the patch and the step time's min,
 * median, p99 and max; "free" runs as fast as it can, without sleeping.
 */
#define _GNU_SOURCE       /* sched_setaffinity (Linux); the rest is POSIX */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rt_loop.h"
#include "rollerrig.h"

#define MAXSTEPS 100000

static double table_data[1L << 16], table_work[RR_RIG_TABLE_WORK_LEN];
static double step_us[MAXSTEPS];

/* Wheel-slide protection of the dump / hold / re-apply kind, on the encoders
 * alone (slide_protection.py: SlideProtection, whose docstring says why). */
typedef struct {
    double demand, begin;                 /* brake demand [N m], from time [s] */
    double slip_on, slip_off, decel_max;  /* thresholds [-], [-], [m/s^2] */
    double dump_rate, apply_rate;         /* of the demand's factor [1/s] */
    double dt, r;                         /* sample time [s], wheel radius [m] */
    double factor, last;                  /* state: the factor, the last wheel speed */
    int primed;
} slide_protection;

static void wsp_start(slide_protection *c, const rr_rig_params *p)
{
    c->dt = p->T;
    c->r = p->creepctl.r_w;
    c->factor = 1.0;
    c->primed = 0;
}

/* The command of one sample; the scenario's references where it does not brake. */
static void wsp_step(slide_protection *c, const rr_rig_signals *s, double roller_ref,
                     double xi_ref, rr_rig_command *cmd)
{
    const double v = s->wheelset_speed * c->r;
    const double decel = c->primed ? (c->last - v) / c->dt : 0.0;
    c->last = v;
    c->primed = 1;
    rr_rig_command_builtin(cmd, roller_ref, xi_ref);
    if (s->t < c->begin)
        return;
    if (s->xi_est > c->slip_on || decel > c->decel_max)
        c->factor = fmax(0.0, c->factor - c->dump_rate * c->dt);
    else if (s->xi_est < c->slip_off)
        c->factor = fmin(1.0, c->factor + c->apply_rate * c->dt);
    /* the drive as a friction brake: against the rotation, fading below 0.5 rad/s */
    cmd->wheelset_mode = RR_CMD_TORQUE;
    cmd->wheelset_ref = -fabs(c->demand * c->factor)
                        * fmax(-1.0, fmin(1.0, s->wheelset_speed / 0.5));
}

int main(int argc, char **argv)
{
    const double period = (argc > 1 ? atof(argv[1]) : 4.0) * 1e-3;
    const int sleep_on = !(argc > 2 && strcmp(argv[2], "free") == 0);
    const char *out = argc > 3 ? argv[3] : NULL;
    static const double targets[] = {0.0}, starts[] = {0.0};
    static const double times[] = {1.5, 1.5, 3.5, 3.5}, mu[] = {0.4, 0.1, 0.1, 0.4};
    slide_protection wsp = {0.25 * 2 * 521.6 * 0.092, 0.2, 0.05, 0.02, 4.0, 8.0, 3.0,
                            0.0, 0.0, 0.0, 0.0, 0};
    rr_rig_config c;
    rr_rig_geometry g;
    rr_contact_table table;
    rr_rig_params p;
    static rr_rig rig;
    rr_rig_signals s;
    rr_rig_command cmd;
    double rec[RR_REC_COUNT], roller_ref, xi_ref, most_in = 0.0, most_after = 0.0;
    struct timespec next;
    FILE *f = NULL;
    long n, k;
    int st;

    if (!(period > 0.0) || (argc > 2 && strcmp(argv[2], "free") != 0
                            && strcmp(argv[2], "sleep") != 0)) {
        fprintf(stderr, "usage: %s [period_ms [sleep|free [records.f64]]]\n", argv[0]);
        return 2;
    }
    rr_rig_config_default(&c);
    if ((st = rr_rig_config_set(&c, "scenario.control_sample_time_s", period)) != RR_OK
        || (st = rr_rig_config_set(&c, "scenario.duration_s", 5.0)) != RR_OK
        || (st = rr_rig_config_set_list(&c, "scenario.targets", 1, targets)) != RR_OK
        || (st = rr_rig_config_set_list(&c, "scenario.target_start_s", 1, starts)) != RR_OK
        || (st = rr_rig_config_set_list(&c, "adhesion.schedule_times_s", 4, times)) != RR_OK
        || (st = rr_rig_config_set_list(&c, "adhesion.schedule_mu0", 4, mu)) != RR_OK) {
        fprintf(stderr, "scenario: %s\n", rr_status_message(st));
        return 2;
    }
    rr_rig_geometry_from(&c, &g);
    if (rr_rig_table_data_len(&g) > (long)(sizeof table_data / sizeof table_data[0])
        || (st = rr_rig_table_build(&g, table_data, rr_rig_table_data_len(&g), table_work,
                                    RR_RIG_TABLE_WORK_LEN, &table, NULL)) != RR_OK
        || (st = rr_rig_params_from(&c, &table, &p)) != RR_OK
        || (st = rr_rig_init(&p, c.roller_speed / c.roller_radius, NULL, 0, &rig)) < 0) {
        fprintf(stderr, "rig: %s\n", rr_status_message(st));
        return 1;
    }
    if (out && !(f = fopen(out, "wb"))) {
        fprintf(stderr, "cannot write %s\n", out);
        return 1;
    }
    n = rr_rig_samples(&c);
    if (n > MAXSTEPS)
        n = MAXSTEPS;
    wsp_start(&wsp, &p);
    rt_task();
    rt_start(&next);
    for (k = 0; k < n; k++) {
        double t0;
        if (sleep_on)
            rt_wait(&next, period);
        t0 = rt_now_us();
        rr_rig_schedule(&c, k, &roller_ref, &xi_ref);
        if ((st = rr_rig_read(&rig, &s)) >= 0) {
            wsp_step(&wsp, &s, roller_ref, xi_ref, &cmd);
            if ((st = rr_rig_write(&rig, &cmd)) >= 0)
                st = rr_rig_advance(&rig, rec);
        }
        step_us[k] = rt_now_us() - t0;
        if (st < 0) {
            fprintf(stderr, "sample %ld (t = %.3f s): %s\n", k, rig.t, rr_status_message(st));
            if (f)
                fclose(f);
            return 1;
        }
        rec[RR_REC_XI_REF] = xi_ref;     /* the scenario's target, as simulate records it */
        if (f && fwrite(rec, sizeof rec[0], RR_REC_COUNT, f) != RR_REC_COUNT) {
            fprintf(stderr, "cannot write %s\n", out);
            fclose(f);
            return 1;
        }
        if (rec[RR_REC_T] > 1.5 && rec[RR_REC_T] < 3.5)
            most_in = fmax(most_in, rec[RR_REC_CREEPAGE]);
        else if (rec[RR_REC_T] > 4.0)
            most_after = fmax(most_after, rec[RR_REC_CREEPAGE]);
    }
    if (f && fclose(f) != 0) {
        fprintf(stderr, "cannot write %s\n", out);
        return 1;
    }
    printf("largest creepage in the patch %.4f, after it %.4f\n", most_in, most_after);
    rt_report(step_us, n, period, sleep_on ? " (fixed-rate loop, C controller in the loop)"
              : " (free run, C controller in the loop)");
    return 0;
}
