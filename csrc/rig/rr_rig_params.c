/*
 * rr_rig_params.c - the rig's parameters, scenario and outputs, declared
 * once (the tables and their accessors), and the rig's parameters derived
 * from a checked configuration (rr_rig_params_from and what goes with it:
 * the drives, the adhesion, the default creep-force method, the contact
 * table's radii, the geometry, the samples and the schedule).  Setting and
 * checking a configuration is rr_rig_config.c's.
 */
#include <math.h>
#include <string.h>
#include "util/rr_common.h"
#include "contact/rr_creep.h"
#include "rig/rr_rig_params.h"

#define OFF(member) ((long)offsetof(rr_rig_config, member))

/* ranges: lo, hi and whether each end is open */
#define RANGE(l, h, lopen, hopen) .lo = (l), .hi = (h), .lo_open = (lopen), .hi_open = (hopen)
#define ANY RANGE(-INFINITY, INFINITY, 0, 0)
#define POS RANGE(0.0, INFINITY, 1, 0)
#define NONNEG RANGE(0.0, INFINITY, 0, 0)

/* the rows by kind (by member: what a kind leaves out is 0 or NULL) */
#define REAL(nm, un, v, range, member, orig)                                             \
    {.name = nm, .unit = un, .type = RR_RIG_REAL, .value = v, .text = #v, range,         \
     .offset = OFF(member), .origin = orig}
#define INT(nm, v, l, h, member, orig)                                                   \
    {.name = nm, .unit = "-", .type = RR_RIG_INT, .value = v, .text = #v, .lo = l,       \
     .hi = h, .offset = OFF(member), .origin = orig}
#define FLAG(nm, v, txt, member, orig)                                                   \
    {.name = nm, .unit = "", .type = RR_RIG_FLAG, .value = v, .text = txt, .lo = 0,      \
     .hi = 1, .offset = OFF(member), .origin = orig}
#define CHOICE(nm, names, index, member, orig)                                           \
    {.name = nm, .unit = "", .type = RR_RIG_CHOICE, .value = index, .choices = names,    \
     .offset = OFF(member), .origin = orig}
#define LIST(nm, un, entries, txt, range, member, orig)                                  \
    {.name = nm, .unit = un, .type = RR_RIG_LIST, .text = txt, range, .list = entries,   \
     .nlist = RR_COUNTOF(entries), .offset = OFF(member), .origin = orig}
/* a list that may be empty, and is by default */
#define LIST0(nm, un, range, member, orig)                                               \
    {.name = nm, .unit = un, .type = RR_RIG_LIST, .text = "[]", range,                   \
     .offset = OFF(member), .origin = orig}
/* creep rows: type, default and its text, and the option of the creep-force
 * method the row sets (NULL: the row that chooses the method); rr_creep_opts
 * checks and applies them */
#define CREEP(nm, opt, un, ty, v, txt, orig)                                             \
    {.name = nm, .unit = un, .type = ty, .value = v, .text = txt, .lo = NAN, .hi = NAN,  \
     .offset = -1, .creep = 1, .option = opt, .origin = orig}

static const char *const drive_modes[] = {"braking", "traction", NULL};
static const int drive_senses[] = {RR_CREEPCTL_BRAKING, RR_CREEPCTL_TRACTION};
/* "points": a real profile whose points the caller gives (rr_rig_profiles,
 * rr_tables.h); rollerrig reads a built-in name or a file into them */
static const char *const wheel_profiles[] = {"conical", "points", NULL};
static const char *const roller_profiles[] = {"crowned cylinder", "points", NULL};
/* a right side of its own ("points"), or "" the left's mirrored */
static const char *const right_profiles[] = {"", "points", NULL};
static const char *const friction_laws[] = {"polach_falling", "coulomb", NULL};
static const char *const contact_patches[] = {"hertz", "nonhertz", NULL};
/* the non-Hertzian table: "" rollerrig builds it, "file" (in rollerrig: a path) */
static const char *const nonhertz_sources[] = {"", "file", NULL};
static const char *const ode_methods[] = {"trbdf2", "ros2", "lineuler", NULL};
static const char *const patch_sides[] = {"both", "left", "right", NULL};
static const int patch_bits[] = {3, 1, 2};
static const int ode_values[] = {RR_ODE_TRBDF2, RR_ODE_ROS2, RR_ODE_LINEULER};
/* the values beside their names (each names list ends in NULL) */
RR_STATIC_ASSERT(RR_COUNTOF(drive_senses) == RR_COUNTOF(drive_modes) - 1, one_sense_per_mode);
RR_STATIC_ASSERT(RR_COUNTOF(patch_bits) == RR_COUNTOF(patch_sides) - 1, one_bit_set_per_side);
RR_STATIC_ASSERT(RR_COUNTOF(ode_values) == RR_COUNTOF(ode_methods) - 1, one_value_per_method);

static const double default_targets[] = {0.04, 0.015, 0.02, 0.03};
static const double default_starts[] = {0.0, 5.0, 10.0, 15.0};

#define MAX_DURATION 1e5

