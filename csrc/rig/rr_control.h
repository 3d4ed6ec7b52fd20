/*
 * rr_control.h - the discrete-time drive and control elements of the rig:
 * PI speed controller with torque limiter, first-order lag of inverter and
 * drive, incremental encoder with its speed estimate, creepage controller.
 *
 * Reference: Bosso, Gugliotta, Somà, Spiryagin, "Model of scaled test rig
 * for real time applications", section 5, eq. (10)-(16).
 *
 * Each element is a pair: a const parameter struct and a state struct, both
 * owned by the caller.  *_check validates the parameters, *_init puts the
 * state at rest, *_reset at a given operating point (the creepage
 * controller has only *_init, which takes its operating point), *_update
 * advances it by one sample (the lag: by any step h).  The sampled-data arrangement
 * (domain notes section 6): the controllers and the encoder are updated
 * once per sample T, their outputs are held until the next sample, and the
 * plant (with the lag) is integrated in between.
 *
 * Errors: parameters out of range give RR_ERR_PARAM (rates, gains, limits,
 * counts, time constants), RR_ERR_GEOMETRY (radii) or RR_ERR_SPEED (the
 * creepage controller's minimum speed); NaN or infinite inputs give
 * RR_ERR_NONFINITE.  On an error in *_update the output is NaN and the
 * state is left as it was, so that one bad sample does not poison it; on an
 * error in *_init / *_reset the state is set to NaN, so that every later
 * update fails with RR_ERR_NONFINITE instead of running on garbage.
 * Parameters are re-checked at every update (a few comparisons): the caller
 * may change them between samples, e.g. a speed-dependent torque limit.
 */
#ifndef RR_CONTROL_H
#define RR_CONTROL_H

/* ---- PI speed controller (eq. 10-11) with torque limiter ------------------ */

/*
 * Reading of eq. (10)-(11): T_ref(n) = Kp e(n) + KI sum_{j=0..n} e(j),
 * G(z) = Kp + KI / (1 - z^-1).  KI multiplies the plain sum of the speed
 * errors, with no sample time in it: KI is the integral gain per sample, in
 * the same unit as Kp, and the equivalent continuous integral gain is
 * KI / T [N m/rad].  The sum includes the current error e(n) (backward
 * rectangle, 1/(1 - z^-1) rather than z^-1/(1 - z^-1)).  This reading makes
 * the paper's gains sensible: Kp = 100..300, KI = 2 put the PI zero at
 * KI/(Kp T) = 6.7..20 rad/s for T = 1 ms, whereas KI = 2 as a continuous
 * gain would put it at 0.007..0.02 rad/s, practically no integral action.  Changing T
 * therefore changes the controller unless KI is scaled with T.
 */
typedef struct {
    double T;     /* sample time [s], > 0: the update is to be called every T */
    double Kp;    /* proportional gain [N m s/rad], >= 0 */
    double KI;    /* integral gain per sample [N m s/rad], >= 0 (continuous: KI/T) */
    double Tmax;  /* torque limit [N m], > 0: the output stays in [-Tmax, Tmax] */
} rr_pi_params;

typedef struct {
    double integral; /* integral term KI sum e(j) [N m], kept within [-Tmax, Tmax] */
    double u;      /* last limited output, the held reference torque T_ref* [N m] */
    int saturated; /* +1 / -1 if the limiter held at the last update, else 0 */
} rr_pi_state;

/*
 * rr_pi_check - validate PI parameters.
 *   given:   p
 *   returns: nothing else
 *   status:  0 OK; RR_ERR_NONFINITE (a field NaN or infinite), RR_ERR_PARAM
 *            (T <= 0, Kp < 0, KI < 0, Tmax <= 0)
 *   reference: eq. (10)-(11)
 */
int rr_pi_check(const rr_pi_params *p);

/*
 * rr_pi_init - PI at rest: integral 0, output 0.
 *   given:   p
 *   returns: *s
 *   status:  as rr_pi_check; on error *s is NaN
 */
int rr_pi_init(const rr_pi_params *p, rr_pi_state *s);

