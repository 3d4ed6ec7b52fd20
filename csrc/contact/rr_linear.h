/* rr_linear.h - Kalker's linear theory of rolling contact (descriptor
 * rr_method_linear, method "linear": no options, no saturation). */
#ifndef RR_LINEAR_H
#define RR_LINEAR_H

#include "contact/rr_creep_opts.h"

/*
 * rr_linear - Kalker's linear theory.
 *   fx = -G c^2 C11 cx,  fy = -G c^2 C22 cy - G c^3 C23 cphi,
 *   mz = G c^3 C23 cy - G c^4 C33 cphi,  c = sqrt(ab).
 *   C11 ... C33 from rr_kalker (Kalker 1990, Table E.3).  The simplified
 *   theory's 32/(15 pi) C23 (b/a)^(3/2) (flexibility L3), used here before,
 *   is 27 % low at a/b = 5, 15 % low at a/b = 1 and 7 % high at a/b = 0.2
 *   (nu = 0.28); FASTSIM keeps L3, which belongs to its own theory.
 *   The friction law goes unused (but an invalid one is refused).
 *   status: RR_ERR_PATCH (a grid problem), rr_contact_problem_check's;
 *   RR_ERR_RANGE where a force overflows (the linear theory does not
 *   saturate); RR_ERR_NULL.
 */
int rr_linear(const rr_contact_problem *p, rr_forces *out);

#endif
