/*
 * rr_tables.h - contact tables from profiles given as points, and the rig's
 * default table, without Python and with the numbers of the Python side:
 * the profile spline is rr_spline_fit (rollerrig.profiles.Profile calls
 * it), the analytic profiles are computed as Profile.conical and
 * Profile.cylinder compute them (they call these functions), and the
 * default table is rollerrig.rig's (rig.py builds it here).  A C program
 * and rr.simulate() therefore hold the same table, bit for bit.
 *
 * Profiles here are in rollerrig.profiles' convention: y lateral towards
 * the field side, z DOWNWARD (rr_geometry.h's surfaces are heights, up:
 * the builders turn one into the other).  Both sides of the rig get the
 * same profiles (the right side is the mirror image in the rig frame, as
 * rollerrig.RigGeometry without wheel_right/roller_right).  No function
 * allocates: the caller passes the workspace, sized by the *_len queries.
 */
#ifndef RR_TABLES_H
#define RR_TABLES_H

#include "util/rr_spline.h"
#include "geometry/rr_geometry.h"

/* Limits of an analytic profile's lateral range, as rollerrig.profiles'
 * MAX_COORD and MIN_WIDTH (a unit mistake beyond them). */
#define RR_PROFILE_MAX_COORD 2.0   /* [m] */
#define RR_PROFILE_MIN_WIDTH 1e-3  /* [m] */

/*
 * rr_profile_conical - the conical wheel: y_i = y_min + i (y_max - y_min)/(n-1)
 * (numpy's linspace: the last point y_max itself), z_i = -tan(alpha) y_i.
 *   given:   alpha in (-pi/2, pi/2) [rad]; y_min < y_max within
 *            +-RR_PROFILE_MAX_COORD, at least RR_PROFILE_MIN_WIDTH apart;
 *            n in [RR_SPLINE_MIN_POINTS, RR_SPLINE_MAX_POINTS]
 *   returns: y[n], z[n]
 *   status:  0 OK; RR_ERR_NULL (y or z NULL), RR_ERR_NONFINITE, RR_ERR_PARAM
 *            (alpha, the range or n out of range); outputs NaN on error
 *            (when n is in range)
 */
int rr_profile_conical(double alpha, double y_min, double y_max, int n, double *y, double *z);

/*
 * rr_profile_crowned - a roller: points as rr_profile_conical, z = 0 (a
 * cylinder, crown_radius == 0) or the crown of radius crown_radius centred
 * at y = 0, z = R - sqrt(R^2 - y^2) computed as y^2 / (R + sqrt(R - y)
 * sqrt(R + y)) (no cancellation, no R^2 to overflow).
 *   status:  as rr_profile_conical; RR_ERR_PARAM also for crown_radius
 *            negative, RR_ERR_GEOMETRY for a range reaching the crown's
 *            radius (|y| >= R)
 */
int rr_profile_crowned(double crown_radius, double y_min, double y_max, int n, double *y,
                       double *z);

/* A profile as points: rollerrig.profiles.Profile(y, z, bc=...). */
typedef struct {
    int n;             /* points, RR_SPLINE_MIN_POINTS..RR_SPLINE_MAX_POINTS */
    const double *y;   /* lateral [m], strictly increasing */
    const double *z;   /* vertical [m], downward */
    int end;           /* RR_SPLINE_NOT_A_KNOT or RR_SPLINE_NATURAL */
} rr_profile_points;

/* Where the profiles sit: rollerrig.RigGeometry's numbers. */
typedef struct {
    double wheel_radius;   /* r0: the wheel's radius at its profile's y = 0, z = 0 [m] */
    double roller_radius;  /* R0: the roller's, likewise [m] */
    double wheel_y;        /* the wheel profile's y = 0 from the wheelset centre [m] */
    double roller_y;       /* the roller profile's y = 0 from the rig's centre line [m] */
} rr_profile_placement;

/*
 * rr_profile_surface - a profile as the geometry reads it: the spline of
 * rr_spline_fit, heights up: zup = -z and mup = -z'' at the knots (the
 * arrays rollerrig.RigGeometry passes to the core).
 *   given:   p; work, 4 p->n doubles
 *   returns: zup[n], mup[n]; with p->y they make an rr_spline
 *   status:  0 OK; RR_ERR_NULL (p NULL), RR_ERR_WORKSPACE (zup, mup or
 *            work NULL), errors of rr_spline_fit and rr_spline_knot_d2
 *            (RR_ERR_RANGE); zup, mup NaN on error (when p->n is in range)
 */
int rr_profile_surface(const rr_profile_points *p, double *zup, double *mup, double *work);

/* Doubles of workspace rr_profile_table_build needs; 0 if a count is out
 * of range. */
long rr_profile_table_work_len(int n_wheel, int n_roller);