static const rr_rig_param params[] = {
    /* [scenario] */
    REAL("scenario.roller_speed_m_s", "m/s", 5.0, ANY, roller_speed,
         "paper section 6: linear velocity of the roller 5 m/s"),
    LIST("scenario.targets", "-", default_targets, "[0.04, 0.015, 0.02, 0.03]",
         RANGE(0.0, 1.0, 0, 1), targets,
         "paper section 6: longitudinal creepage targets, in this order (magnitudes; braking)"),
    LIST("scenario.target_start_s", "s", default_starts, "[0.0, 5.0, 10.0, 15.0]", NONNEG,
         target_start,
         "inferred, not printed: equal 5 s intervals (Fig. 7/8 give no time axis in the "
         "text); see docs/parameters.md"),
    REAL("scenario.duration_s", "s", 20.0, RANGE(0.0, MAX_DURATION, 1, 0), duration,
         "inferred: four equal intervals of 5 s"),
    REAL("scenario.mu0", "-", 0.4, RANGE(0.0, RR_FRICTION_MAX, 1, 0), mu0,
         "paper section 6, Fig. 7/8: static adhesion (friction) coefficient 0.4 (Fig. 9, the "
         "dSpace run, says 0.5)"),
    CHOICE("scenario.drive_mode", drive_modes, 0, drive_mode,
           "paper section 6: braking torque applied to the wheelset, roller speed held "
           "constant"),
    REAL("scenario.control_sample_time_s", "s", 4.0e-3, RANGE(RR_RIG_MIN_T, RR_RIG_MAX_T, 0, 0), T,
         "paper section 6: the real-time model's step on dSpace DS1006 (250 Hz); sample time "
         "of both PI loops, encoders and the creepage controller (stable with these inertias: "
         "tests/test_rig.py)"),
    REAL("scenario.g_m_s2", "m/s^2", 9.81, NONNEG, g, "standard gravity"),
    FLAG("scenario.track", 0, "false", track,
         "choice: the rig (false); true: the same wheelset on tangent track, the rail a "
         "roller of radius RR_RIG_TRACK_RADIUS moving at the constant roller speed "
         "(csrc/rig/rr_rig.h; docs/lateral_dynamics.md)"),
    /* [wheelset] */
    REAL("wheelset.mass_kg", "kg", 14.504, POS, mass, "scaled: 1813 kg / 125 (phi^3)"),
    REAL("wheelset.spin_inertia_kg_m2", "kg m^2", 0.035840, POS, spin_inertia,
         "scaled: Iyy 112 kg m^2 / 3125 (phi^5)"),
    REAL("wheelset.yaw_inertia_kg_m2", "kg m^2", 0.35840, POS, yaw_inertia,
         "scaled: Izz 1120 kg m^2 / 3125 (phi^5)"),
    REAL("wheelset.wheel_radius_m", "m", 0.092, POS, wheel_radius, "scaled: r0 0.46 m / 5"),
    REAL("wheelset.contact_half_spacing_m", "m", 0.15, POS, contact_half_spacing,
         "scaled: 0.75 m / 5 (lateral position of each contact point, centred wheelset; the "
         "roller crowns sit under them)"),
    REAL("wheelset.axlebox_half_spacing_m", "m", 0.20, POS, axlebox_half_spacing,
         "scaled: 1.0 m / 5 (lateral position of the axle-box springs)"),
    CHOICE("wheelset.profile", wheel_profiles, 0, wheel_profile,
           "paper sections 3 and 4.1: conical wheel in the prototype; a real profile: "
           "\"points\" (the caller's, rr_rig_profiles; in rollerrig \"s1002\" or a "
           "SIMPACK, MiniProf or two-column file)"),
    CHOICE("wheelset.profile_right", right_profiles, 0, wheel_profile_right,
           "choice: the right wheel is the left's mirror image; \"points\" (in rollerrig: "
           "a built-in name or a file) where it differs, as the measured pair's"),
    REAL("wheelset.profile_scale", "-", 0.2, POS, wheel_scale,
         "scaled: a real wheel profile (full size, referenced to its taping line: y = 0, z "
         "= 0 there, at contact_half_spacing_m with radius wheel_radius_m) times 1/5, the "
         "rig's length factor; not applied to the cone, which conicity and "
         "profile_half_width_m give at the rig's size"),
    REAL("wheelset.conicity", "-", 0.05, NONNEG, conicity,
         "choice 1:20 (tan alpha; alpha = atan(conicity) is the contact angle of paper eq. "
         "1, 2 and 9): the classic conical tread for 1:20 rail inclination (the Italian RFI "
         "and French networks); same value as the library's geometry tests; 1:40 is the "
         "alternative (docs)"),
    REAL("wheelset.profile_half_width_m", "m", 0.015, POS, profile_half_width,
         "choice: +-15 mm tread, about the scaled 135 mm wheel width (27 mm) plus margin"),
    FLAG("wheelset.gyroscopic", 1, "true", gyroscopic,
         "physics: the spinning wheelset's gyroscopic moments (its own spin_inertia_kg_m2, "
         "not the drive's) in yaw and in the roll balance (docs/lateral_dynamics.md); false "
         "leaves them out, to show what they do"),
    /* [roller] */
    REAL("roller.radius_m", "m", 0.160, POS, roller_radius,
         "scaled: 0.8001 m / 5 (full-scale roller of the CONTACT roller-rig case); R/r0 = 1.74"),
    CHOICE("roller.profile", roller_profiles, 0, roller_profile,
           "choice: a conical wheel on a flat cylinder is a line contact; a crown gives the "
           "Hertz ellipse of paper section 4.2; a real profile: \"points\" (in rollerrig "
           "\"uic60\" or a file)"),
    CHOICE("roller.profile_right", right_profiles, 0, roller_profile_right,
           "choice: the right roller is the left's mirror image; \"points\" where it "
           "differs"),
    REAL("roller.profile_scale", "-", 0.2, POS, roller_scale,
         "scaled: a real roller profile (full size, referenced to its top, z = 0 there at "
         "radius_m, and its gauge point, y = 0) times 1/5; not applied to the crowned "
         "cylinder"),
    REAL("roller.gauge_m", "m", 0.287, POS, gauge,
         "scaled: standard gauge 1435 mm / 5 between the real rollers' gauge points (14 mm "
         "below the top at full size, EN 13848-1); with a wheel's taping line at "
         "wheelset.contact_half_spacing_m = (1360 / 2 + 70) mm / 5 the S1002 wheelset sits "
         "on UIC60 heads as on standard track; not used by the crowned cylinder"),
    REAL("roller.crown_radius_m", "m", 0.060, POS, crown_radius,
         "scaled: UIC60 rail-head crown R300 mm / 5 (gives a/b ~ 1 with the 1:20 cone)"),
    REAL("roller.inertia_kg_m2", "kg m^2", 1.5, POS, roller_inertia,
         "choice: both rollers (two solid steel discs R 0.16 m x 0.04 m: 2 x 0.323), shaft "
         "and roller motor with its coupling and flywheel; the paper's PI gains (Kp = 300) "
         "are stable at its 4 ms sample only if Kp T / J stays below about 1 (here 0.8): with "
         "0.7 kg m^2 the sampled loop rings (docs/parameters.md)"),
    /* [suspension] */
    REAL("suspension.kx_N_per_m", "N/m", 6.2782e6, NONNEG, kx,
         "scaled: 31.391 MN/m / 5 (phi), per axle box"),
    REAL("suspension.ky_N_per_m", "N/m", 7.768e5, NONNEG, ky,
         "scaled: 3.884 MN/m / 5, per axle box"),
    REAL("suspension.kz_N_per_m", "N/m", 2.44e5, NONNEG, kz,
         "scaled: 1.22 MN/m / 5, per axle box"),
    REAL("suspension.cx_N_s_per_m", "N s/m", 4117.0, NONNEG, cx,
         "choice: stiffness-proportional, cx = kx * (cz/kz) = 6.2782e6 * 6.557e-4 s (the "
         "benchmark has no primary x damper)"),
    REAL("suspension.cy_N_s_per_m", "N s/m", 509.4, NONNEG, cy,
         "choice: cy = ky * (cz/kz) = 7.768e5 * 6.557e-4 s (no primary y damper in the "
         "benchmark)"),
    REAL("suspension.cz_N_s_per_m", "N s/m", 160.0, NONNEG, cz,
         "scaled: 4 kN s/m / 25 (phi^2), per axle box"),
    REAL("suspension.preload_total_N", "N", 900.85, NONNEG, preload,
         "paper Fig. 7-9 captions: \"vertical spring load 900.85 N\"; read as F_SPRZ of eq. "
         "1, the sum over both axle boxes (eq. 1: Fz = 0.5 (F_SPRZ + M g) halves spring load "
         "and weight alike; 450.425 N per axle box)"),
    /* [contact] */
    REAL("contact.youngs_modulus_Pa", "Pa", 2.1e11, POS, E,
         "cited: steel, wheel and roller; G = E / (2 (1 + nu)) = 8.20e10 Pa as in CONTACT's "
         "reference cases (G 82000 N/mm^2)"),
    REAL("contact.poisson_ratio", "-", 0.28, RANGE(0.0, 0.5, 0, 0), nu,
         "cited: CONTACT reference cases (POISS 0.28), shared/reference"),
    CREEP("contact.creep_method", NULL, "", RR_RIG_CHOICE, 0, "\"fastsim\"",
          "paper section 4.4: Kalker's FASTSIM"),
    CREEP("contact.fastsim_nx", "nx", "-", RR_RIG_INT, 20, "20",
          "choice: elements along x per strip"),
    CREEP("contact.fastsim_ny", "ny", "-", RR_RIG_INT, 20, "20", "choice: strips across y"),
    CREEP("contact.fastsim_slip_speed", "slip_speed", "", RR_RIG_CHOICE, 0, "\"rigid\"",
          "choice: falling friction at each contact's rigid slip speed (Spiryagin et al. "
          "2013, CONTACT's FASTSIM), one mu per contact: 8x cheaper per rig step than at "
          "every element's own slip speed (\"local\")"),
    CHOICE("contact.friction_law", friction_laws, 0, friction_law,
           "paper section 6: dynamic friction from the static coefficient mu0; Polach 2005 "
           "law mu(w) = mu0 ((1 - A) exp(-B w) + A)"),
    REAL("contact.polach_A", "-", 0.4, RANGE(0.0, 1.0, 1, 0), polach_A,
         "cited: Polach 2005 dry set as commonly quoted "
         "(shared/reference/polach-parameters.csv: equals Open Rails' fit at mu0 = 0.55; "
         "table not read in the paper itself)"),
    REAL("contact.polach_B_s_per_m", "s/m", 0.6, RANGE(0.0, RR_FRICTION_MAX, 0, 0), polach_B,
         "cited: as polach_A (dry: B = 0.6 s/m)"),
    CREEP("contact.polach_kA", "kA", "-", RR_RIG_REAL, 1.0, "1.0",
          "cited: as polach_A (dry: kA = 1.0), for method = \"polach\""),
    CREEP("contact.polach_kS", "kS", "-", RR_RIG_REAL, 0.4, "0.4",
          "cited: as polach_A (dry: kS = 0.4), for method = \"polach\""),
    REAL("contact.min_rolling_speed_m_s", "m/s", 0.01, POS, vmin,
         "choice: creepage denominator max(|V|, 0.01 m/s) at standstill (paper section 4.4: "
         "\"special procedure\" for Vn = 0)"),
    /* the contact's patch (issue 24) */
    CHOICE("contact.patch", contact_patches, 0, contact_patch,
           "paper section 4.2: one Hertz ellipse at the rigid contact point; \"nonhertz\": "
           "the fast non-Hertzian, multi-patch contact from tables per lateral shift built "
           "by the exact theory (csrc/geometry/rr_nonhertz.h; contact.creep_method unused)"),
    CHOICE("contact.nonhertz_table", nonhertz_sources, 0, nonhertz_table,
           "choice: rollerrig builds the table from the rig's profiles, scale, gauge and "
           "material (about 30 s on 2 cores; kept in memory); in rollerrig a file's path "
           "(.npz of rollerrig.rig_nonhertz_table, checked against the rig's pair); read by "
           "rollerrig, not by the C rig (rr_rig_params_set_nonhertz)"),
    REAL("contact.nonhertz_half_range_m", "m", 0.0025, POS, nonhertz_half_range,
         "choice: the built table's rows cover y within +-2.5 mm (the measured pair's flange "
         "excursion reaches 2.05 mm); beyond, a wheel off its table stops the run"),
    REAL("contact.nonhertz_row_spacing_m", "m", 4.0e-5, POS, nonhertz_row_spacing,
         "scaled: 0.2 mm / 5, the full-size table's spacing (benchmarks/RESULTS.md, "
         "nonhertz), a quarter of it within 0.06 mm of the rigid contact point's jumps"),
    INT("contact.nonhertz_elements", 40, 8, 200, nonhertz_elements,
        "choice: elements across the exact theory's grids of a row (the full-size table's "
        "40; the linear coefficients from that grid, no Richardson step)"),
    /* [roller_drive] */
    REAL("roller_drive.kp_N_m_s_per_rad", "N m s/rad", 300.0, NONNEG, roller_kp,
         "paper section 6: Kp = 300 (roller); T_ref = Kp e + KI sum(e), eq. 10, e in rad/s, T "
         "in N m"),
    REAL("roller_drive.ki_N_m_s_per_rad", "N m s/rad", 2.0, NONNEG, roller_ki,
         "paper section 6: KI = 2 (roller); multiplies the plain sum of eq. 10 (continuous "
         "equivalent KI / T)"),
    REAL("roller_drive.torque_limit_N_m", "N m", 100.0, POS, roller_tmax,
         "choice: 1.5 x the steady braking torque mu0 * 2 * 521.6 N * 0.16 m = 66.8 N m"),
    REAL("roller_drive.lag_time_constant_s", "s", 1.0e-3, POS, roller_tau,
         "choice: first-order inverter + current loop + torque lag (paper section 5 low-pass "
         "filter); current loops of small servo drives close at ~1/18-1/6 of a 10-20 kHz "
         "sampling rate (cited: TI app. note SPRACO3), 1 ms is conservative"),
    INT("roller_drive.encoder_counts_per_rev", 8388608, 1, 2147483647.0, roller_counts,
        "choice: a 23-bit single-turn encoder, the class of current servo motors' serial "
        "encoders (20-24 bit); creepage quantum 2 pi/2^23/4 ms * r/V = 3.4e-6. With the "
        "18-bit (262144) default of CiA 402 drives the paper's eq. 14 fires on quantisation "
        "noise and holds 0.015 about 5 % low (tests/test_rig.py); sampled every "
        "scenario.control_sample_time_s, S(z) = (z - 1)/(T z), paper eq. 12"),
    /* [wheelset_drive] */
    REAL("wheelset_drive.kp_N_m_s_per_rad", "N m s/rad", 100.0, NONNEG, wheelset_kp,
         "paper section 6: Kp = 100 (wheelset)"),
    REAL("wheelset_drive.ki_N_m_s_per_rad", "N m s/rad", 2.0, NONNEG, wheelset_ki,
         "paper section 6: KI = 2 (wheelset), per-sample sum of eq. 10"),
    REAL("wheelset_drive.torque_limit_N_m", "N m", 60.0, POS, wheelset_tmax,
         "choice: 1.5 x the peak creep torque mu0 * 2 * 521.6 N * 0.092 m = 38.4 N m"),
    REAL("wheelset_drive.lag_time_constant_s", "s", 1.0e-3, POS, wheelset_tau,
         "choice: as roller_drive"),
    INT("wheelset_drive.encoder_counts_per_rev", 8388608, 1, 2147483647.0, wheelset_counts,
        "choice: as roller_drive"),
    REAL("wheelset_drive.drive_inertia_kg_m2", "kg m^2", 0.50, NONNEG, drive_inertia,
         "choice: braking motor, transmission and flywheel referred to the axle; chosen so "
         "that the paper's Kp = 100 gives Kp T / (J_wheelset + J_drive) = 0.75 at the 4 ms "
         "sample (as for the roller); 0.2 kg m^2 rings at 4 ms (docs/parameters.md)"),
    /* [creepage_controller] */
    REAL("creepage_controller.alpha", "-", 0.01, NONNEG, ctl_alpha,
         "paper eq. 13: K moves by alpha * d_xi per sample when d_xi >= 0"),
    REAL("creepage_controller.beta", "-", 0.002, NONNEG, ctl_beta,
         "paper eq. 14: K moves back by beta per sample when d_xi < 0"),
    REAL("creepage_controller.min_reference_speed_m_s", "m/s", 0.1, POS, ctl_vmin,
         "choice: floor of the roller surface speed in eq. 16's denominator (2 % of 5 m/s)"),
    /* [integration] */
    CHOICE("integration.method", ode_methods, 0, ode_method,
           "choice: TR-BDF2 (csrc/util/rr_ode.h), the method of the paper's ode23tb: "
           "L-stable, one matrix for both stages; with the settings below within 0.20 % / "
           "0.56 % (creepage / force) of an adaptive Radau run at the 4 ms step "
           "(tests/test_rig.py), where \"ros2\" is within 0.6 % / 1.9 % and \"lineuler\" "
           "within 4.9 % / 2.4 %"),
    INT("integration.newton_iterations", 1, 0, RR_ODE_MAX_NEWTON, newton_iterations,
        "choice: TR-BDF2's Newton iterations per stage (csrc/util/rr_ode.h); one sees the "
        "creep force's saturation knee (tests/test_rig.py)"),
    FLAG("integration.linear_first_stage", 1, "true", linear_first_stage,
         "choice: no iteration in the trapezoidal stage, only in the BDF2 stage, which gives "
         "the step's end"),
    FLAG("integration.newton_model", 1, "true", newton_model,
         "choice: the Newton iteration takes the creep forces' change over the step from "
         "Kalker's simplified theory (the cubic law, whose tangent is the Jacobian's), "
         "anchored at FASTSIM's forces at the step's start: one FASTSIM evaluation per step "
         "(csrc/util/rr_ode.h, rr_rig.c); within 0.20 % / 0.56 % of Radau"),
    INT("integration.substeps", 1, 1, 1000, substeps, "choice: plant steps per control sample"),
    REAL("integration.table_half_range_m", "m", 0.008, POS, table_half_range,
         "choice: contact table over +-8 mm of lateral shift"),
    INT("integration.table_rows", 161, 2, 100000, table_rows,
        "choice: 0.1 mm spacing; the cone on its crowned roller is smooth (linear "
        "interpolation within 1e-9 m of the direct search, tests/test_geometry.py style), "
        "and the build costs 0.1 s"),
    REAL("integration.profile_smoothing_m", "m", 0.002, NONNEG, profile_smoothing,
         "choice: profiles read from files are smoothed over this wavelength at full size "
         "(rollerrig.Profile smoothing; 0: interpolated): the measured MiniProf pair read raw "
         "has curvature jitter that makes the contact search reject shifts (B <= 0), "
         "RigGeometry.measured_pair's 2 mm; the built-in S1002 and UIC60 are not smoothed; "
         "read by the file readers (rollerrig), whose points the C rig takes"),
    /* [adhesion] */
    LIST0("adhesion.schedule_times_s", "s", NONNEG, schedule_t,
          "choice: no schedule, the contact section's law (scenario.mu0, contact.polach_A, "
          "polach_B) throughout; with points, mu0 (and A, B) linear between them, held "
          "before the first and after the last, two points at one time a step; taken at "
          "each sample's start"),
    LIST0("adhesion.schedule_mu0", "-", RANGE(0.0, RR_FRICTION_MAX, 1, 0), schedule_mu0,
          "choice: the static friction coefficient at each time of schedule_times_s"),
    LIST0("adhesion.schedule_polach_A", "-", RANGE(0.0, 1.0, 1, 0), schedule_A,
          "choice: the falling law's A at each time; empty: contact.polach_A"),
    LIST0("adhesion.schedule_polach_B_s_per_m", "s/m", RANGE(0.0, RR_FRICTION_MAX, 0, 0),
          schedule_B, "choice: the falling law's B at each time; empty: contact.polach_B"),
    REAL("adhesion.patch_length_m", "m", 0.0, NONNEG, patch_length,
         "choice: no patch; a contaminated sector of this length on the roller "
         "circumference (at roller.radius_m, at most its circumference) passes under the "
         "wheel once a revolution"),
    REAL("adhesion.patch_start_m", "m", 0.0, NONNEG, patch_start,
         "choice: where the patch begins: the arc R0 (theta_r + theta) from the roller's mark, "
         "which is at the top at t = 0; a roller turning forward brings the patch under a "
         "contact at the top after patch_start_m of travel"),
    REAL("adhesion.patch_mu0", "-", 0.1, RANGE(0.0, RR_FRICTION_MAX, 1, 0), patch_mu0,
         "choice: the wet or contaminated rail of slide-protection tests (mu from 0.4 to "
         "0.1 and back, issue 15)"),
    REAL("adhesion.patch_polach_A", "-", 0.4, RANGE(0.0, 1.0, 1, 0), patch_A,
         "cited: as contact.polach_A (Polach's A = 0.4 for dry and wet alike in Open Rails' "
         "fit, shared/reference/polach-parameters.csv)"),
    REAL("adhesion.patch_polach_B_s_per_m", "s/m", 0.2, RANGE(0.0, RR_FRICTION_MAX, 0, 0),
         patch_B, "cited: the set commonly quoted as Polach's wet one (B = 0.2 s/m; Open Rails' "
         "fit at mu0 = 0.3 and its floor, shared/reference/polach-parameters.csv)"),
    REAL("adhesion.patch_edge_m", "m", 0.002, POS, patch_edge,
         "choice: mu changes linearly over this length centred on each edge: about the "
         "contact's length 2a (1.5 mm here), which passes over an edge gradually"),
    CHOICE("adhesion.patch_rollers", patch_sides, 0, patch_rollers,
           "choice: the patch on both rollers (\"left\" or \"right\": one, which yaws the "
           "wheelset)"),
    /* [disturbance] */
    LIST0("disturbance.lateral_force_times_s", "s", NONNEG, lateral_t,
          "choice: no lateral force; with points, the force of lateral_force_N linear "
          "between them, held before the first and after the last, two points at one time a "
          "step; taken at each sample's start"),
    LIST0("disturbance.lateral_force_N", "N", ANY, lateral_f,
          "choice: the lateral force on the wheelset's centre (+ to the left, +Y) at each "
          "time of lateral_force_times_s: pushes a real profile's wheelset to flange contact "
          "(a flange excursion; against both axle boxes' suspension.ky, 1.55 kN per mm)"),
};
#define NPARAMS RR_COUNTOF(params)
/* a report holds a problem per row and per rule (rr_rig_config.c's
 * rr_rig_config_report: twelve at most) */
