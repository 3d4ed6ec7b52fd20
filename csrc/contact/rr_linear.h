/* rr_linear.h - Kalker's linear theory of rolling contact (descriptor
 * rr_method_linear, method "linear": no options, no saturation). */
#ifndef RR_LINEAR_H
#define RR_LINEAR_H

#include "contact/rr_creep_opts.h"

/*
 * rr_linear - Kalker's linear theory.
 *   fx = -G c^2 C11 cx,  fy = -G c^2 C22 cy - G c^3 C23 cphi,
 *   mz = G c^3 C23 cy - G c^4 C33 cphi,  c = sqrt(ab).
 *   Kalker's C33 is not in our source table (Kalker 1990, Table E.3 as
 *   transcribed has C11, C22, C23 only); C33 is taken from the simplified
 *   theory with flexibility L3, C33 = 32/(15 pi) C23 (b/a)^(3/2).
 *   status: as rr_contact_check; RR_ERR_RANGE where a force overflows (the
 *   linear theory does not saturate); RR_ERR_NULL.
 */
int rr_linear(const rr_contact_case *c, rr_forces *out);

#endif
