/* test_fmi2.c - the FMI 2.0 adapter (rollerrig/data/fmi/fmi2_cs.c, compiled
 * into this program with its glue, under -Werror and the sanitizers of make
 * sanitize): instantiation and its refusals, values and their checks through
 * the logger, steps, FMU states and their bytes, calls with NULL or out of
 * order: an error status and a message, never a crash. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rr_test.h"
#include "../../rollerrig/data/fmi/fmi2_cs.c"
#include "../../rollerrig/data/fmi/fmi_glue.c"

/* what `rollerrig fmu` generates (fmu_start.c): here the defaults */
const char rr_fmu_token[] = "{test-fmi2}";

int rr_fmu_start_config(rr_fmu_config *f)
{
    return rr_fmu_config_default(f);
}

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

/* the value reference of a parameter row */
static fmi2ValueReference vr_param(const char *name)
{
    int i;
    for (i = 0; i < rr_rig_param_count(); i++)
        if (strcmp(rr_rig_param_at(i)->name, name) == 0)
            return RR_FMU_VR_PARAM + (fmi2ValueReference)i;
    return 0;
}

static char last[2048];
static int nlog = 0;

static void logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status,
                   fmi2String category, fmi2String message, ...)
{
    va_list ap;
    (void)env;
    (void)name;
    (void)status;
    (void)category;
    va_start(ap, message);
    vsnprintf(last, sizeof last, message, ap);
    va_end(ap);
    nlog++;
}

static int logged(const char *part)
{
    return strstr(last, part) != NULL;
}

#define T 0.004

