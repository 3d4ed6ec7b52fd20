"""Pictures (matplotlib, imported on use, never at ``import rollerrig``)::

    import rollerrig.plot as rp
    rp.creep_curves(cx, {"fastsim": f1, "polach": f2}, mu=0.33, N=106.7e3,
                    reference=rr.reference.creep_curves()[1])
    rp.traction_field(rr.fastsim_field(1e-3, 0, 0.3, a=..., b=..., N=..., mu=...))
    rp.rig_history(res); rp.rig_force(res)       # the seed paper's Fig. 7 and Fig. 8
    rp.profiles(rr.RigGeometry.standard(), y_ws=(0, 0.002, 0.004))
    rp.fit(rr.fit_polach(cx, fx, ...), cx, fx)
    rp.error_map(rr.reference.score("fastsim"))  # the error over the 3220 exact cases
    rp.plot_run(res, "out")                      # rig_creepage.png, rig_force.png

Every function takes ``ax=`` (``axes=`` for the two-panel ones): None draws on
a new figure, otherwise on the axes given; it returns the axes (a numpy array
of axes for several panels).  Forces act on the wheel (Kalker's sign: fx < 0
for cx > 0), so creep curves are drawn as -fx by default.  Bad input raises
RollerRigError.
"""
# the functions live in three files of one seam each (the package's files
# stay under 800 lines with their numpydoc docstrings): _curves (creep
# curves, traction fields), _rig (a rig run, profiles), _maps (error maps,
# fits), over the helpers of _base
from ._base import TRACTION_QUANTITIES
from ._curves import creep_curve, creep_curves, traction_field
from ._maps import error_map, fit
from ._rig import friction_law_text, plot_run, profiles, rig_force, rig_history

__all__ = ["creep_curve", "creep_curves", "traction_field", "rig_history", "rig_force",
           "profiles", "fit", "error_map", "plot_run", "TRACTION_QUANTITIES"]
