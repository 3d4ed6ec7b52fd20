/*
 * fmu_build.h - what `rollerrig fmu` generates for each FMU, in its
 * sources/fmu_start.c: the start values (the default parameters overridden
 * by the scenario file, rr_fmu.h's configuration) and the token that ties
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

#endif