/*
 * rr_pi_reset - PI at an operating point, for a bumpless start.
 *   given:   p; torque0 [N m], the torque the drive is delivering now
 *   returns: *s with integral = u = torque0 clipped to [-Tmax, Tmax]: with zero
 *            speed error the first output is torque0, so a simulation can
 *            start in a steady state without a torque step
 *   status:  as rr_pi_check, RR_ERR_NONFINITE (torque0); on error *s is NaN
 */
int rr_pi_reset(const rr_pi_params *p, rr_pi_state *s, double torque0);

/*
 * rr_pi_update - one sample of the PI: eq. (10) in positional form, limited.
 *   given:   p; s from rr_pi_init/reset/update; w_ref, w_m reference and
 *            measured angular speed [rad/s]
 *   returns: *torque, the limited reference torque T_ref* in [-Tmax, Tmax]
 *            [N m], to be held until the next sample; *s advanced
 *   status:  0 OK; errors as rr_pi_check, RR_ERR_NONFINITE (w_ref, w_m or
 *            the state); on error *torque is NaN and *s is unchanged
 *   Positional form (output = Kp e + integral) rather than the velocity form
 *   (output += Kp (e(n) - e(n-1)) + KI e(n)): it is eq. (10) as written, it
 *   keeps the integral as an explicit state that the anti-windup can act on
 *   and that rr_pi_reset can preset, and it does not lose the proportional
 *   part's history when the output is clipped (the velocity form does).
 *   Anti-windup by conditional integration (clamping), which needs no extra
 *   tuning parameter unlike back-calculation: with e = w_ref - w_m the
 *   integral advances by KI e only as far as the output stays within the
 *   limit; once Kp e + integral reaches the limit in the direction of e it stops.
 *   Then |integral| <= Tmax always, and after any saturation the output leaves the
 *   limit at the first sample at which the error changes sign (if Kp > 0
 *   or KI > 0).  Integration in the direction away from the limit is never
 *   blocked.  The integral is first clipped to the current [-Tmax, Tmax], so a
 *   lowered limit takes effect at once.
 *   Limiter placement: the paper clips after the lag (T_in*); we clip the
 *   reference torque here, where the integrator can see it.  A first-order
 *   lag from a state inside the limits stays inside them (its output is a
 *   convex combination of held inputs), so the drive torque obeys the same
 *   bound; only transients that the paper would clip are slower.
 *   reference: eq. (10)-(11); K. J. Astrom, T. Hagglund, Advanced PID
 *   Control, ISA 2006, ch. 3 (integrator windup, conditional integration)
 */
int rr_pi_update(const rr_pi_params *p, rr_pi_state *s, double w_ref, double w_m,
                 double *torque);

/* ---- a drive's sampled speed loop: its stability ------------------------- */

/*
 * A drive's speed loop as the rig closes it once per sample T: the encoder's
 * estimate (eq. 12: the mean speed over the last sample), the PI (eq.
 * 10-11, the integral including the present error) whose output is held
 * over the sample through the drive's first-order lag tau onto an inertia J
 * turning freely, and around it eq. 13's adaptation of the speed reference:
 * linearised, the reference moves by -alpha times the measured speed's
 * change per sample, before the PI reads it (K changes by s alpha dxi and
 * w_ref = K (r_r/r_w) w_roller, so the radii and speeds cancel); alpha = 0:
 * a fixed reference.  The limiter is left out (small signals), and so is
 * the contact: saturated, as under creepage control, its force barely
 * changes with the speed (the falling friction's slope, 1 % of the gains),
 * so each drive turns its own inertia alone.
 * The closed loop is linear with five states (speed, drive torque, angle
 * increment over the last sample, integral, reference), discretised
 * exactly (zero-order hold), in units that depend only on Kp T / J,
 * KI T / J, T / tau and alpha.
 */
typedef struct {
    rr_pi_params pi;   /* T, Kp, KI (Tmax is not used) */
    double J;          /* inertia the drive turns [kg m^2], > 0 */
    double tau;        /* drive lag [s], > 0 */
    double alpha;      /* eq. 13's gain per sample [-], >= 0; 0: no outer loop */
} rr_speed_loop;