RR_STATIC_ASSERT(NPARAMS + 12 <= RR_RIG_MAX_PROBLEMS, a_report_holds_every_problem);

static const rr_rig_section sections[] = {
    {"scenario", ""},
    {"wheelset", ""},
    {"roller", "the two rollers are fixed together by a rigid joint (paper section 3): one "
               "shaft, one inertia"},
    {"suspension", "one set of three springs (x, y, z) per axle box, in parallel with dampers "
                   "(paper section 3); the resulting static normal load per wheel is "
                   "0.5 * (900.85 + 14.504 * 9.81) = 521.6 N (docs/parameters.md)"},
    {"contact", "normal loads from the wheelset's vertical and roll balance through the "
                "contact constraint (csrc/rig/rr_rig.h), the 3-D form of paper eq. 3-6; eq. "
                "1's contact stiffness k_HZ = 1e7 N/mm is not needed"},
    {"roller_drive", "gains, torques and inertias are referred to the roller axle (no gear "
                     "data published)"},
    {"wheelset_drive", "gains, torques and inertias are referred to the wheelset axle"},
    {"creepage_controller", "eq. 13-14 adapt the coefficient K of eq. 15, omega_ref = K "
                            "(r_r / r_w) omega_roller (the paper: K \"is to be adapted to "
                            "the desired value of the longitudinal creepage\"); alpha and "
                            "beta are therefore dimensionless, per sample "
                            "(csrc/rig/rr_control.h)"},
    {"integration", ""},
    {"adhesion", "friction that changes, as slide protection and traction control are tested "
                 "(csrc/rig/rr_rig.h, rr_rig_adhesion): a schedule in time and a contaminated "
                 "patch on the roller circumference; under contact.friction_law = \"coulomb\" "
                 "A and B are 1 and 0 there too"},
    {"disturbance", "a lateral force on the wheelset in time (csrc/rig/rr_rig.h, "
                    "rr_rig_lateral): flange excursions on real profiles"},
};

