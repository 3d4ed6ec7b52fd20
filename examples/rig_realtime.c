/*
 * rig_realtime.c - the roller rig of the seed paper run from C alone, in a
 * fixed-rate loop as on a real-time target.
 *
 *   make -C csrc example              # builds csrc/build/rig_realtime
 *   csrc/build/rig_realtime [period_ms [seconds [free|floor]]]
 *
 * period_ms: the loop period and control sample time (default 4, the
 * paper's real-time step); seconds: simulated time (default 20, the
 * paper's four creepage targets of 5 s each).  The loop sleeps to the next
 * period (clock_nanosleep, TIMER_ABSTIME); "free" runs as fast as possible
 * instead; "floor" keeps the loop but replaces the rig's step by a fixed
 * amount of arithmetic lasting about as long, so its step times show the
 * machine's own jitter (interrupts, a virtual machine's host) that any code
 * run there would see.  Prints the creepage reached per target and the step
 * time's min, median, p99 and max.  The parameters are those of
 * rollerrig/data/rig_default.toml (conical 1:20 wheel on a crowned roller,
 * FASTSIM 20 x 20 with falling friction at the rigid slip speed, TR-BDF2):
 * the contact table built by rr_rig_table_build (rr.simulate()'s, bit for
 * bit), the rest set in rig_defaults() below.  As a real-time task it
 * locks its memory (mlockall), asks for the SCHED_FIFO policy and, on
 * Linux, stays on the last processor; where that is not allowed it says so
 * and runs as an ordinary process.
 */
#define _GNU_SOURCE       /* sched_setaffinity (Linux); the rest is POSIX */
#include <math.h>
#include <sched.h>
#include <sys/mman.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "rollerrig.h"

#define NROWS 161          /* rig_default.toml's integration.table_rows */
#define MAXSTEPS 200000

static double work[RR_RIG_TABLE_WORK_LEN], table_data[NROWS * RR_CONTACT_TABLE_ROW];
static double step_us[MAXSTEPS];

/* The rig's contact table from rig_default.toml's geometry: conical wheel,
 * tan(alpha) = 1:20, r0 = 0.092 m, on a roller R0 = 0.16 m with a 60 mm
 * crown, profiles over +-15 mm, contact points 0.15 m either side of the
 * centre, rows over +-8 mm.  rr_rig_table_build computes it as rr.simulate()
 * does (rollerrig.rig._rig_table calls it): the same table, bit for bit. */
static int build_geometry(rr_contact_table *t)
{
    rr_rig_geometry g;
    g.wheel_radius = 0.092;
    g.roller_radius = 0.160;
    g.profile_half_width = 0.015;
    g.cone_angle = atan(0.05);
    g.crown_radius = 0.060;
    g.contact_half_spacing = 0.15;
    g.table_half_range = 0.008;
    g.table_rows = NROWS;
    return rr_rig_table_build(&g, table_data, (long)(sizeof table_data / sizeof *table_data),
                              work, RR_RIG_TABLE_WORK_LEN, t, NULL);
}

static void rig_defaults(rr_rig_params *p, const rr_contact_table *t, double T)
{
    memset(p, 0, sizeof *p);
    p->mass = 14.504;
    p->Iyy = 0.03584 + 0.50;          /* wheelset + braking drive */
    p->Izz = 0.3584;
    p->axlebox_y = 0.20;
    p->kx = 6.2782e6; p->ky = 7.768e5; p->kz = 2.44e5;
    p->cx = 4117.0; p->cy = 509.4; p->cz = 160.0;
    p->preload = 900.85;
    p->g = 9.81;
    p->roller_inertia = 1.5;
    p->contact.table = t;
    p->contact.R0 = 0.160;
    p->contact.estar = rr_estar(2.1e11, 0.28, 2.1e11, 0.28);
    p->contact.G = 2.1e11 / (2.0 * 1.28);
    p->contact.nu = 0.28;
    p->contact.friction.mu0 = 0.4;
    p->contact.friction.A = 0.4;
    p->contact.friction.B = 0.6;
    rr_creep_opts_default(&p->contact.creep, RR_METHOD_FASTSIM);
    p->contact.creep.v[RR_FASTSIM_NX] = p->contact.creep.v[RR_FASTSIM_NY] = 20;
    p->contact.creep.v[RR_FASTSIM_SLIP_SPEED] = RR_SLIP_RIGID;
    p->contact.vmin = 0.01;
    p->T = T;
    p->nsub = 1;
    p->method = RR_ODE_TRBDF2;
    p->newton_iters = 1;          /* in the BDF2 stage; */
    p->linear_tr = 1;             /* none in the trapezoidal stage */
    p->newton_model = 1;          /* iterated on the simplified theory: one FASTSIM per step */
    p->roller_pi.T = T; p->roller_pi.Kp = 300.0; p->roller_pi.KI = 2.0; p->roller_pi.Tmax = 100.0;
    p->wheelset_pi.T = T; p->wheelset_pi.Kp = 100.0; p->wheelset_pi.KI = 2.0;
    p->wheelset_pi.Tmax = 60.0;
    p->roller_tau = p->wheelset_tau = 1e-3;
    p->roller_enc.T = p->wheelset_enc.T = T;
    p->roller_enc.counts = p->wheelset_enc.counts = 8388608;
    p->creepctl.r_w = 0.092;
    p->creepctl.r_r = 0.160;
    p->creepctl.alpha = 0.01;
    p->creepctl.beta = 0.002;
    p->creepctl.vmin = 0.1;
    p->creepctl.sense = RR_CREEPCTL_BRAKING;
}