/*
 * rr_speed_loop_radius - the spectral radius of the closed loop's transition
 * matrix A (its largest pole's |z|), as lim ||A^m||^(1/m) by 60 normalised
 * squarings (m = 2^60): robust where the poles crowd near z = 1 at a short
 * sample, which defeats the characteristic polynomial's roots.
 *   given:   l
 *   returns: *rho [-] (a pole at 1, as with zero gains, is a held value:
 *            rho = 1, not above it); +inf where a number of the loop
 *            overflows (gains beyond any stable value)
 *   status:  0; rr_pi_check's status; RR_ERR_NONFINITE (J, tau or alpha);
 *            RR_ERR_PARAM (J <= 0, tau <= 0, alpha < 0); RR_ERR_NULL.  On
 *            error *rho is NaN.
 */
int rr_speed_loop_radius(const rr_speed_loop *l, double *rho);

/* The loop is taken as stable where rho <= 1 + RR_SPEED_LOOP_SLACK: a pole
 * on the unit circle (a held value) within the radius' rounding. */
#define RR_SPEED_LOOP_SLACK 1e-9

/*
 * rr_speed_loop_check - RR_OK if the loop is stable at its sample time
 * pi.T (rr_speed_loop_radius <= 1 + RR_SPEED_LOOP_SLACK), RR_ERR_PARAM if
 * it is not (a controller setting out of range: gains, inertia, lag and
 * sample time do not go together), or rr_speed_loop_radius's error.
 */
int rr_speed_loop_check(const rr_speed_loop *l);

/*
 * rr_speed_loop_range - the sample times in [Tlo, Thi] at which the loop
 * (its gains, inertia, lag and alpha; pi.T is not used) is stable: *lo, *hi
 * the least and the greatest, each from a scan at 40 points a decade
 * refined by bisection to 1e-9 relative; both NaN if none is (status
 * RR_ERR_PARAM).  The times between them are not checked: the stable ones
 * form one interval (too short a sample puts the integral gain per second,
 * KI / T, beyond what the lag's phase allows; too long a one the sample's
 * delay beyond what Kp allows), as in 3000 random loops of 2000 times each
 * (gains, inertias, lags and alpha over 4 to 6 decades).
 *   status:  0; RR_ERR_PARAM (no stable time, or not 0 < Tlo <= Thi);
 *            RR_ERR_NONFINITE (Tlo, Thi); rr_speed_loop_radius's errors;
 *            RR_ERR_NULL.  On error *lo, *hi are NaN.
 */
int rr_speed_loop_range(const rr_speed_loop *l, double Tlo, double Thi, double *lo,
                        double *hi);

/* ---- first-order lag: inverter and traction drive ------------------------- */

typedef struct {
    double tau;  /* time constant [s], >= 0; 0 = pass-through (ideal drive) */
} rr_lag_params;

typedef struct {
    double y;    /* output, the drive torque T_in [N m] (any unit: the lag is linear) */
} rr_lag_state;

/*
 * rr_lag_check - validate lag parameters.
 *   status:  0 OK; RR_ERR_NONFINITE (tau NaN or infinite), RR_ERR_PARAM (tau < 0)
 *   reference: section 5, the low-pass filter of inverter and drive
 */
int rr_lag_check(const rr_lag_params *p);

/*
 * rr_lag_init - lag at rest: y = 0.
 *   returns: *s;  status: as rr_lag_check; on error *s is NaN
 */
int rr_lag_init(const rr_lag_params *p, rr_lag_state *s);

/*
 * rr_lag_reset - lag at output y0 (e.g. the steady torque at the start).
 *   returns: *s;  status: as rr_lag_check, RR_ERR_NONFINITE (y0); on error *s is NaN
 */
int rr_lag_reset(const rr_lag_params *p, rr_lag_state *s, double y0);

/*
 * rr_lag_update - advance y' = (u - y)/tau over a step h with u held.
 *   given:   p; s; u the input held over the step (T_ref*) [N m]; h >= 0 [s]
 *   returns: *y, the output at the end of the step [N m]; *s advanced
 *   status:  0 OK; errors as rr_lag_check, RR_ERR_NONFINITE (u, h or the
 *            state), RR_ERR_PARAM (h < 0); on error *y is NaN, *s unchanged
 *   Exact for a held input (zero-order hold): y += (1 - exp(-h/tau))(u - y),
 *   with 1 - exp(-h/tau) = -expm1(-h/tau) so that steps h << tau keep their
 *   precision.  Because the solution is exact, any split of an interval
 *   into sub-steps gives the same result up to rounding: the plant
 *   integrator may sub-step freely.  tau = 0 gives y = u; h = 0 leaves y.
 *   reference: section 5 (the low-pass filter); the discretisation is the
 *   zero-order-hold equivalent of a first-order system, which is exact
 */
