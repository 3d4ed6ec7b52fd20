/*
 * rr_geometry.h - contact geometry of a wheelset on the two rollers of the
 * rig: contact search on profile splines, the roll and height that keep
 * both wheels on their rollers, and precomputed contact tables.
 *
 * Rig frame: X forward, Y lateral (left positive), Z up; Z = 0 at the top of
 * a roller of nominal radius R0.  Each profile is a height curve z(s) (up
 * positive, a natural cubic spline, rr_spline.h) over a lateral coordinate
 * s that points OUTWARD from the centre line (to +Y on the left side, to -Y
 * on the right): the wheel's lower surface z_w(s) = r0 - r(s) (0 on the
 * nominal rolling circle, r(s) the wheel's radius), the roller's upper
 * surface z_r(s) = R(s) - R0.
 *
 * The contact point minimises the vertical gap between the two surfaces
 * (the paper's minimum-interference search): every wheel sample is mapped
 * into the rig with the wheelset's lateral shift, height and roll, the gap
 * to the roller below it taken, the smallest found and refined by Newton's
 * method on the splines (where the two surfaces are parallel).  A second
 * local minimum of the gap within `two_point_tol` of the first and more
 * than `two_point_sep` away is reported as two-point contact.
 * The search is in the plane of the axle: the wheelset's yaw, and its
 * rotation about the roller axis, move the contact point around the
 * roller (rr_rig_contact.h) and change the rest at second order only.
 */
#ifndef RR_GEOMETRY_H
#define RR_GEOMETRY_H

#include "util/rr_spline.h"

typedef struct {
    rr_spline wheel;   /* z_w(s): wheel lower surface [m] */
    rr_spline roller;  /* z_r(s): roller upper surface [m] */
    double r0;         /* wheel radius where z_w = 0 [m] */
    double R0;         /* roller radius where z_r = 0 [m] */
    double wheel_y;    /* lateral distance of the wheel profile's s = 0 from the wheelset centre [m] */
    double roller_y;   /* lateral distance of the roller profile's s = 0 from the rig centre line [m] */
    int side;          /* +1 left (+Y), -1 right (-Y) */
} rr_wheel_roller;

typedef struct {
    int nsamples;          /* wheel samples of the coarse search, >= 3 */
    double two_point_tol;  /* gap difference that still counts as a second contact [m] */
    double two_point_sep;  /* least lateral distance between two contact points [m] */
} rr_search_opts;

/* Most wheel samples a search takes (a row then costs at most ~0.1 s). */
#define RR_SEARCH_MAX_SAMPLES 100000

/* 400 samples, two-point contact within 0.1 mm of gap and 2 mm apart. */
void rr_search_opts_default(rr_search_opts *o);

typedef struct {
    double y, z;          /* contact point in the rig [m] */
    double s_wheel;       /* profile coordinates of the contact point [m] */
    double s_roller;
    double r, R;          /* wheel rolling radius, roller radius at the contact [m] */
    double delta;         /* contact angle [rad]: > 0 when the roller surface rises
                             outward (tread and flange contact on the gauge side) */
    double A, B;          /* Hertz curvature sums [1/m]: A = (cos delta/r + cos delta/R)/2
                             rolling direction, B = (k_wheel + k_roller)/2 lateral */
    double gap;           /* the vertical gap there [m]; < 0: interference */
    double ha, hb, hd;    /* the Hertz ellipse per unit load and modulus: semi-axes
                             a = ha (N/E*)^(1/3), b = hb (N/E*)^(1/3), approach
                             hd (N/E*)^(2/3); they depend on A and B alone, so the
                             table carries them and the time step needs no
                             elliptic integrals (rr_hertz at N = E* = 1) */
    int two_point;        /* 1 if a second contact point was found */
    double y2, gap2;      /* the second point's lateral position and gap */
} rr_contact_point;

/*
 * rr_contact_search - contact point of one wheel on its roller.
 *   given:   p the pair; the wheelset's lateral shift y_ws, axle height z_ws
 *            and roll angle roll (right-handed about X: positive lifts the left side)
 *   returns: *out
 *   status:  0 OK; RR_ERR_GEOMETRY (no wheel sample lies over the roller:
 *            the wheel is off its roller; or B <= 0: conformal contact, no
 *            Hertz ellipse; or a profile's knots not increasing),
 *            RR_ERR_NONFINITE, RR_ERR_PARAM (nsamples outside [3,
 *            RR_SEARCH_MAX_SAMPLES], a tolerance negative or not finite, r0
 *            or R0 not positive, side not +-1), RR_ERR_NULL.  The profiles
 *            are checked (rr_spline_check) on every call.
 */