static const rr_rig_retired retired[] = {
    {"similarity", "it documented the similarity law the defaults were scaled by: "
                   "docs/parameters.md, Similarity law"},
    {"full_scale_reference", "it documented the full-scale values the defaults were scaled "
                             "from: docs/parameters.md, Full-scale reference"},
    {"scenario.initial_condition", "simulate's start argument sets it: 'rolling' or 'rest'"},
    {"wheelset.roll_inertia_kg_m2", "the wheelset's roll follows the contact constraint; the "
                                    "model has no roll dynamics"},
    {"wheelset.contact_angle_rad", "the cone's angle is atan(wheelset.conicity)"},
    {"roller.contact_half_spacing_m", "the crowns sit under wheelset.contact_half_spacing_m"},
    {"roller.width_m", "it entered the estimate of roller.inertia_kg_m2 only"},
    {"roller.rigidly_joined", "the model's two rollers are always on one shaft"},
    {"suspension.preload_per_axlebox_N", "it is half of suspension.preload_total_N, which "
                                         "acts"},
    {"contact.normal_model", "the model's normal loads are always the 'balance' ones"},
    {"roller_drive.gear_ratio", "gains, torques and inertias are referred to the roller "
                                "axle, ratio 1"},
    {"wheelset_drive.gear_ratio", "gains, torques and inertias are referred to the wheelset "
                                  "axle, ratio 1"},
};

