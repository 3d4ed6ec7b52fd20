"""Studies over the core: parameter sweeps of a vectorised function or of
the rig (sweep), fitting a creep-force method to measured curves (fit), the
comparison with CONTACT's reference data (reference) and the exact theory's
table built by a sweep (exact_table).  This face hands on no names: the
rooms are imported by their paths (rollerrig.analysis.sweep is the module;
rollerrig.sweep, from the package, the function)."""
