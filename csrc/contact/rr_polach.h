/* rr_polach.h - Polach's creep-force method with spin (descriptor
 * rr_method_polach, method "polach": options kA, kS). */
#ifndef RR_POLACH_H
#define RR_POLACH_H

#include "contact/rr_creep_opts.h"

/* Polach's options in rr_creep_opts.v */
enum { RR_POLACH_KA = 0, RR_POLACH_KS = 1 };

/*
 * rr_polach - Polach's creep-force method with spin.
 *   References: O. Polach, "A fast wheel-rail forces calculation computer
 *   code", Vehicle System Dynamics 33 Suppl. (1999) 728-739; O. Polach,
 *   Wear 258 (2005) 992-1000 (reduction factors kA, kS, falling friction).
 *   With s_yC = cy + cphi a if that grows |cy| (else cy), s_C = |(cx, s_yC)|,
 *   mu = mu(speed s_C), eps = pi G a b C s_C / (4 N mu),
 *   C = |(C11 cx, C22 cy)| / |(cx, cy)|:
 *     F = 2 N mu / pi [kA eps / (1 + (kA eps)^2) + atan(kS eps)],
 *     fx = -F cx / s_C, fy = -F cy / s_C + F_yS (Polach's spin force).
 *   The force lies along (cx, cy); for small pure cx, pure cy or pure spin
 *   it reproduces Kalker's linear theory times (kA + kS)/2 (with both cx
 *   and cy only its magnitude does).  0 < kS <= kA <= 1 (Polach 2005).
 *   The method gives no spin moment: mz = 0.  The spin force is added
 *   without a bound of its own, so the sum is kept on the friction limit:
 *   |(fx, fy)| <= mu N, mu at the slip speed s_C speed.
 *   status: RR_ERR_PARAM, RR_ERR_NONFINITE (kA, kS), rr_creep_prepare's
 *   (RR_ERR_PATCH for a grid problem, rr_contact_problem_check's,
 *   RR_ERR_SPEED: falling friction with speed 0), RR_ERR_RANGE (a force
 *   beyond the floating-point range), RR_ERR_NULL.
 */
int rr_polach(const rr_contact_problem *p, double kA, double kS, rr_forces *out);

#endif