/*
 * rr_profile_table_build - the contact table of a wheel profile on a
 * roller profile, both sides alike: rollerrig.contact_table(RigGeometry(
 * Profile(wheel), Profile(roller), ...), y_min, y_max, n), bit for bit
 * when t->y0 = y_min and t->dy = (y_max - y_min)/(n - 1).
 *   given:   wheel, roller the points; place; o the search options; t with
 *            y0, dy, n and data as for rr_contact_table_build, data holding
 *            data_len >= rr_contact_table_len(t->n) doubles; work of
 *            work_len >= rr_profile_table_work_len(...) doubles
 *   returns: the rows in t->data
 *   status:  0 OK; RR_ERR_NULL (wheel, roller, place, o, t or their point
 *            arrays NULL), RR_ERR_WORKSPACE (work or t->data NULL, or either
 *            buffer too short), RR_ERR_PARAM (a point count or end condition
 *            out of range, a radius not positive; y0, dy, n and the search
 *            options as rr_contact_table_build), RR_ERR_NONFINITE,
 *            RR_ERR_GEOMETRY (points not strictly increasing), RR_ERR_RANGE
 *            (rr_spline_fit), and the first error of the build with its
 *            shift in *bad_y (may be NULL; NaN when the error is not a row's)
 */
int rr_profile_table_build(const rr_profile_points *wheel, const rr_profile_points *roller,
                           const rr_profile_placement *place, const rr_search_opts *o,
                           rr_contact_table *t, long data_len, double *work, long work_len,
                           double *bad_y);

/* rr_profile_table_build_rows - the same, rows i0 <= i < i1 only (0 <= i0 <=
 * i1 <= t->n; else RR_ERR_PARAM): a caller builds a table in chunks, each
 * call fitting the profiles' splines again (a few microseconds). */
int rr_profile_table_build_rows(const rr_profile_points *wheel,
                                const rr_profile_points *roller,
                                const rr_profile_placement *place, const rr_search_opts *o,
                                rr_contact_table *t, long data_len, double *work,
                                long work_len, int i0, int i1, double *bad_y);

/* The rig's geometry: rollerrig.rig.GEOMETRY_KEYS (rig_default.toml), the
 * cone angle as an angle (rig.py: atan of wheelset.conicity). */
typedef struct {
    double wheel_radius;          /* r0 [m] */
    double roller_radius;         /* R0 [m] */
    double profile_half_width;    /* both profiles span +-this [m] */
    double cone_angle;            /* the wheel's cone angle alpha [rad] */
    double crown_radius;          /* the roller's crown radius [m] (0: a cylinder) */
    double contact_half_spacing;  /* wheel_y = roller_y [m] */
    double table_half_range;      /* the table spans +-this [m] */
    int table_rows;               /* 2 to RR_RIG_TABLE_MAX_ROWS */
} rr_rig_geometry;

/* Points of each profile of the rig's default table (rig.py's n = 121). */
#define RR_RIG_PROFILE_POINTS 121
/* Most rows of a rig table (rollerrig.geometry.MAX_ROWS). */
#define RR_RIG_TABLE_MAX_ROWS 1000000
/* Doubles of workspace rr_rig_table_build needs, for static storage. */
#define RR_RIG_TABLE_WORK_LEN (12L * RR_RIG_PROFILE_POINTS)

/* Doubles of table data for g (rr_contact_table_len(g->table_rows)); 0 if
 * g is NULL or its rows out of range. */
long rr_rig_table_data_len(const rr_rig_geometry *g);

/*
 * rr_rig_table_build - the rig's default contact table: the conical wheel
 * (rr_profile_conical, RR_RIG_PROFILE_POINTS points over +-half width) on
 * the crowned roller (rr_profile_crowned), not-a-knot splines, placed at
 * r0, R0 and the contact half spacing, the default search options, rows
 * at -reach + i 2 reach/(rows - 1): rollerrig.rig._rig_table's, bit for bit.
 *   given:   g; data of data_len >= rr_rig_table_data_len(g) doubles; work
 *            of work_len >= RR_RIG_TABLE_WORK_LEN doubles
 *   returns: *t (y0, dy, n, data = the caller's data)
 *   status:  0 OK; RR_ERR_NULL (g or t NULL), RR_ERR_WORKSPACE (data or
 *            work NULL or too short), RR_ERR_NONFINITE (a number of g),
 *            RR_ERR_PARAM (radii, half width, half range not positive,
 *            |alpha| >= pi/2, rows out of range; the profiles' range as
 *            rr_profile_conical), RR_ERR_GEOMETRY (the crown radius not
 *            beyond the half width), errors of rr_profile_table_build
 *            with the shift in *bad_y (may be NULL)
 */
int rr_rig_table_build(const rr_rig_geometry *g, double *data, long data_len, double *work,
                       long work_len, rr_contact_table *t, double *bad_y);

/* rr_rig_table_build_rows - the same, rows i0 <= i < i1 only (t set in full
 * at every call; rows out of [0, table_rows]: RR_ERR_PARAM). */
int rr_rig_table_build_rows(const rr_rig_geometry *g, double *data, long data_len,
                            double *work, long work_len, int i0, int i1, rr_contact_table *t,
                            double *bad_y);

#endif
