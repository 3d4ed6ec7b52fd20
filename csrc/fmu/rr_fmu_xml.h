/*
 * rr_fmu_xml.h - the modelDescription.xml of the rig's co-simulation unit
 * (FMI 2.0 or 3.0, co-simulation), written from the unit's variables
 * (rr_fmu.h), which come from the rig's declarations (rr_rig_params.h):
 * names, value references, units (with their SI base units), descriptions,
 * types (enumerations with their items), causality, variability, start
 * values and ranges, the outputs and initial unknowns, the default
 * experiment (the scenario's duration, the control sample time as step).
 *
 * Ranges: FMI's min and max are inclusive; an open end (a mass > 0) is
 * written as its bound, and the unit refuses the bound itself when it is
 * set (rr_fmu_set).  Units are written in the CF / UDUNITS spelling the
 * package writes (rollerrig/_units.py): the declarations' "-"
 * (dimensionless) as "1"; every unit used has its <UnitDefinitions> entry.
 * A name, a flag, a choice and an integer get none (FMI gives units to
 * reals only).
 */
#ifndef RR_FMU_XML_H
#define RR_FMU_XML_H

#include "fmu/rr_fmu.h"

/* What the description says besides the variables. */
typedef struct {
    int fmi_version;                /* 2 or 3 */
    const char *model_identifier;   /* a C identifier: the binary's and the functions' name */
    const char *model_name;
    const char *description;
    const char *generation_tool;
    const char *token;              /* FMI 2's guid, FMI 3's instantiationToken */
    const char *const *sources;     /* FMI 2's <SourceFiles> (relative to sources/); NULL:
                                       none */
    int nsources;
} rr_fmu_xml_info;

/*
 * rr_fmu_xml - the modelDescription.xml of a unit whose start configuration
 * is `start`, into buf[len] (snprintf-like: at most len - 1 characters and a
 * terminating NUL; buf may be NULL with len 0 to ask the length).
 *   returns: the length of the whole text (without the NUL), or a status < 0:
 *            RR_ERR_NULL (info, start or a string of info NULL), RR_ERR_PARAM
 *            (fmi_version not 2 or 3)
 */
long rr_fmu_xml(const rr_fmu_xml_info *info, const rr_fmu_config *start, char *buf, long len);

/*
 * rr_fmu_unit_base - the SI base-unit exponents of a unit text as the rig's
 * declarations write them ("N m s/rad", "kg m^2", "m/s^2": symbols kg, m,
 * s, rad, N, Pa and 1 (dimensionless), separated by spaces, one "/" before
 * the denominator, "^n" powers): e[0..3] the exponents of kg, m, s, rad.
 * 1 if every symbol is known, else 0 (e unspecified).
 */
int rr_fmu_unit_base(const char *unit, int e[4]);

#endif
