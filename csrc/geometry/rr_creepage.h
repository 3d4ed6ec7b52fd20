/*
 * rr_creepage.h - kinematic creepages of a wheel against a roller (or a
 * rail) from the rigid-body motions of both and the contact frame.
 *
 * The creepages are Kalker's: the slip velocity of the wheel's material
 * point at the contact relative to the roller's, projected on the contact
 * frame and divided by the rolling speed,
 *     cx = (v_w(P) - v_r(P)) . t1 / V,   cy = (v_w(P) - v_r(P)) . t2 / V,
 *     cphi = (w_w - w_r) . n / V,
 * with v(P) = v + w x (P - c) for each body, t1 the rolling direction, t2 the
 * lateral direction in the contact plane and n = t1 x t2 the normal pointing
 * into the wheel (CONTACT's convention, rr_contact.h).  The rolling speed V
 * is the mean speed of the two material points along t1,
 * V = |(v_w(P) + v_r(P)) . t1| / 2, and never less than a named minimum
 * vmin > 0: at standstill the creepages stay finite (the seed paper's
 * "special procedure" for V_n = 0), and with V below vmin they are slip
 * velocities divided by vmin.
 *
 * Reference: J. J. Kalker, Three-Dimensional Elastic Bodies in Rolling
 * Contact, 1990, section 1.2 (kinematics of rolling).
 */
#ifndef RR_CREEPAGE_H
#define RR_CREEPAGE_H

/* Rigid-body motion: the velocity of a material point at P is v + w x (P - c). */
typedef struct {
    double c[3];   /* a reference point of the body [m] (centre, or a point on its axis) */
    double v[3];   /* velocity of that point [m/s] */
    double w[3];   /* angular velocity [rad/s] */
} rr_motion;

/* Contact point and frame, all in the same (rig) frame. */
typedef struct {
    double p[3];   /* contact point [m] */
    double t1[3];  /* unit rolling direction */
    double t2[3];  /* unit lateral direction in the contact plane */
} rr_contact_frame;

typedef struct {
    double cx, cy;  /* longitudinal and lateral creepage [-] */
    double cphi;    /* spin creepage [rad/m] */
    double V;       /* rolling speed used as reference [m/s], >= vmin */
    double slip[3]; /* slip velocity of the wheel relative to the roller at P [m/s] */
} rr_creepages;

/*
 * rr_creepage - exact kinematic creepages.
 *   given:   wheel, roller  rigid-body motions; f the contact frame (t1, t2
 *            unit and orthogonal, checked to 1e-9); vmin > 0 [m/s]
 *   returns: *out
 *   status:  0 OK; RR_ERR_NONFINITE, RR_ERR_GEOMETRY (frame not orthonormal),
 *            RR_ERR_SPEED (vmin not positive), RR_ERR_RANGE (a slip or a
 *            creepage overflows: speeds beyond ~1e150 m/s, or a slip over
 *            a tiny vmin), RR_ERR_NULL
 */
int rr_creepage(const rr_motion *wheel, const rr_motion *roller, const rr_contact_frame *f,
                double vmin, rr_creepages *out);

#endif
