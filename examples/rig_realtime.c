/*
 * rig_realtime.c - the roller rig of the seed paper run from C alone, in a
 * fixed-rate loop as on a real-time target.
 *
 *   make -C csrc example              # builds csrc/build/rig_realtime
 *   csrc/build/rig_realtime [period_ms [seconds [free|floor]]]
 *
 * period_ms: the loop period and control sample time (default 4, the
 * paper's real-time step); seconds: simulated time (default
 * scenario.duration_s, the paper's four creepage targets of 5 s each).  The loop sleeps to the next
 * period (clock_nanosleep, TIMER_ABSTIME); "free" runs as fast as possible
 * instead; "floor" keeps the loop but replaces the rig's step by a fixed
 * amount of arithmetic lasting about as long, so its step times show the
 * machine's own jitter (interrupts, a virtual machine's host) that any code
 * run there would see.  Prints the creepage reached per target and the step
 * time's min, median, p99 and max.  The parameters, the scenario (roller
 * speed, the four targets) and the contact table are the declared defaults
 * (csrc/rig/rr_rig_params.h: rr_rig_config_default, rr_rig_table_build;
 * rollerrig/data/rig_default.toml is generated from the same table): conical
 * 1:20 wheel on a crowned roller, FASTSIM 20 x 20 with falling friction at
 * the rigid slip speed, TR-BDF2; only the sample time is this program's.  As a real-time task it locks its memory
 * (mlockall), asks for the SCHED_FIFO policy and, on Linux, stays on the
 * last processor; where that is not allowed it says so and runs as an
 * ordinary process.
 */
#define _GNU_SOURCE       /* sched_setaffinity (Linux); the rest is POSIX */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rt_loop.h"
#include "rollerrig.h"

#define MAXSTEPS 200000

static double table_data[1L << 16], table_work[RR_RIG_TABLE_WORK_LEN];
static double step_us[MAXSTEPS];

/* Fixed work for the "floor" mode: n dependent multiply-adds through a
 * volatile, which the compiler can neither fold nor drop. */
static double busy(long n, double x)
{
    volatile double v = x;
    long i;
    for (i = 0; i < n; i++)
        v = v * 0.999999 + 1e-6;
    return v;
}

int main(int argc, char **argv)
{
    const double period = (argc > 1 ? atof(argv[1]) : 4.0) * 1e-3;
    double seconds = argc > 2 ? atof(argv[2]) : -1.0;   /* default: scenario.duration_s */
    const char *mode = argc > 3 ? argv[3] : "sleep";
    const int sleep_on = strcmp(mode, "free") != 0, floor_on = strcmp(mode, "floor") == 0;
    rr_rig_config c;
    rr_rig_geometry g;
    rr_contact_table table;
    const double *targets;
    double V, R0;
    int ntargets;
    rr_rig_params p;
    static rr_rig rig;
    double rec[RR_REC_COUNT];
    static double last[RR_RIG_MAX_LIST][RR_REC_COUNT];
    struct timespec next;
    long n, k, nsteps, nbusy = 0;
    double sink = 1.0;
    int st;

    if (!(period > 0.0) || !(seconds > 0.0 || argc <= 2)
        || (strcmp(mode, "sleep") != 0 && sleep_on && !floor_on)) {
        fprintf(stderr, "usage: %s [period_ms [seconds [free|floor]]]\n", argv[0]);
        return 2;
    }
    rr_rig_config_default(&c);
    rr_rig_geometry_from(&c, &g);
    if (rr_rig_table_data_len(&g) > (long)(sizeof table_data / sizeof table_data[0])
        || (st = rr_rig_table_build(&g, table_data, rr_rig_table_data_len(&g), table_work,
                                    RR_RIG_TABLE_WORK_LEN, &table, NULL)) != RR_OK) {
        fprintf(stderr, "contact table: %s\n", rr_status_message(RR_ERR_WORKSPACE));
        return 1;
    }
    /* the defaults at this program's sample time; eq. 15-16 with the centred
     * wheelset's rolling radii (a calibrated rig: rr_rig_params_set_table) */
    if ((st = rr_rig_config_set(&c, "scenario.control_sample_time_s", period)) != RR_OK
        || (st = rr_rig_params_from(&c, &table, &p)) != RR_OK) {
        fprintf(stderr, "parameters: %s\n", rr_status_message(st));
        return 2;
    }
    V = c.roller_speed;
    R0 = c.roller_radius;
    targets = c.targets.v;
    ntargets = c.targets.n;
    if (argc <= 2)
        seconds = c.duration;
    nsteps = (long)(seconds / period + 0.5);
    if (nsteps > MAXSTEPS)
        nsteps = MAXSTEPS;
    /* no workspace: the rig's default method needs none (rr_rig_workspace_len) */
    if ((st = rr_rig_init(&p, V / R0, NULL, 0, &rig)) < 0) {
        fprintf(stderr, "rig: %s\n", rr_status_message(st));
        return 1;
    }
    rt_task();
    if (floor_on) {
        /* as long as the rig's median step: calibrate on the step itself */
        double t0 = rt_now_us(), t_step, t_busy;
        for (k = 0; k < 200; k++)
            rr_rig_step(&rig, V / R0, targets[0], rec);
        t_step = (rt_now_us() - t0) / 200.0;
        rr_rig_init(&p, V / R0, NULL, 0, &rig);
        t0 = rt_now_us();
        sink = busy(1000000, sink);
        t_busy = (rt_now_us() - t0) / 1e6;
        nbusy = (long)(t_step / t_busy);
    }
    rt_start(&next);
    for (n = 0; n < nsteps; n++) {
        const int target = (int)(n * period / (seconds / ntargets));
        double t0;
        if (sleep_on)
            rt_wait(&next, period);
        t0 = rt_now_us();
        if (floor_on)
            sink = busy(nbusy, sink);
        else
            st = rr_rig_step(&rig, V / R0, targets[target < ntargets ? target : ntargets - 1], rec);
        step_us[n] = rt_now_us() - t0;
        if (st < 0) {
            fprintf(stderr, "t = %.3f s: %s\n", rig.t, rr_status_message(st));
            return 1;
        }
        memcpy(last[target < ntargets ? target : ntargets - 1], rec, sizeof rec);
    }
    if (!floor_on)
        printf("target  creepage  adhesion  roller m/s  wheel m/s   (end of each target's interval)\n");
    for (k = 0; k < ntargets && !floor_on; k++)
        printf("%6.3f  %8.5f  %8.4f  %10.4f  %9.4f\n", targets[k], last[k][RR_REC_CREEPAGE],
               last[k][RR_REC_ADHESION], last[k][RR_REC_ROLLER_SPEED],
               last[k][RR_REC_WHEELSET_SPEED]);
    {
        long kmax = 0;
        for (k = 1; k < nsteps; k++)
            if (step_us[k] > step_us[kmax])
                kmax = k;
        if (floor_on)
            printf("floor: %ld multiply-adds per step in place of the rig (%g)\n", nbusy,
                   sink);
        printf("slowest step: number %ld (t = %.3f s)\n", kmax, (kmax + 1) * period);
    }
    rt_report(step_us, nsteps, period, floor_on ? " (fixed-rate loop, fixed work: the floor)"
              : sleep_on ? " (fixed-rate loop)" : " (free run)");
    return 0;
}