int main(void)
{
    fmi2CallbackFunctions cb = {logger, NULL, NULL, NULL, NULL};
    const fmi2ValueReference mass = vr_param("wheelset.mass_kg");
    const fmi2ValueReference fx = RR_FMU_VR_RECORD + RR_REC_FX;
    const fmi2ValueReference status_vr = RR_FMU_VR_RECORD + RR_REC_STATUS;
    const fmi2ValueReference mode = RR_FMU_VR_CONTROL + RR_FMU_WHEELSET_MODE;
    const fmi2ValueReference flag = vr_param("integration.linear_first_stage");
    fmi2Component c, d;
    fmi2FMUstate s = NULL, s2 = NULL;
    fmi2Real x, a[50], b[50], t;
    fmi2Integer i;
    fmi2Boolean yes;
    fmi2String none = NULL;
    size_t size;
    fmi2Byte *bytes;
    int k;

    CHECK(strcmp(fmi2GetVersion(), "2.0") == 0 && strcmp(fmi2GetTypesPlatform(), "default") == 0,
          "version");
    CHECK(fmi2Instantiate("a", fmi2CoSimulation, "{test-fmi2}", "", NULL, 0, 0) == NULL,
          "no callbacks");
    CHECK(fmi2Instantiate("a", fmi2CoSimulation, "{other}", "", &cb, 0, 0) == NULL
          && logged("the GUID is not this FMU's"), last);
    CHECK(fmi2Instantiate("a", fmi2ModelExchange, "{test-fmi2}", "", &cb, 0, 0) == NULL
          && logged("co-simulation only"), last);
    c = fmi2Instantiate("a", fmi2CoSimulation, "{test-fmi2}", "", &cb, 0, 1);
    CHECK(c != NULL, "instantiated");
    CHECK(fmi2SetDebugLogging(c, 1, 1, &none) == fmi2Error, "NULL category");
    {
        fmi2String cats[] = {"logBogus"};
        CHECK(fmi2SetDebugLogging(c, 1, 1, cats) == fmi2Error && logged("logBogus"), last);
        cats[0] = "logEvents";
        CHECK(fmi2SetDebugLogging(c, 0, 1, cats) == fmi2OK, "events off");
    }
    x = -1.0;
    CHECK(fmi2SetReal(c, &mass, 1, &x) == fmi2Error
          && logged("fmi2SetReal: wheelset.mass_kg = -1 is out of range"), last);
    CHECK(fmi2SetReal(c, &mass, 1, NULL) == fmi2Error, "NULL values");
    {
        /* start values: NaN and infinities refused with a message (issue 22:
         * creepage_ref = NaN was taken and the unit initialised) */
        const fmi2ValueReference vrs[2] = {RR_FMU_VR_INPUT + RR_FMU_IN_CREEPAGE, mass};
        fmi2Real bad[2] = {NAN, HUGE_VAL};
        CHECK(fmi2SetReal(c, vrs, 1, bad) == fmi2Error
              && logged("fmi2SetReal: creepage_ref = nan: the value must be a finite number"),
              last);
        CHECK(fmi2SetReal(c, vrs + 1, 1, bad + 1) == fmi2Error
              && logged("wheelset.mass_kg = inf: the value must be a finite number"), last);
        bad[0] = 0.02;
        bad[1] = -HUGE_VAL;
        CHECK(fmi2SetReal(c, vrs, 2, bad) == fmi2Error && logged("wheelset.mass_kg = -inf"),
              last);
        CHECK(fmi2GetReal(c, vrs + 1, 1, &x) == fmi2OK && x == 14.504, "the mass kept");
    }
    CHECK(fmi2GetReal(c, &fx, 1, &x) == fmi2Error && logged("initialization mode"), last);
    i = 9;
    CHECK(fmi2SetInteger(c, &mode, 1, &i) == fmi2Error && logged("3 (torque)"), last);
    i = 0;
    CHECK(fmi2SetInteger(c, &mode, 1, &i) == fmi2OK, "enumeration by Integer");
    CHECK(fmi2GetBoolean(c, &flag, 1, &yes) == fmi2OK, "a flag");
    CHECK(fmi2GetString(c, &mass, 1, &none) == fmi2Error && logged("not String"), last);
    CHECK(fmi2GetString(c, &mass, 0, &none) == fmi2OK, "no strings asked");
    CHECK(fmi2DoStep(c, 0.0, T, 1) == fmi2Error && logged("instantiated"), last);
    CHECK(fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0) == fmi2OK, "setup");
    CHECK(fmi2EnterInitializationMode(c) == fmi2OK, "enter");
    CHECK(fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0) == fmi2Error, "setup too late");
    CHECK(fmi2GetReal(c, &fx, 1, &x) == fmi2OK && isfinite(x), "an output at the start");
    CHECK(fmi2ExitInitializationMode(c) == fmi2OK, "exit");
    CHECK(fmi2DoStep(c, 0.0, 0.005, 1) == fmi2Error && logged("not a whole multiple"), last);
    {
        /* inputs while stepping: NaN and infinities refused too */
        const fmi2ValueReference in_vr = RR_FMU_VR_INPUT + RR_FMU_IN_ROLLER_SPEED;
        x = -HUGE_VAL;
        CHECK(fmi2SetReal(c, &in_vr, 1, &x) == fmi2Error
              && logged("roller_speed_ref = -inf: the value must be a finite number"), last);
        x = NAN;
        CHECK(fmi2SetReal(c, &in_vr, 1, &x) == fmi2Error && logged("roller_speed_ref = nan"),
              last);
    }
    for (k = 0; k < 20; k++)
        CHECK(fmi2DoStep(c, k * T, T, 1) == fmi2OK, "step");
    CHECK(fmi2GetInteger(c, &status_vr, 1, &i) == fmi2OK && i == 0, "sample status");
    CHECK(fmi2GetRealStatus(c, fmi2LastSuccessfulTime, &t) == fmi2OK && fabs(t - 20 * T) < 1e-12,
          "last successful time");
    CHECK(fmi2GetBooleanStatus(c, fmi2Terminated, &yes) == fmi2OK && !yes, "not terminated");
    CHECK(fmi2GetStatus(c, fmi2DoStepStatus, NULL) == fmi2Discard, "no pending status");
    CHECK(fmi2CancelStep(c) == fmi2Error && fmi2GetDirectionalDerivative(c, NULL, 0, NULL, 0,
                                                                           NULL, NULL)
                                                == fmi2Error, "not provided");

    /* states: get, step, set back, step again: the same; as bytes in another instance */
    CHECK(fmi2GetFMUstate(c, &s) == fmi2OK && s, "get state");
    CHECK(fmi2GetFMUstate(c, &s) == fmi2OK, "get state into the same");
    CHECK(fmi2SerializedFMUstateSize(c, s, &size) == fmi2OK && size > sizeof(rr_fmu_state),
          "size");
    bytes = malloc(size);
    CHECK(fmi2SerializeFMUstate(c, s, bytes, size - 1) == fmi2Error && logged("bytes"), last);
    CHECK(fmi2SerializeFMUstate(c, s, bytes, size) == fmi2OK, "serialize");
    for (k = 20; k < 60; k++)
        fmi2DoStep(c, k * T, T, 1);
    for (k = 0; k < 50; k++) {
        const fmi2ValueReference vr = RR_FMU_VR_RECORD + 1 + (fmi2ValueReference)(k % 27);
        fmi2GetReal(c, &vr, 1, &a[k]);
    }
    CHECK(fmi2SetFMUstate(c, s) == fmi2OK, "set state");
    for (k = 20; k < 60; k++)
        fmi2DoStep(c, k * T, T, 1);
    for (k = 0; k < 50; k++) {
        const fmi2ValueReference vr = RR_FMU_VR_RECORD + 1 + (fmi2ValueReference)(k % 27);
        fmi2GetReal(c, &vr, 1, &b[k]);
    }
    CHECK(memcmp(a, b, sizeof a) == 0, "the state reproduces the run");
    d = fmi2Instantiate("b", fmi2CoSimulation, "{test-fmi2}", "", &cb, 0, 0);
    bytes[10] ^= 1;
    CHECK(fmi2DeSerializeFMUstate(d, bytes, size, &s2) == fmi2Error && !s2
          && logged("not a state of this FMU"), last);
    bytes[10] ^= 1;
    CHECK(fmi2DeSerializeFMUstate(d, bytes, size - 1, &s2) == fmi2Error, "short");
    CHECK(fmi2DeSerializeFMUstate(d, bytes, size, &s2) == fmi2OK && s2, "deserialize");
    CHECK(fmi2SetFMUstate(d, s2) == fmi2OK, "set in another instance");
    for (k = 20; k < 60; k++)
        fmi2DoStep(d, k * T, T, 1);
    for (k = 0; k < 50; k++) {
        const fmi2ValueReference vr = RR_FMU_VR_RECORD + 1 + (fmi2ValueReference)(k % 27);
        fmi2GetReal(d, &vr, 1, &b[k]);
    }
    CHECK(memcmp(a, b, sizeof a) == 0, "the bytes reproduce the run elsewhere");
    CHECK(fmi2FreeFMUstate(c, &s) == fmi2OK && s == NULL, "free state");
    CHECK(fmi2FreeFMUstate(d, &s2) == fmi2OK, "free state 2");
    CHECK(fmi2SetFMUstate(c, NULL) == fmi2Error, "set NULL state");
    free(bytes);

    CHECK(fmi2Terminate(c) == fmi2OK, "terminate");
    CHECK(fmi2DoStep(c, 60 * T, T, 1) == fmi2Error, "step after terminate");
    CHECK(fmi2Reset(c) == fmi2OK, "reset");
    CHECK(fmi2EnterInitializationMode(c) == fmi2OK && fmi2ExitInitializationMode(c) == fmi2OK
          && fmi2DoStep(c, 0.0, 10 * T, 1) == fmi2OK, "again after reset");
    /* NULL instances: an error, nothing else */
    CHECK(fmi2DoStep(NULL, 0.0, T, 1) == fmi2Error && fmi2GetReal(NULL, &fx, 1, &x) == fmi2Error
          && fmi2Reset(NULL) == fmi2Error, "NULL instance");
    fmi2FreeInstance(NULL);
    fmi2FreeInstance(c);
    fmi2FreeInstance(d);
    CHECK(nlog > 10, "messages logged");
    return rr_test_summary();
}
