/*
 * fmu_build.h - what `rollerrig fmu` generates for each FMU, in its
 * sources/fmu_start.c: the start values (the default parameters overridden
 * by the scenario file, rr_fmu.h's configuration), the points of the real
 * profiles it names, and the token that ties
 * the binary to its modelDescription.xml (FMI 2's guid, FMI 3's
 * instantiationToken).  The FMI adapters and the describing program read
 * both.
 */
#ifndef RR_FMU_BUILD_H
#define RR_FMU_BUILD_H

#include "fmu/rr_fmu.h"

extern const char rr_fmu_token[];

/* The start configuration: rr_fmu_config_default, then the scenario's
 * values; 0, or the status of the first value refused. */
int rr_fmu_start_config(rr_fmu_config *f);

/* The points of the real profiles the scenario names (rr_tables.h's
 * rr_rig_profiles: full size, referenced as rollerrig.rig.real_profiles
 * reads them; n = 0 in a slot without), static data for rr_fmu_set_profiles. */
void rr_fmu_start_profiles(rr_rig_profiles *pr);
/* The non-Hertzian contact's tables the build generated (contact.patch =
 * "nonhertz"; their rows static data, for rr_fmu_set_nonhertz): 1, or 0
 * where the build carries none. */
int rr_fmu_start_nonhertz(rr_nh_table t[2]);

#endif