/* the record's fields, from the one list that also makes their enum (rr_rig.h) */
#define REC(id, name, unit, meaning) {name, 1, -1, unit, meaning},
static const rr_rig_field records[] = {RR_RIG_RECORD(REC)};
RR_STATIC_ASSERT(RR_COUNTOF(records) == RR_REC_COUNT, records_complete);
RR_STATIC_ASSERT(RR_REC_STATUS == RR_REC_COUNT - 1, status_is_last);

/* the per-wheel block, from the list that also counts its fields and values */
#define WF(name, width, member, unit, meaning) \
    {name, width, (long)offsetof(rr_wheel_contact, member), unit, meaning},
static const rr_rig_field wheel_fields[] = {RR_WHEEL_FIELDS(WF)};
RR_STATIC_ASSERT(RR_COUNTOF(wheel_fields) == RR_WHEEL_NFIELDS, wheel_fields_complete);

#define COUNT(a) RR_COUNTOF(a)

int rr_rig_param_count(void)
{
    return NPARAMS;
}

const rr_rig_param *rr_rig_param_at(int i)
{
    return i >= 0 && i < NPARAMS ? &params[i] : NULL;
}

const rr_rig_param *rr_rig_param_find(const char *name)
{
    int i;
    if (!name)
        return NULL;
    for (i = 0; i < NPARAMS; i++)
        if (strcmp(params[i].name, name) == 0)
            return &params[i];
    return NULL;
}

