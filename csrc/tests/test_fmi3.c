/* test_fmi3.c - the FMI 3.0 adapter (rollerrig/data/fmi/fmi3_cs.c, compiled
 * into this program with its glue, under -Werror and the sanitizers of make
 * sanitize): instantiation and its refusals, the typed getters and setters
 * (Float64, Int32, Int64 for enumerations, Boolean; the other types and
 * array sizes refused), steps, FMU states and their bytes, the functions of
 * interfaces the FMU lacks: an error status and a message, never a crash. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rr_test.h"
#include "../../rollerrig/data/fmi/fmi3_cs.c"
#include "../../rollerrig/data/fmi/fmi_glue.c"

const char rr_fmu_token[] = "{test-fmi3}";

/* no real profiles: the cone on its crowned roller */
void rr_fmu_start_profiles(rr_rig_profiles *pr)
{
    memset(pr, 0, sizeof *pr);
}

/* no non-Hertzian tables (contact.patch = "hertz") */
int rr_fmu_start_nonhertz(rr_nh_table t[2])
{
    (void)t;
    return 0;
}

int rr_fmu_start_config(rr_fmu_config *f)
{
    int st = rr_fmu_config_default(f);
    /* a start value of the scenario's: its schedule shorter */
    static const double targets[] = {0.02, 0.01};
    static const double starts[] = {0.0, 0.1};
    if (st == RR_OK)
        st = rr_fmu_config_set_list(f, "scenario.targets", 2, targets);
    if (st == RR_OK)
        st = rr_fmu_config_set_list(f, "scenario.target_start_s", 2, starts);
    return st;
}

static char last[2048];
static int nlog = 0;

static void logger(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category,
                   fmi3String message)
{
    (void)env;
    (void)status;
    (void)category;
    snprintf(last, sizeof last, "%s", message);
    nlog++;
}

static int logged(const char *part)
{
    return strstr(last, part) != NULL;
}

static fmi3Instance make(const char *token)
{
    return fmi3InstantiateCoSimulation("a", token, NULL, 0, 1, 0, 0, NULL, 0, NULL, logger,
                                       NULL);
}

#define T 0.004

