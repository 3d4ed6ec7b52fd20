/* test_creepage.c - kinematic creepages of a wheel on a roller (rr_creepage). */
#include <math.h>
#include <stdio.h>
#include "rr_test.h"
#include "rollerrig.h"

/* Rig frame: X forward, Y to the left, Z up.  A roller of radius R whose
 * top is at the origin turns so that its top moves backward (-X) at speed
 * Omega R, as track passes under a vehicle running forward. */
static void roller_motion(double R, double Omega, rr_motion *m)
{
    m->c[0] = 0.0; m->c[1] = 0.0; m->c[2] = -R;
    m->v[0] = m->v[1] = m->v[2] = 0.0;
    m->w[0] = 0.0; m->w[1] = -Omega; m->w[2] = 0.0;
}

/* A wheel of radius r whose bottom touches the origin, axle yawed by psi,
 * turning at omega about its axle (positive: rolling forward). */
static void wheel_motion(double r, double omega, double psi, rr_motion *m)
{
    m->c[0] = 0.0; m->c[1] = 0.0; m->c[2] = r;
    m->v[0] = m->v[1] = m->v[2] = 0.0;
    m->w[0] = -sin(psi) * omega; m->w[1] = cos(psi) * omega; m->w[2] = 0.0;
}

/* Contact frame at the origin tilted by the contact angle delta about t1. */
static void frame(double psi, double delta, rr_contact_frame *f)
{
    f->p[0] = f->p[1] = f->p[2] = 0.0;
    f->t1[0] = cos(psi); f->t1[1] = sin(psi); f->t1[2] = 0.0;
    f->t2[0] = -sin(psi) * cos(delta); f->t2[1] = cos(psi) * cos(delta); f->t2[2] = sin(delta);
}

static void test_free_rolling(void)
{
    rr_motion w, r;
    rr_contact_frame f;
    rr_creepages c;
    int st;
    roller_motion(0.2, 25.0, &r);            /* 5 m/s surface speed */
    wheel_motion(0.1, 50.0, 0.0, &w);         /* the same surface speed */
    frame(0.0, 0.0, &f);
    st = rr_creepage(&w, &r, &f, 1e-3, &c);
    CHECK_STATUS(st, RR_OK, "free rolling status");
    /* both surface speeds are 5 m/s to rounding: |cx| at the 1e-16 level */
    CHECK(fabs(c.cx) < 1e-12 && fabs(c.cy) < 1e-12 && fabs(c.cphi) < 1e-12,
          "free rolling: zero creepage");
    CHECK_CLOSE(c.V, 5.0, 0.0, 1e-15, "rolling speed = surface speed");
}

static void test_sign(void)
{
    rr_motion w, r;
    rr_contact_frame f;
    rr_creepages c;
    roller_motion(0.2, 25.0, &r);
    wheel_motion(0.1, 51.0, 0.0, &w);         /* wheel 2 % faster: traction */
    frame(0.0, 0.0, &f);
    rr_creepage(&w, &r, &f, 1e-3, &c);
    /* the wheel's contact point moves backward relative to the roller's:
     * slip -0.1 m/s over V = 5.05 m/s (Kalker's sign: traction gives cx < 0) */
    CHECK_CLOSE(c.cx, -0.1 / 5.05, 0.0, 1e-13, "traction: cx = -(wr - OR)/V");
}

static void test_yawed_wheel(void)
{
    /* yaw -0.3 rad, roller surface speed 0.1 cos 0.3 m/s, wheel lateral
     * velocity -0.1 sin 0.3 m/s, wheel surface speed 0.1 m/s: zero slip */
    const double psi = -0.3, r = 0.1, R = 0.2;
    rr_motion w, ro;
    rr_contact_frame f;
    rr_creepages c;
    roller_motion(R, 0.1 * cos(0.3) / R, &ro);
    wheel_motion(r, 0.1 / r, psi, &w);
    w.v[1] = -0.1 * sin(0.3);
    frame(psi, 0.0, &f);
    CHECK_STATUS(rr_creepage(&w, &ro, &f, 1e-3, &c), RR_OK, "yawed status");
    /* products of sines and cosines of 0.3: rounding at 1e-16 of 0.1 m/s */
    CHECK(fabs(c.slip[0]) < 1e-15 && fabs(c.slip[1]) < 1e-15 && fabs(c.slip[2]) < 1e-15,
          "yawed wheel with cancelling lateral velocity: zero slip");
    CHECK(fabs(c.cx) < 1e-13 && fabs(c.cy) < 1e-13, "yawed wheel: zero creepage");
    /* without the lateral velocity the lateral creepage is the yaw angle's
     * share of the roller speed: cy = -sin(0.3) * 0.1 / V ... nonzero */
    w.v[1] = 0.0;
    rr_creepage(&w, &ro, &f, 1e-3, &c);
    CHECK(fabs(c.cy) > 0.1, "yawed wheel without lateral velocity: lateral creepage");
}

static void test_spin(void)
{
    /* seed paper eq. (9): spin = -/+ sin(delta) (1/r + 1/R) for a wheel on a
     * roller in free rolling with contact angle delta */
    const double r = 0.1, R = 0.2, delta = 0.05;
    rr_motion w, ro;
    rr_contact_frame f;
    rr_creepages c;
    roller_motion(R, 25.0, &ro);
    wheel_motion(r, 50.0, 0.0, &w);
    frame(0.0, delta, &f);
    rr_creepage(&w, &ro, &f, 1e-3, &c);
    /* n = t1 x t2 = (0, -sin delta, cos delta) and w_w - w_r = (0, omega + Omega, 0):
     * cphi = -sin(delta) (1/r + 1/R), exact up to rounding */
    CHECK_CLOSE(c.cphi, -sin(delta) * (1.0 / r + 1.0 / R), 0.0, 1e-13,
                "spin = -sin(delta) (1/r + 1/R) (eq. 9, contact plane rising toward +y)");
    frame(0.0, -delta, &f);
    rr_creepage(&w, &ro, &f, 1e-3, &c);
    CHECK_CLOSE(c.cphi, sin(delta) * (1.0 / r + 1.0 / R), 0.0, 1e-13,
                "spin changes sign with the contact angle (the other wheel)");
}

static void test_standstill_and_bad_input(void)
{
    rr_motion w, r;
    rr_contact_frame f;
    rr_creepages c;
    roller_motion(0.2, 0.0, &r);
    wheel_motion(0.1, 0.0, 0.0, &w);
    w.v[1] = 1e-3;
    frame(0.0, 0.0, &f);
    CHECK_STATUS(rr_creepage(&w, &r, &f, 0.01, &c), RR_OK, "standstill status");
    /* at rest the reference speed is vmin: 1 mm/s over 10 mm/s */
    CHECK(c.V == 0.01 && fabs(c.cy - 0.1) < 1e-15, "standstill: slip / vmin, finite");
    CHECK_STATUS(rr_creepage(&w, &r, &f, 0.0, &c), RR_ERR_SPEED, "vmin = 0");
    CHECK(c.cx != c.cx, "vmin = 0: NaN");
    w.w[0] = NAN;
    CHECK_STATUS(rr_creepage(&w, &r, &f, 0.01, &c), RR_ERR_NONFINITE, "NaN state");
    w.w[0] = 0.0;
    f.t2[0] = 0.5;
    CHECK_STATUS(rr_creepage(&w, &r, &f, 0.01, &c), RR_ERR_GEOMETRY, "frame not orthonormal");
}

int main(void)
{
    test_free_rolling();
    test_sign();
    test_yawed_wheel();
    test_spin();
    test_standstill_and_bad_input();
    return rr_test_summary();
}
