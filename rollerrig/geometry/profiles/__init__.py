"""Wheel and rail/roller profiles: readers, checks and a C2 cubic spline.

A :class:`Profile` is the cross-section of a wheel tread or of a rail head
(a roller of the rig carries a rail-head shape: its kind is ``"rail"``) as a
single-valued curve z(y), held as points and interpolated by a cubic spline.

Conventions (SIMPACK's and MiniProf's, which CONTACT shares)
------------------------------------------------------------
* SI units: y and z in metres; slopes dimensionless; curvature in 1/m.
* y is lateral, positive towards the FIELD side (away from the track
  centre, outward), for the profile's own side of the track.  The flange
  of a wheel, and the gauge face of a rail, lie at the negative-y end.
* z is vertical, positive DOWNWARD, the same for wheels and rails.  A rail
  or roller has its material below the curve (z larger than the profile),
  a wheel above it (z smaller).
* References as the files give them: the UIC60 rail has z = 0 at the top of
  its head (at y = -0.2 mm; the benchmark rail is already canted 1:40); the
  S1002 wheel has y = 0 at the taping line with z = 0 there, the flange tip
  28 mm below at y = -55 mm and the flange back at y = -70 mm.  MiniProf
  wheels have y = 0 at the flange back (the taping line is then at
  ``WheelDiameterTaperline``, 70 mm) and MiniProf rails their own origin.
* So a wheel and a rail drawn in the same axes sit one above the other:
  the rail head's top near z = 0 and the wheel tread just above it; moved
  by ``wheel.shifted(dy, dz)`` the gap is ``rail.z_at(y) - wheel.z_at(y)``
  (>= 0 where they do not overlap).  The right-hand side of a track is the
  mirror image: ``profile.mirrored()``.
* Curvature ``kappa = z'' / (1 + z'^2)^1.5`` is signed: positive where the
  curve bends towards +z (down).  For a rail or roller that is a convex
  surface (the UIC60 crown: +1/0.3 m); for a wheel a concave one (the flange
  root), and its convex tread has kappa < 0.  The lateral curvature sum of
  the Hertz module (contact.hertz, gap h = A x^2 + B y^2) at a contact point
  is therefore ``B = (kappa_rail - kappa_wheel) / 2``, each profile's kappa
  taken at its own contact point (curvature does not change under the
  wheelset's roll rotation).
* Point order never matters: a Profile stores y strictly increasing.

Interpolation
-------------
A C2 cubic spline through the points (not-a-knot end conditions by default,
``bc="natural"`` on request), its slopes found by a tridiagonal solve.  The
paper interpolates with parabolas; a piecewise parabola is at best C1, so
its second derivative -- the profile curvature that sets the lateral
semi-axis of the Hertz ellipse -- jumps at every node: the contact patch
would jump as the contact point moves across a node, and contact tables
interpolated in y would inherit the steps.  The cubic spline has continuous
curvature (piecewise linear in y), is the interpolant of least bending
energy (it minimises the integral of z''^2, so it does not add wiggles), and
converges as h^4 in z and h^2 in curvature on smooth data.

Measured profiles carry noise that the curvature amplifies (1/h^2).
``smoothing=L`` [m] replaces the interpolating spline by the penalised
least-squares smoothing spline (Reinsch 1967): it minimises
``sum w_i (z_i - f(y_i))^2 + lam * integral f''^2 dy`` with w_i the lateral
length each point stands for (trapezoid weights, so the result does not
depend on the point density) and ``lam = (L / 2 pi)^4``.  A ripple of
wavelength W passes with the gain 1 / (1 + (L/W)^4): half its amplitude at
W = L, 0.4 % lost at W = 4 L, 99.6 % removed at W = L/4; straight lines,
parabolas and cubics pass unchanged away from the ends (a crown keeps its
radius).
The smoothing spline is natural (z'' = 0 at both ends).  On the shipped
MiniProf profiles (points 0.25 mm apart) 1 to 3 mm remove the point-to-point
jitter of the curvature and keep its features of 10 mm wavelength; noise
of 1 um on points 0.25 mm apart needs about 10 mm before a crown radius
shows within 10 % (tests).  Smoothing works on z(y): on steep faces
(|z'| >> 1, the flange back, a gauge face) it moves points vertically by
up to ~0.5 mm; it is meant for the running surface.

Layout of this package
----------------------
``_spline`` the spline numerics (the interpolating spline is the C core's,
csrc/util/rr_spline.h; the smoothing spline is numpy), ``_checks`` the
limits and the checks of points, ``_profile`` the Profile class and
``read_profile``, ``readers`` the file readers and ``READERS``, the table
of formats by extension that ``read_profile`` dispatches on: a new format is
one reader function and one entry there (the readers return points, never
a Profile: ``_profile`` imports ``readers``, not the reverse).

Reading files
-------------
``read_profile(path)`` chooses the format by the extension: SIMPACK ``.prw``
(wheel) and ``.prr`` (rail), MiniProf ``.whl`` (wheel) and ``.ban`` (rail),
and plain two-column text ``.txt``, ``.csv``, ``.dat`` (lateral, vertical;
millimetres unless ``units="m"``).  Each reader documents its own rules.
Checks raise RollerRigError naming the file and the line: text where a
number should be, NaN or infinite values, fewer than 4 points, repeated y,
coordinates beyond 2 m (millimetres read as metres) or a profile narrower
than 1 mm (metres read as millimetres), a point count that contradicts the
header.

Folds.  A measuring instrument that follows a vertical face (the flange
back, a rail's gauge face below the head) may return points whose y steps
back.  The profile is kept single-valued by the rule of CONTACT's
``delete_foldback``: starting at the point that certainly lies on the
running surface (the top of a rail head, min z; the flange tip of a wheel,
max z) the points are walked outward to both ends and each one is kept
only if it extends the lateral range covered so far; the points dropped
(the fold) are reported in a RollerRigWarning with their count and extent
(``on_fold="raise"`` makes a fold an error instead).  A point that only
repeats the y of the point before it, without stepping back, is not a fold
but a duplicate: always an error.  The shipped rollers fold on their gauge
face, 17 to 52 mm below the top, away from any contact: 6 and 4 points go.
"""
from ._checks import (BCS, KINDS, MAX_COORD, MAX_POINTS, MIN_POINTS, MIN_SPACING,
                      MIN_WIDTH, UNITS)
from ._profile import DATA_DIR, Profile, _rebuild, read_profile
from .readers import (MAX_FILE_BYTES, MINIPROF_EXT, READERS, SIMPACK_EXT, TEXT_EXT, Format,
                      RawProfile)

__all__ = ["Profile", "read_profile", "KINDS", "DATA_DIR", "MIN_POINTS", "READERS"]

# the public path, also the one pickles of a Profile name
Profile.__module__ = _rebuild.__module__ = __name__