int rr_lag_update(const rr_lag_params *p, rr_lag_state *s, double u, double h, double *y);

/* ---- incremental encoder and speed estimate (eq. 12) ---------------------- */

typedef struct {
    double T;    /* sample time [s], > 0 */
    int counts;  /* counts per revolution, >= 1 */
} rr_encoder_params;

typedef struct {
    double count;   /* counter at the last sample (an integer, exact in a double) */
    double theta_q; /* quantised angle at the last sample, count 2 pi/counts [rad] */
    double w;       /* last speed estimate [rad/s] */
    int primed;     /* 1 once a sample has been taken, so a difference exists */
} rr_encoder_state;

/*
 * rr_encoder_check - validate encoder parameters.
 *   status:  0 OK; RR_ERR_NONFINITE (T NaN or infinite), RR_ERR_PARAM (T <= 0,
 *            counts < 1)
 *   reference: eq. (12)
 */
int rr_encoder_check(const rr_encoder_params *p);

/*
 * rr_encoder_init - encoder with no sample yet; reports speed 0 at its first
 * sample (rr_encoder_reset with w0 = 0: the rig starts at rest).
 *   returns: *s;  status: as rr_encoder_check; on error *s is NaN
 */
int rr_encoder_init(const rr_encoder_params *p, rr_encoder_state *s);

/*
 * rr_encoder_reset - encoder with no sample yet that reports w0 at its
 * first sample.
 *   given:   p; w0 [rad/s], the speed known at the start (the simulation's
 *            initial condition)
 *   returns: *s
 *   status:  as rr_encoder_check, RR_ERR_NONFINITE (w0); on error *s is NaN
 *   First sample: a difference needs two positions, so the first update only
 *   latches the counter and reports w0.  Reporting 0 there when the shaft is
 *   already turning would hand the speed controller an error of the full
 *   speed for one sample, i.e. a torque kick of Kp w; the caller knows the
 *   initial speed, so it says it here.
 */
int rr_encoder_reset(const rr_encoder_params *p, rr_encoder_state *s, double w0);

/*
 * rr_encoder_update - one sample: quantise the angle, estimate the speed.
 *   given:   p; s; theta the shaft's unwrapped angle of rotation [rad] (the
 *            plant's integrated angle, not reduced modulo 2 pi: an
 *            incremental encoder counts edges)
 *   returns: *w the speed estimate [rad/s]; *s advanced (s->theta_q is the
 *            quantised position)
 *   status:  0 OK; errors as rr_encoder_check, RR_ERR_NONFINITE (theta or
 *            the state); on error *w is NaN and *s unchanged
 *   count = floor(theta counts / (2 pi)), the number of edges passed (floor,
 *   not rounding, as a counter does; exact while |count| < 2^53);
 *   w = (count_k - count_{k-1}) (2 pi/counts) / T, i.e. S(z) = (z-1)/(T z)
 *   applied to the quantised position.  At constant speed with a whole
 *   number m of counts per sample the estimate is exactly m 2 pi/(counts T)
 *   from the second sample on; on a speed ramp it is the mean speed over
 *   the last sample, i.e. the speed half a sample ago (a lag of T/2); the
 *   quantisation error is below one count per sample, 2 pi/(counts T).
 *   reference: eq. (12), after Ellis (2002) and Vukosavic (2007) as cited
 *   by the paper
 */
int rr_encoder_update(const rr_encoder_params *p, rr_encoder_state *s, double theta,
                      double *w);

/* ---- creepage controller (eq. 13-16) --------------------------------------- */