int rr_rig_section_count(void)
{
    return COUNT(sections);
}

const rr_rig_section *rr_rig_section_at(int i)
{
    return i >= 0 && i < COUNT(sections) ? &sections[i] : NULL;
}

int rr_rig_retired_count(void)
{
    return COUNT(retired);
}

const rr_rig_retired *rr_rig_retired_at(int i)
{
    return i >= 0 && i < COUNT(retired) ? &retired[i] : NULL;
}

const rr_rig_field *rr_rig_record_field(int i)
{
    return i >= 0 && i < RR_REC_COUNT ? &records[i] : NULL;
}

const rr_rig_field *rr_wheel_field(int i)
{
    return i >= 0 && i < RR_WHEEL_NFIELDS ? &wheel_fields[i] : NULL;
}

void rr_wheel_store(const rr_wheel_contact *w, double *v, long stride)
{
    int i, j;
    long k = 0;
    if (!w || !v)
        return;
    for (i = 0; i < RR_WHEEL_NFIELDS; i++) {
        const double *src = (const double *)((const char *)w + wheel_fields[i].offset);
        for (j = 0; j < wheel_fields[i].width; j++, k++)
            v[k * stride] = src[j];
    }
}

int rr_rig_param_choice(const rr_rig_param *row, const char *choice)
{
    int i;
    if (!row || !choice || row->type != RR_RIG_CHOICE || !row->choices)
        return -1;
    for (i = 0; row->choices[i]; i++)
        if (strcmp(row->choices[i], choice) == 0)
            return i;
    return -1;
}