int main(void)
{
    const fmi3ValueReference fx = RR_FMU_VR_RECORD + RR_REC_FX;
    const fmi3ValueReference status_vr = RR_FMU_VR_RECORD + RR_REC_STATUS;
    const fmi3ValueReference mode = RR_FMU_VR_CONTROL + RR_FMU_MU_SOURCE;
    const fmi3ValueReference mu = RR_FMU_VR_INPUT + RR_FMU_IN_MU;
    const fmi3ValueReference target3 = RR_FMU_VR_LIST + RR_FMU_VR_LIST_ROW * 1 + 2;
    fmi3Instance c, d;
    fmi3FMUState s = NULL, s2 = NULL;
    fmi3Float64 x, a[27], b[27], t;
    fmi3Float32 f32;
    fmi3Int32 i32 = 0;
    fmi3Int64 i64;
    fmi3Boolean ev, term, early;
    fmi3String str;
    size_t size, nd;
    fmi3Byte *bytes;
    int k;

    CHECK(strcmp(fmi3GetVersion(), "3.0") == 0, "version");
    CHECK(make("{other}") == NULL && logged("instantiationToken is not this FMU's"), last);
    CHECK(fmi3InstantiateCoSimulation("a", "{test-fmi3}", NULL, 0, 0, 1, 0, NULL, 0, NULL,
                                      logger, NULL) == NULL && logged("no event mode"), last);
    CHECK(fmi3InstantiateModelExchange("a", "{test-fmi3}", NULL, 0, 0, NULL, logger) == NULL
          && fmi3InstantiateScheduledExecution("a", "{test-fmi3}", NULL, 0, 0, NULL, logger, NULL,
                                               NULL, NULL) == NULL, "co-simulation only");
    c = make("{test-fmi3}");
    CHECK(c != NULL, "instantiated");
    CHECK(fmi3GetFloat64(c, &target3, 1, &x, 1) == fmi3Error
          && logged("unknown value reference 101002"), last);
    CHECK(fmi3GetFloat64(c, &fx, 1, &x, 2) == fmi3Error && logged("nValues"), last);
    CHECK(fmi3GetFloat32(c, &fx, 1, &f32, 1) == fmi3Error
          && logged("fx (value reference 206) is of type Float64, not Float32"), last);
    CHECK(fmi3GetString(c, &fx, 0, &str, 0) == fmi3OK, "no strings asked");
    i64 = 1;
    CHECK(fmi3SetInt64(c, &mode, 1, &i64, 1) == fmi3OK, "mu from the input");
    CHECK(fmi3SetInt32(c, &mode, 1, &i32, 1) == fmi3Error && logged("Int64 (enumeration)"),
          last);
    x = -0.5;
    CHECK(fmi3SetFloat64(c, &mu, 1, &x, 1) == fmi3Error && logged("mu = -0.5"), last);
    {
        /* start values and inputs: NaN and infinities refused with a message
         * (issue 22: creepage_ref = NaN was taken and the unit initialised) */
        const fmi3ValueReference cr = RR_FMU_VR_INPUT + RR_FMU_IN_CREEPAGE;
        x = NAN;
        CHECK(fmi3SetFloat64(c, &cr, 1, &x, 1) == fmi3Error
              && logged("fmi3SetFloat64: creepage_ref = nan: the value must be a finite "
                        "number"), last);
        x = HUGE_VAL;
        CHECK(fmi3SetFloat64(c, &mu, 1, &x, 1) == fmi3Error
              && logged("mu = inf: the value must be a finite number"), last);
        x = -HUGE_VAL;
        CHECK(fmi3SetFloat64(c, &target3, 1, &x, 1) == fmi3Error, "an unknown one still");
        CHECK(fmi3GetFloat64(c, &cr, 1, &x, 1) == fmi3OK, "creepage_ref");
        CHECK(x == 0.02, "creepage_ref kept: the first target");
    }
    x = 0.3;
    CHECK(fmi3SetFloat64(c, &mu, 1, &x, 1) == fmi3OK, "mu 0.3");
    CHECK(fmi3DoStep(c, 0.0, T, 1, &ev, &term, &early, &t) == fmi3Error, "step too early");
    CHECK(fmi3EnterInitializationMode(c, 0, 0.0, 0.0, 0, 0.0) == fmi3OK, "enter");
    CHECK(fmi3ExitInitializationMode(c) == fmi3OK, "exit");
    CHECK(fmi3EnterStepMode(c) == fmi3Error && fmi3EnterEventMode(c) == fmi3Error, "no events");
    x = NAN;
    CHECK(fmi3SetFloat64(c, &mu, 1, &x, 1) == fmi3Error && logged("mu = nan"),
          "an input NaN while stepping");
    for (k = 0; k < 30; k++)
        CHECK(fmi3DoStep(c, k * T, T, 1, &ev, &term, &early, &t) == fmi3OK && !ev && !term
              && !early, "step");
    CHECK(fabs(t - 30 * T) < 1e-12, "last successful time");
    CHECK(fmi3GetInt32(c, &status_vr, 1, &i32, 1) == fmi3OK && i32 == 0, "sample status");
    {
        const fmi3ValueReference mu_left = RR_FMU_VR_RECORD + RR_REC_MU_LEFT;
        CHECK(fmi3GetFloat64(c, &mu_left, 1, &x, 1) == fmi3OK && x == 0.3, "mu from the input");
    }
    CHECK(fmi3GetFMUState(c, &s) == fmi3OK && s, "get state");
    CHECK(fmi3SerializedFMUStateSize(c, s, &size) == fmi3OK, "size");
    bytes = malloc(size);
    CHECK(fmi3SerializeFMUState(c, s, bytes, size) == fmi3OK, "serialize");
    for (k = 30; k < 70; k++)
        fmi3DoStep(c, k * T, T, 1, &ev, &term, &early, &t);
    for (k = 0; k < 27; k++) {
        const fmi3ValueReference vr = RR_FMU_VR_RECORD + 1 + (fmi3ValueReference)k;
        fmi3GetFloat64(c, &vr, 1, &a[k], 1);
    }
    d = make("{test-fmi3}");
    CHECK(fmi3DeserializeFMUState(d, bytes, size, &s2) == fmi3OK && s2, "deserialize");
    CHECK(fmi3SetFMUState(d, s2) == fmi3OK, "set in another instance");
    for (k = 30; k < 70; k++)
        fmi3DoStep(d, k * T, T, 1, &ev, &term, &early, &t);
    for (k = 0; k < 27; k++) {
        const fmi3ValueReference vr = RR_FMU_VR_RECORD + 1 + (fmi3ValueReference)k;
        fmi3GetFloat64(d, &vr, 1, &b[k], 1);
    }
    CHECK(memcmp(a, b, sizeof a) == 0, "the bytes reproduce the run elsewhere");
    CHECK(fmi3FreeFMUState(c, &s) == fmi3OK && fmi3FreeFMUState(d, &s2) == fmi3OK && !s && !s2,
          "free");
    free(bytes);
    /* the rest of the standard: refused with a message */
    CHECK(fmi3GetNumberOfVariableDependencies(c, fx, &nd) == fmi3Error
          && fmi3GetDirectionalDerivative(c, NULL, 0, NULL, 0, NULL, 0, NULL, 0) == fmi3Error
          && fmi3GetClock(c, &fx, 1, &ev) == fmi3Error && fmi3SetTime(c, 0.0) == fmi3Error
          && fmi3UpdateDiscreteStates(c, NULL, NULL, NULL, NULL, NULL, NULL) == fmi3Error
          && fmi3GetOutputDerivatives(c, &fx, 1, &i32, &x, 1) == fmi3Error
          && fmi3ActivateModelPartition(c, 0, 0.0) == fmi3Error, "not supported");
    CHECK(logged("co-simulation FMU"), last);
    CHECK(fmi3Terminate(c) == fmi3OK && fmi3Reset(c) == fmi3OK, "terminate, reset");
    CHECK(fmi3GetFloat64(c, &mu, 1, &x, 1) == fmi3OK && x == 0.4, "reset to the start");
    CHECK(fmi3DoStep(NULL, 0.0, T, 1, &ev, &term, &early, &t) == fmi3Error
          && fmi3EnterStepMode(NULL) == fmi3Error, "NULL instance");
    fmi3FreeInstance(NULL);
    fmi3FreeInstance(c);
    fmi3FreeInstance(d);
    CHECK(nlog > 10, "messages logged");
    return rr_test_summary();
}
