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

/*
 * The rig's profiles as points: real profiles (S1002, UIC60, measured
 * ones) where the rig's parameters say "points" (wheelset.profile,
 * roller.profile and their _right rows, rr_rig_params.h).  The points are
 * the caller's (not copied, not owned), at full scale in
 * rollerrig.profiles' convention (y to the field side, z down) and
 * referenced to the rig's nominal geometry:
 *   wheel:  y = 0, z = 0 at the taping line (the nominal rolling circle),
 *           which sits at the geometry's contact half spacing with radius
 *           wheel_radius;
 *   roller: y = 0 at its gauge point, z = 0 at its top, which has radius
 *           roller_radius; the gauge points sit at +-gauge/2.
 * The build scales each by its scale (rig size / full size: 0.2 on the 1/5
 * rig).  A slot with n = 0 is not given: the left wheel is then the
 * geometry's cone, the left roller its crowned cylinder (placed as
 * rr_rig_table_build places them), and a right slot the left's (mirrored
 * in the rig, as every right side).
 */
typedef struct {
    rr_profile_points wheel, roller;              /* the left side's */
    rr_profile_points wheel_right, roller_right;  /* the right side's, in its own
                                                     coordinates (field side +y) */
    double wheel_scale, roller_scale;             /* rig / full size, > 0 */
    double gauge;                                 /* between the rollers' gauge points [m]
                                                     (rig size; read with a roller given) */
} rr_rig_profiles;

/* Which profile of an rr_rig_profiles (rr_rig_profiles_check's *which). */
enum rr_rig_profile_slot {
    RR_RIG_WHEEL = 0, RR_RIG_ROLLER, RR_RIG_WHEEL_RIGHT, RR_RIG_ROLLER_RIGHT
};

/* Most lateral distance between neighbouring points of a given profile, as
 * given (full size): wider, the spline would invent the surface under a
 * contact patch (a measured or standard profile has points 0.1-0.7 mm
 * apart; a patch is about 10 mm wide). */
#define RR_PROFILE_MAX_GAP 5e-3   /* [m] */

/*
 * rr_rig_profiles_check - the given profiles' points as the build needs
 * them: counts in [RR_SPLINE_MIN_POINTS, RR_SPLINE_MAX_POINTS] (or 0), end
 * conditions, arrays not NULL, numbers finite, y strictly increasing (a
 * vertical or overhanging segment is not), neighbours at most
 * RR_PROFILE_MAX_GAP apart, coordinates within RR_PROFILE_MAX_COORD and a
 * lateral span of at least RR_PROFILE_MIN_WIDTH (millimetres given as
 * metres, or metres as millimetres), scales and a given roller's gauge
 * finite and positive.
 *   returns: *which (enum rr_rig_profile_slot, -1 for the scales or the
 *            gauge) and *point (the first point at fault, -1 for the whole
 *            profile) of the first problem; each may be NULL
 *   status:  0 OK; RR_ERR_NULL (pr NULL, an array of a given profile NULL,
 *            a count of -1: said to be given by rr_rig_profiles_from, and not),
 *            RR_ERR_PARAM (a count, an end condition, a scale, the gauge,
 *            a coordinate or a span out of range), RR_ERR_NONFINITE,
 *            RR_ERR_GEOMETRY (y not increasing, or a gap)
 */
int rr_rig_profiles_check(const rr_rig_profiles *pr, int *which, int *point);

/* Doubles of workspace rr_rig_table_build_profiles needs for pr (4 per point
 * of each profile it builds, the analytic ones RR_RIG_PROFILE_POINTS each,
 * and 4 per point of the longest); 0 if pr is NULL or a count is out of
 * range. */
long rr_rig_profiles_work_len(const rr_rig_profiles *pr);

/*
 * rr_rig_table_build_profiles - the rig's contact table on the profiles pr
 * (rr_rig_table_build where every slot of pr has n = 0, bit for bit): the
 * given ones scaled and placed as above, the others as rr_rig_table_build
 * makes them; rows as rr_rig_table_build's.
 *   given:   g, pr (checked by rr_rig_profiles_check); data of data_len >=
 *            rr_rig_table_data_len(g) doubles; work of work_len >=
 *            rr_rig_profiles_work_len(pr) doubles
 *   status:  as rr_rig_table_build, and rr_rig_profiles_check's; a shift
 *            where the profiles do not touch (a wheel off its roller, or
 *            conformal: no Hertz ellipse) is RR_ERR_GEOMETRY with the
 *            shift in *bad_y
 */
int rr_rig_table_build_profiles(const rr_rig_geometry *g, const rr_rig_profiles *pr,
                                double *data, long data_len, double *work, long work_len,
                                rr_contact_table *t, double *bad_y);

/* rr_rig_table_build_profiles_rows - the same, rows i0 <= i < i1 only. */
int rr_rig_table_build_profiles_rows(const rr_rig_geometry *g, const rr_rig_profiles *pr,
                                     double *data, long data_len, double *work, long work_len,
                                     int i0, int i1, rr_contact_table *t, double *bad_y);

#endif