/* The drives of primary values: sample time, PI gains and limits, lags,
 * the wheelset's inertia with its drive's, eq. 13-16's settings (the
 * radii nominal: rr_rig_params_set_table calibrates them). */
static void drives_from(const rr_rig_config *c, rr_rig_params *p)
{
    p->T = c->T;
    p->Iyy = c->spin_inertia + c->drive_inertia;
    p->roller_inertia = c->roller_inertia;
    p->roller_pi.T = p->wheelset_pi.T = p->roller_enc.T = p->wheelset_enc.T = c->T;
    p->roller_pi.Kp = c->roller_kp;
    p->roller_pi.KI = c->roller_ki;
    p->roller_pi.Tmax = c->roller_tmax;
    p->wheelset_pi.Kp = c->wheelset_kp;
    p->wheelset_pi.KI = c->wheelset_ki;
    p->wheelset_pi.Tmax = c->wheelset_tmax;
    p->roller_tau = c->roller_tau;
    p->wheelset_tau = c->wheelset_tau;
    p->roller_enc.counts = c->roller_counts;
    p->wheelset_enc.counts = c->wheelset_counts;
    p->creepctl.r_w = c->wheel_radius;
    p->creepctl.r_r = c->roller_radius;
    p->creepctl.alpha = c->ctl_alpha;
    p->creepctl.beta = c->ctl_beta;
    p->creepctl.vmin = c->ctl_vmin;
    /* a mode out of range (rr_rig_config_speed_loops checks nothing, and the
     * report reads the loops of any config): no sense, which no loop reads */
    p->creepctl.sense = c->drive_mode >= 0 && c->drive_mode < RR_COUNTOF(drive_senses)
                      ? drive_senses[c->drive_mode] : 0;
}

int rr_rig_config_speed_loops(const rr_rig_config *c, rr_speed_loop loops[2])
{
    rr_rig_params p;
    if (!c || !loops)
        return RR_ERR_NULL;
    memset(&p, 0, sizeof p);
    drives_from(c, &p);
    rr_rig_speed_loops(&p, loops);
    return RR_OK;
}

int rr_rig_params_set_table(rr_rig_params *p, const rr_contact_table *t)
{
    rr_wheelset_pose pose;
    rr_contact_point cl, cr;
    int st;
    if (!p || !t)
        return RR_ERR_NULL;
    if ((st = rr_contact_table_lookup(t, 0.0, &pose, NULL, &cl, &cr)) < 0)
        return st;
    p->contact.table = t;
    p->creepctl.r_w = cl.r;
    p->creepctl.r_r = cl.R;
    return st;
}

/* A creep row's default as a name: its TOML text without the quotes. */
static void row_text(const rr_rig_param *row, char *buf, size_t len)
{
    size_t n = 0;
    const char *t = row->text;
    for (; *t && n + 1 < len; t++)
        if (*t != '"')
            buf[n++] = *t;
    buf[n] = '\0';
}

/* The rig's default creep-force method from the creep rows: the method of
 * contact.creep_method, then each row that declares an option (its option
 * column: contact.fastsim_nx sets nx, contact.polach_kS kS) where the method
 * has it; a choice's text is looked up among the option's names. */
static void creep_default(rr_creep_opts *o)
{
    char text[64];
    const rr_method_desc *d;
    int i, k;
    row_text(rr_rig_param_find("contact.creep_method"), text, sizeof text);
    rr_creep_opts_default(o, rr_method_find(text));
    d = rr_method_get(o->method);
    for (i = 0; d && i < rr_rig_param_count(); i++) {
        const rr_rig_param *row = rr_rig_param_at(i);
        if (!row->option)
            continue;
        for (k = 0; k < d->nopts; k++) {
            const rr_creep_option *op = &d->opts[k];
            double v = row->value;
            if (strcmp(op->name, row->option) != 0)
                continue;
            if (op->type == RR_OPT_CHOICE) {
                int j;
                row_text(row, text, sizeof text);
                for (j = 0; op->choices[j] && strcmp(op->choices[j], text) != 0; j++)
                    ;
                v = j;
            }
            rr_creep_opts_set(o, op->name, v);
        }
    }
}

/* The adhesion of checked primary values; base: the contact's law (its A, B
 * where the schedule has none; A = 1, B = 0 throughout under Coulomb). */
static void adhesion_from(const rr_rig_config *c, rr_friction base, rr_rig_adhesion *a)
{
    const int coulomb = strcmp(friction_laws[c->friction_law], "coulomb") == 0;
    int i;
    a->n = c->schedule_t.n;
    for (i = 0; i < a->n; i++) {
        a->t[i] = c->schedule_t.v[i];
        a->law[i].mu0 = c->schedule_mu0.v[i];
        a->law[i].A = coulomb || c->schedule_A.n == 0 ? base.A : c->schedule_A.v[i];
        a->law[i].B = coulomb || c->schedule_B.n == 0 ? base.B : c->schedule_B.v[i];
    }
    a->patch_start = c->patch_start;
    a->patch_length = c->patch_length;
    a->patch_edge = c->patch_edge;
    a->patch.mu0 = c->patch_mu0;
    a->patch.A = coulomb ? 1.0 : c->patch_A;
    a->patch.B = coulomb ? 0.0 : c->patch_B;
    a->patch_rollers = patch_bits[c->patch_rollers];
}

