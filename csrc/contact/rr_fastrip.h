/* rr_fastrip.h - FaStrip (Sichani, Enblom and Berg 2016) as CONTACT's
 * modified FaStrip (descriptor rr_method_fastrip, method "fastrip"). */
#ifndef RR_FASTRIP_H
#define RR_FASTRIP_H

#include "contact/rr_creep_opts.h"

/* FaStrip's options in rr_creep_opts.v */
enum {
    RR_FASTRIP_NX = 0,          /* elements along x per row, 1 .. RR_FASTRIP_MAX_GRID */
    RR_FASTRIP_NY = 1,          /* rows (strips), 1 .. RR_FASTRIP_MAX_GRID */
    RR_FASTRIP_FLEX = 2,        /* enum rr_fastrip_flex */
    RR_FASTRIP_GEOMETRY = 3,    /* enum rr_fastrip_geometry */
    RR_FASTRIP_K0 = 4,          /* slope reduction of the FASTSIM part (Spiryagin 2013) */
    RR_FASTRIP_ALPHA_INF = 5,
    RR_FASTRIP_BETA = 6
};

/* the FASTSIM part's flexibilities */
enum rr_fastrip_flex {
    RR_FASTRIP_FLEX_KALKER = 0,   /* Kalker's three, L1, L2, L3 */
    RR_FASTRIP_FLEX_BLENDED = 1   /* blended towards one as the creepage grows (CONTACT's) */
};

/* the discretisation of the pressure and of the strips */
enum rr_fastrip_geometry {
    RR_FASTRIP_ELLIPSE = 0,   /* the ellipse's chords; pressure summing to N on the grid */
    RR_FASTRIP_CONTACT = 1    /* CONTACT's: the grid's element extents and its
                                 equivalent ellipse; Hertz's peak pressure */
};

#define RR_FASTRIP_MAX_GRID 4096

extern const rr_method_desc rr_method_fastrip;

/*
 * rr_fastrip - FaStrip's creep forces on an nx by ny grid over the
 * ellipse's bounding box (every element 2a/nx by 2b/ny).
 *   References: M. Sh. Sichani, R. Enblom, M. Berg, "A fast wheel-rail
 *   contact model for application to damage analysis in vehicle dynamics
 *   simulation", Vehicle System Dynamics 54 (2016) 748-764 (FaStrip: each
 *   lateral strip a 2-D strip-theory problem); E. Vollebregt's CONTACT
 *   (m_solvpt.f90 modif_fastrip, M=5; m_hertz.f90 simpflex, the blending).
 *   Each row y_j of half-length a_j: Kalker's strip theory with the
 *   elliptical traction bound, creepages made dimensionless with C11, C22,
 *   C23 (so that the linear limit is Kalker's), gives the slip length 2d
 *   and the tractions of the adhesion zone x > 2d - a_j in closed form;
 *   in the slip zone the traction is mu pn along FASTSIM's (three
 *   flexibilities, spin scaled by L1/L3, L2/L3).  A row whose closed-form
 *   tractions exceed mu pmax keeps FASTSIM's tractions.
 *   RR_FASTRIP_ELLIPSE (default): a_j the ellipse's chord, every element
 *   the average over its cell of the closed form and of the pressure (the
 *   linear limit's square-root traction at the trailing edge, sampled at
 *   centres, converges at h^(1/2) only), the pressure summing to N, so that
 *   |F| <= mu N but for rounding.  RR_FASTRIP_CONTACT: CONTACT's values at
 *   the centres, a_j the extent of the row's elements, the strip theory on
 *   the elements' equivalent ellipse (Kik-Piotrowski), Hertz's pressure
 *   1.5 N / (pi a b) unnormalised: CONTACT's M=5 to 2e-7 mu N.
 *   Not done: CONTACT's "original" FaStrip (M=6, 7: per-row parabolic
 *   pressure, a one-flexibility rerun when the leading edge slips).
 *   Coulomb friction only (mu0).  status: rr_creep_prepare's (RR_ERR_PATCH
 *   for a grid problem, rr_contact_problem_check's), RR_ERR_FRICTION (a
 *   falling law), rr_method_check's, RR_ERR_RANGE (results beyond the
 *   floating-point range), RR_ERR_NULL.
 */
int rr_fastrip(const rr_contact_problem *p, const rr_creep_opts *o, rr_forces *out);

#endif