int rr_contact_search(const rr_wheel_roller *p, double y_ws, double z_ws, double roll,
                      const rr_search_opts *o, rr_contact_point *out);

typedef struct {
    double z;      /* axle height [m] */
    double roll;   /* roll angle [rad] */
} rr_wheelset_pose;

/*
 * rr_wheelset_contact - axle height and roll for lateral shift y_ws such
 * that both wheels touch their rollers (zero gap), and both contact points.
 *   status:  0 OK; RR_WARN_NOT_CONVERGED; errors of rr_contact_search;
 *            RR_ERR_NULL (pose, cl or cr NULL); RR_ERR_RANGE (a pose so
 *            far from the origin, beyond ~5e5 m, that the gap's rounding
 *            exceeds 1e-9 m: absurd radii)
 */
int rr_wheelset_contact(const rr_wheel_roller *left, const rr_wheel_roller *right, double y_ws,
                        const rr_search_opts *o, rr_wheelset_pose *pose,
                        rr_contact_point *cl, rr_contact_point *cr);

/*
 * Contact table: the geometry at n equally spaced lateral shifts
 * y_ws = y0 + i dy, computed once, interpolated linearly in O(1).
 * Storage is the caller's: rr_contact_table_len(n) doubles.
 */
typedef struct {
    double y0, dy;
    int n;
    double *data;
} rr_contact_table;

long rr_contact_table_len(int n);

/* Doubles per table row (rr_contact_table_len(n) = n RR_CONTACT_TABLE_ROW),
 * for callers sizing static storage. */
#define RR_CONTACT_TABLE_ROW 28

/*
 * rr_contact_table_build - fill the table (calls rr_wheelset_contact n times).
 *   given:   t->y0, t->dy > 0, t->n >= 2 (finite, the last row's shift
 *            too), t->data of rr_contact_table_len(t->n) doubles
 *   status:  0 OK, or the first error with the shift that caused it left in
 *            *bad_y (may be NULL); RR_ERR_WORKSPACE (no data), RR_ERR_PARAM
 *            (y0, dy or n invalid), RR_ERR_NULL, errors of rr_contact_search
 */
int rr_contact_table_build(const rr_wheel_roller *left, const rr_wheel_roller *right,
                           const rr_search_opts *o, rr_contact_table *t, double *bad_y);

/*
 * rr_contact_table_build_rows - rows i0 <= i < i1 of the table only (a caller
 * that builds a large table in parts, e.g. to stay responsive); the same
 * rows, bit for bit, as rr_contact_table_build.  RR_ERR_PARAM unless
 * 0 <= i0 <= i1 <= t->n.
 */
int rr_contact_table_build_rows(const rr_wheel_roller *left, const rr_wheel_roller *right,
                                const rr_search_opts *o, rr_contact_table *t, int i0, int i1,
                                double *bad_y);

/*
 * rr_contact_table_lookup - interpolated geometry at lateral shift y_ws.
 *   returns: *pose, both contact points; *slope (if not NULL) the
 *            derivatives dz/dy_ws and droll/dy_ws of the interpolant, which
 *            turn a lateral velocity into the vertical and roll rates the
 *            contact constraint implies.
 *   The two-point flag is that of the nearer row.  No allocation, O(1).
 *   The caller's buffer must hold t->n rows (it cannot be checked here).
 *   status:  0 OK; RR_ERR_GEOMETRY (y_ws outside the table: below y0 or
 *            above the last row's y0 + (n - 1) dy), RR_ERR_NONFINITE,
 *            RR_ERR_PARAM (y0, dy, n invalid as for the build), RR_ERR_NULL
 *            (t, t->data, pose, cl or cr NULL)
 */
int rr_contact_table_lookup(const rr_contact_table *t, double y_ws, rr_wheelset_pose *pose,
                            rr_wheelset_pose *slope, rr_contact_point *cl, rr_contact_point *cr);

#endif