static double now_us(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return 1e6 * (double)ts.tv_sec + 1e-3 * (double)ts.tv_nsec;
}

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

static int cmp(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    static const double targets[4] = {0.04, 0.015, 0.02, 0.03};
    const double period = (argc > 1 ? atof(argv[1]) : 4.0) * 1e-3;
    const double seconds = argc > 2 ? atof(argv[2]) : 20.0;
    const char *mode = argc > 3 ? argv[3] : "sleep";
    const int sleep_on = strcmp(mode, "free") != 0, floor_on = strcmp(mode, "floor") == 0;
    const double V = 5.0, R0 = 0.160;
    rr_contact_table table;
    rr_rig_params p;
    static rr_rig rig;
    double rec[RR_REC_COUNT], last[4][RR_REC_COUNT];
    struct timespec next;
    long n, k, nsteps, nbusy = 0;
    double sink = 1.0;
    int st;

    if (!(period > 0.0) || !(seconds > 0.0)
        || (strcmp(mode, "sleep") != 0 && sleep_on && !floor_on)) {
        fprintf(stderr, "usage: %s [period_ms [seconds [free|floor]]]\n", argv[0]);
        return 2;
    }
    nsteps = (long)(seconds / period + 0.5);
    if (nsteps > MAXSTEPS)
        nsteps = MAXSTEPS;
    if ((st = build_geometry(&table)) != RR_OK) {
        fprintf(stderr, "contact table: %s\n", rr_status_message(st));
        return 1;
    }
    rig_defaults(&p, &table, period);
    {
        /* eq. 15-16 with the centred wheelset's rolling radii (a calibrated rig) */
        rr_wheelset_pose pose;
        rr_contact_point cl, cr;
        rr_contact_table_lookup(&table, 0.0, &pose, NULL, &cl, &cr);
        p.creepctl.r_w = cl.r;
        p.creepctl.r_r = cl.R;
    }
    if ((st = rr_rig_init(&p, V / R0, &rig)) < 0) {
        fprintf(stderr, "rig: %s\n", rr_status_message(st));
        return 1;
    }
    {
        /* real-time task: no page faults, not preempted by ordinary processes,
         * not moved between processors */
        struct sched_param sp;
        const int locked = mlockall(MCL_CURRENT | MCL_FUTURE) == 0;
        int pinned = 0;
#ifdef __linux__
        cpu_set_t cpus;
        const long ncpu = sysconf(_SC_NPROCESSORS_ONLN);
        CPU_ZERO(&cpus);
        CPU_SET(ncpu > 1 ? (int)ncpu - 1 : 0, &cpus);
        pinned = sched_setaffinity(0, sizeof cpus, &cpus) == 0;
#endif
        sp.sched_priority = sched_get_priority_max(SCHED_FIFO) - 1;
        printf("memory %slocked, SCHED_FIFO %s, %s\n", locked ? "" : "not ",
               sched_setscheduler(0, SCHED_FIFO, &sp) == 0 ? "on" : "refused",
               pinned ? "pinned to the last processor" : "not pinned");
    }
    if (floor_on) {
        /* as long as the rig's median step: calibrate on the step itself */
        double t0 = now_us(), t_step, t_busy;
        for (k = 0; k < 200; k++)
            rr_rig_step(&rig, V / R0, targets[0], rec);
        t_step = (now_us() - t0) / 200.0;
        rr_rig_init(&p, V / R0, &rig);
        t0 = now_us();
        sink = busy(1000000, sink);
        t_busy = (now_us() - t0) / 1e6;
        nbusy = (long)(t_step / t_busy);
    }
    clock_gettime(CLOCK_MONOTONIC, &next);
    for (n = 0; n < nsteps; n++) {
        const int target = (int)(n * period / (seconds / 4.0));
        double t0;
        if (sleep_on) {
            next.tv_nsec += (long)(period * 1e9);
            while (next.tv_nsec >= 1000000000L) {
                next.tv_nsec -= 1000000000L;
                next.tv_sec++;
            }
            clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &next, NULL);
        }
        t0 = now_us();
        if (floor_on)
            sink = busy(nbusy, sink);
        else
            st = rr_rig_step(&rig, V / R0, targets[target < 4 ? target : 3], rec);
        step_us[n] = now_us() - t0;
        if (st < 0) {
            fprintf(stderr, "t = %.3f s: %s\n", rig.t, rr_status_message(st));
            return 1;
        }
        memcpy(last[target < 4 ? target : 3], rec, sizeof rec);
    }
    if (!floor_on)
        printf("target  creepage  adhesion  roller m/s  wheel m/s   (end of each target's interval)\n");
    for (k = 0; k < 4 && !floor_on; k++)
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
    qsort(step_us, (size_t)nsteps, sizeof step_us[0], cmp);
    printf("%ld steps of %.1f ms%s: step time min %.1f us, median %.1f us, p99 %.1f us, "
           "max %.1f us\n", nsteps, period * 1e3, floor_on ? " (fixed-rate loop, fixed work: the floor)"
           : sleep_on ? " (fixed-rate loop)" : " (free run)",
           step_us[0], step_us[nsteps / 2], step_us[(long)(0.99 * (nsteps - 1))],
           step_us[nsteps - 1]);
    return 0;
}