/*
 * Reading of eq. (13)-(15).  Eq. (15) sets the wheelset's speed reference
 * from the roller's speed, w_ref = K (r_r/r_w) w_roller, "where K is a
 * coefficient (0 <= K <= 1), which is to be adapted to the desired value of
 * the longitudinal creepage"; eq. (13)-(14) are that adaptation.  They are
 * applied here to the dimensionless K, not to w_ref in rad/s: with the
 * paper's alpha = 0.01 and beta = 0.002 a step on w_ref in rad/s would be
 * alpha dxi ~ 4e-4 rad/s per sample on a wheel turning at ~54 rad/s (5 m/s),
 * a time constant of ~5000 samples, and a recovery step of 4e-5 in
 * creepage, too small to do anything; on K, alpha = 0.01 is a proportional
 * gain on the creepage error with a time constant of 100 samples and beta
 * = 0.002 a recovery step of 0.002 in creepage per sample: sensible values.
 * The reference then follows the measured roller speed at every sample.
 *
 * Sign convention.  Angular speeds are taken each in its own rolling sense,
 * so that at free rolling w_wheelset r_w = w_roller r_r (wheel and roller
 * physically turn in opposite directions; the rig passes both as positive
 * when it runs forward).  Eq. (16), xi = (w_wheelset r_w - w_roller r_r) /
 * (w_roller r_r), is positive when the wheel is faster (traction).  The
 * paper brakes the wheelset and still gives positive targets (0.04, 0.015,
 * ...): they are creepage magnitudes in the sense of the manoeuvre.  So the
 * controller has a sense s = +1 (traction) or -1 (braking) and works with
 *     xi_est = s (w_wheelset r_w - w_roller r_r) / (w_roller r_r),
 * braking: xi_est = (w_roller r_r - w_wheelset r_w)/(w_roller r_r) > 0 when
 * the wheel is slower than the roller.  A wheel at the reference of eq. (15)
 * has the kinematic creepage xi = s (K - 1), i.e. K = 1 + s xi (braking
 * K = 1 - xi, traction K = 1 + xi), whatever the direction of travel: w_ref
 * carries w_roller's sign, so running backward mirrors the reference with
 * no extra factor.  With dxi = xi_ref - xi_est, eq. (13)-(14) become
 *     dxi >= 0:  K += s alpha dxi   (too little creepage: move the wheel
 *                                    away from the roller's speed)
 *     dxi <  0:  K -= s beta        (too much: recover with a fixed step
 *                                    toward the roller's speed)
 *     w_ref = K (r_r/r_w) w_roller                                (15)
 * which for traction is eq. (13)-(14) literally.  K is kept >= 0 (the
 * wheel is not driven backward against the roller; braking K = 0 is the
 * locked wheel, xi = 1); it is not capped at 1, since traction needs K > 1.
 * The asymmetry is the paper's: creepage beyond the target risks passing
 * the adhesion peak into macro-slip, so it is undone fast; below the target
 * the approach is proportional and slow.  For braking the recovery step
 * raises the wheelset speed (applying eq. (14) literally with a negative
 * braking target would lower it, driving the wheel toward lock).  With an
 * ideal speed loop (the wheel at w_ref by the next sample) and a steady
 * roller, xi_est = s (K - 1): below the target the deficit contracts by the
 * factor (1 - alpha) per sample, monotonically if alpha <= 1; above it each
 * recovery step lowers the creepage by exactly beta.  w_roller r_r is never
 * smaller in magnitude than vmin in the denominator (eq. (16) requires
 * w_roller != 0); below vmin the estimate is s (K - 1) |w_roller r_r|/vmin.
 */
enum rr_creepctl_sense {
    RR_CREEPCTL_TRACTION = 1,
    RR_CREEPCTL_BRAKING = -1
};

typedef struct {
    double r_w;    /* wheel rolling radius [m], > 0 */
    double r_r;    /* roller rolling radius [m], > 0 */
    double alpha;  /* eq. (13) gain on K [per unit creepage error, per sample,
                      dimensionless], >= 0: K moves by s alpha dxi */
    double beta;   /* eq. (14) recovery step on K [per sample, dimensionless],
                      >= 0: the creepage drops by beta per sample */
    double vmin;   /* smallest roller surface speed |w_roller r_r| used as the
                      creepage's denominator [m/s], > 0 */
    int sense;     /* RR_CREEPCTL_TRACTION or RR_CREEPCTL_BRAKING */
} rr_creepctl_params;

