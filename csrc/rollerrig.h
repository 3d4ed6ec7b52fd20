/*
 * rollerrig.h - umbrella header of the rollerrig C core.
 *
 * The core is plain C99 with no Python, no globals that change and no
 * allocation: callers own every buffer.  Modules, bottom up:
 *   rr_common.h    status codes and their messages
 *   rr_elliptic.h  Carlson's R_F, R_D; complete elliptic integrals K, E
 *   rr_hertz.h     Hertzian contact ellipse
 *   rr_kalker.h    Kalker's creep coefficients C11, C22, C23, C33
 *   rr_friction.h  Coulomb and Polach's falling friction
 *   rr_contact.h   the contact problem every method takes (the Hertz ellipse or an
 *                  undeformed distance on a grid; its check) and the forces it returns
 *   rr_creep_opts.h  method options and descriptors, what every method shares
 *   rr_linear.h    Kalker's linear theory
 *   rr_polach.h    Polach's method
 *   rr_fastsim.h   FASTSIM, blended and modified, with its traction field
 *   rr_fastrip.h   FaStrip (CONTACT's modified FaStrip)
 *   rr_creep.h     the methods' registry (rr_methods.def) and dispatcher
 *   rr_creepage.h  kinematic creepages of a wheel on a roller
 *   rr_spline.h    natural cubic splines for profiles
 *   rr_geometry.h  contact search, wheelset pose, contact tables
 *   rr_tables.h    tables from profile points, the rig's default table
 *   rr_gap.h       the undeformed distance of a wheel on its roller (non-Hertzian patch)
 *   rr_wheel_exact.h  one wheel solved by the exact theory on that patch, its load found
 *   rr_rig_contact.h  one contact evaluation of the wheelset on the rollers
 *   rr_control.h   PI speed controllers, drive lag, encoders, creepage controller
 *   rr_ode.h       fixed-step L-stable integrators (ROS2, TR-BDF2, lin. Euler)
 *   rr_exact_table.h  the exact theory's forces from a table (method exact_table)
 *   rr_fft.h       mixed-radix FFT and the 2-D convolutions of the exact
 *                  contact solver (influence coefficients by FFT)
 *   rr_rig.h       the rig in time: plant, normal loads, sampled-data control
 *   rr_rig_params.h  the rig's parameters (names, units, defaults, ranges, origins),
 *                  its scenario and its outputs, declared once
 *   rr_fmu.h       the rig as a co-simulation unit, FMI-independent: variables with
 *                  value references, get/set with range checks, steps, states
 *   rr_fmu_xml.h   its modelDescription.xml (FMI 2.0 and 3.0)
 */
#ifndef ROLLERRIG_H
#define ROLLERRIG_H

#include "util/rr_common.h"
#include "util/rr_elliptic.h"
#include "contact/rr_hertz.h"
#include "contact/rr_kalker.h"
#include "contact/rr_friction.h"
#include "contact/rr_contact.h"
#include "contact/rr_creep_opts.h"
#include "contact/rr_linear.h"
#include "contact/rr_polach.h"
#include "contact/rr_fastsim.h"
#include "contact/rr_fastrip.h"
#include "util/rr_fft.h"
#include "contact/rr_influence.h"
#include "contact/rr_exact.h"
#include "contact/rr_exact_table.h"
#include "contact/rr_creep.h"
#include "geometry/rr_creepage.h"
#include "util/rr_spline.h"
#include "geometry/rr_geometry.h"
#include "geometry/rr_tables.h"
#include "geometry/rr_gap.h"
#include "geometry/rr_wheel_exact.h"
#include "geometry/rr_nonhertz.h"
#include "geometry/rr_nonhertz_table.h"
#include "rig/rr_rig_contact.h"
#include "rig/rr_control.h"
#include "util/rr_ode.h"
#include "rig/rr_rig.h"
#include "rig/rr_rig_params.h"
#include "fmu/rr_fmu.h"
#include "fmu/rr_fmu_xml.h"

#endif