int rr_rig_params_from(const rr_rig_config *c, const rr_contact_table *t, rr_rig_params *p)
{
    int st, i;
    if (!p)
        return RR_ERR_NULL;
    memset(p, 0, sizeof *p);
    if ((st = rr_rig_config_check(c, NULL)) != RR_OK)
        return st;
    drives_from(c, p);
    p->mass = c->mass;
    p->Izz = c->yaw_inertia;
    p->axlebox_y = c->axlebox_half_spacing;
    p->kx = c->kx;
    p->ky = c->ky;
    p->kz = c->kz;
    p->cx = c->cx;
    p->cy = c->cy;
    p->cz = c->cz;
    p->preload = c->preload;
    p->g = c->g;
    p->contact.R0 = c->roller_radius;
    /* rollerrig.rig_contact.elastic_constants: the same doubles */
    p->contact.estar = c->E / (2.0 * (1.0 - c->nu * c->nu));
    p->contact.G = c->E / (2.0 * (1.0 + c->nu));
    p->contact.nu = c->nu;
    p->contact.friction.mu0 = c->mu0;
    if (strcmp(friction_laws[c->friction_law], "coulomb") == 0) {
        p->contact.friction.A = 1.0;
        p->contact.friction.B = 0.0;
    } else {
        p->contact.friction.A = c->polach_A;
        p->contact.friction.B = c->polach_B;
    }
    creep_default(&p->contact.creep);
    p->contact.vmin = c->vmin;
    p->contact.patch = c->contact_patch == 1 ? RR_RIG_PATCH_NONHERTZ : RR_RIG_PATCH_HERTZ;
    adhesion_from(c, p->contact.friction, &p->adhesion);
    p->lateral.n = c->lateral_t.n;
    for (i = 0; i < c->lateral_t.n; i++) {
        p->lateral.t[i] = c->lateral_t.v[i];
        p->lateral.f[i] = c->lateral_f.v[i];
    }
    p->nsub = c->substeps;
    p->method = ode_values[c->ode_method];
    p->newton_iters = c->newton_iterations;
    p->linear_tr = c->linear_first_stage;
    p->newton_model = c->newton_model;
    /* lateral dynamics (docs/lateral_dynamics.md) */
    p->gyro_inertia = c->gyroscopic ? c->spin_inertia : 0.0;
    p->track = c->track;
    /* the derived doubles: values each in range can overflow together */
    {
        const double derived[3] = {p->Iyy, p->contact.estar, p->contact.G};
        if (!rr_all_finite(derived, 3)) {
            memset(p, 0, sizeof *p);
            return RR_ERR_RANGE;
        }
    }
    return t ? rr_rig_params_set_table(p, t) : RR_OK;
}

int rr_rig_params_set_nonhertz(rr_rig_params *p, const rr_nh_table *left,
                               const rr_nh_table *right)
{
    if (!p || !left || !right)
        return RR_ERR_NULL;
    p->contact.nonhertz[0] = left;
    p->contact.nonhertz[1] = right;
    return RR_OK;
}

int rr_rig_params_default(rr_rig_params *p)
{
    rr_rig_config c;
    if (!p)
        return RR_ERR_NULL;
    rr_rig_config_default(&c);
    return rr_rig_params_from(&c, NULL, p);
}

int rr_rig_geometry_from(const rr_rig_config *c, rr_rig_geometry *g)
{
    if (!c || !g)
        return RR_ERR_NULL;
    memset(g, 0, sizeof *g);      /* its padding too: callers compare it byte for byte */
    g->wheel_radius = c->wheel_radius;
    g->roller_radius = c->roller_radius;
    g->profile_half_width = c->profile_half_width;
    g->cone_angle = atan(c->conicity);
    g->crown_radius = c->crown_radius;
    g->contact_half_spacing = c->contact_half_spacing;
    g->table_half_range = c->table_half_range;
    g->table_rows = c->table_rows;
    return RR_OK;
}

int rr_rig_profiles_from(const rr_rig_config *c, rr_rig_profiles *pr)
{
    if (!c || !pr)
        return RR_ERR_NULL;
    memset(pr, 0, sizeof *pr);
    pr->wheel.n = c->wheel_profile == 1 ? -1 : 0;
    pr->roller.n = c->roller_profile == 1 ? -1 : 0;
    pr->wheel_right.n = c->wheel_profile_right == 1 ? -1 : 0;
    pr->roller_right.n = c->roller_profile_right == 1 ? -1 : 0;
    pr->wheel_scale = c->wheel_scale;
    pr->roller_scale = c->roller_scale;
    pr->gauge = c->gauge;
    return RR_OK;
}

long rr_rig_samples(const rr_rig_config *c)
{
    double n;
    if (!c || !(c->T > 0.0) || !isfinite(c->duration))
        return 0;
    n = floor(c->duration / c->T + 0.5);
    return n < 1.0 ? 1 : n > 1e15 ? 0 : (long)n;
}

int rr_rig_schedule(const rr_rig_config *c, long k, double *roller_ref, double *xi_ref)
{
    const double t = (double)k * (c ? c->T : 0.0);
    int i, idx = -1;
    if (!c || !roller_ref || !xi_ref)
        return RR_ERR_NULL;
    if (k < 0)
        return RR_ERR_PARAM;
    for (i = 0; i < c->target_start.n && i < RR_RIG_MAX_LIST; i++)
        if (c->target_start.v[i] <= t)
            idx = i;
    *roller_ref = c->roller_speed / c->roller_radius;
    *xi_ref = idx >= 0 && idx < c->targets.n ? c->targets.v[idx] : NAN;
    if (!isfinite(*roller_ref)) {
        /* a radius so small (each value in its range) that the speed over
         * it overflows */
        *roller_ref = *xi_ref = NAN;
        return RR_ERR_RANGE;
    }
    return RR_OK;
}