typedef struct {
    double K;       /* eq. (15) coefficient [-], >= 0, adapted by eq. (13)-(14);
                       1 + sense xi for the kinematic creepage xi */
    double w_ref;   /* wheelset speed reference K (r_r/r_w) w_roller [rad/s] of
                       the last init/update, for the wheelset's PI */
    double xi_est;  /* creepage estimated at the last update, in the sense [-] */
    double dxi;     /* xi_ref - xi_est at the last update [-] */
} rr_creepctl_state;

/*
 * rr_creepctl_check - validate creepage-controller parameters.
 *   status:  0 OK; RR_ERR_NONFINITE, RR_ERR_GEOMETRY (r_w or r_r <= 0),
 *            RR_ERR_PARAM (alpha < 0, beta < 0, sense not +1 or -1),
 *            RR_ERR_SPEED (vmin <= 0)
 *   reference: eq. (13)-(16)
 */
int rr_creepctl_check(const rr_creepctl_params *p);

/*
 * rr_creepctl_init - the controller at coefficient K, with the initial
 * wheelset speed reference by eq. (15), w_ref = K (r_r/r_w) w_roller.
 *   given:   p; K >= 0 [-]; w_roller the roller speed now [rad/s]
 *   returns: *s with K and w_ref set, xi_est and dxi 0
 *   status:  as rr_creepctl_check, RR_ERR_NONFINITE (K, w_roller),
 *            RR_ERR_PARAM (K < 0); on error *s is NaN
 *   The paper asks 0 <= K <= 1, adapted to the target: K = 1 - xi_ref
 *   braking (1 + xi_ref traction, which needs K > 1, so K is not capped at
 *   1) puts the kinematic creepage on the target at once; K = 1 starts at
 *   free rolling.
 */
int rr_creepctl_init(const rr_creepctl_params *p, rr_creepctl_state *s, double K,
                     double w_roller);

/*
 * rr_creepctl_xi - estimated creepage, eq. (16), in the controller's sense.
 *   given:   p; w_wheelset, w_roller measured speeds [rad/s], each in its
 *            own rolling sense
 *   returns: *xi = sense (w_wheelset r_w - V)/D [-], V = w_roller r_r and
 *            D = V with |D| raised to vmin if smaller (V = 0 counts as
 *            forward): only the denominator is guarded, so at rest xi = 0
 *   status:  as rr_creepctl_check, RR_ERR_NONFINITE; on error *xi is NaN
 */
int rr_creepctl_xi(const rr_creepctl_params *p, double w_wheelset, double w_roller,
                   double *xi);

/*
 * rr_creepctl_update - one sample of eq. (13)-(15) on K.
 *   given:   p; s from rr_creepctl_init/update; xi_ref the target creepage
 *            in the sense [-] (the paper's positive numbers); w_wheelset,
 *            w_roller measured speeds [rad/s]
 *   returns: *w_ref = K (r_r/r_w) w_roller with the adapted K, the new
 *            wheelset speed reference w_ref(t+1) [rad/s]; *s advanced (K,
 *            w_ref, and xi_est, dxi of this sample)
 *   status:  0 OK; errors as rr_creepctl_check, RR_ERR_NONFINITE (inputs or
 *            state); on error *w_ref is NaN and *s unchanged
 *   alpha and beta act per sample, as in the paper: a different sample time
 *   needs them rescaled.  K is bounded below by 0 only: if the drive cannot
 *   follow (its torque saturated) K keeps moving, as in the paper.  The
 *   reference carries the roller's measured speed, so the roller encoder's
 *   noise enters it directly.
 *   The rule is biased low: a negative dxi of any size (a count of encoder
 *   noise, a slight overshoot of the speed loop) fires the full step beta,
 *   a positive one moves only alpha dxi.  Each firing drops the creepage by
 *   beta, from where it climbs back with the factor (1 - alpha) per
 *   sample, so the held creepage is a sawtooth up to one beta deep below
 *   the target and its mean lies below the target by a fraction of beta
 *   (with the paper's values and a 2^22-count encoder, in the closed-loop
 *   test of tests/test_control.c: 0.2 - 0.25 beta = 4 - 5e-4, 1.3 - 2.7 %
 *   of the paper's targets); a smaller beta shrinks it in proportion.
 *   reference: eq. (13), (14), (15), (16)
 */
int rr_creepctl_update(const rr_creepctl_params *p, rr_creepctl_state *s, double xi_ref,
                       double w_wheelset, double w_roller, double *w_ref);

#endif
